"""Residual signatures that localise what a time-record fit leaves: a line in time (frequency,
amplitude, and whether it stays at one frequency across speeds or moves with the speed), a spot on
the stroke (where, how wide, in which directions) and a decay within the run (time constant, a
friction or a force).

Each is an added-variable probe of :mod:`.residual` (share of the residual against the model's
columns, chi-square with the effective number of rows) scanned over its nonlinear parameter, and
pays for the scan with a Bonferroni factor of the number of independent trials: frequencies 1/span
apart, positions a narrowest width apart times the widths, the time constants tried.  The effective
number of rows is that of the residual with the probe's fit taken out (``neff``, a function of a
residual): the noise's correlation, not that of the structure tested (a slow drift left in the
residual would make its own lag-1 correlation near one and hide itself).  The scans reuse the
effects' own (:mod:`.effects.disturbance`); the probe's columns are computed as the regression's
(filtered, decimated).
"""

from __future__ import annotations

import math

import numpy as np

from .. import residual as rs
from ..effects.disturbance import bump, frequency_band, golden, line_scan, spot_scan
from .estimators import predict

# a line is at a fixed frequency when every speed group holds at least this share of its amplitude
TIED_RATIO = 0.5
# a spot: at least this many passes over it, this share of them agreeing in sign
PASSES_MIN, AGREE_MIN = 3, 0.8
DECAY_TAUS = np.geomspace(0.3, 30.0, 13)  # [s] time constants the decay probe tries


def _blocks(runs, pooled, cols):
    """Per-run copies of ``cols(rw)`` (a run's own coefficients: its own phase or level),
    stacked."""
    G = pooled(runs, cols)
    k = G.shape[1]
    out = np.zeros((G.shape[0], k * len(runs)))
    i0 = 0
    for j, rw in enumerate(runs):
        out[i0 : i0 + rw.n, j * k : (j + 1) * k] = G[i0 : i0 + rw.n]
        i0 += rw.n
    return out


def _rescore(p: rs.Probe, r, G, W, neff, scans: int) -> rs.Probe:
    """``p`` with its significance on the effective rows of the residual with its own fit taken
    out."""
    Go = rs.orthogonal(G, W)
    coef, *_ = np.linalg.lstsq(Go, r, rcond=None)
    n = neff(r - Go @ coef)
    chi = n * p.share / max(1.0 - p.share, 1e-12)
    p.log10_p = min(rs.log10_p_chi2(chi, p.k) + math.log10(max(scans, 1)), 0.0)
    return p


def _joint(r, G, W) -> np.ndarray:
    """Coefficients of ``G`` in the least-squares fit of ``r`` on the model's span and ``G``
    together."""
    coef, *_ = np.linalg.lstsq(np.column_stack([W.Q, G]), r, rcond=None)
    return coef[W.Q.shape[1] :]


def line_probe(runs, r, W, neff, pooled) -> rs.Probe:
    """The strongest line of the residual in time (per-run phase), its amplitude, and whether it is
    tied to the
    speed: its amplitude is fitted in three speed groups (terciles of |v|); a line present in each
    at half its amplitude or more stays at a fixed frequency, else it appears at one speed only (a
    ripple in position seen at v/P) and the period in position v/f is given."""
    proc = runs[0].proc
    spans = [float(np.ptp(rw.sig["t"][rw.keep])) for rw in runs]
    lo, hi = frequency_band(max(spans), proc, fit=False)
    if hi <= lo:
        return rs.Probe("line", 0.0, 0.0, 2, {})
    i0, score, freqs = 0, None, None
    for rw in runs:
        t = rw.sig["t"][rw.keep]
        f, s = line_scan(
            t,
            r[i0 : i0 + rw.n],
            lo,
            hi,
            oversample=4.0 * max(spans) / max(float(np.ptp(t)), 1e-9),
            step=1.0 / proc.fs,
        )
        rr = float(np.sum((r[i0 : i0 + rw.n] - r[i0 : i0 + rw.n].mean()) ** 2))
        m = min(len(f), len(score)) if score is not None else len(f)
        score = s[:m] * rr if score is None else score[:m] + s[:m] * rr
        freqs = f[:m]
        i0 += rw.n
    scans = max(1, int(len(freqs) / 4))

    def lines(f):
        def cols(rw):
            ph = 2.0 * np.pi * f * rw.sig["t"]
            return np.column_stack([np.sin(ph), np.cos(ph)])

        return _blocks(runs, pooled, cols)

    f0, df = float(freqs[int(np.argmax(score))]), 1.0 / max(spans)
    f0 = golden(lambda f: -rs.share(r, lines(f), W), f0 - 0.5 * df, f0 + 0.5 * df, 16)
    G = lines(f0)
    p = _rescore(rs.probe("line", r, G, W, 1.0, scans=scans, frequency=f0), r, G, W, neff, scans)
    coef = _joint(r, G, W)
    p.detail["amplitude"] = float(math.hypot(coef[0], coef[1]))  # the estimation run's
    v = np.abs(np.concatenate([rw.sig["v"][rw.keep] for rw in runs]))
    edges = np.quantile(v, [1 / 3, 2 / 3])
    grp = np.searchsorted(edges, v)
    amps, speeds = [], []
    for g in range(3):
        m = grp == g
        c, *_ = np.linalg.lstsq(G[m], r[m] - r[m].mean(), rcond=None)
        amps.append(
            float(
                np.sqrt(
                    np.mean([math.hypot(c[2 * j], c[2 * j + 1]) ** 2 for j in range(len(runs))])
                )
            )
        )
        speeds.append(float(np.median(v[m])))
    top = max(amps) or 1.0
    p.detail["fixed"] = min(amps) >= TIED_RATIO * top
    k = int(np.argmax(amps))
    p.detail["speed"] = speeds[k]
    p.detail["group_amplitudes"] = amps
    p.detail["period"] = speeds[k] / f0
    # a line above it is seen, not fitted
    p.detail["fit_band"] = frequency_band(max(spans), proc)[1]
    return p


def spot_probe(runs, r, W, neff, pooled) -> rs.Probe:
    """A narrow bump over position in the residual, fitted separately in + and - travel (2 columns);
    where (x0), how wide (w) and the height in each direction (friction convention: positive opposes
    the motion)."""
    sq = runs[0].proc.stroke_q
    q = np.concatenate([rw.sig["q"][rw.keep] for rw in runs])
    s = np.sign(np.concatenate([rw.sig["v"][rw.keep] for rw in runs]))
    cols = np.column_stack([(s > 0).astype(float), (s < 0).astype(float)])
    xs, widths, score = spot_scan(q, cols, r, sq)
    i, j = np.unravel_index(int(np.argmax(score)), score.shape)
    x0, w = float(xs[i]), float(widths[j])
    scans = score.size

    def gcols(rw):
        b, sg = bump(rw.sig["q"], x0, w), np.sign(rw.sig["v"])
        return np.column_stack([b * (sg > 0), b * (sg < 0)])

    G = pooled(runs, gcols)
    p = _rescore(rs.probe("spot", r, G, W, 1.0, scans=scans, x0=x0, width=w), r, G, W, neff, scans)
    # a direction the rows cross the spot in
    seen = [float(G[:, k] @ G[:, k]) >= 1.0 for k in (0, 1)]
    coef = np.zeros(2)
    if any(seen):
        coef[np.array(seen)] = _joint(r, G[:, np.array(seen)], W)
    # the friction each direction adds (opposing the motion)
    up, down = float(coef[0]), -float(coef[1])
    p.detail["crossed"] = "both" if all(seen) else "+" if seen[0] else "-"
    p.detail.update(height_plus=up, height_minus=down)
    # a spot is crossed on every pass: the height fitted on each pass over x0 +- 2w alone must agree
    # in sign (a transient of one move that happens to end there does not)
    near = np.abs(q - x0) < 2.0 * w
    g = np.exp(-0.5 * ((q - x0) / w) ** 2) * s
    starts = np.nonzero(near & ~np.r_[False, near[:-1]])[0]
    ends = np.nonzero(near & ~np.r_[near[1:], False])[0]
    sign = 1.0 if up + down >= 0 else -1.0
    votes = []
    for a, b in zip(starts, ends + 1):
        gg = float(g[a:b] @ g[a:b])
        if b - a >= 3 and gg > 0.5:
            votes.append(sign * float(g[a:b] @ (r[a:b] - np.median(r))) / gg > 0)
    p.detail["passes"] = len(votes)
    p.detail["agree"] = float(np.mean(votes)) if votes else 0.0
    if len(votes) < PASSES_MIN or p.detail["agree"] < AGREE_MIN:
        p.log10_p = 0.0  # not a spot on the stroke: too few passes agree
    big = max(abs(up), abs(down))
    p.detail["directions"] = (
        "both" if min(abs(up), abs(down)) >= 0.3 * big else "+" if abs(up) > abs(down) else "-"
    )
    # opposes the motion both ways (a force of one sign does not); when crossed one way only, its
    # sign there
    p.detail["friction"] = up * down > 0 if all(seen) else up + down > 0
    return p


def decay_probe(runs, r, W, neff, pooled) -> rs.Probe:
    """A decay within the run, exp(-t/tau) and sgn(v) exp(-t/tau) (t from each run's start), the
    best of :data:`DECAY_TAUS` that a run can show (tau up to twice its length); ``friction_share``:
    the part that follows the direction."""
    span = max(float(np.ptp(rw.sig["t"])) for rw in runs)
    taus = [t for t in DECAY_TAUS if t <= 2.0 * span]
    best = None
    for tau in taus:

        def cols(rw, tau=tau):
            e = np.exp(-rw.sig["t"] / tau)
            return np.column_stack([e, np.sign(rw.sig["v"]) * e])

        G = pooled(runs, cols)
        p = rs.probe("decay", r, G, W, 1.0, scans=len(taus), tau=float(tau))
        if best is None or p.share > best[0].share:
            best = (p, G)
    p, G = best
    p = _rescore(p, r, G, W, neff, len(taus))
    force, fric = _joint(r, G, W)
    p.detail.update(amplitude=float(fric), force_amplitude=float(force))
    p.detail["friction_share"] = fric**2 / (fric**2 + force**2) if fric or force else 0.0
    return p


# a spectral peak is a steady line when one sin, cos pair through the run holds this share
STEADY_SHARE = 0.5


def steady_line(rows, est, f_peak: float):
    """(frequency, share) when one sin, cos pair near ``f_peak`` (refined on a fine scan) holds at
    least :data:`STEADY_SHARE` of the residual of ``est`` on ``rows``: a line with one phase through
    the run (a periodic disturbance), which a resonance excited by each move (its own phase each
    time) is not; else None."""
    if not f_peak > 0:
        return None
    t = rows.sig["t"][rows.keep]
    r = rows.y - predict(rows, est)
    df = 1.0 / max(float(np.ptp(t)), 1e-9)

    def share(f):
        ph = 2.0 * np.pi * f * t
        return rs.share(r, np.column_stack([np.sin(ph), np.cos(ph)]), None)

    # the resolution of the spectrum the peak comes from (Welch, 512 samples)
    bin_ = rows.proc.fs / 512.0
    freqs, sc = line_scan(
        t, r, max(f_peak - 2.0 * bin_, df), f_peak + 2.0 * bin_, step=1.0 / rows.proc.fs
    )
    f1 = float(freqs[int(np.argmax(sc))])
    f0 = golden(lambda f: -share(f), f1 - 0.5 * df, f1 + 0.5 * df, 16)
    s = share(f0)
    return (f0, s) if s >= STEADY_SHARE else None
