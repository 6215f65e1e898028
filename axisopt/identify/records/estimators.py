"""Estimators of the time-record regression (:mod:`.timemodel`): least squares (seed eq. 29) and
instrumental variables (seed eq. 30, IDIM-IV: A. Janot, P.-O. Vandanjon, M. Gautier, "A generic
instrumental variable approach for industrial robot identification", IEEE Trans. Control Syst.
Technol. 22 (2014) 132-145).

* LS: :math:`\\hat\\theta = (W^T W)^{-1} W^T y`,
  :math:`\\sigma^2 = \\|y - W\\hat\\theta\\|^2/(n - p)`,
  :math:`\\operatorname{cov} = \\sigma^2 (W^T W)^{-1}`.
* IV: instruments V are the same columns computed from the closed loop simulated with the current
  estimate -- the PD position controller (+ velocity and acceleration feed-forward) is fitted to the
  record from its ``reference`` column and driven by that reference; no measurement noise enters V.
  Iterated :math:`\\hat\\theta_{k+1} = (V_k^T W)^{-1} V_k^T y` until the estimate moves by less than
  1e-4 of a standard deviation (at most 30 iterations), :math:`\\operatorname{cov} = \\sigma^2 (V^T
  W)^{-1} V^T V (V^T W)^{-T}`.  A record without ``reference`` cannot be re-simulated in
  closed loop: V is then the regressor delayed by two decimated rows (a delayed-regressor
  instrument, not iterated).  A column the rigid simulation cannot produce (a term declared
  ``simulated=False``, the extra mode's) is its own instrument.
* A shape parameter (the Stribeck velocity) is found by a 1-D search on the LS residual, then held
  fixed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..effects import time_effects
from ..effects.disturbance import golden
from .controller import Controller, fit_controller  # noqa: F401 (the loop, fitted)
from .record import TimeRecord
from .regression import Processing, Rows, decimate, full_matrix, matrix, signals, term
from .signal import derivatives

IV_TOL = 1e-4
IV_MAXIT = 30


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


def lstsq(W, y):
    sc = np.linalg.norm(W, axis=0)
    sc[sc == 0] = 1.0
    th, *_ = np.linalg.lstsq(W / sc, y, rcond=None)
    return th / sc


def least_squares(rows: Rows, terms, shape=None) -> Estimate:
    """LS on the decimated rows (seed eq. 29) with the standard deviations from the residual
    variance."""
    shape = dict(shape or {})
    W = matrix(rows, terms, shape)
    th = lstsq(W, rows.y)
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
    return math.exp(golden(rss, a, b, 18))


# ---------------------------------------------------------------------------------- closed-loop
# model
def simulate_loop(
    rec: TimeRecord,
    ctrl: Controller,
    params: dict,
    shape: dict,
    proc: Processing,
    substeps: int = 2,
) -> np.ndarray | None:
    """Closed loop of the identified rigid model driven by the record's reference; the position [q
    units] at every sample, or None if the simulation diverges.  Exact sticking (implicit Coulomb
    step)."""
    r, dr, ddr = derivatives(rec.reference, proc.fs, proc.fc, 2, rec.segments)
    # a long record's windows: the loop restarts at rest in each
    starts = {a for a, _ in rec.segments}
    seg, integ, casc = -1, 0.0, ctrl.structure == "p_pi_cascade"
    ki, u0 = ctrl.ki, ctrl.u0
    m = params.get("M", 0.0) + (float(rec.aux["payload"][0]) if "payload" in rec.aux else 0.0)
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
    # load and temperature friction (:mod:`.effects.load`) as Coulomb and viscous levels per sample
    n = rec.n
    lev = np.zeros(n)
    visc = np.zeros(n)
    if params.get("mu_g") and "normal" in rec.aux:
        lev += params["mu_g"] * rec.aux["normal"]
    if "temperature" in rec.aux:
        dt_ref = rec.aux["temperature"] - 293.15
        lev += params.get("dFc_dT", 0.0) * dt_ref
        if params.get("Fvt"):
            visc += params["Fvt"] * (np.exp(-shape["beta"] * dt_ref) - 1.0)
    kload = params.get("ka", 0.0)
    levl, viscl = lev.tolist(), visc.tolist()
    sin, cos = math.sin, math.cos
    fvp, fvn = fv + dfv / 2, fv - dfv / 2
    kp, kd, kv, ka = ctrl.kp, ctrl.kd, ctrl.kv, ctrl.ka
    h = 1.0 / (proc.fs * substeps)
    dtk = 1.0 / proc.fs
    hm = h / m
    sq = 2.0 / proc.stroke_q
    q, v = float(rec.q[0]), 0.0
    out = np.empty(rec.n)
    rl, drl, ddrl = r.tolist(), dr.tolist(), ddr.tolist()
    exp = math.exp
    bound = 1e3 * (float(np.ptp(rec.q)) + 1.0)
    ql = rec.q.tolist()
    for k in range(rec.n):
        if k in starts:
            q, v = ql[k], 0.0
            seg, integ = seg + 1, 0.0
        out[k] = q
        u = kp * (rl[k] - q) + kd * (drl[k] - v) + kv * drl[k] + ka * ddrl[k] - off
        if casc:  # the P-PI cascade's integral of the position error (.controller)
            integ += (rl[k] - q) * dtk
            u += ki * integ + (u0[max(seg, 0)] if u0 else 0.0)
        load = levl[k] + kload * abs(u)
        if ext is not None:
            u += ext[k]
        for _ in range(substeps):
            xi = sq * q - 1.0
            dpos = c1 * xi + c2 * (1.5 * xi * xi - 0.5) + load
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
                    fr = fc + (fvp + viscl[k]) * v + fsx * exp(-v / vs) + dpos + cq * v * v
                else:
                    fr = -fc + (fvn + viscl[k]) * v - fsx * exp(v / vs) - dpos - cq * v * v
                vn = v + hm * (uk - fr)
                v = 0.0 if vn * v < 0 else vn
            q += h * v
        if not abs(q) < bound:
            return None
    return out


def instrumental_variables(
    rows: Rows, terms, shape=None, ctrl: Controller | None = None, start: Estimate | None = None
) -> Estimate:
    """IDIM-IV (seed eq. 30); see the module docstring for the instruments."""
    shape = dict(shape or {})
    terms = tuple(terms)
    W = matrix(rows, terms, shape)
    y = rows.y
    ls = start or least_squares(rows, terms, shape)
    th = ls.theta.copy()
    n, p = W.shape
    own = [terms.index(t) for t in terms if not term(t).simulated]

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
        V = decimate(Vf, rows.proc, rows.keep, rows.record.segments)
        th = solve(V)
        note = (
            "delayed-regressor instrument (no reference column: the closed loop cannot be "
            "re-simulated)"
        )
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
            sim = signals(qs, rows.proc, rows.record.segments)
            V = matrix(rows, terms, shape, sig={**rows.sig, **sim})  # conditions as measured
            for j in own:
                V[:, j] = W[:, j]
            new = solve(V)
            step = np.max(np.abs(new - th) / np.maximum(ls.std, 1e-12 * np.abs(th) + 1e-300))
            th = new
            if step < IV_TOL:
                converged = True
                break
        if converged:
            note = (
                f"instruments from the closed loop simulated from the reference ({it} iterations)"
            )
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
    """The effort ``est`` predicts at the rows.  An effect whose phase is each run's own
    (``per_run``: a sin, cos pair) keeps its fitted amplitude and takes the phase that fits the run
    best given the other terms (on the run it was fitted on that is its fitted phase: the LS normal
    equations make them equal)."""
    W = matrix(rows, est.terms, est.shape)
    y = W @ est.theta
    for eff in time_effects().values():
        if not eff.per_run or not all(t in est.terms for t in eff.terms):
            continue
        idx = [est.terms.index(t) for t in eff.terms]
        part = W[:, idx] @ est.theta[idx]
        ab = lstsq(W[:, idx], rows.y - (y - part))
        amp, n = float(np.linalg.norm(est.theta[idx])), float(np.linalg.norm(ab))
        if n > 0.0:
            y = y - part + W[:, idx] @ (ab * amp / n)
    return y


def rel_error(rows: Rows, est: Estimate) -> float:
    """||y - y_hat|| / ||y|| on the kept rows [-]."""
    r = rows.y - predict(rows, est)
    ny = float(np.linalg.norm(rows.y))
    return float(np.linalg.norm(r) / ny) if ny > 0.0 else float("nan")


def rmse(rows: Rows, est: Estimate) -> float:
    r = rows.y - predict(rows, est)
    return float(np.sqrt(np.mean(r**2)))


def mode_frequency(est: Estimate) -> float | None:
    """The extra mode's resonance :math:`f_r = \\sqrt{M/\\beta}/2\\pi` [Hz] (None without a physical
    mode)."""
    if "beta" not in est.terms:
        return None
    m, b = est.value("M"), est.value("beta")
    return math.sqrt(m / b) / (2 * math.pi) if b > 0 and m > 0 else None
