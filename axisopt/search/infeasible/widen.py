"""What the problem's screw mountings and ``catalog:`` filters left out that would make an
infeasible problem feasible (:func:`widened`, one kind of :func:`.advice.design_changes`): another
mounting, the next part size or series, before any axis value is lowered.

The groups of filters, each offered where the closest designs' misses call for it:

- **the mountings** (``catalog.mountings``, or ``axis.mounting`` alone): the stronger mountings
  admitted, when the closest designs miss a check or limit other than the drive's (fixed-free is
  never proposed: it only saves the support bearing's cost, which a raised budget says better).  A
  screw fixed at both ends runs to (lambda_ff / lambda_fs)^2 = (4.730 / 3.927)^2 = 1.45 times the
  critical speed and carries eta_ff / eta_fs = 4 / 2 = 2 times the buckling load of a
  fixed-supported one on the same span (THK A15-32 eq. 7, A15-30 eq. 5:
  :data:`axisopt.physics.checks.CRITICAL_SPEED_LAMBDA1`,
  :data:`~axisopt.physics.checks.BUCKLING_ETA1`);
- **the drive's parts**, when the closest designs miss a drive check (motor, coupling or reduction:
  torque, speed, inertia ratio, brake) or a limit: ``motor_vendors``, ``motor_series``,
  ``coupling_series`` and the motor and coupling slots of ``require``/``exclude`` left out;
- **the mechanical parts**, as the mountings: ``vendors``, ``nut_types``, ``bearing_arrangements``,
  ``bearing_preload``, ``guide_types``, ``guide_preload``, ``screw_grades`` and the mechanical slots
  of ``require``/``exclude`` left out.

Not widened: ``status`` and ``estimated`` (which rows the user trusts: derived and paper rows,
estimated cells),
``drive: no``, ``max_motor_flange`` (the room the machine has; no shipped motor lists its flange),
and the reductions (``reductions: no``, a required reduction; a lost-motion limit that leaves
reductions out is :func:`.advice.design_changes`' own kind).

Two searches at most find a design: the group whose checks the closest designs miss most, widened
alone, then every group the misses call for at once (which holds any design of each group alone).  A
search is the default method's stopped at its first feasible design (in the order of the problem's
objective; no optimum).  The advice is what that design needs of the widened filters: the mounting,
vendor, series, type, grade or part id to add (``add Sigma-7 SGM7G to catalog.motor_series``), the
id to take out of ``exclude``.  The design is one of the problem changed by exactly these edits, so
the edits alone make it feasible: the search is the verification.  The first design found need not
be the least change; while the budget lasts, each value it adds is left out in turn and a search
looks for a design without it (its edits, fewer, are then taken).  A value may still be further than
the least part that fits (a larger motor than needed), which the user may narrow again.
"""

from __future__ import annotations

import math
import time
from contextvars import ContextVar
from dataclasses import replace

import numpy as np

from ... import model
from ...catalog.columns import MECH_SLOTS
from ...catalog.grades import grade_table
from ...design import MOUNTINGS
from ...errors import InputError
from ...model.limits import LIMITS
from ...physics.checks import BUCKLING_ETA1, CRITICAL_SPEED_LAMBDA1
from .answer import DesignChange

# the checks of the drive's parts (model.limits: Check.drive)
DRIVE_CHECKS = frozenset(model.DRIVE_CHECKS)
DRIVE_SLOTS = ("motor", "coupling")  # require/exclude slots the drive group widens
# the filters each group widens to 'every value' (None)
DRIVE_FILTERS = ("motor_vendors", "motor_series", "coupling_series")
MECH_FILTERS = (
    "vendors",
    "nut_types",
    "bearing_arrangements",
    "bearing_preload",
    "guide_types",
    "guide_preload",
)
GROUPS = ("mounting", "drive", "mechanical")
# the command's deadline (time.perf_counter()) for the advice's verifying searches, None: none; set
# by advice.design_changes for the searches it runs (a search cut by it finds nothing; ``CUT``
# records that one was)
DEADLINE: ContextVar = ContextVar("advice_deadline", default=None)
CUT: ContextVar = ContextVar("advice_cut", default=None)


def _slots_left(pairs: tuple, slots) -> tuple:
    """require/exclude pairs ``((slot, ids), ...)`` without ``slots``."""
    return tuple((s, ids) for s, ids in pairs if s not in slots)


def _widen(problem, group: str):
    """The problem's restrictions with ``group``'s filters widened (the same object when it has none
    set)."""
    r = problem.restrictions
    if group == "mounting":
        stronger = _stronger(problem.mountings)
        return replace(r, mountings=tuple(problem.mountings) + stronger) if stronger else r
    if group == "drive":
        if not r.drive:
            return r
        return replace(
            r,
            **dict.fromkeys(DRIVE_FILTERS),
            require=_slots_left(r.require, DRIVE_SLOTS),
            exclude=_slots_left(r.exclude, DRIVE_SLOTS),
        )
    grades = r.screw_grades if r.screw_grades is None else tuple(grade_table().names)
    return replace(
        r,
        **dict.fromkeys(MECH_FILTERS),
        screw_grades=grades,
        require=_slots_left(r.require, MECH_SLOTS),
        exclude=_slots_left(r.exclude, MECH_SLOTS),
    )


def _stronger(mountings) -> tuple:
    """The mountings whose screw runs faster before it whirls than the strongest of ``mountings``
    (its critical- speed factor lambda larger; the buckling factor eta ranks them alike)."""
    best = max(CRITICAL_SPEED_LAMBDA1[m] for m in mountings)
    return tuple(m for m in MOUNTINGS if CRITICAL_SPEED_LAMBDA1[m] > best)


def _groups(misses) -> list:
    """The groups the closest designs' misses call for, the one whose checks they miss most first
    (ties in :data:`GROUPS` order); ``misses``: per closest design, {check or limit name: relative
    miss}.  The mounting and the mechanical parts answer the mechanical checks and the limits, the
    drive's parts its checks and the limits."""
    worst = {g: 0.0 for g in GROUPS}
    for d in misses:
        for name, m in d.items():
            drive, limit = name in DRIVE_CHECKS, name in LIMITS
            for g, on in zip(GROUPS, (not drive, drive or limit, not drive)):
                if on:
                    worst[g] = max(worst[g], float(m))
    return sorted((g for g in GROUPS if worst[g] > 0), key=lambda g: -worst[g])


def _listed(key: str, new: list, note: str = "") -> list:
    """An 'add' edit of the list ``key`` (none when ``new`` is empty), values in order of first
    appearance."""
    vals = tuple(dict.fromkeys(str(v) for v in new))
    return [DesignChange(key, "", math.nan, math.nan, note, "add", vals)] if vals else []


def _mounting_note(old: tuple, new: str) -> str:
    """What the mounting changes against the strongest one the problem had: critical speed and
    buckling load."""
    best = max(old, key=CRITICAL_SPEED_LAMBDA1.__getitem__)
    speed = (CRITICAL_SPEED_LAMBDA1[new] / CRITICAL_SPEED_LAMBDA1[best]) ** 2
    buckling = BUCKLING_ETA1[new] / BUCKLING_ETA1[best]
    if speed <= 1.0:
        return ""
    return (
        f"{speed:.3g} x the critical speed and {buckling:.3g} x the buckling load of {best} on the "
        "same span, THK A15-32 and A15-30"
    )


def design_edits(problem, space, combo: int) -> list:
    """The edits of ``problem``'s mountings and catalog filters that admit combination ``combo`` of
    ``space`` (a space of the problem with filters widened): :class:`.answer.DesignChange` rows,
    empty when it needs none."""
    from ..candidates import part_rows

    r = problem.restrictions
    mi, n, b, g = (int(v) for v in space.unravel(combo))
    screw, nut, bearing, guide, motor, coupling, reduction = part_rows(space, n, b, g)
    rows = {
        "screw": screw,
        "nut": nut,
        "bearing": bearing,
        "guide": guide,
        "motor": motor,
        "coupling": coupling,
    }
    mounting = space.mountings[mi]
    out = (
        []
        if mounting in problem.mountings
        else _listed("catalog.mountings", [mounting], _mounting_note(problem.mountings, mounting))
    )

    def outside(allowed, values):
        return [] if allowed is None else [v for v in values if v not in allowed]

    mech = (screw, nut, bearing, guide)
    out += _listed("catalog.vendors", outside(r.vendors, [row["vendor"] for row in mech]))
    out += _listed("catalog.nut_types", outside(r.nut_types, [nut["type"]]))
    out += _listed(
        "catalog.bearing_arrangements", outside(r.bearing_arrangements, [bearing["arrangement"]])
    )
    out += _listed(
        "catalog.bearing_preload", outside(r.bearing_preload, [bearing["preload_class"]])
    )
    out += _listed("catalog.guide_types", outside(r.guide_types, [guide["type"]]))
    if r.guide_preload is not None and not {guide["preload_level"], guide["preload_class"]} & set(
        r.guide_preload
    ):
        out += _listed("catalog.guide_preload", [guide["preload_level"]])
    if space.grades is not None:
        out += _listed("catalog.screw_grades", outside(r.screw_grades, [space.grades[n]]))
    if motor is not None:
        out += _listed("catalog.motor_vendors", outside(r.motor_vendors, [motor["vendor"]]))
        out += _listed("catalog.motor_series", outside(r.motor_series, [motor["series"]]))
    if coupling is not None:
        out += _listed("catalog.coupling_series", outside(r.coupling_series, [coupling["series"]]))
    for slot, row in rows.items():
        if row is None:
            continue
        pid = str(row["id"])
        req = r.required(slot)
        if req and pid not in req:
            out += _listed(f"catalog.require.{slot}", [pid])
        if pid in r.excluded(slot):
            out.append(
                DesignChange(
                    f"catalog.exclude.{slot}", "", math.nan, math.nan, "", "remove", (pid,)
                )
            )
    return out


def first_design(problem, space=None):
    """(space, combination) of the first feasible design the default search finds for ``problem``
    (stopped there), or None: none, or the problem's inputs refuse the change (widened filters with
    nothing left to choose from, a duty cycle a lowered speed breaks).  ``space``: the problem's
    search space when the change left the parts as they were (a limit, not the axis or the
    filters)."""
    found = first_feasible(problem, space)
    return None if found is None else found[:2]


def first_feasible(problem, space=None):
    """:func:`first_design` with the design's preload: (space, combination, preload [N]) or None."""
    from ..bestfirst import bound_order_search
    from ..parts import build_space
    from ..task.constraints import build_constraints
    from ..task.objective import objective_spec

    deadline = DEADLINE.get()
    if deadline is not None and time.perf_counter() >= deadline:
        _cut()
        return None
    try:
        space = build_space(problem) if space is None else space
    # a change the inputs refuse (build_space: nothing left to choose from) gives no advice
    except InputError:
        return None
    spec = objective_spec(problem.objective.mode, problem)
    ex, stats = bound_order_search(
        space, build_constraints(problem), spec, top=1, first_feasible=True, deadline=deadline
    )
    ok = np.nonzero(np.isfinite(ex.objective))[0]
    if not len(ok) and stats.timed_out:
        _cut()
    return (space, int(ex.idx[ok[0]]), float(ex.preload[ok[0]])) if len(ok) else None


def _cut() -> None:
    flag = CUT.get()
    if flag is not None:
        flag.append(True)


def with_edits(problem, edits):
    """``problem`` with the catalog edits (:func:`design_edits` rows) made: its restrictions as the
    YAML edited so would read them."""
    r = problem.restrictions
    kw: dict = {}
    for e in edits:
        field = e.key.split(".")[1]
        if field in ("require", "exclude"):
            slot = e.key.split(".")[2]
            pairs = dict(kw.get(field, getattr(r, field)))
            ids = pairs.get(slot, ())
            pairs[slot] = (
                tuple(i for i in ids if i not in e.values) if e.edit == "remove" else ids + e.values
            )
            kw[field] = tuple((k, v) for k, v in pairs.items() if v)
        else:
            have = problem.mountings if field == "mountings" else getattr(r, field)
            kw[field] = tuple(have) + e.values
    return replace(problem, restrictions=replace(r, **kw))


def _without(edits, key: str, value: str) -> list:
    """The edits with ``value`` no longer added to ``key`` (an edit left empty dropped)."""
    out = []
    for e in edits:
        if e.key == key and e.edit == "add":
            e = replace(e, values=tuple(v for v in e.values if v != value))
            if not e.values:
                continue
        out.append(e)
    return out


def widened(problem, misses, budget: int) -> tuple:
    """(edits, searches): the mounting and catalog-filter edits that make ``problem`` feasible (the
    module docstring), [] when none is found within ``budget`` searches; ``misses``: per closest
    design, {check or limit name: relative miss} (a check's name without ``margin_``).  A design
    that needs more than one value added is narrowed while the budget lasts: each value left out in
    turn, the design a search finds without it taken when there is one (its edits are fewer)."""
    tries, every = [], problem.restrictions
    for group in _groups(misses):
        r = _widen(problem, group)
        if r != problem.restrictions:
            tries.append(r)
            every = _widen(replace(problem, restrictions=every), group)
    # the group the misses call for most, then every group at once (a superset of each group alone:
    # a design of any one group is in it, and one may need parts of two groups); the narrowing finds
    # the fewer edits
    tries = tries[:1] + ([every] if len(tries) > 1 else [])
    used, edits = 0, []
    for r in tries:
        if used >= budget:
            return [], used
        used += 1
        found = first_design(replace(problem, restrictions=r))
        edits = design_edits(problem, *found) if found is not None else []
        if edits:
            break
    tried: set = set()
    while used < budget:
        adds = [
            (e.key, v)
            for e in edits
            if e.edit == "add"
            for v in e.values
            if (e.key, v) not in tried
        ]
        if sum(len(e.values) for e in edits) < 2 or not adds:
            break
        key, value = adds[0]
        tried.add((key, value))
        used += 1
        found = first_design(with_edits(problem, _without(edits, key, value)))
        if found is not None:
            edits = design_edits(problem, *found) or edits
    return edits, used


__all__ = [
    "widened",
    "design_edits",
    "first_design",
    "first_feasible",
    "with_edits",
    "DRIVE_CHECKS",
]
