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
  column itself (a rigid-body simulation has no mode).  Not offered when the residual's spectral peak
  follows the position (a ripple moves in frequency with the speed; a mode does not).
* ``lead_ripple``: a force ripple sin, cos(2 pi q/P) (the same both ways: lead error, run-out) and a friction
  ripple sgn(v) sin, sgn(v) cos(2 pi q/P) (ball recirculation), P the lead / k for k = 1, 2, 3 (the best by
  RSS); parameters rs, rc, ks, kc, each pair's amplitude up to the Coulomb level.
* ``quadratic_drag``: v|v|, parameter Cq > 0 (seals, lubricant churning).

An ``external_force`` column (:mod:`.timerecord`) is added to the effort before the regression and enters
the closed-loop simulation of IV.

Selection: forward, each round the candidate with the lowest dBIC = n ln(RSS1/RSS0) + dp ln n on the
estimation run that passes: dBIC < -10, the RMSE of the effort predicted on the validation runs (or, with
no validation run, 5 contiguous blocks of the estimation run held out in turn) falls by at least 5 %, and
its values are physical; every other candidate keeps the first criterion it failed as its reason.  When no
single effect passes, pairs of the candidates that lower BIC alone are fitted together and accepted on the
same tests when each member is needed (:func:`_best_pair`).  The baseline and final fits carry plausibility
and identifiability flags (:func:`baseline_flags`), and the final residual is tested for structure
(:func:`analyse_residual`, :mod:`.residual`): what remains is reported as "unexplained" with its signature.
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
    "rs": ("force ripple, sin(2 pi q/P) coefficient", "effort"),
    "rc": ("force ripple, cos(2 pi q/P) coefficient", "effort"),
    "ks": ("friction ripple, sgn(v) sin(2 pi q/P) coefficient", "effort"),
    "kc": ("friction ripple, sgn(v) cos(2 pi q/P) coefficient", "effort"),
    "Cq": ("quadratic drag c v|v|", "drag2"),
}
UNITS = {
    "force": {"mass": ("kg", 1.0), "damping": ("N.s/m", 1.0), "effort": ("N", 1.0), "snap": ("kg.s^2", 1.0),
              "speed": ("mm/s", 1e3), "position": ("mm", 1e3), "drag2": ("N.s^2/m^2", 1.0)},
    "torque": {"mass": ("kg.m^2", 1.0), "damping": ("N.m.s/rad", 1.0), "effort": ("N.m", 1.0),
               "snap": ("kg.m^2.s^2", 1.0), "speed": ("rad/s", 1.0), "position": ("rad", 1.0),
               "drag2": ("N.m.s^2/rad^2", 1.0)},
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
    "lead_ripple": TimeEffect("lead_ripple", ("rs", "rc", "ks", "kc"), shape="period",
                              summary="force or friction ripple periodic in position at the lead or a harmonic "
                                      "(lead error, ball recirculation)"),
    "quadratic_drag": TimeEffect("quadratic_drag", ("Cq",),
                                 summary="drag growing with v|v| (seals, lubricant churning)"),
}
RIPPLE_HARMONICS = (1, 2, 3)  # the ripple's period is the lead / k for one of these k (chosen by RSS)


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
    lead_q: float = 0.0  # the screw's lead in the record's coordinate (table [m] or motor angle 2 pi [rad])


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
    if term in ("rs", "rc", "ks", "kc"):
        ph = 2.0 * math.pi * sig["q"] / shape["period"]
        w = np.sin(ph) if term in ("rs", "ks") else np.cos(ph)
        return w if term in ("rs", "rc") else s * w
    if term == "Cq":
        return v * np.abs(v)
    raise KeyError(term)


def full_matrix(sig: dict, terms, proc: Processing, shape: dict) -> np.ndarray:
    return np.column_stack([_columns(t, sig, proc, shape) for t in terms])


def decimate(rows_full: np.ndarray, proc: Processing, keep: np.ndarray) -> np.ndarray:
    """Parallel decimation: the same low-pass on every column, then the kept rows."""
    return lowpass(rows_full, proc.fs, proc.fdec)[keep]


def processing_for(rec: TimeRecord, stroke_q: float, lead_q: float = 0.0) -> Processing:
    fs = rec.fs
    cut = choose_cutoff(rec.q, fs)
    nd = decimation_factor(fs, cut.fc)
    fdec = 0.8 * fs / (2.0 * nd)
    q, v = derivatives(rec.q, fs, cut.fc, 1)
    vmin = VMIN_REL * float(np.max(np.abs(v)))
    return Processing(fs, cut.fc, nd, fdec, cut.f_motion, cut.rule, vmin, stroke_q, lead_q)


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
    y = lowpass(rec.effort + rec.external if rec.external is not None else rec.effort, proc.fs, proc.fdec)[keep]
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
    rs, rc, ks, kc = (params.get(t, 0.0) for t in ("rs", "rc", "ks", "kc"))
    ripple = any((rs, rc, ks, kc))
    kq = 2.0 * math.pi / shape["period"] if ripple else 0.0
    cq = params.get("Cq", 0.0)
    ext = rec.external.tolist() if rec.external is not None else None
    sin, cos = math.sin, math.cos
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
        if ext is not None:
            u += ext[k]
        for _ in range(substeps):
            xi = sq * q - 1.0
            dpos = c1 * xi + c2 * (1.5 * xi * xi - 0.5)
            uk = u
            if ripple:
                sn, cn = sin(kq * q), cos(kq * q)
                uk = u - rs * sn - rc * cn
                dpos += ks * sn + kc * cn
            if v == 0.0:
                brk = fc + fsx + dpos
                if brk < 0.0:
                    brk = 0.0
                if uk > brk:
                    v = hm * (uk - brk)
                elif uk < -brk:
                    v = hm * (uk + brk)
            else:
                if v > 0:
                    fr = fc + fvp * v + fsx * exp(-v / vs) + dpos + cq * v * v
                else:
                    fr = -fc + fvn * v - fsx * exp(v / vs) - dpos - cq * v * v
                vn = v + hm * (uk - fr)
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
    reason: str = ""  # why it was not accepted ('' when accepted or not yet judged)
    together: str = ""  # accepted as a pair with this effect (neither passes alone)


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
    pairs: list = field(default_factory=list)  # (round, TimeCandidate, TimeCandidate, Estimate, dBIC, gain, reason)
    unexplained: Unexplained | None = None  # structure left in the final residual
    flags: dict = field(default_factory=dict)  # 'baseline' / 'final' -> [plausibility or identifiability notes]
    lost: LostMotion | None = None  # lost motion between motor and table (records with motor_position)

    @property
    def verdict(self) -> list:
        return [c.effect.name for c in self.accepted] + (["backlash"] if self.lost and self.lost.accepted else [])

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


# ------------------------------------------------------------------------ lost motion (motor vs table position)
LOST_MOTION_MAX = 0.2e-3  # [m] table travel: a preloaded ball-screw axis loses at most a few um; a lost motion
#                          above 0.2 mm is a loose coupling, key or nut, reported as implausible, not fitted
LOST_MOTION_T = 5.0  # the lost motion's estimate must be this many standard deviations above zero


@dataclass
class LostMotion:
    """Motor encoder against table position: e = motor_q - q = e0 + (b/2) sgn(F) + F/k - (c/k) de/dt, F = f - m1 a1 the
    force the transmission carries (f the effort, a1 the motor side's acceleration, m1 the motor-side mass or
    inertia, found by a 1-D search)."""

    width: float  # b, the lost motion [record coordinate]
    width_std: float
    stiffness: float  # k [effort / coordinate]; inf when the windup is not measurable
    motor_mass: float  # m1 [mass or inertia]
    rms_before: float  # [coordinate] held-out RMS of e with only offset and windup (no lost motion)
    rms_after: float
    gain: float  # [%]
    reason: str = ""  # why it is not accepted ('' when it is)

    @property
    def accepted(self) -> bool:
        return not self.reason


def _lost_motion_rows(rows: Rows, m1: float, fmin: float):
    """(e, columns [1, sgn F, f, a1, de/dt]) at the rows where |F| = |f - m1 a1| > fmin (the side of the gap is
    certain there): e = e0 + (b/2) sgn F + f/k - (m1/k) a1 - (c/k) de/dt."""
    rec = rows.record
    if "lost_motion" not in rows.sig:  # e, the motor side's own acceleration and de/dt, filtered as the effort is
        sm, se = signals(rec.motor_q, rows.proc), signals(rec.motor_q - rec.q, rows.proc)
        rows.sig["lost_motion"] = decimate(np.column_stack([se["q"], sm["a"], se["v"]]), rows.proc, rows.keep)
    e, a1, de = rows.sig["lost_motion"].T
    F = rows.y - m1 * a1
    ok = np.abs(F) > fmin
    return e[ok], np.column_stack([np.ones(ok.sum()), np.sign(F[ok]), rows.y[ok], a1[ok], de[ok]])


def lost_motion(est_rows: Rows, val_rows: list, base: Estimate, noise: float, lead_m: float = 0.0) -> LostMotion | None:
    """The lost motion and windup between motor and table when every record has a ``motor_position`` column;
    judged like an effect: significant, plausible and better on the held-out rows (validation runs, else
    the estimation run's second half).  m1 enters linearly (the a1 column) but also decides which side of the
    gap each row is on: a coarse grid, then the fit's own m1 until the sides stop changing."""
    if est_rows.record.motor_q is None or any(v.record.motor_q is None for v in val_rows):
        return None
    M = max(base.value("M"), 0.0)
    fmin = 3.0 * noise

    def fit(m1):
        e, G = _lost_motion_rows(est_rows, m1, fmin)
        if len(e) < 20:
            return None
        th, *_ = np.linalg.lstsq(G, e, rcond=None)
        return float(np.sum((e - G @ th) ** 2)), m1, th, e, G

    fits = [f for f in (fit(m) for m in np.linspace(0.0, M, 21)) if f is not None]
    if not fits:
        return None
    best = min(fits, key=lambda f: f[0])
    for _ in range(20):
        th = best[2]
        m1 = float(np.clip(-th[3] / th[2], 0.0, M)) if th[2] > 0 else best[1]
        if abs(m1 - best[1]) <= 1e-6 * max(M, 1e-12):
            break
        nxt = fit(m1)
        if nxt is None or nxt[0] > best[0]:
            break
        best = nxt
    rss, m1, th, e, G = best
    dof = max(len(e) - G.shape[1], 1)
    cov = rss / dof * np.linalg.pinv(G.T @ G)
    half, half_std = float(th[1]), float(math.sqrt(max(cov[1, 1], 0.0)))
    k = 1.0 / th[2] if th[2] > 0 else float("inf")
    if val_rows:
        held = [_lost_motion_rows(v, m1, fmin) for v in val_rows]
        fit_e, fit_G = e, G
    else:  # no validation run: fit on the first half, judge on the second
        n2 = len(e) // 2
        held, fit_e, fit_G = [(e[n2:], G[n2:])], e[:n2], G[:n2]
    th_full, *_ = np.linalg.lstsq(fit_G, fit_e, rcond=None)
    other = [0, 2, 3, 4]  # every column but the lost motion's
    th_base, *_ = np.linalg.lstsq(fit_G[:, other], fit_e, rcond=None)
    r_full = np.concatenate([he - hG @ th_full for he, hG in held])
    r_base = np.concatenate([he - hG[:, other] @ th_base for he, hG in held])
    before, after = float(np.sqrt(np.mean(r_base**2))), float(np.sqrt(np.mean(r_full**2)))
    gain = 100.0 * (1.0 - after / before) if before > 0 else 0.0
    width, width_std = 2.0 * half, 2.0 * half_std
    to_q = 1.0 if est_rows.record.quantity == "force" else (2.0 * math.pi / lead_m if lead_m > 0 else float("inf"))
    lim = LOST_MOTION_MAX * to_q
    reason = ""
    if width <= LOST_MOTION_T * width_std or width <= 0.0:
        reason = f"not significant (b = {width:.3g} +- {width_std:.2g}, below {LOST_MOTION_T:g} standard deviations)"
    elif gain < MIN_GAIN:
        reason = f"held-out gain {gain:.1f} % < {MIN_GAIN:g} %"
    elif width > lim:
        reason = "would need a lost motion above 0.2 mm of table travel (a loose coupling, key or nut, not backlash)"
    return LostMotion(width, width_std, k, m1, before, after, gain, reason)


# ------------------------------------------------------------------------------ what remains unexplained
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


def noise_floor(rows: Rows) -> float:
    """Sensor noise of the effort at the regression rows: the white part of the raw effort from its second
    differences (median absolute deviation, var(e1 - 2 e2 + e3) = 6 sigma^2), through the decimation low-pass
    (equivalent noise bandwidth of |H|^2 = 1/(1 + (f/f_d)^8): 1.026 f_d)."""
    e = rows.record.effort
    d2 = e[2:] - 2.0 * e[1:-1] + e[:-2]
    s = 1.4826 * float(np.median(np.abs(d2 - np.median(d2)))) / math.sqrt(6.0)
    return s * math.sqrt(min(1.0, 2.0 * 1.026 * rows.proc.fdec / rows.proc.fs))


def _pooled(runs: list, full_cols) -> np.ndarray:
    """Columns computed at full rate on each run (``full_cols(rows) -> (N, k)``), decimated alike, stacked."""
    return np.vstack([decimate(np.asarray(full_cols(r)).reshape(r.record.n, -1), r.proc, r.keep) for r in runs])


def since_reversal(rw: Rows) -> np.ndarray:
    """Travel since the last reversal of the motion at every full-rate sample, in the record's coordinate:
    the direction is sgn(v) where the axis moves faster than the record's speed threshold, held through
    slow stretches; the travel is measured from the position where it last changed (from the first sample
    before the first reversal)."""
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


REVERSAL_SCALES = (0.0005, 0.002, 0.01)  # travel scales of the reversal probe, as fractions of the stroke


def _legendre(x, deg):
    return [np.polynomial.legendre.Legendre.basis(j)(x) for j in range(1, deg + 1)]


def analyse_residual(runs: list, est: Estimate, kinds=None) -> Unexplained:
    """Test the residual of ``est`` on ``runs`` (estimation first) for structure: over position (a period
    scan, the lead and its harmonics named in advance), velocity, position along the stroke, time within a
    run, between runs and acceleration; see :mod:`.residual`."""
    from . import residual as rs

    proc = runs[0].proc
    W = np.vstack([matrix(r, est.terms, est.shape) for r in runs])
    y = np.concatenate([r.y for r in runs])
    r = y - W @ est.theta
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
            return _pooled(runs, cols)
        q_rows = np.concatenate([rw.sig["q"][rw.keep] for rw in runs])
        s_rows = np.concatenate([np.sign(rw.sig["v"][rw.keep]) for rw in runs])
        hi = max(float(np.ptp(q_rows)) / 3.0, proc.lead_q)
        probes.append(rs.period_scan(r, q_rows, s_rows, periodic, proc.lead_q / 4.0, hi, W, neff,
                                     fixed=[proc.lead_q / k for k in RIPPLE_HARMONICS]))
    if kinds is not None:
        return Unexplained(probes, float(np.sqrt(np.mean(r**2))), 0.0, rho, len(r))

    def vel_cols(rw):
        v = rw.sig["v"]
        u = 2.0 * np.abs(v) / vmax - 1.0
        sg = np.sign(v)
        return np.column_stack(_legendre(u, 4) + [sg * p for p in _legendre(u, 4)])
    pv = rs.probe("velocity", r, _pooled(runs, vel_cols), W, neff)
    shapes = {"v|v|": _pooled(runs, lambda rw: rw.sig["v"] * np.abs(rw.sig["v"]))[:, 0],
              "|v|": _pooled(runs, lambda rw: np.abs(rw.sig["v"]))[:, 0],
              "sqrt": _pooled(runs, lambda rw: np.sign(rw.sig["v"]) * np.sqrt(np.abs(rw.sig["v"])))[:, 0]}
    for f in (0.01, 0.03, 0.1):
        shapes[f"low_speed_{f}"] = _pooled(runs, lambda rw, f=f: np.sign(rw.sig["v"])
                                          * np.exp(-np.abs(rw.sig["v"]) / (f * vmax)))[:, 0]
    nm, sh = rs.best_shape(r, shapes, W)
    pv.detail.update(shape="low_speed" if nm.startswith("low_speed") else nm,
                     shape_share=sh / pv.share if pv.share > 0 else 0.0)
    probes.append(pv)
    sq = proc.stroke_q

    def pos_cols(rw):
        xi = 2.0 * rw.sig["q"] / sq - 1.0
        sg = np.sign(rw.sig["v"])
        return np.column_stack(_legendre(xi, 4) + [sg * p for p in _legendre(xi, 4)])
    G = _pooled(runs, pos_cols)
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
        return np.column_stack(_legendre(2.0 * (t - t[0]) / (t[-1] - t[0]) - 1.0, 3))
    probes.append(rs.probe("time", r, _pooled(runs, time_cols), W, neff))
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
        probes.append(rs.probe("load", r, _pooled(runs, load_cols), W, neff))

    def rev_cols(rw):
        d, sg = since_reversal(rw), np.sign(rw.sig["v"])
        cols = [np.exp(-d / (f * sq)) for f in REVERSAL_SCALES]
        return np.column_stack(cols + [sg * c for c in cols])
    pr = rs.probe("reversal", r, _pooled(runs, rev_cols), W, neff)
    rev_shapes = {f: _pooled(runs, lambda rw, f=f: np.column_stack([np.exp(-since_reversal(rw) / (f * sq))]))[:, 0]
                  for f in REVERSAL_SCALES}
    best, _ = rs.best_shape(r, rev_shapes, W)
    pr.detail["scale"] = best * sq
    probes.append(pr)

    def acc_cols(rw):
        a, sg = rw.sig["a"], np.sign(rw.sig["v"])
        return np.column_stack([sg * a, np.abs(a), a * np.abs(a)])
    probes.append(rs.probe("acceleration", r, _pooled(runs, acc_cols), W, neff))
    probes.sort(key=lambda p: p.log10_p)
    noise = math.sqrt(sum(noise_floor(rw) ** 2 * rw.n for rw in runs) / sum(rw.n for rw in runs))
    return Unexplained(probes, float(np.sqrt(np.mean(r**2))), noise, rho, len(r))


def _periodic_peak(rows: Rows, est: Estimate):
    """(period, share) when the residual of ``est`` is mostly periodic in position (a significant probe holding
    at least half of it), else None: a spectral peak that moves with speed is a ripple, not a mode."""
    if rows.proc.lead_q <= 0:
        return None
    u = analyse_residual([rows], est, kinds=("position_periodic",))
    p = u.probes[0] if u.probes else None
    return (p.detail["period"], p.share) if p is not None and p.significant and p.share >= 0.5 else None


def implausible(cand_terms, est: Estimate, base: Estimate) -> str:
    """Why an effect's fitted terms leave their physical range ('' when they do not).  Ranges, relative to
    the baseline's own friction: a Stribeck excess between 0 and twice the Coulomb level (breakaway up to
    three times it); a viscous direction difference up to the viscous coefficient itself; a Coulomb
    variation along the stroke (each Legendre coefficient) up to the Coulomb level; an extra mode with a
    positive m1 m2 / k (a real mass behind a real spring); a quadratic drag with a positive coefficient; a
    force or friction ripple (amplitude of each) up to the Coulomb level."""
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
        elif t == "Cq" and v <= 0.0:
            out.append(f"Cq = {v:.4g} not positive (a drag that falls with v|v| is no drag)")
        elif t == "rs" and math.hypot(v, est.value("rc")) > fc:
            out.append(f"a force ripple of amplitude {math.hypot(v, est.value('rc')):.4g} beyond {fc:.4g} "
                       "(the whole Coulomb friction)")
        elif t == "ks" and math.hypot(v, est.value("kc")) > fc:
            out.append(f"a friction ripple of amplitude {math.hypot(v, est.value('kc')):.4g} beyond {fc:.4g} "
                       "(the friction would reverse)")
    return "; ".join(out)


def _fit_candidate(est_rows, terms, effect, shape):
    shape = dict(shape)
    if effect.shape == "vs":
        vmax = float(np.max(np.abs(est_rows.sig["v"])))
        shape["vs"] = search_shape(est_rows, terms, shape, max(est_rows.proc.vmin, 1e-4 * vmax), 0.5 * vmax)
    elif effect.shape == "period":
        fits = [least_squares(est_rows, terms, {**shape, "period": est_rows.proc.lead_q / k})
                for k in RIPPLE_HARMONICS]
        best = min(fits, key=lambda e: e.rss)
        return best, dict(best.shape)
    return least_squares(est_rows, terms, shape), shape


def diagnose_time(records: list, *, stroke_q: float, candidates=None, max_effects: int = 3,
                  design: dict | None = None, lead_q: float = 0.0) -> TimeDiagnosis:
    """Identify the estimation record ``records[0]`` (LS and IV), select effects, validate on the rest."""
    import time

    t0 = time.perf_counter()
    est = records[0]
    proc = processing_for(est, stroke_q, lead_q)
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
        elif nm == "extra_mode" and (per := _periodic_peak(est_rows, base_ls)) is not None:
            skipped[nm] = (f"the residual's spectral peak ({peak[0]:.0f} Hz) follows the position: periodic over "
                           f"{per[0] * UNITS[est.quantity]['position'][1]:.3g} {UNITS[est.quantity]['position'][0]}, "
                           f"{100 * per[1]:.0f} % of the residual (a ripple, not a resonance)")
        elif nm == "position_friction" and span < 0.1 * stroke_q:
            skipped[nm] = "the record covers less than 10 % of the stroke"
        elif nm == "lead_ripple" and not (lead_q > 0 and span >= 2.0 * lead_q):
            skipped[nm] = "the record covers less than two leads" if lead_q > 0 else "no lead known"
        else:
            pool.append(e)

    terms, shape = list(BASE), {}
    cur = base_ls
    cur_ho = _heldout_rmse(est_rows, val_rows, terms, shape)
    accepted, rounds, rejected, pairs = [], [], [], []
    while len(accepted) < max_effects:
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
        for c in scored:  # the best candidate by dBIC that is physical and predicts held-out data better
            why = implausible(c.effect.terms, c.estimate, base_ls)
            if why:
                rejected.append((len(rounds), c, why))
            if c.dbic >= ACCEPT_DBIC:  # the first criterion it fails is its reason
                c.reason = f"dBIC {c.dbic:.1f} not below {ACCEPT_DBIC:g}"
            elif c.gain < MIN_GAIN:
                c.reason = f"held-out gain {c.gain:.1f} % below {MIN_GAIN:g} %"
            elif why:
                c.reason = f"would need {why}"
            if why and not c.reason.startswith("would need"):
                c.reason += f"; and it would need {why}"
            if not c.reason and top is None:
                top = c
        if top is not None:
            top.reason = ""
            for c in scored:
                if c is not top and not c.reason:
                    c.reason = f"{top.effect.name} explains more (dBIC {top.dbic:.1f})"
            accepted.append(top)
            terms += list(top.effect.terms)
            shape.update(top.estimate.shape)
            cur = top.estimate
            cur_ho = _heldout_rmse(est_rows, val_rows, terms, shape)
            continue
        # pairs only when some candidate found signal (dBIC < -10) that no single effect turns into an accepted
        # explanation: a residual at the noise floor costs no pair fits
        if len(accepted) + 2 > max_effects or not any(c.dbic < ACCEPT_DBIC for c in scored):
            break
        pair = _best_pair(est_rows, val_rows, scored, terms, shape, cur, cur_ho, base_ls, len(rounds), pairs)
        if pair is None:
            break
        a_, b_, fit = pair[1], pair[2], pair[3]
        for c, other in ((a_, b_), (b_, a_)):
            c.reason, c.together = f"alone: {c.reason}; accepted together with {other.effect.name}", other.effect.name
        accepted += [a_, b_]
        terms += list(a_.effect.terms) + list(b_.effect.terms)
        shape = dict(fit.shape)
        cur = fit
        cur_ho = _heldout_rmse(est_rows, val_rows, terms, shape)
        for c in (a_, b_):
            c.gain = pair[5]
    final_ls = least_squares(est_rows, terms, shape) if accepted else base_ls
    final = instrumental_variables(est_rows, terms, shape, ctrl=ctrl, start=final_ls) if accepted else base_iv
    un = analyse_residual([est_rows] + val_rows, final)
    flags = {"baseline": baseline_flags(base_iv, est.quantity), "final": baseline_flags(final, est.quantity)}
    if "vs" in final.shape:  # a shape parameter at the end of its 1-D search is not identified by the record
        vmax = float(np.max(np.abs(est_rows.sig["v"])))
        lo, hi = max(proc.vmin, 1e-4 * vmax), 0.5 * vmax
        if not 1.05 * lo < final.shape["vs"] < 0.95 * hi:
            u, f = UNITS[est.quantity]["speed"]
            flags["final"].append(f"vs = {final.shape['vs'] * f:.3g} {u} is at the end of its search range "
                                  f"({lo * f:.3g}..{hi * f:.3g} {u}): the Stribeck velocity is not identifiable from "
                                  "this record")
    lost = lost_motion(est_rows, val_rows, final_ls, noise_floor(est_rows), (design or {}).get("lead", 0.0))
    times = {"ls": t_ls, "iv": t_iv, "diagnose": time.perf_counter() - t0}
    return TimeDiagnosis(est.quantity, est_rows, val_rows, ctrl, base_ls, base_iv, final, final_ls, accepted,
                         rounds, skipped, peak, times, dict(design or {}), rejected, pairs, un, flags, lost)


MAX_PAIR_POOL = 6  # pairs are tried among at most this many single candidates (the best by dBIC): 15 fits


def _best_pair(est_rows, val_rows, scored, terms, shape, cur, cur_ho, base_ls, rnd, log):
    """When no single effect passes, effects that only help together: every pair of the round's candidates
    that lower BIC at all alone (at most ``MAX_PAIR_POOL``), fitted jointly with the shapes each found alone;
    a pair is accepted when it lowers BIC by 10, predicts the held-out data at least ``MIN_GAIN`` % better,
    keeps every value in its physical range, and beats each of its members alone by ``MIN_GAIN`` % (each is
    needed).  The pair with the largest held-out gain wins;
    every pair tried is logged with its reason."""
    pool = [c for c in scored if c.dbic < 0.0][:MAX_PAIR_POOL]  # each must show some signal alone
    best = None
    for i in range(len(pool)):
        for j in range(i + 1, len(pool)):
            a, b = pool[i], pool[j]
            sh0 = {**shape, **{k: v for k, v in a.estimate.shape.items() if k not in shape},
                   **{k: v for k, v in b.estimate.shape.items() if k not in shape}}
            tt = terms + list(a.effect.terms) + list(b.effect.terms)
            fit, sh = least_squares(est_rows, tt, sh0), sh0  # shapes as found for each alone
            dbic = fit.bic - cur.bic
            ho = _heldout_rmse(est_rows, val_rows, tt, sh)
            gain = 100.0 * (1.0 - ho / cur_ho) if cur_ho > 0 else 0.0
            why = implausible(a.effect.terms + b.effect.terms, fit, base_ls)
            alone = max(a.gain, b.gain)
            if dbic >= ACCEPT_DBIC:
                reason = f"dBIC {dbic:.1f} not below {ACCEPT_DBIC:g}"
            elif gain < MIN_GAIN:
                reason = f"held-out gain {gain:.1f} % below {MIN_GAIN:g} %"
            elif why:
                reason = f"would need {why}"
            elif gain - alone < MIN_GAIN:
                reason = f"held-out gain {gain:.1f} % is not {MIN_GAIN:g} % above the better member alone " \
                         f"({alone:.1f} %)"
            else:
                reason = ""
            entry = [rnd, a, b, fit, dbic, gain, reason]
            log.append(entry)
            if not reason and (best is None or gain > best[5]):
                best = entry
    if best is not None:
        for e in log:
            if e is not best and e[0] == rnd and not e[6]:
                e[6] = f"{best[1].effect.name} + {best[2].effect.name} predicts better ({best[5]:.1f} %)"
    return best


def baseline_flags(est: Estimate, quantity: str) -> list:
    """Plausibility and identifiability of a fit's baseline terms: a moving mass or inertia, viscous or Coulomb
    friction that is not positive is never a physical fit; a term whose standard deviation is zero or
    undefined, or larger than its value, is not identifiable from the record."""
    out = []
    sym = "J" if quantity == "torque" else "M"
    for t in est.terms:
        i = est.terms.index(t)
        v, sd = float(est.theta[i]), float(est.std[i])
        u, f = _unit(quantity, t)
        name = _sym(quantity, t)
        if t == "M" and v <= 0.0:
            out.append(f"{sym} = {v * f:.3g} {u} is not positive: no moving body has zero or negative "
                       "inertia -- the record does not excite acceleration enough for its sampling and noise "
                       "(too coarse, too slow), or effort and position disagree in sign")
        elif t == "Fc" and v < 0.0:
            out.append(f"Fc = {v * f:.3g} {u} is negative: friction that drives the axis -- check the signs of "
                       "the effort and position columns, or a force the record does not carry "
                       "(external_force)")
        elif t == "Fv" and v < 0.0:
            out.append(f"Fv = {v * f:.3g} {u} is negative: damping that feeds energy in -- a missing low-speed "
                       "(Stribeck) rise or a force the record does not carry pulls it below zero")
        if t in BASE or t in PARAMS:
            if not math.isfinite(sd) or sd == 0.0:
                out.append(f"{name} is not identifiable from this record: its uncertainty is "
                           f"{'undefined' if not math.isfinite(sd) else 'zero'} (a degenerate column)")
            elif t in ("M", "Fv", "Fc") and sd >= abs(v):
                out.append(f"{name} = {v * f:.3g} ± {sd * f:.3g} {u} is not identifiable from this record "
                           "(the uncertainty exceeds the value)")
    return out


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
    for f in diag.flags.get("baseline", []):
        L += _wrap(f"! {f}", indent="  ", cont="      ")
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
    for k, rnd in enumerate(diag.rounds, start=1):
        for cnd in rnd:
            if cnd.reason:
                L += _wrap(f"{k}  {cnd.effect.name:<20} not accepted: {cnd.reason}", cont=" " * 26)
    rest = 0
    for k, a, b, _est, dbic, gain, why in diag.pairs:
        if why and (dbic >= ACCEPT_DBIC or gain < MIN_GAIN):
            rest += 1
            continue
        L += _wrap(f"{k}  pair {a.effect.name} + {b.effect.name}: dBIC {dbic:.1f}, gain {gain:.1f} %: "
                   + (f"not accepted: {why}" if why else "accepted (neither passes alone)"), cont=" " * 26)
    if rest:
        L += _wrap(f"-  {rest} pair{'s' if rest > 1 else ''} of these candidates tried together: none lowers BIC "
                   f"by {-ACCEPT_DBIC:g} and predicts the held-out data {MIN_GAIN:g} % better", cont=" " * 26)
    L.append("")
    if diag.accepted:
        parts = []
        for c in diag.accepted:
            if c.together and parts and parts[-1].startswith(c.together):
                parts[-1] = parts[-1].replace(" (", f" together with {c.effect.name} (", 1)
                continue
            parts.append(f"{c.effect.name} ({c.effect.summary}; gain {c.gain:.0f} % on held-out data)")
        L += _wrap("verdict: " + ", then ".join(parts), indent="", cont="  ")
        L += _wrap(f"final fit ({diag.final.method}" + (f"; {diag.final.note}" if diag.final.note else "") + ")",
                   cont="    ")
        L += _param_lines(q, diag.final)
        L += _wrap(f"{q} error: {_errors(diag, diag.final)}", indent="    ")
        for f in diag.flags.get("final", []):
            L += _wrap(f"! {f}", indent="  ", cont="      ")
    elif not (diag.lost and diag.lost.accepted):
        L += _wrap("verdict: nothing named beyond the baseline: " + _why_none(diag), indent="", cont="  ")
    L += _lost_motion_lines(diag)
    L += _unexplained_lines(diag)
    L += _wrap(f"the offset [{unit_eff}] holds any Coulomb asymmetry (Fc+ - Fc-)/2: while the axis moves the two "
               "are the same column")
    return "\n".join(L)


def _lost_motion_lines(diag: TimeDiagnosis) -> list:
    lm = diag.lost
    if lm is None:
        return []
    q = diag.quantity
    b, sb = _mm(diag, lm.width) * 1e3, _mm(diag, lm.width_std) * 1e3
    what = (f"motor_position against position: e = e0 + (b/2) sgn(F) + F/k, F = {q} - m1 a1 the force the "
            f"transmission carries; b = {b:.3g} ± {sb:.2g} um of table travel")
    if math.isfinite(lm.stiffness) and lm.stiffness > 0:
        per_m = lm.stiffness / (_mm(diag, 1.0) * 1e-3)  # effort per metre of table travel
        k_txt = f"{per_m / 1e6:.3g} N/um" if q == "force" else f"{per_m / 1e6:.3g} N.m per um of table travel"
        what += f", windup stiffness k {k_txt}"
    m_u = UNITS[q]["mass"][0]
    what += (f", motor-side m1 {lm.motor_mass:.3g} {m_u}; held-out RMS of e {_mm(diag, lm.rms_before) * 1e3:.3g} -> "
             f"{_mm(diag, lm.rms_after) * 1e3:.3g} um (gain {lm.gain:.0f} %)")
    if lm.accepted:
        head = "verdict: backlash (lost motion between motor and table, measured by the two encoders): "
        return _wrap(head + what, indent="", cont="  ")
    return _wrap(f"lost motion between motor and table not named ({lm.reason}): {what}", indent="", cont="  ")


def _why_none(diag: TimeDiagnosis) -> str:
    """The true reason no effect was named: the best candidates and what stopped each."""
    if not diag.rounds:
        return "no candidate effect applies to this record"
    best = diag.rounds[0][:3]
    out = [f"{c.effect.name}: " + (f"dBIC {c.dbic:.1f} and gain {c.gain:.1f} %, but {c.reason}"
                                   if c.reason.startswith("would need") else c.reason) for c in best]
    return "; ".join(out)


def _mm(diag: TimeDiagnosis, q_len: float) -> float:
    """A length in the record's coordinate as table travel [mm]."""
    if diag.quantity == "force":
        return q_len * 1e3
    return q_len / (2.0 * math.pi) * diag.design.get("lead", 0.0) * 1e3


SIGNATURE_WORDS = {
    # kind -> (candidate causes, the measurement that separates them)
    "position_periodic_lead": (
        "lead error or ball recirculation (a circuit per turn), screw run-out or a bent screw",
        "repeat at two speeds and in both directions: a ripple fixed in millimetres stays while a resonance or "
        "the controller moves with speed; a friction ripple changes sign with the direction, a lead error or "
        "run-out does not; measure the lead error with a laser against the scale"),
    "position_periodic": (
        "ball recirculation over a circuit of several turns, the guide's ball pitch, a coupling misalignment "
        "or motor cogging geared to this period",
        "repeat at two speeds (a period fixed in millimetres stays) and compare the period with the nut's "
        "circuit length, the guide-ball pitch and the motor's pole pitch through the lead"),
    "velocity_v|v|": (
        "quadratic drag, e.g. seals or lubricant churning, or air drag on a large table",
        "a friction curve at constant speeds up to the maximum in both directions (v|v| against a steeper "
        "viscous slope), repeated warm: churning falls as the lubricant thins"),
    "velocity_low_speed": (
        "a low-speed friction rise the fitted terms do not hold (a second Stribeck constant, breakaway)",
        "a friction curve with many constant speeds below 10 mm/s in both directions"),
    "velocity_|v|": (
        "viscous friction that differs by direction (a seal or wiper lip, a gravity or cable-chain load)",
        "constant-speed runs at several speeds in both directions"),
    "velocity": (
        "a velocity dependence of friction that none of the library's terms has",
        "a friction curve at constant speeds over the whole speed range in both directions"),
    "position": (
        "friction or a force that varies along the stroke: guide misalignment, screw straightness, preload "
        "varying along the screw, a cable chain or hose",
        "a slow constant-speed run over the full stroke in both directions (a friction changes sign with the "
        "direction, a cable-chain or weight force does not)"),
    "time": (
        "a drift within the run: warm-up (friction falls as the lubricant heats) or a load that changes",
        "repeat the run cold and warm, and with a temperature sensor on the nut"),
    "run": (
        "runs that differ: temperature, lubrication or load changed between the estimation and validation "
        "runs",
        "repeat one run twice in a row and note the nut temperature"),
    "load": (
        "a dependence on the process force: nut or guide friction growing with the load (efficiency), a "
        "compliant support that shifts under it, or an external_force column with a wrong sign or scale",
        "runs at one speed with different constant process forces, both directions, and a check of the force "
        "sensor's sign and calibration"),
    "reversal": (
        "lost motion (backlash) between the motor and the table, or the impact of taking up the lost motion "
        "exciting the drive, or the elastic windup of a compliant transmission",
        "record the motor encoder's position beside the table position (a motor_position column): the "
        "diagnosis then measures the lost motion and the windup; or a reversal test per ISO 230-2 at low speed"),
    "acceleration": (
        "a dependence on acceleration beyond M a: a compliant transmission (the motor side lags), lost motion, "
        "or an inertia that differs by direction",
        "runs with the same speeds at different accelerations, and a second encoder on the motor"),
}


def signature_text(diag: TimeDiagnosis, p) -> tuple:
    """(what the residual does, candidate causes, separating measurement) of a probe, in words."""
    d = p.detail
    if p.kind == "position_periodic":
        P = _mm(diag, d["period"])
        lead_mm = _mm(diag, diag.estimation.proc.lead_q)
        ratio = lead_mm / P if P > 0 else 0.0
        k = round(ratio)
        at_lead = k >= 1 and abs(ratio - k) < 0.02 * k
        name = "the lead" if k == 1 else f"the lead / {k}"
        kind = ("a friction (changes sign with the direction)" if d.get("friction_share", 0) > 0.5 else
                "a force (the same sign both ways)")
        what = f"periodic in position with period {P:.1f} mm" + (f" = {name}" if at_lead else
                                                                  f" (the lead is {lead_mm:.3g} mm)") + f", {kind}"
        key = "position_periodic_lead" if at_lead else "position_periodic"
    elif p.kind == "velocity":
        shape = d.get("shape", "")
        sh = d.get("shape_share", 0.0)
        words = {"v|v|": "grows with v|v|", "low_speed": "rises at low speed", "|v|": "differs by direction, "
                 "growing with speed", "sqrt": "grows with the square root of speed"}
        if sh >= 0.7 and shape in words:
            what = f"depends on velocity: {words[shape]}"
            key = f"velocity_{shape}" if f"velocity_{shape}" in SIGNATURE_WORDS else "velocity"
        else:
            what, key = "depends on velocity in a shape none of the library's terms has", "velocity"
    elif p.kind == "position":
        lo, hi = d.get("worst", (0.0, 0.0))
        what = f"varies along the stroke (largest at {_mm(diag, lo):.0f}-{_mm(diag, hi):.0f} mm)"
        key = "position"
    elif p.kind == "time":
        what, key = "drifts with time within a run", "time"
    elif p.kind == "run":
        what, key = "differs between the estimation and validation runs", "run"
    elif p.kind == "load":
        what, key = "depends on the external force", "load"
    elif p.kind == "reversal":
        what = (f"is concentrated in the first {_mm(diag, d.get('scale', 0.0)):.2g} mm of travel after each "
                "direction reversal")
        key = "reversal"
    else:
        what, key = "depends on acceleration beyond M a", "acceleration"
    causes, measure = SIGNATURE_WORDS[key]
    return what, causes, measure


NOISE_RATIO = 2.0  # a residual this many times the noise floor is unexplained even when no probe names it


def _unexplained_lines(diag: TimeDiagnosis) -> list:
    u = diag.unexplained
    if u is None:
        return []
    unit = UNITS[diag.quantity]["effort"][0]
    L = []
    rem = u.remaining
    ratio = u.rms / u.noise if u.noise > 0 else float("inf")
    if rem:
        L += _wrap(f"unexplained: the residual keeps structure beyond noise (RMS {u.rms:.3g} {unit} against a "
                   f"{u.noise:.3g} {unit} noise floor, lag-1 correlation {u.lag1:.2f}):", indent="", cont="  ")
        for p in rem:
            what, causes, measure = signature_text(diag, p)
            L += _wrap(f"- residual {what}: {100 * p.share:.0f} % of the residual variance. Candidates: {causes}. "
                       f"To separate them: {measure}.", indent="  ", cont="    ")
    elif ratio > NOISE_RATIO:
        L += _wrap(f"unexplained: the residual is {ratio:.1f} times the noise floor (RMS {u.rms:.3g} {unit} "
                   f"against {u.noise:.3g} {unit}, lag-1 correlation {u.lag1:.2f}) but none of the tests over "
                   "position, velocity, time, reversals and acceleration holds it: an effect outside the "
                   "library (a resonance, a time delay, or lost motion"
                   + ("" if diag.lost is not None else ": a motor_position column beside the table's position "
                      "measures it") + ")", indent="", cont="  ")
    else:
        L += _wrap(f"residual: no structure beyond noise (RMS {u.rms:.3g} {unit} against a {u.noise:.3g} {unit} "
                   "noise floor; tested over position incl. its period, velocity, time, reversals and acceleration)",
                   indent="", cont="  ")
    return L


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
        "not_accepted": [{"round": k, "effect": c.effect.name, "dBIC": c.dbic, "gain_percent": c.gain,
                          "reason": c.reason} for k, rnd in enumerate(diag.rounds, start=1) for c in rnd if c.reason],
        "pairs": [{"round": k, "effects": [a.effect.name, b.effect.name], "dBIC": dbic, "gain_percent": gain,
                   "accepted": not why, "reason": why} for k, a, b, _e, dbic, gain, why in diag.pairs],
        "flags": diag.flags,
        "unexplained": _unexplained_dict(diag),
        "lost_motion": None if diag.lost is None else {
            "accepted": diag.lost.accepted, "reason": diag.lost.reason,
            "width_um": _mm(diag, diag.lost.width) * 1e3, "width_std_um": _mm(diag, diag.lost.width_std) * 1e3,
            "gain_percent": diag.lost.gain},
        "final": {**_est_dict(q, diag.final), "relative_error": errs(diag.final)},
        "seconds": diag.times,
    }


def _unexplained_dict(diag: TimeDiagnosis) -> dict | None:
    u = diag.unexplained
    if u is None:
        return None
    out = []
    for p in u.remaining:
        what, causes, measure = signature_text(diag, p)
        det = {k: v for k, v in p.detail.items() if isinstance(v, (int, float, str))}
        if "period" in det:
            det["period_mm"] = _mm(diag, det.pop("period"))
        out.append({"kind": p.kind, "share": p.share, "log10_p": p.log10_p, "signature": what, "causes": causes,
                    "to_separate": measure, **det})
    return {"remaining": bool(out) or (u.noise > 0 and u.rms / u.noise > NOISE_RATIO), "rms": u.rms,
            "noise_floor": u.noise, "lag1": u.lag1, "signatures": out}


def diagnose_time_files(paths, *, plant, gain: str | None = None, candidates=None,
                        max_effects: int = 3) -> TimeDiagnosis:
    """Read the records (the first the estimation run, the others validation runs) and diagnose them against
    ``plant`` (:class:`.plant.Plant`: lead, efficiency and stroke are used)."""
    from .timerecord import check_same_columns, read_time_record

    if candidates:
        unknown = [c for c in candidates if c not in EFFECTS]
        if unknown:
            raise InputError(f"--effects: unknown time-record effect '{unknown[0]}'; known: {', '.join(EFFECTS)}")
    if max_effects < 0:
        raise InputError("--max-effects must not be negative")
    recs = [read_time_record(p, lead=plant.lead, gain=gain, efficiency=plant.efficiency) for p in paths]
    for r in recs[1:]:
        check_same_columns(recs[0], r)
        if r.quantity != recs[0].quantity:
            raise InputError(f"a {r.quantity} record cannot validate the {recs[0].quantity} record {recs[0].name}",
                             source=r.source)
    to_q = 1.0 if recs[0].quantity == "force" else 2.0 * math.pi / plant.lead
    design = {"name": plant.name, "lead": plant.lead, "efficiency": plant.efficiency}
    return diagnose_time(recs, stroke_q=plant.stroke * to_q, candidates=candidates, max_effects=max_effects,
                         design=design, lead_q=plant.lead * to_q)
