"""A design change that makes an infeasible problem feasible, proposed before any limit is relaxed: the axis's
rapid speed or acceleration lowered as far as the closest designs' misses say (the duty cycle's moves capped at
it), each proposal re-solved to check that the catalogs then hold a design (:func:`design_changes`).

A margin of a speed check (critical speed, DN, the motor's, coupling's, reduction's or rotating-nut unit's
speed: available / needed >= L) needs the speed it is short of in proportion: a design that reaches L (1 - m)
meets L at the rapid speed times (1 - m).  A torque check of the motor or reduction is short of torque, which
the acceleration sets with the mass: the acceleration is lowered by the same factor (more than is needed, since
the friction and process force do not scale with it).  Each proposal is verified by the default method's search
on the changed problem, stopped at its first feasible design (no optimum, no explanation), so it is offered only
when the catalogs then hold a design; its value is rounded down to three significant figures.  The first kind
that a search verifies is the advice (one search per kind, the speed first: an answer within the 2 s of an
infeasible one).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from .result import DesignChange

# the checks whose needed value grows with the rapid speed, and with the acceleration (margin_<check>)
SPEED_CHECKS = frozenset({"critical_speed", "dn", "motor_speed", "coupling_speed", "reduction_speed",
                          "unit_speed"})
TORQUE_CHECKS = frozenset({"motor_peak_torque", "motor_rated_torque", "reduction_accel_torque",
                           "reduction_rated_torque"})
SAFETY = 0.98  # the proposal a little below the closest designs' bare need (their misses are at one preload)


def _round_down(x: float) -> float:
    """x rounded down to three significant figures."""
    if x <= 0:
        return x
    e = math.floor(math.log10(x)) - 2
    return math.floor(x / 10**e) * 10**e


def _factors(constraints, infeasibility, checks) -> list[float]:
    """Per closest design that misses a limit of ``checks``: 1 - its largest miss among those (the change may
    also free its other misses, or another design: the search verifies it).  The advice takes the least of
    them: the largest change any closest design needs."""
    by_label = {c.label: c for c in constraints}
    out = []
    for cand in infeasibility.closest:
        misses = [m for label, m in cand.misses.items()
                  if (c := by_label.get(label)) is not None and c.name.startswith("margin_")
                  and c.name[len("margin_"):] in checks]
        if misses:
            out.append(1.0 - max(misses))
    return [f for f in out if 0.0 < f < 1.0]


def _with(axis, key: str, to: float):
    """``axis`` with ``key`` (max_speed or acceleration) lowered to ``to``, and the duty cycle's moves capped at it
    (a move's speed or acceleration left out in the YAML is the axis's, filled in when read)."""
    field = "speed" if key == "max_speed" else "acceleration"
    cycle = tuple(replace(sg, **{field: min(getattr(sg, field), to)}) if sg.kind == "move" else sg
                  for sg in (axis.duty_cycle or ()))
    return replace(axis, **{key: to}, **({"duty_cycle": cycle} if axis.duty_cycle else {}))


def design_changes(problem, constraints, infeasibility) -> list:
    """The axis changes (:class:`.result.DesignChange`) that make ``problem`` feasible, each verified by a search;
    empty when none of the kinds applies or none is verified."""
    from .bestfirst import bound_order_search
    from .parts import build_space
    from .task.constraints import build_constraints
    from .task.objective import objective_spec

    axis = problem.axis
    out = []
    for key, checks, unit, scale in (("max_speed", SPEED_CHECKS, "m/min", 60.0),
                                     ("acceleration", TORQUE_CHECKS, "m/s^2", 1.0)):
        value = getattr(axis, key, None)
        factors = _factors(constraints, infeasibility, checks)
        if not value or not factors:
            continue
        # the largest change the closest designs suggest (the likeliest to free one of them), one search each
        to = _round_down(value * scale * min(factors) * SAFETY) / scale
        if to <= 0:
            continue
        changed = replace(problem, axis=_with(axis, key, to))
        try:
            space = build_space(changed)
        except Exception:  # noqa: BLE001 - a change the inputs refuse (a duty cycle it breaks) is no advice
            continue
        spec = objective_spec(changed.objective.mode, changed)
        ex, _ = bound_order_search(space, build_constraints(changed), spec, top=1, first_feasible=True)
        if np.isfinite(ex.objective).any():
            out.append(DesignChange(f"axis.{key}", unit, value * scale, to * scale))
            break  # one verified change is the advice; the limits to relax follow it
    return out
