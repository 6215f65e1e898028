"""What the problem's screw mountings and ``catalog:`` filters left out that would make an infeasible problem
feasible (:func:`widened`, one kind of :func:`.advice.design_changes`).

The groups widened, each on its own and in this order, then all of those that apply together:

- **the mountings** (``catalog.mountings``, or ``axis.mounting`` alone): every mounting admitted, when the closest
  designs miss a check or limit other than the drive's.  A screw fixed at both ends runs to
  (lambda_ff / lambda_fs)^2 = (4.730 / 3.927)^2 = 1.45 times the critical speed and carries eta_ff / eta_fs =
  4 / 2 = 2 times the buckling load of a fixed-supported one on the same span (THK A15-32 eq. 7, A15-30 eq. 5:
  :data:`axisopt.physics.checks.CRITICAL_SPEED_LAMBDA1`, :data:`~axisopt.physics.checks.BUCKLING_ETA1`);
- **the drive's parts**, when the closest designs miss a drive check (motor, coupling or reduction: torque,
  speed, inertia ratio, brake) or a limit: ``motor_vendors``, ``motor_series``, ``coupling_series`` and the
  drive slots of ``require``/``exclude`` left out, ``max_motor_flange`` raised to the largest flange listed,
  ``reductions: no`` turned to yes;
- **the mechanical parts**: ``vendors``, ``nut_types``, ``bearing_arrangements``, ``bearing_preload``,
  ``guide_types``, ``guide_preload``, ``screw_grades`` and the mechanical slots of ``require``/``exclude`` left
  out.

Not widened: ``status`` and ``estimated`` (which rows the user trusts: derived and paper rows, estimated cells),
``drive: no``, and a required reduction (a lost-motion limit that leaves reductions out is
:func:`.advice.design_changes`' own kind).

Each widened problem gets one search, the default method's stopped at its first feasible design (ordered by
the problem's objective; no optimum).  The advice is what that design needs of the widened filters: the mounting,
vendor, series, type, grade or part id to add (``catalog.motor_series: add Sigma-7 SGM7G``), the id to take out
of ``exclude``, the flange limit to raise.  The design is one of the problem changed by exactly these edits, so
the edits alone make it feasible (the verification is the search itself).  The first design found is not the
least change: a filter may be widened further than the least part that would fit (a larger motor, another
vendor's screw), which the user may narrow again.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..design import MOUNTINGS
from ..grades import grade_table
from ..model.limits import CHECK_RECORDS, LIMITS
from ..physics.checks import BUCKLING_ETA1, CRITICAL_SPEED_LAMBDA1
from .result import DesignChange

# the checks of the drive's parts (model.limits: Check.drive)
DRIVE_CHECKS = frozenset(name for name, c in CHECK_RECORDS.items() if c.drive)
DRIVE_SLOTS = ("motor", "coupling")  # require/exclude slots the drive group widens
MECH_SLOTS = ("screw", "nut", "bearing", "guide")
# the filters each group widens to 'every value' (None)
DRIVE_FILTERS = ("motor_vendors", "motor_series", "coupling_series")
MECH_FILTERS = ("vendors", "nut_types", "bearing_arrangements", "bearing_preload", "guide_types", "guide_preload")
GROUPS = ("mounting", "drive", "mechanical")


def _slots_left(pairs: tuple, slots) -> tuple:
    """require/exclude pairs ``((slot, ids), ...)`` without ``slots``."""
    return tuple((s, ids) for s, ids in pairs if s not in slots)


def _widen(problem, group: str):
    """The problem's restrictions with ``group``'s filters widened (the same object when it has none set)."""
    r = problem.restrictions
    if group == "mounting":
        return replace(r, mountings=MOUNTINGS) if set(problem.mountings) != set(MOUNTINGS) else r
    if group == "drive":
        if not r.drive:
            return r
        flange = r.max_motor_flange
        if flange is not None:
            listed = problem.catalog.rows("motors").number("flange")
            top = float(np.nanmax(listed)) if np.isfinite(listed).any() else flange
            flange = max(flange, top)
        return replace(r, **dict.fromkeys(DRIVE_FILTERS), max_motor_flange=flange, reductions=True,
                       require=_slots_left(r.require, DRIVE_SLOTS), exclude=_slots_left(r.exclude, DRIVE_SLOTS))
    grades = r.screw_grades if r.screw_grades is None else tuple(grade_table().names)
    return replace(r, **dict.fromkeys(MECH_FILTERS), screw_grades=grades,
                   require=_slots_left(r.require, MECH_SLOTS), exclude=_slots_left(r.exclude, MECH_SLOTS))


def _groups(misses) -> list:
    """The groups the closest designs' misses call for, the one whose checks they miss most first (ties in
    :data:`GROUPS` order); ``misses``: per closest design, {check or limit name: relative miss}.  The mounting
    and the mechanical parts answer the mechanical checks and the limits, the drive's parts its checks and the
    limits."""
    worst = {g: 0.0 for g in GROUPS}
    for d in misses:
        for name, m in d.items():
            drive, limit = name in DRIVE_CHECKS, name in LIMITS
            for g, on in zip(GROUPS, (not drive, drive or limit, not drive)):
                if on:
                    worst[g] = max(worst[g], float(m))
    return sorted((g for g in GROUPS if worst[g] > 0), key=lambda g: -worst[g])


def _listed(key: str, new: list, note: str = "") -> list:
    """An 'add' edit of the list ``key`` (none when ``new`` is empty), values in order of first appearance."""
    vals = tuple(dict.fromkeys(str(v) for v in new))
    return [DesignChange(key, "", math.nan, math.nan, note, "add", vals)] if vals else []


def _mounting_note(old: tuple, new: str) -> str:
    """What the mounting changes against the strongest one the problem had: critical speed and buckling load."""
    best = max(old, key=CRITICAL_SPEED_LAMBDA1.__getitem__)
    speed = (CRITICAL_SPEED_LAMBDA1[new] / CRITICAL_SPEED_LAMBDA1[best]) ** 2
    buckling = BUCKLING_ETA1[new] / BUCKLING_ETA1[best]
    if speed <= 1.0:
        return ""
    return (f"{speed:.3g} x the critical speed and {buckling:.3g} x the buckling load of {best} on the same span, "
            "THK A15-32 and A15-30")


def design_edits(problem, space, combo: int) -> list:
    """The edits of ``problem``'s mountings and catalog filters that admit combination ``combo`` of ``space`` (a
    space of the problem with filters widened): :class:`.result.DesignChange` rows, empty when it needs none."""
    from .candidates import part_rows

    r = problem.restrictions
    mi, n, b, g = (int(v) for v in space.unravel(combo))
    screw, nut, bearing, guide, motor, coupling, reduction = part_rows(space, n, b, g)
    rows = {"screw": screw, "nut": nut, "bearing": bearing, "guide": guide, "motor": motor, "coupling": coupling}
    mounting = space.mountings[mi]
    out = [] if mounting in problem.mountings else _listed("catalog.mountings", [mounting],
                                                           _mounting_note(problem.mountings, mounting))

    def outside(allowed, values):
        return [] if allowed is None else [v for v in values if v not in allowed]

    mech = (screw, nut, bearing, guide)
    out += _listed("catalog.vendors", outside(r.vendors, [row["vendor"] for row in mech]))
    out += _listed("catalog.nut_types", outside(r.nut_types, [nut["type"]]))
    out += _listed("catalog.bearing_arrangements", outside(r.bearing_arrangements, [bearing["arrangement"]]))
    out += _listed("catalog.bearing_preload", outside(r.bearing_preload, [bearing["preload_class"]]))
    out += _listed("catalog.guide_types", outside(r.guide_types, [guide["type"]]))
    if r.guide_preload is not None and not {guide["preload_level"], guide["preload_class"]} & set(r.guide_preload):
        out += _listed("catalog.guide_preload", [guide["preload_level"]])
    if space.grades is not None:
        out += _listed("catalog.screw_grades", outside(r.screw_grades, [space.grades[n]]))
    if motor is not None:
        out += _listed("catalog.motor_vendors", outside(r.motor_vendors, [motor["vendor"]]))
        out += _listed("catalog.motor_series", outside(r.motor_series, [motor["series"]]))
        if r.max_motor_flange is not None and float(motor["flange"]) > r.max_motor_flange * (1 + 1e-9):
            out.append(DesignChange("catalog.max_motor_flange", "mm", r.max_motor_flange * 1e3,
                                    float(motor["flange"]) * 1e3, f"motor {motor['id']}"))
    if coupling is not None:
        out += _listed("catalog.coupling_series", outside(r.coupling_series, [coupling["series"]]))
    if reduction is not None and not r.reductions:
        out.append(DesignChange("catalog.reductions", "", math.nan, math.nan, f"reduction {reduction['id']}",
                                "set", ("yes",)))
    for slot, row in rows.items():
        if row is None:
            continue
        pid = str(row["id"])
        req = r.required(slot)
        if req and pid not in req:
            out += _listed(f"catalog.require.{slot}", [pid])
        if pid in r.excluded(slot):
            out.append(DesignChange(f"catalog.exclude.{slot}", "", math.nan, math.nan, "", "remove", (pid,)))
    return out


def first_design(problem):
    """(space, combination) of the first feasible design the default search finds for ``problem`` (stopped
    there), or None: none, or the problem's inputs refuse the widened filters."""
    from .bestfirst import bound_order_search
    from .parts import build_space
    from .task.constraints import build_constraints
    from .task.objective import objective_spec

    try:
        space = build_space(problem)
    except Exception:  # noqa: BLE001 - filters the inputs refuse (nothing left to choose from) give no advice
        return None
    spec = objective_spec(problem.objective.mode, problem)
    ex, _ = bound_order_search(space, build_constraints(problem), spec, top=1, first_feasible=True)
    ok = np.nonzero(np.isfinite(ex.objective))[0]
    return (space, int(ex.idx[ok[0]])) if len(ok) else None


def widened(problem, misses, budget: int) -> tuple:
    """(edits, searches): the mounting and catalog-filter edits that make ``problem`` feasible (the module
    docstring), [] when none is found within ``budget`` searches; ``misses``: per closest design,
    {check or limit name: relative miss} (a check's name without ``margin_``)."""
    tries = []
    for group in _groups(misses):
        r = _widen(problem, group)
        if r != problem.restrictions:
            tries.append((group, r))
    if len(tries) > 1:  # every group at once: a design may need parts of two groups
        r = problem.restrictions
        for group, _ in tries:
            r = _widen(replace(problem, restrictions=r), group)
        tries.append(("all", r))
    used = 0
    for _, r in tries[:max(budget, 0)]:
        used += 1
        found = first_design(replace(problem, restrictions=r))
        if found is not None:
            edits = design_edits(problem, *found)
            if edits:
                return edits, used
    return [], used


__all__ = ["widened", "design_edits", "first_design", "DRIVE_CHECKS"]
