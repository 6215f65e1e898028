"""What a fit leaves unexplained: tests of the final residual for structure against noise, and the
structure's signature in words (what it looks like, what could cause it, which measurement would
separate the causes).

A *probe* is a set of columns G (functions of the recorded factors: position, velocity, direction,
time, ...).  Its share of the residual r is the added-variable (partial regression) statistic (R. D.
Cook, S. Weisberg, *Residuals and Influence in Regression*, Chapman & Hall 1982): G is first made
orthogonal to the fitted model's own columns W, so a probe is never credited with what the model can
already absorb by refitting, then

.. math:: s = \\|P_{G_\\perp} r\\|^2 / \\|r\\|^2, \\qquad
          \\chi^2 = n_{eff}\\, s/(1 - s) \\sim \\chi^2_k \\text{ under white noise}

with :math:`n_{eff} = n (1 - \\rho_1)/(1 + \\rho_1)` (lag-1 autocorrelation :math:`\\rho_1` of the
residual in row order: filtered, decimated rows are not independent).  A probe scanned over a
parameter (a period) pays for the scan with a Bonferroni factor.  Structure *remains* when a probe
holds at least ``MIN_SHARE`` of the residual variance at ``log10 p < LOG10_P``.  Numpy only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

MIN_SHARE = 0.10  # a signature must hold at least this share of the residual variance ...
LOG10_P = -8.0  # ... at this significance (after the scan's Bonferroni factor)


@dataclass
class Probe:
    """One structure test of the residual."""

    # 'position_periodic' | 'velocity' | 'position' | 'time' | 'reversal' | 'acceleration' | 'run' |
    # 'load' (time records) or a recorded factor's name (tables)
    kind: str
    share: float  # share of the residual variance it explains [-]
    log10_p: float  # significance under white noise (n_eff, Bonferroni for scans)
    k: int  # columns
    detail: dict = field(default_factory=dict)  # kind-specific: period, shape, worst level, ...

    @property
    def significant(self) -> bool:
        return self.share >= MIN_SHARE and self.log10_p < LOG10_P


class Span:
    """An orthonormal basis Q of the span of a model's columns W (computed once, rank-safe by SVD),
    so the many probes of one residual project with ``Q Q^T`` instead of a least-squares solve
    each."""

    def __init__(self, W: np.ndarray):
        sc = np.linalg.norm(W, axis=0)
        sc[sc == 0] = 1.0
        u, sv, _ = np.linalg.svd(W / sc, full_matrices=False)
        self.Q = u[:, sv > 1e-10 * (sv.max() if sv.size else 0.0)]
        self.size = W.size


def orthogonal(G: np.ndarray, W) -> np.ndarray:
    """G minus its projection on the span of W (an array, column-scaled and rank-safe, or a
    :class:`Span`)."""
    G = np.asarray(G, dtype=float)
    if G.ndim == 1:
        G = G[:, None]
    if isinstance(W, Span):
        return G - W.Q @ (W.Q.T @ G)
    if W is None or W.size == 0:
        return G - G.mean(axis=0)
    sc = np.linalg.norm(W, axis=0)
    sc[sc == 0] = 1.0
    coef, *_ = np.linalg.lstsq(W / sc, G, rcond=None)
    return G - (W / sc) @ coef


def share(r: np.ndarray, G: np.ndarray, W: np.ndarray | None = None) -> float:
    """Share of ``r``'s sum of squares explained by the columns of ``G`` made orthogonal to
    ``W``."""
    Go = orthogonal(G, W)
    sc = np.linalg.norm(Go, axis=0)
    ok = sc > 1e-9 * (np.max(sc) if len(sc) else 1.0)
    if not ok.any():
        return 0.0
    Go = Go[:, ok] / sc[ok]
    coef, *_ = np.linalg.lstsq(Go, r, rcond=None)
    fit = Go @ coef
    rr = float(r @ r)
    return float(fit @ fit) / rr if rr > 0 else 0.0


def lag1(r: np.ndarray, breaks: np.ndarray | None = None) -> float:
    """Lag-1 autocorrelation of ``r`` in row order; pairs across ``breaks`` (True where row i+1 does
    not follow row i) are left out."""
    a, b = r[:-1], r[1:]
    if breaks is not None:
        a, b = a[~breaks], b[~breaks]
    d = math.sqrt(float(a @ a) * float(b @ b))
    return float(a @ b) / d if d > 0 else 0.0


def n_effective(n: int, rho: float) -> float:
    rho = min(max(rho, 0.0), 0.95)
    return n * (1.0 - rho) / (1.0 + rho)


def log10_p_chi2(x: float, k: int) -> float:
    """log10 of the upper tail of chi^2_k at x (Wilson-Hilferty normal approximation; tails below
    1e-300 are extended with the normal's asymptote)."""
    if x <= 0:
        return 0.0
    z = ((x / k) ** (1.0 / 3.0) - (1.0 - 2.0 / (9.0 * k))) / math.sqrt(2.0 / (9.0 * k))
    if z < 30:
        return math.log10(max(0.5 * math.erfc(z / math.sqrt(2.0)), 1e-300))
    return (-0.5 * z * z - math.log(z * math.sqrt(2.0 * math.pi))) / math.log(10.0)


def probe(
    kind: str,
    r: np.ndarray,
    G: np.ndarray,
    W: np.ndarray | None,
    n_eff: float,
    scans: int = 1,
    **detail,
) -> Probe:
    G = np.asarray(G, dtype=float)
    k = 1 if G.ndim == 1 else G.shape[1]
    s = share(r, G, W)
    chi = n_eff * s / max(1.0 - s, 1e-12)
    lp = log10_p_chi2(chi, k) + math.log10(max(scans, 1))
    return Probe(kind, s, min(lp, 0.0), k, dict(detail))


def period_scan(
    r: np.ndarray,
    q: np.ndarray,
    sgn: np.ndarray,
    columns,
    p_min: float,
    p_max: float,
    W: np.ndarray | None,
    n_eff: float,
    fixed=(),
) -> Probe:
    """Spectrum of the residual over position.  A coarse scan on a uniform grid of spatial frequency
    (spacing a quarter of 1/span, so no peak falls between grid points) with the plain columns sin,
    cos, sgn(v) sin, sgn(v) cos of 2 pi q/P at the rows ``q``, ``sgn``; then the two best periods,
    refined on a local grid, and the periods named in advance (``fixed``: the lead and its
    harmonics, no scan factor) are scored with ``columns(P)`` (the same columns computed as the
    regression's: filtered and decimated) against the model's columns W.  Returns the best as a
    'position_periodic' probe with detail ``period`` and ``friction_share`` (the share of the
    periodic part that follows the direction)."""
    span = float(np.ptp(q)) or 1.0
    df = 0.25 / span
    freqs = np.arange(1.0 / p_max, 1.0 / p_min + df, df)
    rc = r - r.mean()
    scores = np.zeros(len(freqs))
    for i0 in range(0, len(freqs), 64):  # share of the four plain columns, 64 frequencies at a time
        f = freqs[i0 : i0 + 64]
        ph = 2.0 * np.pi * np.outer(f, q)
        sn, cs = np.sin(ph), np.cos(ph)
        G = np.stack([sn, cs, sn * sgn, cs * sgn], axis=2)  # (nf, n, 4)
        Gt = G.transpose(0, 2, 1)
        A = np.matmul(Gt, G) + 1e-9 * np.eye(4)
        b = np.matmul(Gt, rc)
        scores[i0 : i0 + 64] = np.einsum("fi,fi->f", b, np.linalg.solve(A, b[..., None])[..., 0])
    scans = len(freqs)
    tops = []
    for k in np.argsort(-scores):
        if all(abs(freqs[k] - freqs[t]) > 2 * df for t in tops):
            tops.append(int(k))
        if len(tops) == 2:
            break
    trial = [(float(P), 1) for P in fixed if p_min <= P <= p_max]
    for k in tops:
        trial += [(1.0 / f, scans) for f in freqs[k] + df * np.array([-0.35, 0.0, 0.35]) if f > 0]
    best = None
    for P, sc in trial:
        G = columns(P)
        pr = probe("position_periodic", r, G, W, n_eff, scans=sc, period=float(P))
        if best is None or pr.log10_p < best[0].log10_p:
            best = (pr, G)
    pr, G = best
    s_force = share(r, G[:, :2], W)  # the columns without sgn(v): a force the same both ways
    pr.detail["friction_share"] = max(0.0, 1.0 - s_force / pr.share) if pr.share > 0 else 0.0
    return pr


def best_shape(r: np.ndarray, shapes: dict, W: np.ndarray | None) -> tuple:
    """The single column of ``shapes`` (name -> column) that explains most of ``r`` (after W):
    (name, share)."""
    scores = {nm: share(r, g, W) for nm, g in shapes.items()}
    nm = max(scores, key=scores.get)
    return nm, scores[nm]


# ------------------------------------------------------------------------------------ reduced
# tables factor of a test table -> (what the residual does, candidate causes, the measurement that
# separates them)
FACTOR_WORDS = {
    "position": (
        "varies with position",
        "a support or chain compliance that changes along the screw, guide misalignment, screw "
        "straightness",
        "repeat at more positions, and at one position with the load reversed",
    ),
    "force": (
        "varies with the load",
        "a contact stiffness (Hertz) or nut lift-off the model does not hold, a load-dependent "
        "friction",
        "vary the load in small steps at one position, both directions",
    ),
    "direction": (
        "differs with the direction",
        "lost motion (backlash) or friction hysteresis, a direction-dependent friction",
        "measure the reversal at several positions and with different lubrication or speed",
    ),
    "cycle": (
        "changes from cycle to cycle",
        "wear or run-in, warm-up, a loosening joint",
        "repeat the test cold and warm and after a rest",
    ),
    "time": (
        "drifts with time",
        "warm-up (thermal expansion, lubricant viscosity), creep",
        "repeat the test cold and warm, with a temperature sensor on the nut",
    ),
    "temperature": (
        "follows the temperature",
        "thermal expansion or lubricant viscosity",
        "hold the temperature and repeat, or vary it on purpose",
    ),
    "normal_load": (
        "grows with the guide load",
        "guide friction mu N, seals pressed harder",
        "vary the normal load independently of the axial load",
    ),
    "axial_load": (
        "grows with the axial load",
        "nut friction with load (efficiency), bearing friction",
        "vary the axial load at one speed",
    ),
    "mode": ("differs by mode", "a mode shape or mass the model lacks", "measure the mode shapes"),
    "frequency": (
        "depends on frequency",
        "a mode or damping the model lacks",
        "a finer frequency sweep around the misfit, at several positions",
    ),
}
VELOCITY_WORDS = {
    "v|v|": (
        "grows with v|v|",
        "quadratic drag, e.g. seals or lubricant churning",
        "a friction curve at constant speeds up to the maximum in both directions, repeated warm",
    ),
    "v": (
        "grows in proportion to speed",
        "viscous friction other than the catalog's",
        "a friction curve over the whole speed range",
    ),
    "low_speed": (
        "rises at low speed",
        "a Stribeck rise, breakaway",
        "many constant speeds below 10 mm/s in both directions",
    ),
    "|v|": (
        "differs by direction, growing with speed",
        "viscous friction differing by direction (a seal lip)",
        "constant-speed runs at several speeds in both directions",
    ),
    "sgn": (
        "differs by direction by a constant",
        "a gravity or cable-chain force, a Coulomb asymmetry",
        "runs in both directions at several speeds and loads",
    ),
}


def factor_probe(name: str, r: np.ndarray, values: np.ndarray, max_bins: int = 6) -> Probe:
    """Share of ``r`` (noise-weighted residual of a table: unit variance at the noise floor) held by
    the levels of one recorded factor (at most ``max_bins`` quantile bins) and the worst
    level.  Significance: with the noise known, :math:`\\chi^2 = \\sum_i n_i (\\bar r_i - \\bar r)^2
    \\sim \\chi^2_{k-1}` over the k levels."""
    values = np.asarray(values, dtype=float)
    levels = np.unique(values)
    if len(levels) > max_bins:
        edges = np.quantile(values, np.linspace(0, 1, max_bins + 1)[1:-1])
        idx = np.searchsorted(edges, values, side="right")
    else:
        idx = np.searchsorted(levels, values)
    groups = np.unique(idx)
    G = (
        np.column_stack([(idx == g).astype(float) for g in groups[1:]])
        if len(groups) > 1
        else np.zeros((len(r), 0))
    )
    if G.shape[1] == 0:
        return Probe(name, 0.0, 0.0, 0, {"factor": name})
    s = share(r, G, None)
    mu = float(np.mean(r))
    chi = sum(float(np.sum(idx == g)) * (float(np.mean(r[idx == g])) - mu) ** 2 for g in groups)
    pr = Probe(name, s, min(log10_p_chi2(chi, len(groups) - 1), 0.0), len(groups) - 1, {})
    means = [abs(float(np.mean(r[idx == g]))) for g in groups]
    g = groups[int(np.argmax(means))]
    sel = values[idx == g]
    pr.detail.update(factor=name, worst=(float(sel.min()), float(sel.max())))
    return pr
