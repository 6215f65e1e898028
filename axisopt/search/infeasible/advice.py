"""Design changes that make an infeasible problem feasible, proposed before any limit is relaxed,
each verified by a search on the changed problem (:func:`design_changes`).

The kinds of change, each offered only where the closest designs' misses call for it:

- **a budget or mass raised**: no combination meets ``max_cost`` (or a mass limit) on its own, or
  every closest design misses it: the least value at which the catalogs hold a design meeting every
  other limit (the budget by its own least-cost search, :mod:`.budget`; a mass bisected toward the
  closest designs' need), first of all;
- **another mounting, or parts a catalog filter left out** (:mod:`.widen`): the mounting, vendor,
  series, type, grade or part id to add to the problem's ``catalog:`` section, with the axis as
  asked, before any axis value is lowered (a search per group of filters, counted in
  :data:`BUDGET`);
- **rapid speed** lowered: a margin of a speed check (critical speed, DN, the support bearings', the
  motor's, coupling's, reduction's or rotating-nut unit's speed: available / needed >= L) needs the
  speed it is short of in proportion: a design that reaches L (1 - m) meets L at the rapid speed
  times (1 - m);
- **acceleration** lowered: a torque check of the motor or reduction is short of torque, a lift-off
  check of the nut or support bearings short of preload against the largest axial force, both of
  which the acceleration sets with the mass: the acceleration is lowered by the same factor (more
  than is needed, since the friction, the weight and the process force do not scale with it);
- **a reduction admitted**: the problem's ``max_backlash`` left every gearbox and belt out, and the
  closest designs miss the inertia ratio, a torque or a motor speed, which a reduction changes by
  its ratio: the least lost motion at the table that admits the least-backlash reduction on every
  screw of the catalogs;
- **a counterbalance** on a vertical axis whose closest designs miss a torque, a lift-off or a life:
  a balance cylinder taking :data:`BALANCE_SHARE` of the head's weight where there is none, or the
  counterweight or cylinder raised to that share (a design rule of thumb, an estimate:
  docs/assumptions.md);
- **the user's own limits** (cost, stiffness, mass, positioning error, ...:
  :data:`axisopt.model.limits.LIMITS`) the closest designs miss, last, with the speed or
  acceleration change on top where the misses call for one: each set to what the first design a
  search finds without them reaches (rounded outward), so that every vendor rule holds as the vendor
  wrote it (:func:`_limits_step`; the vendor margins are relaxed only in the list that follows the
  advice, :mod:`.relax`, never below 0.95).

Single changes are tried first (the speed and acceleration once more 10 % further), then each
structural change (reduction, counterbalance) with the speed and acceleration changes on top: the
first that a search verifies is the advice.  A verifying search is the default method's, stopped at
its first feasible design (no optimum, no explanation); the whole advice stops after :data:`BUDGET`
of them (an answer within the 2 s of an infeasible one, bench/bench_axes.py).  Values are rounded to
three significant figures, down for what is lowered and up for what is raised.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np

from ...design.axis import Counterbalance, G
from ...errors import InputError
from ...model.limits import ACCEL, LIMITS, RATIO, SPEED, WEIGHT, check_name, checks_set_by
from .answer import DesignChange
from .widen import first_design, first_feasible, widened

# the checks whose needed value the rapid speed, the acceleration, the weight or a reduction's ratio
# sets (model.limits.CHECK_TABLE's set_by), as the advice's miss names (margin_<check> without
# margin_)
SPEED_CHECKS = checks_set_by(SPEED)
ACCEL_CHECKS = checks_set_by(ACCEL)  # the motor and reduction torques, the nut and bearing lift-off
# the axis values lowered: (key, display unit, display per SI, the checks whose misses set the
# factor)
SCALARS = (("max_speed", "m/min", 60.0, SPEED_CHECKS), ("acceleration", "m/s^2", 1.0, ACCEL_CHECKS))
# the process's axial load sets the largest axial force with the acceleration: the nut's and support
# bearings' lift-off and static checks (the advice's last resort before the user's own limits, with
# speed and acceleration)
LOAD_CHECKS = frozenset({"nut_lift_off", "bearing_lift_off", "nut_static", "bearing_static"})
# a reduction's ratio scales the reflected inertia, the torque and the motor speed
REDUCTION_CHECKS = checks_set_by(RATIO)
# what a counterbalance relieves on a vertical axis: the weight in the torques, lift-off, the brake
# and the lives
BALANCE_CHECKS = checks_set_by(WEIGHT)
BALANCE_LIMITS = frozenset({"min_life"})
# the share of the head's weight a proposed counterbalance takes: an estimate (machine builders
# balance 80-100 % of the weight; the shipped balanced Zs take 83 and 90 %)
BALANCE_SHARE = 0.9
FURTHER = 0.9  # the second proposal of a speed or acceleration: 10 % below the first
# a budget or mass limit every closest design misses: raised (bisected) before any other change
RAISED_LIMITS = ("max_cost", "max_total_mass", "max_moving_mass")
BISECT = 4  # halvings of the raise (after the verified need)
# the proposal a little below the closest designs' bare need (their misses are at one preload)
SAFETY = 0.98
BUDGET = 6  # verifying searches at most (a count, not a time: the same answer on any machine)
# the mountings the last kind admits (fixed-free: too weak)
WIDE_MOUNTINGS = ("fixed-supported", "fixed-fixed")
# searches of the last kind, the user's own limits (with a speed or acceleration change on top)
LIMITS_BUDGET = 3


def _round(x: float, up: bool = False) -> float:
    """x rounded to three significant figures, down (or up)."""
    if x <= 0:
        return x
    e = math.floor(math.log10(x)) - 2
    return (math.ceil if up else math.floor)(x / 10**e - (1e-9 if up else -1e-9)) * 10**e


def _misses(constraints, infeasibility) -> list[dict]:
    """Per closest design: {check or limit name: relative miss} (a margin's name without
    ``margin_``)."""
    by_label = {c.label: c for c in constraints}
    out = []
    for cand in infeasibility.closest:
        named = {}
        for label, m in cand.misses.items():
            c = by_label.get(label)
            if c is not None:
                named[check_name(c.name) or c.name] = m
        out.append(named)
    return out


def _factor(misses, checks) -> float | None:
    """1 - the largest miss among ``checks`` of the closest design that misses them most (the
    largest change any closest design needs; the search verifies it), None when no closest design
    misses one."""
    need = [max(m for k, m in d.items() if k in checks) for d in misses if checks & d.keys()]
    f = [1.0 - m for m in need if 0.0 < 1.0 - m < 1.0]
    return min(f) if f else None


def _with(axis, key: str, to: float):
    """``axis`` with ``key`` (max_speed, acceleration or axial_load) lowered to ``to``, and the duty
    cycle's moves capped at it (a move's speed, acceleration or force left out in the YAML is the
    axis's, filled in when read)."""
    field = {"max_speed": "speed", "acceleration": "acceleration", "axial_load": "force"}[key]

    def cap(v):
        return v if v is None else math.copysign(min(abs(v), to), v)

    cycle = tuple(
        replace(sg, **{field: cap(getattr(sg, field))}) if sg.kind == "move" else sg
        for sg in (axis.duty_cycle or ())
    )
    return replace(axis, **{key: to}, **({"duty_cycle": cycle} if axis.duty_cycle else {}))


@dataclass(frozen=True)
class _Step:
    """One change: what it says (DesignChange rows) and what it does to the problem."""

    changes: tuple
    apply: object  # Problem -> Problem


def _scalar_step(problem, key, unit, scale, factor) -> _Step | None:
    value = getattr(problem.axis, key, None)
    if not value or factor is None:
        return None
    to = _round(value * scale * factor * SAFETY) / scale
    if to <= 0:
        return None
    return _Step(
        (DesignChange(f"axis.{key}", unit, value * scale, to * scale),),
        lambda p, k=key, t=to: replace(p, axis=_with(p.axis, k, t)),
    )


def _reduction_step(problem, misses, space) -> _Step | None:
    """Admit the reductions the problem's max_backlash left out of ``space`` (parts: lost motion =
    backlash x lead / 2 pi at the table), when the closest designs miss what a reduction's ratio
    changes."""
    from ..parts import build_space

    if not space.reductions_by_backlash or not any(REDUCTION_CHECKS & d.keys() for d in misses):
        return None
    limit = problem.limit_map.get("max_backlash")
    if limit is None:
        return None
    try:
        wide = build_space(problem.with_limit("max_backlash", None))
    # the search space without the limit has nothing to choose from: no advice of this kind
    except InputError:
        return None
    if wide.reductions is None or not len(wide.s_arr["lead"]):
        return None
    lost = (
        float(np.nanmin(wide.reductions.number("backlash")))
        * float(np.max(wide.s_arr["lead"]))
        / (2 * np.pi)
    )
    to = _round(lost * 1e6, up=True) * 1e-6
    if not to > limit:
        return None
    return _Step(
        (
            DesignChange(
                "limits.max_backlash",
                "um",
                limit * 1e6,
                to * 1e6,
                "admits a gearbox or belt: its lost motion at the table",
            ),
        ),
        lambda p: p.with_limit("max_backlash", to),
    )


def _balance_step(problem, misses, constraints) -> _Step | None:
    """A vertical axis: a balance cylinder taking BALANCE_SHARE of the head's weight, or the
    counterbalance raised to it, when the closest designs miss what the weight sets."""
    a = problem.axis
    names = {c.name for c in constraints}
    if a.orientation != "vertical" or problem.arrangements:
        return None
    if not any((BALANCE_CHECKS | (BALANCE_LIMITS & names)) & d.keys() for d in misses):
        return None
    target = BALANCE_SHARE * a.moving_mass * G
    cb = a.counterbalance
    if cb is None or cb.kind == "none":
        force = _round(target, up=True)
        new = Counterbalance("cylinder", force=force)
        change = DesignChange("axis.counterbalance", "N", 0.0, force)
    elif cb.kind == "cylinder":
        if cb.force >= target:
            return None
        force = _round(target, up=True)
        end = (
            None if cb.force_at_end is None else _round(cb.force_at_end * force / cb.force, up=True)
        )
        new = replace(cb, force=force, force_at_end=end)
        change = DesignChange(
            "axis.counterbalance.force",
            "N",
            cb.force,
            force,
            "" if end is None else f"force_at_end {cb.force_at_end:g} to {end:g} N",
        )
    else:
        mass = _round(BALANCE_SHARE * a.moving_mass, up=True)
        if cb.mass >= mass:
            return None
        new = replace(cb, mass=mass)
        change = DesignChange("axis.counterbalance.mass", "kg", cb.mass, mass)
    return _Step((change,), lambda p: replace(p, axis=replace(p.axis, counterbalance=new)))


def _feasible(problem, space=None) -> bool:
    """Whether the catalogs hold a design of ``problem`` (:func:`.widen.first_design`: the default
    search, stopped at its first feasible design); ``space``: its search space when the change left
    the parts as they were (a limit, not the axis)."""
    return first_design(problem, space) is not None


def _raise_limit(problem, constraints, infeasibility, misses, name: str, space) -> list:
    """The least value of the budget or mass limit ``name`` (max_cost, max_total_mass,
    max_moving_mass) at which the catalogs hold a design meeting every other limit, when no
    combination meets the limit on its own (the explanation's single-limit check) or every closest
    design misses it; [] otherwise, or when none is found.  Rounded up to three significant figures.
    A budget or mass limit leaves the parts as they are: every search reuses ``space``.

    The budget: the least cost of a design meeting every other limit, found by its own search
    (:func:`.budget.least_cost`, proven least), apart from the closest designs (which the miss sum
    ranks, and which an explanation cut short leaves poor).  A mass: the closest designs' need first
    (the limit times one plus their largest miss of it, verified), then halved toward the limit
    :data:`BISECT` times."""
    from .budget import least_cost

    c = next((c for c in constraints if c.name == name), None)
    if c is None or not c.limit > 0:
        return []
    alone = c.label in {u[0] for u in infeasibility.unmeetable}
    need = [d[name] for d in misses if name in d]
    if not alone and not (need and len(need) == len(misses)):
        return []
    if name == "max_cost":
        found = least_cost(problem, space)
        if found is None:  # no design even without the budget: not the budget alone
            return []
        least, _, proven = found
        to = _round(least / c.factor, up=True)
        what = (
            "the cheapest such design costs"
            if proven
            else "the search for a cheaper one was cut; a design costs"
        )
        return [
            DesignChange(
                f"limits.{name}",
                c.unit,
                c.limit / c.factor,
                to,
                f"every other limit kept; {what} {least / c.factor:,.0f} {c.unit}",
            )
        ]
    if not need:
        return []
    lo, hi = c.limit, c.limit * (1.0 + max(need)) / SAFETY
    hi = _round(hi / c.factor, up=True) * c.factor
    if not _feasible(problem.with_limit(name, hi), space):
        return []
    for _ in range(BISECT):
        mid = _round(0.5 * (lo + hi) / c.factor, up=True) * c.factor
        if not lo < mid < hi:
            break
        if _feasible(problem.with_limit(name, mid), space):
            hi = mid
        else:
            lo = mid
    return [
        DesignChange(
            f"limits.{name}", c.unit, c.limit / c.factor, hi / c.factor, "every other limit kept"
        )
    ]


def _limits_step(problem, constraints, misses, combos, budget: int) -> list:
    """The user's own limits the closest designs miss, set to what a design reaches, on top of each
    change of ``combos`` (tuples of :class:`_Step`, the empty one first) in turn, with the screw's
    other mountings admitted (a mounting the design needs is added to ``catalog.mountings``): the
    first design the default search finds with those limits left out gives each limit's new value
    (rounded outward to three significant figures), and a search on the problem so changed verifies
    it.  [] when the misses name no such limit, or no design is found within ``budget`` searches.
    The design the search finds is the verification: it meets every vendor check and the other
    limits, and the limits at their new values (its own values, rounded outward)."""
    from ..candidates import make_candidate
    from ..task.objective import objective_spec
    from .widen import design_edits, with_edits

    names = [c for c in constraints if c.name in LIMITS and any(c.name in d for d in misses)]
    if not names:
        return []
    mountings = tuple(dict.fromkeys(tuple(problem.mountings) + WIDE_MOUNTINGS))
    used = 0
    for combo in combos:
        if used >= budget:
            break
        changed = problem
        for step in combo:
            changed = step.apply(changed)
        free = replace(changed, restrictions=replace(changed.restrictions, mountings=mountings))
        for c in names:
            free = free.with_limit(c.name, None)
        used += 1
        found = first_feasible(free)
        if found is None:
            continue
        space, idx, preload = found
        edits = design_edits(changed, space, idx)
        cand = make_candidate(space, idx, preload, objective_spec(problem.objective.mode, problem))
        rows, relaxed = [], with_edits(changed, edits)
        for c in names:
            lim = LIMITS[c.name]
            v = cand.outputs.get(lim.output)
            if v is None or not math.isfinite(v):
                break
            up = c.sense == "<="
            if (v <= c.limit) if up else (v >= c.limit):
                continue  # this design meets the limit as asked
            to = _round(v / c.factor, up=up)
            relaxed = relaxed.with_limit(c.name, to * c.factor)
            rows.append(
                DesignChange(f"limits.{c.name}", c.unit, c.limit / c.factor, to, "your own limit")
            )
        else:
            # the design found is the witness: it meets every vendor check and the other limits (the
            # search), and these limits as rounded outward (its own values);
            # tests/search/test_unseen_axes.py re-solves
            return [ch for step in combo for ch in step.changes] + edits + rows
    return []


def design_changes(
    problem,
    constraints,
    infeasibility,
    budget: int = BUDGET,
    *,
    space=None,
    deadline: float | None = None,
    cut: list | None = None,
) -> list:
    """The changes (:class:`.answer.DesignChange`, to be made together) that make ``problem``
    feasible, verified by a search; empty when no kind applies, none is verified or the budget is
    spent.  ``space``: the problem's search space, if built.  ``deadline`` (a time.perf_counter()
    value): no verifying search runs past it (one it cuts finds nothing); ``cut``, a list: True is
    appended when it cut one."""
    from .widen import CUT, DEADLINE

    if deadline is not None and time.perf_counter() >= deadline:
        if cut is not None:
            cut.append(True)
        return []
    flags: list = []
    tokens = DEADLINE.set(deadline), CUT.set(flags)
    try:
        return _design_changes(problem, constraints, infeasibility, budget, space)
    finally:
        DEADLINE.reset(tokens[0])
        CUT.reset(tokens[1])
        if cut is not None and flags:
            cut.append(True)


def _design_changes(problem, constraints, infeasibility, budget: int, space) -> list:
    from ..parts import build_space

    misses = _misses(constraints, infeasibility)
    if not misses:
        return []
    space = build_space(problem) if space is None else space
    # a budget or mass the closest designs all need more of: how much more, first
    for name in RAISED_LIMITS:
        if found := _raise_limit(problem, constraints, infeasibility, misses, name, space):
            return found
    # another mounting, or parts a catalog filter left out (search.widen): the axis as asked, before
    # it is lowered
    edits, used = widened(problem, misses, budget)
    if edits:
        return edits
    budget -= used
    # the speed and the acceleration as the closest designs' misses say, and one step further each
    # (their misses are at one preload and one screw: another may need more)
    factors = [(key, unit, scale, _factor(misses, checks)) for key, unit, scale, checks in SCALARS]
    speed, accel = (_scalar_step(problem, k, u, sc, f) for k, u, sc, f in factors)
    further = [_scalar_step(problem, k, u, sc, f and f * FURTHER) for k, u, sc, f in factors]
    structural = [
        s
        for s in (
            _reduction_step(problem, misses, space),
            _balance_step(problem, misses, constraints),
        )
        if s
    ]
    singles = [s for s in [speed, accel, *further] if s] + structural
    # a structural change with the speed and acceleration on top (the misses it leaves need them)
    pairs = [(s, t) for s in structural for t in (speed, accel) if t]
    for combo in ([(s,) for s in singles] + pairs)[:budget]:
        changed = problem
        for step in combo:
            changed = step.apply(changed)
        if _feasible(changed):
            return [c for step in combo for c in step.changes]
    # last, the user's own limits, with the speed and acceleration changes on top where the misses
    # call for them, and then the process's axial load lowered with the acceleration (a lighter cut:
    # lift-off, static checks)
    f_load = _factor(misses, LOAD_CHECKS)
    load = _scalar_step(problem, "axial_load", "N", 1.0, f_load and f_load * FURTHER)
    # the limits alone, then with the speed and acceleration as the misses say, then one step
    # further with the lighter cut (each one search)
    both = tuple(s for s in (speed, accel) if s)
    far = tuple(s for s in further if s) + ((load,) if load else ())
    combos = [c for c in (both, far) if c]
    return _limits_step(problem, constraints, misses, [()] + combos, LIMITS_BUDGET)
