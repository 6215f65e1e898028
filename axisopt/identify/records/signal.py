"""Signal processing of time records: the zero-phase Butterworth low-pass (applied exactly by FFT),
Welch spectra, the choice of the cut-off frequency, derivatives of the filtered signals, the
decimation a cut-off allows, and the windows a long record is fitted in.  Knows nothing of files
(:mod:`.record` reads them)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .record import TimeRecord

BUTTER_ORDER = 4


def lowpass(x, fs: float, fc: float, order: int = BUTTER_ORDER, segments=()) -> np.ndarray:
    """Zero-phase Butterworth low-pass: the squared magnitude :math:`|H|^2 = 1/(1 + (f/f_c)^{2n})`
    that a forward-backward (filtfilt) pass of an order-``n`` Butterworth applies, applied exactly
    by FFT.  The ends are extended by odd reflection over ``3 fs/fc`` samples (as filtfilt pads) so
    they do not ring.
    ``x``: (n,) or (n, k) along axis 0; ``segments``: (start, end) index ranges filtered each on its
    own (the windows of a long record, :func:`windowed`)."""
    if len(segments) > 1:
        return np.concatenate([lowpass(x[a:b], fs, fc, order) for a, b in segments], axis=0)
    x = np.asarray(x, dtype=float)
    one = x.ndim == 1
    X = x[:, None] if one else x
    n = X.shape[0]
    pad = min(n - 1, int(3.0 * fs / fc) + 1)
    head = 2.0 * X[0] - X[pad:0:-1]
    tail = 2.0 * X[-1] - X[-2 : -pad - 2 : -1]
    ext = np.concatenate([head, X, tail])
    m = ext.shape[0]
    nfft = 1 << (m - 1).bit_length()
    spec = np.fft.rfft(ext, n=nfft, axis=0)
    f = np.fft.rfftfreq(nfft, 1.0 / fs)
    h2 = 1.0 / (1.0 + (f / fc) ** (2 * order))
    y = np.fft.irfft(spec * h2[:, None], n=nfft, axis=0)[pad : pad + n]
    return y[:, 0] if one else y


def welch(x, fs, nseg=1024):
    nseg = min(nseg, len(x))
    step = nseg // 2
    win = np.hanning(nseg)
    segs = [x[i : i + nseg] for i in range(0, len(x) - nseg + 1, step)]
    ps = np.mean([np.abs(np.fft.rfft((s - s.mean()) * win)) ** 2 for s in segs], axis=0)
    return np.fft.rfftfreq(nseg, 1.0 / fs), ps / (fs * np.sum(win**2))


@dataclass
class CutoffChoice:
    fc: float  # [Hz] low-pass cut-off before differentiation
    f_motion: float  # [Hz] 99 % of the velocity signal power lies below
    f_snr: float  # [Hz] highest frequency where the velocity spectrum is 10x its noise floor
    rule: str


def choose_cutoff(q, fs: float, segments=()) -> CutoffChoice:
    """Cut-off from the data: the velocity spectrum (backward differences of the position) is
    compared with its noise floor -- white position noise (quantisation) gives
    :math:`N_0 \\sin^2(\\pi f/f_s)`, fitted on the upper half of the band -- and the cut-off is the
    highest frequency where the signal is still 10x that floor, but at least 5x the motion bandwidth
    (99 % of the signal power) and at most fs/8."""
    v = np.concatenate([np.diff(q[a:b]) for a, b in segments]) * fs if segments else np.diff(q) * fs
    f, ps = welch(v, fs)
    shape = np.sin(np.pi * f / fs) ** 2 + 1e-30
    upper = f > fs / 4
    n0 = float(np.median(ps[upper] / shape[upper]))
    noise = n0 * shape
    sig = np.clip(ps - noise, 0.0, None)
    cum = np.cumsum(sig)
    f99 = float(f[np.searchsorted(cum, 0.99 * cum[-1])]) if cum[-1] > 0 else fs / 50
    smooth = np.convolve(ps, np.ones(5) / 5, mode="same")
    above = np.nonzero(smooth > 10.0 * noise)[0]
    f_snr = float(f[above[-1]]) if len(above) else f99
    fc = min(max(f_snr, 5.0 * f99), fs / 8)
    rule = (
        "highest frequency with velocity spectrum > 10x noise floor"
        if fc == f_snr
        else "5x the motion bandwidth"
        if fc == 5.0 * f99
        else "fs/8 cap"
    )
    return CutoffChoice(fc, f99, f_snr, rule)


def derivatives(q, fs: float, fc: float, orders: int = 2, segments=()) -> list:
    """[q_f, v, a, ...] up to ``orders`` (central differences of the zero-phase filtered position),
    each of ``segments`` on its own."""
    if len(segments) > 1:
        parts = [derivatives(q[a:b], fs, fc, orders) for a, b in segments]
        return [np.concatenate([p[i] for p in parts]) for i in range(orders + 1)]
    out = [lowpass(q, fs, fc)]
    for _ in range(orders):
        out.append(np.gradient(out[-1]) * fs)
    return out


def decimation_factor(fs: float, fc: float) -> int:
    """Parallel decimation keeps every nd-th row after a low-pass at 0.8 of the new Nyquist
    frequency; nd is the largest with that cut-off still at or above ``fc``."""
    return max(1, int(0.8 * fs / (2.0 * fc)))


# ------------------------------------------------------------------------------------------ long
# records
LONG_SAMPLES = 150_000  # a record longer than this is identified in windows spread over it
WINDOWS = 8  # how many
WINDOW_SAMPLES = 8_000  # samples in each (8 s at 1 kHz), a window starts where the axis rests


def windowed(
    rec: TimeRecord,
    long_samples: int = LONG_SAMPLES,
    count: int = WINDOWS,
    size: int = WINDOW_SAMPLES,
) -> TimeRecord:
    """``rec`` itself when it has at most ``long_samples`` samples; else ``count`` windows of
    ``size`` samples spread evenly over it, each starting at the first rest (the position still for
    50 ms) at or after its nominal start, as one record whose ``segments`` keep them apart: every
    filter, derivative and closed-loop simulation then runs in each window on its own, and the times
    stay those of the record (a warm-up's temperature, a drift's time from the start, a line's
    phase).  The slow physics a long record is taken for (a warm-up over minutes) is sampled by the
    windows; the cost is that of ``count x size`` samples.  Windows on a record:
    :attr:`TimeRecord.segments`."""
    n = rec.n
    if n <= long_samples:
        return rec
    size = min(size, n // count)
    m = max(1, int(0.05 * rec.fs))
    still = np.abs(rec.q[m:] - rec.q[:-m]) <= 1e-4 * max(float(np.ptp(rec.q)), 1e-12)
    starts = []
    for k in range(count):
        a = (k * (n - size)) // max(count - 1, 1)
        rest = np.nonzero(still[a : a + size // 2])[0]
        a = a + int(rest[0]) if len(rest) else a
        starts.append(min(a, n - size))
    idx = np.concatenate([np.arange(a, a + size) for a in starts])
    segs, pos = [], 0
    for _ in starts:
        segs.append((pos, pos + size))
        pos += size

    def cut(x):
        return None if x is None else x[idx]

    return TimeRecord(
        rec.source,
        rec.t[idx],
        rec.q[idx],
        rec.effort[idx],
        rec.quantity,
        cut(rec.reference),
        rec.header,
        rec.effort_column,
        rec.lines[idx],
        rec.gain_note,
        cut(rec.external),
        cut(rec.motor_q),
        {k: v[idx] for k, v in rec.aux.items()},
        tuple(segs),
        (n, float(np.ptp(rec.t))),
    )
