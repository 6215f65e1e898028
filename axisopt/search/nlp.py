"""The continuous problem of one combination, solved by IPOPT on the symbolic axis model.

Variables: the nut preload, scaled to w in [0, 1] over the allowed range, and one epigraph variable
per objective term (the minimum over the position grid).  Objective and constraints are scaled
(N/um, Hz, limit ratios, logarithms of life and margin ratios) before IPOPT sees them.  Only the
preload-dependent limits enter; the others do not change with the preload and are checked exactly
before any NLP is built.  One solver per (mounting, grid, objective, limit set) and process.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from .. import model
from .space import N_PER_UM, STIFFNESS_OUTPUTS, Constraint, ObjectiveSpec

_IPOPT = {"ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes", "ipopt.tol": 1e-10,
          "ipopt.max_iter": 300, "ipopt.bound_push": 1e-9, "ipopt.bound_frac": 1e-9,
          "ipopt.mu_init": 1e-4}
_SOLVERS: dict = {}


@dataclass
class NLPResult:
    success: bool
    status: str
    preload: float
    objective: float  # display units


def _scaled(key, v):
    return v / N_PER_UM if key in STIFFNESS_OUTPUTS else v


def _solver(mounting: str, x: np.ndarray, cons: tuple, objective: ObjectiveSpec, duty: tuple = ()):
    key = (mounting, tuple(np.round(x, 12)), tuple((c.key, c.sense) for c in cons), objective.terms, duty)
    if key in _SOLVERS:
        return _SOLVERS[key]
    F = model.model_for(mounting, len(x), duty).function
    P = ca.SX.sym("params", len(model.PARAM_NAMES))
    lim = ca.SX.sym("limits", len(cons))
    plo, phi = ca.SX.sym("plo"), ca.SX.sym("phi")
    w = ca.SX.sym("w")
    t = ca.SX.sym("t", len(objective.terms))
    out = F.call({"params": P, "preload": plo + w * (phi - plo), "x": ca.DM(x)})
    g, lbg, ubg = [], [], []
    for i, (okey, _wt) in enumerate(objective.terms):
        g.append(_scaled(okey, out[okey]) - t[i])
        lbg += [0.0] * len(x)
        ubg += [ca.inf] * len(x)
    for j, c in enumerate(cons):
        v = out[c.key]
        if c.key in ("life",) or c.key.startswith("margin_"):
            expr = ca.log(ca.fmax(v, 1e-300) / lim[j])  # >= 0 (or <= 0)
        else:
            expr = v / lim[j] - 1.0
        n = v.shape[0]
        g.append(expr)
        if c.sense == ">=":
            lbg += [0.0] * n
            ubg += [ca.inf] * n
        else:
            lbg += [-ca.inf] * n
            ubg += [0.0] * n
    f = -sum(wt * t[i] for i, (_k, wt) in enumerate(objective.terms))
    nlp = {"x": ca.vertcat(w, t), "p": ca.vertcat(P, plo, phi, lim), "f": f, "g": ca.vertcat(*g)}
    solver = ca.nlpsol(f"preload_{mounting.replace('-', '_')}", "ipopt", nlp, _IPOPT)
    _SOLVERS[key] = (solver, np.array(lbg, float), np.array(ubg, float))
    return _SOLVERS[key]


def solve_preload(mounting: str, x, params: dict, plo: float, phi: float, constraints, objective: ObjectiveSpec,
                  guess: float | None = None) -> NLPResult:
    """IPOPT on one combination; ``constraints`` may include preload-independent ones (ignored)."""
    cons = tuple(c for c in constraints if c.direction != 0)
    duty = params.get("duty", ())
    solver, lbg, ubg = _solver(mounting, np.asarray(x, float), cons, objective, duty)
    pv = np.array([float(params[n]) for n in model.PARAM_NAMES])
    span = phi - plo
    w0 = 1.0 if guess is None or span <= 0 else float(np.clip((guess - plo) / span, 0.0, 1.0))
    f = model.model_for(mounting, len(x), duty)(
        dict(zip(model.PARAM_NAMES, pv)), plo + w0 * max(span, 0.0), x)
    t0 = [float(np.min(_scaled(k, f[k]))) * (1 - 1e-6) for k, _ in objective.terms]
    arg = {"x0": np.array([w0] + t0), "lbx": np.array([0.0] + [-np.inf] * len(t0)),
           "ubx": np.array([1.0 if span > 0 else 0.0] + [np.inf] * len(t0)),
           "p": np.concatenate([pv, [plo, phi], [c.limit for c in cons]]), "lbg": lbg, "ubg": ubg}
    sol = solver(**arg)
    st = solver.stats()
    xs = np.asarray(sol["x"]).ravel()
    pre = plo + float(np.clip(xs[0], 0.0, 1.0)) * max(span, 0.0)
    return NLPResult(bool(st["success"]), str(st["return_status"]), pre, -float(sol["f"]))


__all__ = ["solve_preload", "NLPResult", "Constraint"]
