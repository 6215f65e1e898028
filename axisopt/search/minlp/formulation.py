"""The one-hot MINLP formulation shared by Bonmin and SCIP, and the recovery of a design from a
solver's point.

One binary per part of each slot chooses the nut (which fixes the screw), the bearing arrangement
and the guide (with the drive: one binary per guide-and-drive entry of the space's last axis), with
``sum z = 1`` per slot.  A part parameter is the binary-weighted sum of its catalog column,
``p = sum_i z_i p_i``, linear in z (the standard form of a discrete choice in an MINLP) and exact at
every integer point, so the symbolic :func:`axisopt.model.axis_response` evaluated on these mixtures
is the model of the chosen parts.

A solver's point is turned back into a catalog combination (the largest binary of each slot) and a
preload within the chosen nut's range; the combination is re-evaluated with the project's own model,
and a preload that misses a limit by the solver's feasibility tolerance is moved into the limits
before it is reported.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Mapping

import casadi as ca
import numpy as np

from ..polish import feasible_at

SLOTS = ("nut", "bearing", "guide")  # the one-hot slots, in the order of the space's axes 1..3


def slot_params(space, mounting: str) -> dict:
    """Param name -> (slot, values) where slot is 'nut' | 'bearing' | 'guide' | 'axis' (one value
    for the axis, else one per part of the slot), from the space's structured (broadcastable)
    parameter arrays."""
    ps = space.params_structured(mounting)
    out = {}
    for name, v in ps.items():
        if name == "duty":
            continue
        a = np.asarray(v, dtype=float)
        if a.ndim == 0 or a.size == 1:
            out[name] = ("axis", float(a.reshape(-1)[0]) if a.ndim else float(a))
        elif a.shape[0] > 1 or (a.ndim == 4 and a.shape[1] == 1 and a.shape[2] == 1):
            out[name] = ("nut", a.reshape(-1))
        elif a.shape[1] > 1 or (a.ndim == 4 and a.shape[2] == 1):
            out[name] = ("bearing", a.reshape(-1))
        else:
            out[name] = ("guide", a.reshape(-1))
    return out


def one_hot_symbols(space) -> dict:
    """Slot -> the CasADi column of its binaries (``z_nut``, ``z_bearing``, ``z_guide``)."""
    _, N, B, G = space.shape
    return {s: ca.SX.sym(f"z_{s}", n) for s, n in zip(SLOTS, (N, B, G))}


def one_hot_params(space, mounting: str, z: dict, floor: float = 0.0) -> dict:
    """The model's parameter dict on the one-hot mixtures ``sum_i z_i p_i`` (axis values as they
    are, the duty cycle of the mounting's axis).

    ``floor``: plus ``floor`` times the column mean, so that no stiffness, diameter or preload is
    exactly 0 at the fractional points z = 0 a nonlinear branch-and-bound visits (NaN derivatives of
    cube roots and 1/k otherwise); at integer points it is a relative change of ``floor``, and the
    chosen design is re-evaluated exactly afterwards."""
    p = {}
    for name, (slot, vals) in slot_params(space, mounting).items():
        if slot == "axis":
            p[name] = vals
        elif floor:
            p[name] = ca.dot(ca.DM(vals), z[slot]) + floor * float(np.mean(vals))
        else:
            p[name] = ca.dot(ca.DM(vals), z[slot])
    p["duty"] = space.problem.axis_for(mounting).phases
    return p


def integral(z: Mapping[str, np.ndarray], atol: float = 1e-6) -> bool:
    """Every slot's largest binary is 1 (within ``atol``): the solver returned an integer point."""
    return all(np.isclose(np.max(z[s]), 1.0, atol=atol) for s in SLOTS)


@dataclass(frozen=True)
class Recovered:
    """A solver's point as a design: ``combination`` (flat index into the space), ``proposed`` (the
    solver's preload within the nut's range) and ``preload`` (the one that meets every limit on the
    exact model, None when no move found one)."""

    combination: int
    proposed: float
    preload: float | None


def recover(
    space,
    mounting_index: int,
    z: Mapping[str, np.ndarray],
    preload: Callable[[float, float], float],
    constraints,
    moves=(),
) -> Recovered:
    """The design at a solver's point.

    ``z``       : slot -> the binaries' values (the part with the largest value is chosen)
    ``preload`` : ``preload(lo, hi)`` -> the solver's preload within the chosen nut's range [lo, hi]
    ``moves``   : relative preload moves tried in turn when the proposed preload misses a limit on
                  the exact model (the solver's feasibility tolerance); a move m tries
                  ``P + m max(hi - lo, 1 N)`` clipped to the range"""
    n, b, g = (int(np.argmax(z[s])) for s in SLOTS)
    combo = int(np.ravel_multi_index((mounting_index, n, b, g), space.shape))
    lo, hi = float(space.preload_lo[n]), float(space.preload_hi[n])
    pre = preload(lo, hi)
    if feasible_at(space, combo, pre, constraints):
        return Recovered(combo, pre, pre)
    for move in moves:
        p2 = float(np.clip(pre + move * max(hi - lo, 1.0), lo, hi))
        if feasible_at(space, combo, p2, constraints):
            return Recovered(combo, pre, p2)
    return Recovered(combo, pre, None)


__all__ = [
    "SLOTS",
    "slot_params",
    "one_hot_symbols",
    "one_hot_params",
    "integral",
    "Recovered",
    "recover",
]
