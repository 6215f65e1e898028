"""Effects that time records alone show and smooth terms in position or speed miss: a force periodic
in time (a pump, a spindle or a fan's unbalance coupled into the table, mains hum in the current
sensor), friction local to one place on the stroke (a damaged or contaminated spot, a cable-chain
kink) and friction that drifts within a run (the lubricant warming up).  Each is a few regression
columns fitted jointly with the rigid baseline :math:`f = M \\ddot q + F_v \\dot q + F_c
\\operatorname{sgn}\\dot q + f_0` (Gautier's inverse dynamic identification model) with nonlinear
shape parameters found on the residual of the model so far (a scan) and then refined on the joint
least-squares RSS (:class:`.base.Shape` ``search``):

* ``time_periodic``: :math:`a \\sin 2\\pi f t + b \\cos 2\\pi f t`, amplitude
  :math:`\\sqrt{a^2+b^2}`; ``f`` from the residual's line spectrum (Lomb-Scargle least-squares
  periodogram on the regression rows, N. R. Lomb, Astrophys. Space Sci. 39 (1976) 447-462), then
  refined by golden section within one frequency bin. The phase is each run's own (a pump does not
  start with the record): a held-out run keeps the amplitude and frequency and takes its own phase
  (:data:`.base.TimeModel` ``per_run``).
* ``local_friction``: :math:`h\\, e^{-(q - x_0)^2/2w^2} \\operatorname{sgn}\\dot q`: a Gaussian bump
  of height ``h`` in the Coulomb level at ``x0``, standard width ``w``; (x0, w) from a 2-D grid on
  the residual, then refined.
* ``friction_drift``: :math:`A\\, e^{-t/\\tau} \\operatorname{sgn}\\dot q`, t from the start of each
  run (every run is taken to start from the same rest, e.g. after a pause): a Coulomb level that
  settles with time constant tau; tau by the log grid and golden section of the other shape
  parameters.
"""

from __future__ import annotations

import math

import numpy as np

from .base import Effect, Shape, Term, TimeModel, register_effect

GOLDEN = (math.sqrt(5) - 1) / 2
PERIODS = 20.0  # a line is resolved when the run holds this many of its periods


def golden(f, a: float, b: float, it: int = 22) -> float:
    """Minimum of ``f`` on [a, b] by golden section (``it`` steps)."""
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(it):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - GOLDEN * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLDEN * (b - a)
            fd = f(d)
    return (a + b) / 2


# ------------------------------------------------------------------------------------------ time-
# periodic
def frequency_band(t_span: float, proc, fit: bool = True) -> tuple:
    """(lo, hi) [Hz] a record can show a line in: at least 20 periods in the run (its frequency bin
    1/span is then 5 % of the frequency, which the refinement narrows to better than 2 %) and above
    the motion bandwidth (the moves themselves fill the spectrum below it); below 0.6x the position
    filter's cut-off, where its |H|^2 = 1/(1 + (f/f_c)^8) still passes 98 % (a line above the loop's
    bandwidth moves the table, and an acceleration the filter attenuates would leave part of it in
    the line) and below 0.9x the decimation cut-off.  ``fit=False``: the band a line can be seen in
    (its frequency, not its amplitude), up to 0.9x the decimation cut-off."""
    hi = min(0.6 * proc.fc, 0.9 * proc.fdec) if fit else 0.9 * proc.fdec
    return max(PERIODS / t_span, 1.5 * proc.f_motion), hi


def line_scan(
    t: np.ndarray, r: np.ndarray, lo: float, hi: float, oversample: float = 4.0, step=None
) -> tuple:
    """Least-squares periodogram (Lomb-Scargle) of ``r`` at the times ``t``: (frequencies, share of
    the sum of squares the pair sin, cos 2 pi f t holds at each), on a grid ``oversample`` points
    per 1/span.  Rows on a uniform time grid with gaps (the kept regression rows) take the FFT form
    of the same sums (W. H. Press, G. B. Rybicki, Astrophys. J. 338 (1989) 277-280), exact on a
    finer grid, interpolated to this one.  ``step`` [s]: the record's sample period, the grid the
    rows lie on when their smallest gap is not one (the windows of a long record start at any
    sample, not at a multiple of the decimation)."""
    span = float(np.ptp(t)) or 1.0
    freqs = np.arange(lo, hi, 1.0 / (oversample * span))
    rc = r - r.mean()
    rr = float(rc @ rc) or 1.0
    if len(freqs) * len(t) > FFT_SCAN_WORK:
        for dt, tol in ((float(np.min(np.diff(t))), 1e-3), (step, 0.02)):
            k = _grid_index(t, dt, tol) if dt else None
            if k is not None:
                return freqs, _fft_scan(k, dt, rc, freqs, oversample) / rr
    out = np.zeros(len(freqs))
    for i0 in range(0, len(freqs), 128):
        ph = 2.0 * np.pi * np.outer(freqs[i0 : i0 + 128], t)
        s, c = np.sin(ph), np.cos(ph)
        ss, cc, sc = (s * s).sum(1), (c * c).sum(1), (s * c).sum(1)
        bs, bc = s @ rc, c @ rc
        det = ss * cc - sc * sc + 1e-12
        out[i0 : i0 + 128] = (cc * bs * bs - 2 * sc * bs * bc + ss * bc * bc) / det / rr
    return freqs, out


FFT_SCAN_WORK = 4_000_000  # frequencies x rows above which the scan takes the FFT form


def _grid_index(t: np.ndarray, dt: float, tol: float = 1e-3):
    """Integer sample indices of ``t`` on the grid of step ``dt`` (within ``tol`` of a step), or
    None when it is not on one."""
    d = np.diff(t)
    if len(d) == 0 or not np.min(d) > 0 or not dt > 0:
        return None
    k = (t - t[0]) / dt
    ki = np.rint(k)
    return ki.astype(np.int64) if np.max(np.abs(k - ki)) < tol else None


def _fft_scan(
    k: np.ndarray, dt: float, rc: np.ndarray, freqs: np.ndarray, oversample: float
) -> np.ndarray:
    """The Lomb-Scargle sums of :func:`line_scan` (times k dt) from two FFTs: of the residual and of
    the sampling mask, the latter at twice the frequency for the sin^2, cos^2 and sin cos sums."""
    n = int(k[-1]) + 1
    m = 1 << int(math.ceil(math.log2(2.0 * oversample * n)))
    fm = np.arange(m // 2 + 1) / (m * dt)
    top = min(m // 2, int(np.searchsorted(fm, freqs[-1] if len(freqs) else 0.0)) + 2)
    bot = max(0, int(np.searchsorted(fm, freqs[0] if len(freqs) else 0.0)) - 2)
    j = np.arange(bot, top)
    # the mask's spectrum at 2 j (mod m): above m/2 the conjugate of its mirror
    i2 = (2 * j) % m
    lo2 = i2 <= m // 2
    # real input: half spectra (rfft), one at a time, only the bins used kept (a long record's grid
    # holds millions of samples)
    x = np.zeros(m)
    x[k] = rc
    X = np.fft.rfft(x)[j]
    x[:] = 0.0
    x[k] = 1.0
    Wm = np.fft.rfft(x)
    del x
    w2 = np.where(lo2, Wm[np.minimum(i2, m // 2)], np.conj(Wm[np.minimum((m - i2) % m, m // 2)]))
    del Wm
    bc, bs = X.real, -X.imag
    c2, s2 = w2.real, -w2.imag
    nk = float(len(k))
    cc, ss, sc = 0.5 * (nk + c2), 0.5 * (nk - c2), 0.5 * s2
    det = ss * cc - sc * sc + 1e-12
    score = (cc * bs * bs - 2 * sc * bs * bc + ss * bc * bc) / det
    return np.interp(freqs, fm[j], score)


def _freq_search(rows, r0, rss) -> dict:
    t = rows.sig["t"][rows.keep]
    lo, hi = frequency_band(float(np.ptp(t)), rows.proc)
    if hi <= lo:
        return {"freq": lo}
    freqs, score = line_scan(t, r0, lo, hi, step=1.0 / rows.proc.fs)
    f0 = float(freqs[int(np.argmax(score))])
    df = 1.0 / float(np.ptp(t))
    return {"freq": golden(lambda f: rss({"freq": f}), f0 - 0.5 * df, f0 + 0.5 * df)}


def _periodic_short(ctx) -> str:
    t = ctx.rows.sig["t"][ctx.rows.keep]
    span = float(np.ptp(t))
    lo, hi = frequency_band(span, ctx.rows.proc)
    return (
        ""
        if hi > lo
        else (
            f"{span:.3g} s of motion resolves no line: {PERIODS:g} periods need "
            f"{PERIODS / hi:.3g} s at the "
            f"highest frequency fitted, {hi:.3g} Hz (0.6x the position filter's cut-off)"
        )
    )


def pair_amplitude(s, c):
    """The amplitude of a sin, cos pair of fitted coefficients named ``s`` and ``c``."""
    return lambda value: math.hypot(value(s), value(c))


def pair_implausible(s, c, what):
    """The plausibility check of a force line (a sin, cos pair ``s``, ``c``): implausible when its
    amplitude exceeds the whole Coulomb friction."""
    amplitude = pair_amplitude(s, c)

    def check(value, fc, fv):
        a = amplitude(value)
        return (
            [f"{what} of amplitude {a:.4g} beyond {fc:.4g} (the whole Coulomb friction)"]
            if a > fc
            else []
        )

    return check


def _periodic(trig):
    return lambda sig, proc, shape: trig(2.0 * math.pi * shape["freq"] * sig["t"])


@register_effect
class TimePeriodic(Effect):
    """A force periodic in time at a frequency that does not move with speed or position."""

    name = "time_periodic"
    title = (
        "a force periodic in time (a pump, spindle or fan unbalance, mains hum in the current "
        "sensor)"
    )
    time = TimeModel(
        "a force periodic in time, not in position (a pump, spindle or fan unbalance, mains hum)",
        (
            Term(
                "ps",
                "periodic force, sin(2 pi f t) coefficient",
                "effort",
                _periodic(np.sin),
                simulated=False,
            ),
            Term(
                "pc",
                "periodic force, cos(2 pi f t) coefficient",
                "effort",
                _periodic(np.cos),
                simulated=False,
            ),
        ),
        shape=Shape(
            "freq",
            "frequency of the periodic force (spectrum, refined)",
            "frequency",
            search=_freq_search,
        ),
        skip=_periodic_short,
        too_short=_periodic_short,
        implausible=pair_implausible("ps", "pc", "a periodic force"),
        evidence="a record at rest in position control with the suspected source running: the line "
        "stays",
        derived=(
            (
                "amp",
                "amplitude of the periodic force sqrt(ps^2 + pc^2)",
                "effort",
                pair_amplitude("ps", "pc"),
            ),
        ),
        per_run=True,
    )


# ------------------------------------------------------------------------------------------ local
# friction
def bump(q: np.ndarray, x0: float, w: float) -> np.ndarray:
    """Gaussian bump exp(-(q - x0)^2 / 2 w^2)."""
    return np.exp(-0.5 * ((q - x0) / w) ** 2)


def width_range(stroke_q: float) -> tuple:
    """Widths a local spot is searched over: 0.5 % to 4 % of the stroke (4 to 32 mm on 0.8 m)."""
    return 0.005 * stroke_q, 0.04 * stroke_q


def spot_scan(q: np.ndarray, cols: np.ndarray, r: np.ndarray, stroke_q: float) -> tuple:
    """2-D grid (position x width) of the residual ``r``'s share held by bump(q) times each column
    of ``cols`` (n, k) fitted jointly: (x0 grid, widths, share (nx, nw)).  Positions every half of
    the narrowest width."""
    w_lo, w_hi = width_range(stroke_q)
    widths = np.geomspace(w_lo, w_hi, 9)
    xs = np.arange(q.min(), q.max() + 0.5 * w_lo, 0.5 * w_lo)
    rc = r - r.mean()
    rr = float(rc @ rc) or 1.0
    out = np.zeros((len(xs), len(widths)))
    for j, w in enumerate(widths):
        for i0 in range(0, len(xs), 64):
            B = np.exp(-0.5 * ((q[None, :] - xs[i0 : i0 + 64, None]) / w) ** 2)  # (nx, n)
            G = B[:, :, None] * cols[None, :, :]  # (nx, n, k)
            A = np.einsum("xnk,xnl->xkl", G, G) + 1e-9 * np.eye(cols.shape[1])
            b = np.einsum("xnk,n->xk", G, rc)
            out[i0 : i0 + 64, j] = (
                np.einsum("xk,xk->x", b, np.linalg.solve(A, b[..., None])[..., 0]) / rr
            )
    return xs, widths, out


def _spot_search(rows, r0, rss) -> dict:
    q = rows.sig["q"][rows.keep]
    sg = np.sign(rows.sig["v"][rows.keep])[:, None]
    xs, widths, score = spot_scan(q, sg, r0, rows.proc.stroke_q)
    i, j = np.unravel_index(int(np.argmax(score)), score.shape)
    x0, lw = float(xs[i]), math.log(float(widths[j]))
    step = math.log(widths[1] / widths[0])
    a_lo, a_hi = math.log(widths[0]), math.log(widths[-1])
    # coordinate refinement on the joint RSS: position, then width (within its range)
    for _ in range(2):
        w = math.exp(lw)
        x0 = golden(lambda x, w=w: rss({"x0": x, "width": w}), x0 - w, x0 + w, 16)
        lw = golden(
            lambda a, x0=x0: rss({"x0": x0, "width": math.exp(a)}),
            max(lw - step, a_lo),
            min(lw + step, a_hi),
            14,
        )
    return {"x0": x0, "width": math.exp(lw)}


def _spot_skip(ctx) -> str:
    return "the record covers less than 10 % of the stroke" if ctx.span < 0.1 * ctx.stroke_q else ""


def _spot_implausible(value, fc, fv) -> list:
    h = value("hs")
    if h <= 0.0:
        return [f"a local friction height {h:.4g} not positive (a spot that drives the axis)"]
    return (
        [f"a local friction height {h:.4g} beyond {2 * fc:.4g} (twice the Coulomb friction)"]
        if h > 2 * fc
        else []
    )


@register_effect
class LocalFriction(Effect):
    """Friction raised over a short stretch of the stroke, both directions."""

    name = "local_friction"
    title = (
        "friction raised at one place on the stroke (a damaged or contaminated spot, a cable-chain "
        "kink)"
    )
    time = TimeModel(
        "friction raised at one place on the stroke (a damaged or contaminated spot, a cable-chain "
        "kink)",
        (
            Term(
                "hs",
                "local friction height",
                "effort",
                lambda sig, proc, shape: (
                    np.sign(sig["v"]) * bump(sig["q"], shape["x0"], shape["width"])
                ),
            ),
        ),
        shape=Shape(
            "x0",
            "position of the local friction (grid, then refined)",
            "position",
            search=_spot_search,
            also=(("width", "standard width of the local friction", "position"),),
        ),
        skip=_spot_skip,
        implausible=_spot_implausible,
        evidence="slow constant-speed passes over the place in both directions: the bump stays at "
        "the same millimetres",
    )


# ------------------------------------------------------------------------------------------
# friction drift
def _tau_bounds(sig, proc) -> tuple:
    """Time constants a run can show: from 0.3 s to twice the run's length."""
    return 0.3, 2.0 * float(np.ptp(sig["t"]))


def _drift_implausible(value, fc, fv) -> list:
    a = value("Ad")
    return (
        [f"a friction drift of {a:.4g} beyond {fc:.4g} (the whole Coulomb friction)"]
        if abs(a) > fc
        else []
    )


@register_effect
class FrictionDrift(Effect):
    """A Coulomb level that settles within a run: A exp(-t/tau) sgn(v)."""

    name = "friction_drift"
    title = "friction drifts within a run (warm-up of the lubricant)"
    time = TimeModel(
        "friction settles within the run (warm-up of the lubricant: high at the start)",
        (
            Term(
                "Ad",
                "friction drift amplitude at the run's start",
                "effort",
                lambda sig, proc, shape: np.sign(sig["v"]) * np.exp(-sig["t"] / shape["tau"]),
            ),
        ),
        shape=Shape(
            "tau", "time constant of the friction drift (1-D search)", "time", bounds=_tau_bounds
        ),
        implausible=_drift_implausible,
        evidence="the same run repeated warm (after a warm-up cycle): the drift is gone",
    )
