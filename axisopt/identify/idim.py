"""Inverse dynamic identification (IDIM) of a feed axis from time records: least squares (seed eq. 29),
instrumental variables (seed eq. 30, IDIM-IV), and effects beyond the rigid baseline selected by BIC with the
validation run's gain.

Model, in the coordinate of the record's effort (table [m] for force, motor angle [rad] for torque;
:mod:`.timerecord`):

.. math:: f = M \\ddot q + F_v \\dot q + F_c \\operatorname{sgn}\\dot q + f_0 \\;(+\\ \\text{effects})

Processing (Gautier's IDIM): the position is low-pass filtered with a zero-phase Butterworth whose cut-off
comes from the data (:func:`.timerecord.choose_cutoff`), differentiated by central differences, every
column of the regression and the effort are low-pass filtered alike and every nd-th row kept (parallel
decimation); rows at low speed (``|v| < 0.5 %`` of the peak speed) and around reversals, where sgn(v) of
the estimate is not that of the axis, are left out.

* LS: :math:`\\hat\\theta = (W^T W)^{-1} W^T y`, :math:`\\sigma^2 = \\|y - W\\hat\\theta\\|^2/(n - p)`,
  :math:`\\operatorname{cov} = \\sigma^2 (W^T W)^{-1}` (eq. 29).
* IV (eq. 30): instruments V are the same columns computed from the closed loop simulated with the current
  estimate -- the PD position controller (+ velocity and acceleration feed-forward) is fitted to the record
  from its ``reference`` column and driven by that reference; no measurement noise enters V.  Iterated
  :math:`\\hat\\theta_{k+1} = (V_k^T W)^{-1} V_k^T y` until the estimate moves by less than 1e-4 of a
  standard deviation (at most 30 iterations),
  :math:`\\operatorname{cov} = \\sigma^2 (V^T W)^{-1} V^T V (V^T W)^{-T}`.  A record without ``reference``
  cannot be re-simulated in closed loop: V is then the regressor delayed by two decimated rows (a
  delayed-regressor instrument, not iterated).

Effects (each a few columns added to W, fitted jointly with the baseline):

* ``direction_asymmetry``: viscous friction differing by direction, column |v|/2, parameter
  dFv = Fv(v>0) - Fv(v<0).  A Coulomb asymmetry (Fc(v>0) - Fc(v<0))/2 is a constant while moving and
  cannot be told from the offset on moving rows: it is reported inside the offset.
* ``stribeck``: sgn(v) exp(-|v|/vs), parameter Fs - Fc; the velocity constant vs is a shape parameter
  found by a 1-D search (log grid, then golden section) on the LS residual and then held fixed.
* ``position_friction``: Coulomb level varying with position, sgn(v) P1(xi), sgn(v) P2(xi) (Legendre,
  xi = 2 x/stroke - 1 over the design's stroke), parameters c1, c2.
* ``extra_mode``: a second mass behind a spring (motor side m1, table m2, stiffness k, table position
  measured): exactly :math:`f = M\\ddot q + (m_1 m_2/k) q^{(4)}` without damping and friction, so the
  column is the fourth derivative, parameter beta = m1 m2/k, reported as the resonance
  :math:`f_r = \\sqrt{M/\\beta}/2\\pi`.  Only a candidate when the baseline's residual spectrum has a peak
  (5x its median between 3x the motion bandwidth and the cut-off).  Its IV instrument is the measured
  column itself (a rigid-body simulation has no mode).

Selection: forward, each round the candidate with the lowest dBIC = n ln(RSS1/RSS0) + dp ln n on the
estimation run; accepted if dBIC < -10 and the RMSE of the effort predicted on the validation runs (or, with
no validation run, 5 contiguous blocks of the estimation run held out in turn) falls by at least 5 %.
Nothing here imports the CLI or YAML.
"""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from .timerecord import (
    BUTTER_ORDER,
    TimeRecord,
    _welch,
    choose_cutoff,
    decimation_factor,
    derivatives,
    lowpass,
)

ACCEPT_DBIC = -10.0
MIN_GAIN = 5.0  # [%] validation RMSE must fall by at least this much
BASE = ("M", "Fv", "Fc", "offset")
IV_TOL = 1e-4
IV_MAXIT = 30
VMIN_REL = 0.005
SIGN_KEEP = 0.98
PEAK_RATIO = 5.0

# parameter -> (label, unit kind)
PARAMS = {
    "M": ("moving mass", "mass"),
    "Fv": ("viscous friction", "damping"),
    "Fc": ("Coulomb friction", "effort"),
    "offset": ("offset (gravity, sensor, Coulomb asymmetry)", "effort"),
    "dFv": ("viscous asymmetry Fv+ - Fv-", "damping"),
    "Fs": ("Stribeck excess Fs - Fc", "effort"),
    "c1": ("Coulomb vs position, P1 coefficient", "effort"),
    "c2": ("Coulomb vs position, P2 coefficient", "effort"),
    "beta": ("m1 m2/k of the extra mode", "snap"),
}
UNITS = {
    "force": {"mass": ("kg", 1.0), "damping": ("N.s/m", 1.0), "effort": ("N", 1.0), "snap": ("kg.s^2", 1.0),
              "speed": ("mm/s", 1e3), "position": ("mm", 1e3)},
    "torque": {"mass": ("kg.m^2", 1.0), "damping": ("N.m.s/rad", 1.0), "effort": ("N.m", 1.0),
               "snap": ("kg.m^2.s^2", 1.0), "speed": ("rad/s", 1.0), "position": ("rad", 1.0)},
}
SYMBOL = {"force": {"M": "M"}, "torque": {"M": "J"}}


@dataclass(frozen=True)
class TimeEffect:
    name: str
    terms: tuple
    shape: str | None = None  # shape parameter found by 1-D search
    summary: str = ""


EFFECTS = {
    "direction_asymmetry": TimeEffect("direction_asymmetry", ("dFv",),
                                      summary="viscous friction differs by direction"),
    "stribeck": TimeEffect("stribeck", ("Fs",), shape="vs", summary="friction rises at low speed (Stribeck)"),
    "position_friction": TimeEffect("position_friction", ("c1", "c2"),
                                    summary="Coulomb friction varies along the stroke"),
    "extra_mode": TimeEffect("extra_mode", ("beta",), summary="a second mass behind a spring (resonance)"),
}


def time_effects() -> dict:
    return dict(EFFECTS)


# ------------------------------------------------------------------------------------- regression rows
@dataclass
class Processing:
    fs: float
    fc: float
    nd: int
    fdec: float
    f_motion: float
    rule: str
    vmin: float
    stroke_q: float  # stroke in the record's coordinate


@dataclass
class Rows:
    """Filtered full-rate signals of one record and the kept decimated rows."""

    record: TimeRecord
    sig: dict  # q, v, a, snap (full rate, filtered)
    keep: np.ndarray  # full-rate indices of the kept rows
    y: np.ndarray  # effort at the kept rows after the decimation filter
    proc: Processing

    @property
    def n(self) -> int:
        return len(self.keep)


def _columns(term: str, sig: dict, proc: Processing, shape: dict) -> np.ndarray:
    v = sig["v"]
    s = np.sign(v)
    if term == "M":
        return sig["a"]
    if term == "Fv":
        return v
    if term == "Fc":
        return s
    if term == "offset":
        return np.ones_like(v)
    if term == "dFv":
        return 0.5 * np.abs(v)
    if term == "Fs":
        return s * np.exp(-np.abs(v) / shape["vs"])
    if term in ("c1", "c2"):
        xi = 2.0 * sig["q"] / proc.stroke_q - 1.0
        return s * (xi if term == "c1" else 1.5 * xi**2 - 0.5)
    if term == "beta":
        return sig["snap"]
    raise KeyError(term)


def full_matrix(sig: dict, terms, proc: Processing, shape: dict) -> np.ndarray:
    return np.column_stack([_columns(t, sig, proc, shape) for t in terms])


def decimate(rows_full: np.ndarray, proc: Processing, keep: np.ndarray) -> np.ndarray:
    """Parallel decimation: the same low-pass on every column, then the kept rows."""
    return lowpass(rows_full, proc.fs, proc.fdec)[keep]


def processing_for(rec: TimeRecord, stroke_q: float) -> Processing:
    fs = rec.fs
    cut = choose_cutoff(rec.q, fs)
    nd = decimation_factor(fs, cut.fc)
    fdec = 0.8 * fs / (2.0 * nd)
    q, v = derivatives(rec.q, fs, cut.fc, 1)
    vmin = VMIN_REL * float(np.max(np.abs(v)))
    return Processing(fs, cut.fc, nd, fdec, cut.f_motion, cut.rule, vmin, stroke_q)


def signals(q: np.ndarray, proc: Processing) -> dict:
    qf, v, a, j, snap = derivatives(q, proc.fs, proc.fc, 4)
    return {"q": qf, "v": v, "a": a, "snap": snap}


def make_rows(rec: TimeRecord, proc: Processing) -> Rows:
    if abs(rec.fs - proc.fs) > 1e-3 * proc.fs:
        raise InputError(f"sampled at {rec.fs:.6g} Hz, the estimation run at {proc.fs:.6g} Hz (the same filters "
                         "are applied to every run)", source=rec.source, where="column time")
    sig = signals(rec.q, proc)
    v = sig["v"]
    sf = lowpass(np.sign(v), proc.fs, proc.fdec)
    edge = int(2.0 * proc.fs / min(proc.fc, proc.fdec)) + proc.nd
    idx = np.arange(edge, rec.n - edge, proc.nd)
    # a row is kept when the axis moves one way for a whole filter window around it: the zero-phase filters
    # smear starts and stops, where sgn(v) of the estimate leads the axis's
    w = int(proc.fs / proc.fdec)
    bad = (np.abs(v) < proc.vmin).astype(float)
    bad = np.convolve(bad, np.ones(2 * w + 1), mode="same") > 0
    keep = idx[~bad[idx] & (np.abs(sf[idx]) >= SIGN_KEEP)]
    if len(keep) < 20:
        raise InputError(f"only {len(keep)} usable rows after filtering and decimation (the axis must move: "
                         f"speeds above {proc.vmin:.3g} in the record's unit/s)", source=rec.source)
    y = lowpass(rec.effort, proc.fs, proc.fdec)[keep]
    return Rows(rec, sig, keep, y, proc)


def matrix(rows: Rows, terms, shape: dict, sig: dict | None = None) -> np.ndarray:
    return decimate(full_matrix(sig or rows.sig, terms, rows.proc, shape), rows.proc, rows.keep)


# ------------------------------------------------------------------------------------------- estimators
@dataclass
class Estimate:
    method: str  # 'LS' | 'IV'
    terms: tuple
    theta: np.ndarray
    std: np.ndarray
    shape: dict
    rss: float
    n: int
    iterations: int = 0
    converged: bool = True
    note: str = ""

    def value(self, term: str) -> float:
        return float(self.theta[self.terms.index(term)])

    def as_dict(self) -> dict:
        return {t: float(v) for t, v in zip(self.terms, self.theta)}

    @property
    def bic(self) -> float:
        p = len(self.terms) + len(self.shape)
        return self.n * math.log(max(self.rss, 1e-300) / self.n) + p * math.log(self.n)


def _lstsq(W, y):
    sc = np.linalg.norm(W, axis=0)
    sc[sc == 0] = 1.0
    th, *_ = np.linalg.lstsq(W / sc, y, rcond=None)
    return th / sc


def least_squares(rows: Rows, terms, shape=None) -> Estimate:
    """LS on the decimated rows (seed eq. 29) with the standard deviations from the residual variance."""
    shape = dict(shape or {})
    W = matrix(rows, terms, shape)
    th = _lstsq(W, rows.y)
    r = rows.y - W @ th
    n, p = W.shape
    rss = float(r @ r)
    s2 = rss / max(n - p, 1)
    sc = np.linalg.norm(W, axis=0)
    sc[sc == 0] = 1.0
    cov = np.linalg.pinv((W / sc).T @ (W / sc)) * s2 / np.outer(sc, sc)
    return Estimate("LS", tuple(terms), th, np.sqrt(np.clip(np.diag(cov), 0, None)), shape, rss, n)


def search_shape(rows: Rows, terms, shape: dict, lo: float, hi: float, name: str = "vs") -> float:
    """1-D search of a shape parameter (log grid, then golden section on the LS RSS)."""
    def rss(logv):
        return least_squares(rows, terms, {**shape, name: math.exp(logv)}).rss

    grid = np.linspace(math.log(lo), math.log(hi), 14)
    vals = [rss(g) for g in grid]
    k = int(np.argmin(vals))
    a, b = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc_, fd = rss(c), rss(d)
    for _ in range(18):
        if fc_ < fd:
            b, d, fd = d, c, fc_
            c = b - g * (b - a)
            fc_ = rss(c)
        else:
            a, c, fc_ = c, d, fd
            d = a + g * (b - a)
            fd = rss(d)
    return math.exp((a + b) / 2)


# ---------------------------------------------------------------------------------- closed-loop model
@dataclass
class Controller:
    """u = Kp (r - q) + Kd (r' - q') + Kv r' + Ka r'' (fitted to the record; SI of the record's coordinate)."""

    kp: float
    kd: float
    kv: float
    ka: float
    r2: float

    def as_dict(self) -> dict:
        return {"Kp": self.kp, "Kd": self.kd, "Kv_ff": self.kv, "Ka_ff": self.ka, "R2": self.r2}


def fit_controller(rows: Rows) -> Controller | None:
    rec, proc = rows.record, rows.proc
    if rec.reference is None:
        return None
    r, dr, ddr = derivatives(rec.reference, proc.fs, proc.fc, 2)
    X = np.column_stack([r - rows.sig["q"], dr - rows.sig["v"], dr, ddr])
    y = lowpass(rec.effort, proc.fs, proc.fc)
    e = int(2.0 * proc.fs / proc.fc)
    X, y = X[e:-e], y[e:-e]
    th = _lstsq(X, y)
    res = y - X @ th
    ss = float(np.sum((y - y.mean()) ** 2))
    if not ss > 0.0:  # a constant effort explains nothing about the controller
        return None
    r2 = 1.0 - float(res @ res) / ss
    return Controller(*map(float, th), r2)


def simulate_loop(rec: TimeRecord, ctrl: Controller, params: dict, shape: dict, proc: Processing,
                  substeps: int = 2) -> np.ndarray | None:
    """Closed loop of the identified rigid model driven by the record's reference; the position [q units] at
    every sample, or None if the simulation diverges.  Exact sticking (implicit Coulomb step)."""
    r, dr, ddr = derivatives(rec.reference, proc.fs, proc.fc, 2)
    m = params.get("M", 0.0)
    if not m > 0:
        return None
    fv, fc, off = params.get("Fv", 0.0), params.get("Fc", 0.0), params.get("offset", 0.0)
    dfv, fsx = params.get("dFv", 0.0), params.get("Fs", 0.0)
    vs = shape.get("vs", 1.0)
    c1, c2 = params.get("c1", 0.0), params.get("c2", 0.0)
    fvp, fvn = fv + dfv / 2, fv - dfv / 2
    kp, kd, kv, ka = ctrl.kp, ctrl.kd, ctrl.kv, ctrl.ka
    h = 1.0 / (proc.fs * substeps)
    hm = h / m
    sq = 2.0 / proc.stroke_q
    q, v = float(rec.q[0]), 0.0
    out = np.empty(rec.n)
    rl, drl, ddrl = r.tolist(), dr.tolist(), ddr.tolist()
    exp = math.exp
    bound = 1e3 * (float(np.ptp(rec.q)) + 1.0)
    for k in range(rec.n):
        out[k] = q
        u = kp * (rl[k] - q) + kd * (drl[k] - v) + kv * drl[k] + ka * ddrl[k] - off
        for _ in range(substeps):
            xi = sq * q - 1.0
            dpos = c1 * xi + c2 * (1.5 * xi * xi - 0.5)
            if v == 0.0:
                brk = fc + fsx + dpos
                if brk < 0.0:
                    brk = 0.0
                if u > brk:
                    v = hm * (u - brk)
                elif u < -brk:
                    v = hm * (u + brk)
            else:
                if v > 0:
                    fr = fc + fvp * v + fsx * exp(-v / vs) + dpos
                else:
                    fr = -fc + fvn * v - fsx * exp(v / vs) - dpos
                vn = v + hm * (u - fr)
                v = 0.0 if vn * v < 0 else vn
            q += h * v
        if not abs(q) < bound:
            return None
    return out


NO_SIM_INSTRUMENT = ("beta",)


def instrumental_variables(rows: Rows, terms, shape=None, ctrl: Controller | None = None,
                           start: Estimate | None = None) -> Estimate:
    """IDIM-IV (seed eq. 30); see the module docstring for the instruments."""
    shape = dict(shape or {})
    terms = tuple(terms)
    W = matrix(rows, terms, shape)
    y = rows.y
    ls = start or least_squares(rows, terms, shape)
    th = ls.theta.copy()
    n, p = W.shape
    own = [terms.index(t) for t in terms if t in NO_SIM_INSTRUMENT]

    def solve(V):
        A = V.T @ W
        sc = np.linalg.norm(A, axis=0)
        sc[sc == 0] = 1.0
        return np.linalg.solve(A / sc, V.T @ y) / sc

    it, converged, note = 0, True, ""
    if ctrl is None:
        lag = 2 * rows.proc.nd
        Wf = full_matrix(rows.sig, terms, rows.proc, shape)
        Vf = np.vstack([np.repeat(Wf[:1], lag, axis=0), Wf[:-lag]])
        V = decimate(Vf, rows.proc, rows.keep)
        th = solve(V)
        note = "delayed-regressor instrument (no reference column: the closed loop cannot be re-simulated)"
        it = 1
    else:
        V = W
        converged = False
        for it in range(1, IV_MAXIT + 1):
            qs = simulate_loop(rows.record, ctrl, dict(zip(terms, th)), shape, rows.proc)
            if qs is None:
                note = f"closed-loop simulation diverged at iteration {it}; LS kept"
                th, V = ls.theta.copy(), W
                break
            V = matrix(rows, terms, shape, sig=signals(qs, rows.proc))
            for j in own:
                V[:, j] = W[:, j]
            new = solve(V)
            step = np.max(np.abs(new - th) / np.maximum(ls.std, 1e-12 * np.abs(th) + 1e-300))
            th = new
            if step < IV_TOL:
                converged = True
                break
        if converged:
            note = f"instruments from the closed loop simulated from the reference ({it} iterations)"
        elif not note:
            note = f"not converged in {IV_MAXIT} iterations"
    r = y - W @ th
    rss = float(r @ r)
    s2 = rss / max(n - p, 1)
    A = V.T @ W
    try:
        Ai = np.linalg.inv(A)
        cov = s2 * Ai @ (V.T @ V) @ Ai.T
        std = np.sqrt(np.clip(np.diag(cov), 0, None))
    except np.linalg.LinAlgError:
        std = np.full(p, np.nan)
    return Estimate("IV", terms, th, std, shape, rss, n, it, converged, note)


def predict(rows: Rows, est: Estimate) -> np.ndarray:
    return matrix(rows, est.terms, est.shape) @ est.theta


def rel_error(rows: Rows, est: Estimate) -> float:
    """||y - y_hat|| / ||y|| on the kept rows [-]."""
    r = rows.y - predict(rows, est)
    ny = float(np.linalg.norm(rows.y))
    return float(np.linalg.norm(r) / ny) if ny > 0.0 else float("nan")


def rmse(rows: Rows, est: Estimate) -> float:
    r = rows.y - predict(rows, est)
    return float(np.sqrt(np.mean(r**2)))


# ---------------------------------------------------------------------------------------- diagnosis
@dataclass
class TimeCandidate:
    effect: TimeEffect
    estimate: Estimate
    dbic: float
    gain: float  # [%] validation (or held-out block) RMSE reduction


@dataclass
class TimeDiagnosis:
    quantity: str
    estimation: Rows
    validation: list
    controller: Controller | None
    baseline_ls: Estimate
    baseline_iv: Estimate
    final: Estimate  # IV with the accepted effects
    final_ls: Estimate
    accepted: list  # TimeCandidate in order
    rounds: list  # list of lists of TimeCandidate
    skipped: dict  # effect -> reason it was not a candidate
    residual_peak: tuple  # (frequency [Hz], ratio to median) of the baseline residual spectrum
    times: dict  # seconds: ls, iv, diagnose
    design: dict = field(default_factory=dict)  # name, lead, efficiency (for the torque -> force note)
    rejected: list = field(default_factory=list)  # (round, TimeCandidate, reason): outside its physical range

    @property
    def verdict(self) -> list:
        return [c.effect.name for c in self.accepted]

    @property
    def validation_mode(self) -> str:
        return "validation runs" if self.validation else "5 held-out blocks of the estimation run"


def _heldout_rmse(est_rows: Rows, val_rows: list, terms, shape) -> float:
    if val_rows:
        e = least_squares(est_rows, terms, shape)
        r = np.concatenate([v.y - predict(v, e) for v in val_rows])
        return float(np.sqrt(np.mean(r**2)))
    W = matrix(est_rows, terms, shape)
    y = est_rows.y
    blocks = np.array_split(np.arange(len(y)), 5)
    err = []
    for b in blocks:
        m = np.ones(len(y), bool)
        m[b] = False
        th = _lstsq(W[m], y[m])
        err.append(y[b] - W[b] @ th)
    r = np.concatenate(err)
    return float(np.sqrt(np.mean(r**2)))


def residual_peak(rows: Rows, est: Estimate) -> tuple:
    """Peak of the baseline residual spectrum between 3x the motion bandwidth and the cut-off."""
    proc = rows.proc
    W = lowpass(full_matrix(rows.sig, est.terms, proc, est.shape), proc.fs, proc.fdec)
    y = lowpass(rows.record.effort, proc.fs, proc.fdec)
    r = np.zeros(len(y))
    r[rows.keep[0] : rows.keep[-1]] = (y - W @ est.theta)[rows.keep[0] : rows.keep[-1]]
    moving = np.zeros(len(y), bool)
    moving[rows.keep] = True
    moving = np.convolve(moving, np.ones(proc.nd), mode="same") > 0
    r[~moving] = 0.0
    f, ps = _welch(r, proc.fs, 512)
    band = (f >= 3.0 * proc.f_motion) & (f <= proc.fc)
    if band.sum() < 5:
        return 0.0, 0.0
    k = int(np.argmax(ps[band]))
    return float(f[band][k]), float(ps[band][k] / np.median(ps[band]))


def implausible(cand_terms, est: Estimate, base: Estimate) -> str:
    """Why an effect's fitted terms leave their physical range ('' when they do not).  Ranges, relative to
    the baseline's own friction: a Stribeck excess between 0 and twice the Coulomb level (breakaway up to
    three times it); a viscous direction difference up to the viscous coefficient itself; a Coulomb
    variation along the stroke (each Legendre coefficient) up to the Coulomb level; an extra mode with a
    positive m1 m2 / k (a real mass behind a real spring)."""
    fc, fv = abs(base.value("Fc")), abs(base.value("Fv"))
    out = []
    for t in cand_terms:
        v = est.value(t)
        if t == "Fs" and not 0.0 <= v <= 2.0 * fc:
            out.append(f"Fs = {v:.4g} outside 0..{2 * fc:.4g} (breakaway up to 3x Coulomb)")
        elif t == "dFv" and abs(v) > fv:
            out.append(f"dFv = {v:.4g} beyond +-{fv:.4g} (the whole viscous coefficient)")
        elif t in ("c1", "c2") and abs(v) > fc:
            out.append(f"{t} = {v:.4g} beyond +-{fc:.4g} (the whole Coulomb friction)")
        elif t == "beta" and v <= 0.0:
            out.append(f"beta = {v:.4g} not positive (no mass-spring pair has m1 m2/k <= 0)")
    return "; ".join(out)


def _fit_candidate(est_rows, terms, effect, shape):
    shape = dict(shape)
    if effect.shape == "vs":
        vmax = float(np.max(np.abs(est_rows.sig["v"])))
        shape["vs"] = search_shape(est_rows, terms, shape, max(est_rows.proc.vmin, 1e-4 * vmax), 0.5 * vmax)
    return least_squares(est_rows, terms, shape), shape


def diagnose_time(records: list, *, stroke_q: float, candidates=None, max_effects: int = 2,
                  design: dict | None = None) -> TimeDiagnosis:
    """Identify the estimation record ``records[0]`` (LS and IV), select effects, validate on the rest."""
    import time

    t0 = time.perf_counter()
    est = records[0]
    proc = processing_for(est, stroke_q)
    est_rows = make_rows(est, proc)
    val_rows = [make_rows(r, proc) for r in records[1:]]
    ctrl = fit_controller(est_rows)
    tl = time.perf_counter()
    base_ls = least_squares(est_rows, BASE)
    t_ls = time.perf_counter() - tl
    ti = time.perf_counter()
    base_iv = instrumental_variables(est_rows, BASE, ctrl=ctrl, start=base_ls)
    t_iv = time.perf_counter() - ti

    names = list(candidates) if candidates else list(EFFECTS)
    pool, skipped = [], {}
    peak = residual_peak(est_rows, base_ls)
    span = float(np.ptp(est_rows.sig["q"][est_rows.keep]))
    for nm in names:
        e = EFFECTS[nm]
        if nm == "extra_mode" and peak[1] < PEAK_RATIO:
            skipped[nm] = f"no residual spectral peak (at most {peak[1]:.1f}x the median, {peak[0]:.0f} Hz)"
        elif nm == "position_friction" and span < 0.1 * stroke_q:
            skipped[nm] = "the record covers less than 10 % of the stroke"
        else:
            pool.append(e)

    terms, shape = list(BASE), {}
    cur = base_ls
    cur_ho = _heldout_rmse(est_rows, val_rows, terms, shape)
    accepted, rounds, rejected = [], [], []
    for _ in range(max_effects):
        scored = []
        for e in pool:
            if e in [c.effect for c in accepted]:
                continue
            tt = terms + list(e.terms)
            fit, sh = _fit_candidate(est_rows, tt, e, shape)
            dbic = fit.bic - cur.bic
            ho = _heldout_rmse(est_rows, val_rows, tt, sh)
            scored.append(TimeCandidate(e, fit, dbic, 100.0 * (1.0 - ho / cur_ho) if cur_ho > 0 else 0.0))
        if not scored:
            break
        scored.sort(key=lambda c: c.dbic)
        rounds.append(scored)
        top = None
        for c in scored:  # the best candidate whose values are physical; an implausible one is reported
            why = implausible(c.effect.terms, c.estimate, base_ls)
            if why:
                rejected.append((len(rounds), c, why))
                continue
            top = c
            break
        if top is None or top.dbic >= ACCEPT_DBIC or top.gain < MIN_GAIN:
            break
        accepted.append(top)
        terms += list(top.effect.terms)
        shape.update(top.estimate.shape)
        cur = top.estimate
        cur_ho = _heldout_rmse(est_rows, val_rows, terms, shape)
    final_ls = least_squares(est_rows, terms, shape) if accepted else base_ls
    final = instrumental_variables(est_rows, terms, shape, ctrl=ctrl, start=final_ls) if accepted else base_iv
    times = {"ls": t_ls, "iv": t_iv, "diagnose": time.perf_counter() - t0}
    return TimeDiagnosis(est.quantity, est_rows, val_rows, ctrl, base_ls, base_iv, final, final_ls, accepted,
                         rounds, skipped, peak, times, dict(design or {}), rejected)


# ------------------------------------------------------------------------------------------- output
def _unit(quantity, term):
    return UNITS[quantity][PARAMS[term][1]]


def _sym(quantity, term):
    return SYMBOL[quantity].get(term, term)


def _fmt(v, s=None):
    if s is None or not math.isfinite(s):
        return f"{v:.4g}"
    return f"{v:.4g} ± {s:.2g}"


def mode_frequency(est: Estimate) -> float | None:
    if "beta" not in est.terms:
        return None
    m, b = est.value("M"), est.value("beta")
    return math.sqrt(m / b) / (2 * math.pi) if b > 0 and m > 0 else None


def _param_lines(q, est: Estimate, only=None, indent="    ") -> list:
    out = []
    for t, v, s in zip(est.terms, est.theta, est.std):
        if only is not None and t not in only:
            continue
        u, f = _unit(q, t)
        label = "moving inertia (motor side)" if (q, t) == ("torque", "M") else PARAMS[t][0]
        out.append(f"{indent}{_sym(q, t):<7}{_fmt(v * f, s * f):>22} {u:<10} {label}".rstrip())
    if "vs" in est.shape and (only is None or "Fs" in only):
        u, f = UNITS[q]["speed"]
        out.append(f"{indent}{'vs':<7}{est.shape['vs'] * f:>22.4g} {u:<10} Stribeck velocity (1-D search)")
    fr = mode_frequency(est)
    if fr is not None and (only is None or "beta" in only):
        out.append(f"{indent}{'f_r':<7}{fr:>22.4g} {'Hz':<10} resonance sqrt(M/beta)/2pi")
    return out


def _errors(diag, est) -> str:
    parts = [f"estimation {100 * rel_error(diag.estimation, est):.2f} %"]
    parts += [f"{v.record.name} {100 * rel_error(v, est):.2f} %" for v in diag.validation]
    return ", ".join(parts)


WIDTH = 100


def _wrap(text: str, indent: str = "  ", cont: str = "      ") -> list:
    return textwrap.wrap(text, WIDTH, initial_indent=indent, subsequent_indent=cont, break_on_hyphens=False)


def _compact(q, est: Estimate, terms) -> str:
    out = []
    for t in terms:
        i = est.terms.index(t)
        u, f = _unit(q, t)
        out.append(f"{_sym(q, t)} {_fmt(est.theta[i] * f, est.std[i] * f)} {u}")
    if "vs" in est.shape and "Fs" in terms:
        u, f = UNITS[q]["speed"]
        out.append(f"vs {est.shape['vs'] * f:.3g} {u}")
    fr = mode_frequency(est)
    if fr is not None and "beta" in terms:
        out.append(f"f_r {fr:.3g} Hz")
    return ", ".join(out)


def time_diagnosis_text(diag: TimeDiagnosis) -> str:
    """Console text, at most 100 columns (prose wrapped with indented continuation)."""
    q = diag.quantity
    er, p = diag.estimation, diag.estimation.proc
    rec = er.record
    unit_eff = UNITS[q]["effort"][0]
    spd_u, spd_f = UNITS[q]["speed"]
    L = [f"time-record identification (IDIM) of {diag.design.get('name', 'the axis')}: {q} data, "
         + ("table coordinate" if q == "force" else "motor angle coordinate")]
    L += _wrap(f"estimation  {rec.name}: {rec.n} samples at {p.fs:.6g} Hz, {er.n} regression rows"
               + (f"; {rec.gain_note}" if rec.gain_note else ""), cont="              ")
    for v in diag.validation:
        L.append(f"  validation  {v.record.name}: {v.record.n} samples, {v.n} regression rows")
    L += _wrap(f"filter      zero-phase Butterworth, order {BUTTER_ORDER} (|H|^2 by FFT, as forward-backward), "
               f"cut-off {p.fc:.1f} Hz: {p.rule}; motion bandwidth {p.f_motion:.1f} Hz", cont="              ")
    L += _wrap(f"decimation  parallel: every column and the {q} low-passed at {p.fdec:.1f} Hz, every {p.nd}th "
               f"row kept; rows below {p.vmin * spd_f:.3g} {spd_u} or at reversals left out",
               cont="              ")
    c = diag.controller
    if c is not None:
        L += _wrap(f"controller  PD fitted from the reference: Kp {c.kp:.4g}, Kd {c.kd:.4g}, feed-forward "
                   f"v {c.kv:.3g}, a {c.ka:.3g} (R2 {c.r2:.3f})", cont="              ")
    L.append("")
    L.append("baseline  f = M a + Fv v + Fc sgn(v) + offset" if q == "force" else
             "baseline  T = J a + Fv w + Fc sgn(w) + offset (motor side)")
    for est in (diag.baseline_ls, diag.baseline_iv):
        L += _wrap(f"{est.method}" + (f"  ({est.note})" if est.note else ""), cont="      ")
        L += _param_lines(q, est)
        L += _wrap(f"{q} error ||y - y_hat||/||y||: {_errors(diag, est)}", indent="    ")
    if q == "torque" and diag.design.get("lead"):
        lead, eta = diag.design["lead"], diag.design.get("efficiency", 1.0)
        g = 2 * math.pi / lead
        b = diag.baseline_iv.as_dict()
        L += _wrap(f"table side through lead {lead * 1e3:g} mm and efficiency {eta:g} (F = T 2pi eta/p, "
                   f"M = J (2pi/p)^2 eta): M {b['M'] * g * g * eta:.4g} kg, Fv {b['Fv'] * g * g * eta:.4g} N.s/m, "
                   f"Fc {b['Fc'] * g * eta:.4g} N, offset {b['offset'] * g * eta:.4g} N")
    L.append("")
    L += _wrap(f"candidates, each fitted (LS) jointly with the baseline; dBIC on the estimation run, gain on the "
               f"{diag.validation_mode}; accepted if dBIC < {ACCEPT_DBIC:g} and gain >= {MIN_GAIN:g} %",
               indent="", cont="  ")
    for k, rnd in enumerate(diag.rounds, start=1):
        for cnd in rnd:
            L += _wrap(f"{k}  {cnd.effect.name:<20} dBIC {cnd.dbic:>8.1f}  gain {cnd.gain:>6.1f} %  "
                       + _compact(q, cnd.estimate, cnd.effect.terms), cont=" " * 52)
    for nm, why in diag.skipped.items():
        L += _wrap(f"-  {nm:<20} not tried: {why}", cont=" " * 26)
    for k, cnd, why in diag.rejected:
        L += _wrap(f"{k}  {cnd.effect.name:<20} not accepted: would need {why}", cont=" " * 26)
    L.append("")
    if diag.accepted:
        L += _wrap("verdict: " + ", then ".join(f"{c.effect.name} ({c.effect.summary}; gain {c.gain:.0f} % on "
                                                f"held-out data)" for c in diag.accepted), indent="", cont="  ")
        L += _wrap(f"final fit ({diag.final.method}" + (f"; {diag.final.note}" if diag.final.note else "") + ")",
                   cont="    ")
        L += _param_lines(q, diag.final)
        L += _wrap(f"{q} error: {_errors(diag, diag.final)}", indent="    ")
    else:
        L += _wrap("verdict: nothing beyond the baseline (no effect lowers BIC by 10 and the held-out error by "
                   f"{MIN_GAIN:g} %)", indent="", cont="  ")
    L += _wrap(f"the offset [{unit_eff}] holds any Coulomb asymmetry (Fc+ - Fc-)/2: while the axis moves the two "
               "are the same column")
    return "\n".join(L)


def _est_dict(q, est: Estimate) -> dict:
    d = {"method": est.method, "note": est.note, "iterations": est.iterations, "converged": est.converged,
         "parameters": [{"name": _sym(q, t), "value": float(v * _unit(q, t)[1]), "std": float(s * _unit(q, t)[1]),
                         "unit": _unit(q, t)[0], "label": PARAMS[t][0]} for t, v, s in
                        zip(est.terms, est.theta, est.std)]}
    if "vs" in est.shape:
        u, f = UNITS[q]["speed"]
        d["parameters"].append({"name": "vs", "value": est.shape["vs"] * f, "std": None, "unit": u,
                                "label": "Stribeck velocity (1-D search)"})
    fr = mode_frequency(est)
    if fr is not None:
        d["parameters"].append({"name": "f_r", "value": fr, "std": None, "unit": "Hz", "label": "resonance"})
    return d


def time_diagnosis_dict(diag: TimeDiagnosis) -> dict:
    q, p = diag.quantity, diag.estimation.proc
    runs = [diag.estimation] + diag.validation

    def errs(est):
        return {r.record.source: rel_error(r, est) for r in runs}

    return {
        "kind": "time_record",
        "design": diag.design.get("name"),
        "quantity": q,
        "files": [{"file": r.record.source, "role": "estimation" if i == 0 else "validation",
                   "samples": r.record.n, "rows": r.n} for i, r in enumerate(runs)],
        "processing": {"fs_Hz": p.fs, "cutoff_Hz": p.fc, "cutoff_rule": p.rule, "motion_bandwidth_Hz": p.f_motion,
                       "decimation": p.nd, "decimation_cutoff_Hz": p.fdec,
                       "filter": f"zero-phase Butterworth order {BUTTER_ORDER} (|H|^2 by FFT)"},
        "controller": diag.controller.as_dict() if diag.controller else None,
        "baseline": {"LS": {**_est_dict(q, diag.baseline_ls), "relative_error": errs(diag.baseline_ls)},
                     "IV": {**_est_dict(q, diag.baseline_iv), "relative_error": errs(diag.baseline_iv)}},
        "candidates": [[{"effect": c.effect.name, "dBIC": c.dbic, "gain_percent": c.gain,
                         **_est_dict(q, c.estimate)} for c in rnd] for rnd in diag.rounds],
        "skipped": diag.skipped,
        "verdict": diag.verdict,
        "rejected": [{"round": k, "effect": c.effect.name, "dBIC": c.dbic, "would_need": why}
                     for k, c, why in diag.rejected],
        "gain_percent": [c.gain for c in diag.accepted],
        "final": {**_est_dict(q, diag.final), "relative_error": errs(diag.final)},
        "seconds": diag.times,
    }


def diagnose_time_files(paths, *, plant, gain: str | None = None, candidates=None,
                        max_effects: int = 2) -> TimeDiagnosis:
    """Read the records (the first the estimation run, the others validation runs) and diagnose them against
    ``plant`` (:class:`.plant.Plant`: lead, efficiency and stroke are used)."""
    from .timerecord import check_same_columns, read_time_record

    if candidates:
        unknown = [c for c in candidates if c not in EFFECTS]
        if unknown:
            raise InputError(f"--effects: unknown time-record effect '{unknown[0]}'; known: {', '.join(EFFECTS)}")
    if max_effects < 0:
        raise InputError("--max-effects must not be negative")
    recs = [read_time_record(p, lead=plant.lead, gain=gain) for p in paths]
    for r in recs[1:]:
        check_same_columns(recs[0], r)
        if r.quantity != recs[0].quantity:
            raise InputError(f"a {r.quantity} record cannot validate the {recs[0].quantity} record {recs[0].name}",
                             source=r.source)
    stroke_q = plant.stroke * (1.0 if recs[0].quantity == "force" else 2.0 * math.pi / plant.lead)
    design = {"name": plant.name, "lead": plant.lead, "efficiency": plant.efficiency}
    return diagnose_time(recs, stroke_q=stroke_q, candidates=candidates, max_effects=max_effects, design=design)
