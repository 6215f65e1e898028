"""What a time-record fit leaves unexplained: the residual of the final fit (estimation and
validation rows pooled) tested for structure over position (a period scan, the lead and its
harmonics named in advance), velocity, position along the stroke, time within a run, between runs,
the external force, travel since a reversal and acceleration (:mod:`.residual`: added-variable
shares against the noise floor), a line in time, a spot on the stroke and a decay within the run
(:mod:`.timesignature`); and the baseline residual's spectral peak that makes an extra mode a
candidate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import residual as rs
from ..effects.friction import RIPPLE_HARMONICS
from .estimators import Estimate, predict
from .regression import Rows, decimate, full_matrix, matrix
from .signal import lowpass, welch
from .signature import decay_probe, line_probe, spot_probe


def residual_peak(rows: Rows, est: Estimate) -> tuple:
    """Peak of the baseline residual spectrum between 3x the motion bandwidth and the cut-off."""
    proc = rows.proc
    segs = rows.record.segments
    W = lowpass(
        full_matrix(rows.sig, est.terms, proc, est.shape), proc.fs, proc.fdec, segments=segs
    )
    e = rows.record.effort
    if "payload" in rows.record.aux:  # a known mass's inertial force is not the model's misfit
        e = e - rows.record.aux["payload"] * rows.sig["a"]
    y = lowpass(e, proc.fs, proc.fdec, segments=segs)
    r = np.zeros(len(y))
    r[rows.keep[0] : rows.keep[-1]] = (y - W @ est.theta)[rows.keep[0] : rows.keep[-1]]
    moving = np.zeros(len(y), bool)
    moving[rows.keep] = True
    moving = np.convolve(moving, np.ones(proc.nd), mode="same") > 0
    r[~moving] = 0.0
    f, ps = welch(r, proc.fs, 512)
    band = (f >= 3.0 * proc.f_motion) & (f <= proc.fc)
    if band.sum() < 5:
        return 0.0, 0.0
    k = int(np.argmax(ps[band]))
    return float(f[band][k]), float(ps[band][k] / np.median(ps[band]))


@dataclass
class Unexplained:
    """Structure left in the final fit's residual (estimation and validation rows pooled)."""

    probes: list  # residual.Probe, every test made, most significant first
    rms: float  # residual RMS on the pooled rows [effort unit, SI]
    noise: float  # noise floor at the rows (sensor noise through the decimation filter) [SI]
    lag1: float  # lag-1 autocorrelation of the residual in row order
    n: int

    @property
    def remaining(self) -> list:
        """The significant probes (see :mod:`.residual`), largest share first."""
        return sorted([p for p in self.probes if p.significant], key=lambda p: -p.share)


def noise_floor(rows: Rows, est: Estimate | None = None) -> float:
    """Sensor noise of the effort at the regression rows, the larger of two estimates:

    * white: the raw effort's second differences (median absolute deviation, var(e1 - 2 e2 + e3) = 6
      sigma^2) through the decimation low-pass (equivalent noise bandwidth of |H|^2 = 1/(1 +
      (f/f_d)^8): 1.026 f_d).  Correlated (coloured) noise hides from second differences: its power
      sits at low frequencies, where the regression rows keep it;
    * coloured (:func:`ar_noise`): an AR(1) spectrum fitted to the effort above the motion's band,
      through the same low-pass -- the noise as the rows see it when it is correlated."""
    e = rows.record.effort
    d2 = e[2:] - 2.0 * e[1:-1] + e[:-2]
    s = 1.4826 * float(np.median(np.abs(d2 - np.median(d2)))) / math.sqrt(6.0)
    white = s * math.sqrt(min(1.0, 2.0 * 1.026 * rows.proc.fdec / rows.proc.fs))
    coloured = ar_noise(rows, est)
    return max(white, coloured) if coloured is not None else white


# periods down to the lead / 16 are scanned (a belt tooth or motor cogging through a reduction)
SHORT_PERIODS = 16
# the grid of the AR(1) coefficient fitted to the noise's spectrum
AR_RHO = np.linspace(-0.5, 0.98, 149)


def ar_noise(rows: Rows, est: Estimate | None = None):
    """RMS of the effort's noise through the decimation low-pass when the noise is coloured: an
    AR(1) spectrum S(f) = s^2 / (1 - 2 rho cos(2 pi f/fs) + rho^2) is fitted (least squares on the
    log of the averaged periodogram, a running median over 9 bins first so lines do not count) to
    the full-rate residual of ``est`` over windows of 0.256 s where the axis moves one way (the kept
    rows), above twice the motion bandwidth (where the model's own misfit, which follows the motion,
    is small); the fitted spectrum is then integrated under |H|^2 of the decimation filter, the band
    the regression rows keep.  None without an estimate or with fewer than 4 windows."""
    if est is None:
        return None
    proc = rows.proc
    rec = rows.record
    y = rec.effort + rec.external if rec.external is not None else rec.effort
    res = y - full_matrix(rows.sig, est.terms, proc, est.shape) @ est.theta
    m = 256
    good = np.zeros(rec.n, dtype=bool)
    good[rows.keep] = True
    good = np.convolve(good.astype(float), np.ones(2 * proc.nd + 1), mode="same") > 0
    win = np.hanning(m)
    ps, count, k = np.zeros(m // 2 + 1), 0, 0
    while k + m <= rec.n:
        if good[k : k + m].all():
            seg = res[k : k + m]
            ps += np.abs(np.fft.rfft((seg - seg.mean()) * win)) ** 2
            count += 1
            k += m // 2
        else:
            k += m // 4
    if count < 4:
        return None
    ps /= count * proc.fs * float(win @ win)
    f = np.fft.rfftfreq(m, 1.0 / proc.fs)
    band = (f >= max(2.0 * proc.f_motion, 4.0 * f[1])) & (f <= 0.95 * proc.fs / 2.0)
    if int(band.sum()) < 8:
        return None
    pad = np.pad(ps, 4, mode="edge")
    smooth = np.median(np.lib.stride_tricks.sliding_window_view(pad, 9), axis=1)[band]
    w = 2.0 * np.pi * f[band] / proc.fs
    logp = np.log(np.maximum(smooth, 1e-300))
    best = None
    for rho in AR_RHO:
        shape = -np.log(1.0 - 2.0 * rho * np.cos(w) + rho * rho)
        c = float(np.mean(logp - shape))
        err = float(np.sum((logp - shape - c) ** 2))
        if best is None or err < best[0]:
            best = (err, rho, c)
    _, rho, c = best
    fa = np.linspace(0.0, proc.fs / 2.0, 2049)
    wa = 2.0 * np.pi * fa / proc.fs
    sa = math.exp(c) / (1.0 - 2.0 * rho * np.cos(wa) + rho * rho)
    h2 = 1.0 / (1.0 + (fa / proc.fdec) ** 8)
    return math.sqrt(2.0 * float(np.sum(sa * h2)) * (fa[1] - fa[0]))  # welch: the two-sided density


def pooled(runs: list, full_cols) -> np.ndarray:
    """Columns computed at full rate on each run (``full_cols(rows) -> (N, k)``), decimated alike,
    stacked."""
    return np.vstack(
        [
            decimate(
                np.asarray(full_cols(r)).reshape(r.record.n, -1), r.proc, r.keep, r.record.segments
            )
            for r in runs
        ]
    )


def since_reversal(rw: Rows) -> np.ndarray:
    """Travel since the last reversal of the motion at every full-rate sample, in the
    record's coordinate: the direction is sgn(v) where the axis moves faster than the record's speed
    threshold, held through slow stretches; the travel is measured from the position where it last
    changed (from the first sample before the first reversal)."""
    q, v = rw.sig["q"], rw.sig["v"]
    d = np.where(np.abs(v) >= rw.proc.vmin, np.sign(v), 0.0)
    idx = np.where(d != 0, np.arange(len(d)), 0)
    np.maximum.accumulate(idx, out=idx)
    held = d[idx]  # the last non-zero direction
    turn = np.zeros(len(d), dtype=np.int64)
    change = np.nonzero(held[1:] * held[:-1] < 0)[0] + 1
    turn[change] = change
    np.maximum.accumulate(turn, out=turn)
    return np.abs(q - q[turn])


# travel scales of the reversal probe, as fractions of the stroke
REVERSAL_SCALES = (0.0005, 0.002, 0.01)


def legendre(x, deg):
    return [np.polynomial.legendre.Legendre.basis(j)(x) for j in range(1, deg + 1)]


def analyse_residual(runs: list, est: Estimate, kinds=None) -> Unexplained:
    """Test the residual of ``est`` on ``runs`` (estimation first) for structure: over position (a
    period scan, the lead and its harmonics named in advance), velocity, position along the stroke,
    time within a run, between runs and acceleration; see :mod:`.residual`."""
    proc = runs[0].proc
    W = np.vstack([matrix(r, est.terms, est.shape) for r in runs])
    # a per-run phase is each run's own
    r = np.concatenate([rw.y - predict(rw, est) for rw in runs])
    W = rs.Span(W)
    breaks = np.concatenate([np.append(np.diff(rw.keep) != proc.nd, True) for rw in runs])[:-1]
    rho = rs.lag1(r, breaks)
    neff = rs.n_effective(len(r), rho)
    vmax = max(float(np.max(np.abs(rw.sig["v"][rw.keep]))) for rw in runs)
    probes = []
    if proc.lead_q > 0 and (kinds is None or "position_periodic" in kinds):

        def periodic(P):
            def cols(rw):
                ph = 2.0 * np.pi * rw.sig["q"] / P
                sg = np.sign(rw.sig["v"])
                return np.column_stack([np.sin(ph), np.cos(ph), sg * np.sin(ph), sg * np.cos(ph)])

            return pooled(runs, cols)

        q_rows = np.concatenate([rw.sig["q"][rw.keep] for rw in runs])
        s_rows = np.concatenate([np.sign(rw.sig["v"][rw.keep]) for rw in runs])
        hi = max(float(np.ptp(q_rows)) / 3.0, proc.lead_q)
        probes.append(
            rs.period_scan(
                r,
                q_rows,
                s_rows,
                periodic,
                proc.lead_q / SHORT_PERIODS,
                hi,
                W,
                neff,
                fixed=[proc.lead_q / k for k in RIPPLE_HARMONICS],
            )
        )
    if kinds is not None:
        return Unexplained(probes, float(np.sqrt(np.mean(r**2))), 0.0, rho, len(r))

    def vel_cols(rw):
        v = rw.sig["v"]
        u = 2.0 * np.abs(v) / vmax - 1.0
        sg = np.sign(v)
        return np.column_stack(legendre(u, 4) + [sg * p for p in legendre(u, 4)])

    pv = rs.probe("velocity", r, pooled(runs, vel_cols), W, neff)
    shapes = {
        "v|v|": pooled(runs, lambda rw: rw.sig["v"] * np.abs(rw.sig["v"]))[:, 0],
        "|v|": pooled(runs, lambda rw: np.abs(rw.sig["v"]))[:, 0],
        "sqrt": pooled(runs, lambda rw: np.sign(rw.sig["v"]) * np.sqrt(np.abs(rw.sig["v"])))[:, 0],
    }
    for f in (0.01, 0.03, 0.1):
        shapes[f"low_speed_{f}"] = pooled(
            runs, lambda rw, f=f: np.sign(rw.sig["v"]) * np.exp(-np.abs(rw.sig["v"]) / (f * vmax))
        )[:, 0]
    nm, sh = rs.best_shape(r, shapes, W)
    pv.detail.update(
        shape="low_speed" if nm.startswith("low_speed") else nm,
        shape_share=sh / pv.share if pv.share > 0 else 0.0,
    )
    probes.append(pv)
    sq = proc.stroke_q

    def pos_cols(rw):
        xi = 2.0 * rw.sig["q"] / sq - 1.0
        sg = np.sign(rw.sig["v"])
        return np.column_stack(legendre(xi, 4) + [sg * p for p in legendre(xi, 4)])

    G = pooled(runs, pos_cols)
    pp = rs.probe("position", r, G, W, neff)
    q_rows = np.concatenate([rw.sig["q"][rw.keep] for rw in runs])
    fitpart = rs.orthogonal(G, W)
    coef, *_ = np.linalg.lstsq(fitpart, r, rcond=None)
    along = fitpart @ coef
    bins = np.linspace(q_rows.min(), q_rows.max(), 9)
    idx = np.clip(np.searchsorted(bins, q_rows) - 1, 0, 7)
    means = [float(np.mean(np.abs(along[idx == i]))) if np.any(idx == i) else 0.0 for i in range(8)]
    k = int(np.argmax(means))
    pp.detail["worst"] = (float(bins[k]), float(bins[k + 1]))
    probes.append(pp)

    def time_cols(rw):
        t = rw.record.t
        return np.column_stack(legendre(2.0 * (t - t[0]) / (t[-1] - t[0]) - 1.0, 3))

    probes.append(rs.probe("time", r, pooled(runs, time_cols), W, neff))
    if len(runs) > 1:
        ind = np.zeros((len(r), len(runs) - 1))
        i0 = runs[0].n
        for j, rw in enumerate(runs[1:]):
            ind[i0 : i0 + rw.n, j] = 1.0
            i0 += rw.n
        probes.append(rs.probe("run", r, ind, W, neff))

    if all(rw.record.external is not None for rw in runs):

        def load_cols(rw):
            f, sg = rw.record.external, np.sign(rw.sig["v"])
            return np.column_stack([f, np.abs(f), sg * np.abs(f), sg * f])

        probes.append(rs.probe("load", r, pooled(runs, load_cols), W, neff))

    def rev_cols(rw):
        d, sg = since_reversal(rw), np.sign(rw.sig["v"])
        cols = [np.exp(-d / (f * sq)) for f in REVERSAL_SCALES]
        return np.column_stack(cols + [sg * c for c in cols])

    pr = rs.probe("reversal", r, pooled(runs, rev_cols), W, neff)
    rev_shapes = {
        f: pooled(runs, lambda rw, f=f: np.column_stack([np.exp(-since_reversal(rw) / (f * sq))]))[
            :, 0
        ]
        for f in REVERSAL_SCALES
    }
    best, _ = rs.best_shape(r, rev_shapes, W)
    pr.detail["scale"] = best * sq
    probes.append(pr)

    def acc_cols(rw):
        a, sg = rw.sig["a"], np.sign(rw.sig["v"])
        return np.column_stack([sg * a, np.abs(a), a * np.abs(a)])

    probes.append(rs.probe("acceleration", r, pooled(runs, acc_cols), W, neff))

    def neff_of(res):
        return rs.n_effective(len(res), rs.lag1(res, breaks))

    probes += [f(runs, r, W, neff_of, pooled) for f in (line_probe, spot_probe, decay_probe)]
    probes.sort(key=lambda p: p.log10_p)
    noise = math.sqrt(
        sum(noise_floor(rw, est) ** 2 * rw.n for rw in runs) / sum(rw.n for rw in runs)
    )
    return Unexplained(probes, float(np.sqrt(np.mean(r**2))), noise, rho, len(r))


def periodic_peak(rows: Rows, est: Estimate):
    """(period, share) when the residual of ``est`` is mostly periodic in position (a significant
    probe holding at least half of it), else None: a spectral peak that moves with speed is a
    ripple, not a mode."""
    if rows.proc.lead_q <= 0:
        return None
    u = analyse_residual([rows], est, kinds=("position_periodic",))
    p = u.probes[0] if u.probes else None
    return (
        (p.detail["period"], p.share)
        if p is not None and p.significant and p.share >= 0.5
        else None
    )
