"""What to change when no rack-and-pinion or linear-motor design fits: the closest designs (fewest
summed relative misses of the checks and limits) with the checks they miss, and the least change of
the axis (acceleration, then rapid speed, each lowered by bisection to 1/256 of it) at which the
default search finds a design -- verified, the design is named."""

from __future__ import annotations

import time
from dataclasses import replace

from .drivespace import evaluate_one

STEPS = 8  # bisection steps (a factor resolved to 1/256)
TYPE_LABELS = {"rack_pinion": "rack and pinion", "linear_motor": "linear motor"}
# the axis values lowered, in this order: (key, label, display unit, display per SI)
KEYS = (
    ("acceleration", "acceleration", "m/s^2", 1.0),
    ("max_speed", "rapid speed", "m/min", 60.0),
)


def scaled(axis, key: str, factor: float):
    """``axis`` with its acceleration (``key`` 'acceleration') or rapid speed ('max_speed') times
    ``factor``, in its duty cycle too (each move's acceleration scaled, each move's speed capped at
    the new rapid speed)."""
    value = getattr(axis, key) * factor
    segs = []
    for seg in axis.duty_cycle:
        if seg.kind == "move" and key == "acceleration":
            seg = replace(seg, acceleration=seg.acceleration * factor)
        elif seg.kind == "move":
            seg = replace(seg, speed=min(seg.speed, value))
        segs.append(seg)
    return replace(axis, **{key: value}, duty_cycle=tuple(segs))


def design_change(problem, closest: dict, spec):
    """(closest designs, design change text) for an infeasible drive-type problem (see the
    module)."""
    from .drivedesigns import design_of

    shown = []
    for space, flats in closest.values():
        for i in flats[:1]:
            d = design_of(space, i, evaluate_one(space, i), spec, problem)
            d.margins = {k: v for k, v in d.margins.items() if v < 1.0}
            shown.append(d)
    if not closest:
        return shown, ""
    best = None
    axis = problem.axis
    for key, label, unit, scale in KEYS:
        found = lowest_change(problem, key)
        if found is not None:
            value = getattr(axis, key) * found[0]
            text = (
                f"lower {label} to {value * scale:.3g} {unit} (from "
                f"{getattr(axis, key) * scale:.3g}): verified, {TYPE_LABELS[found[1][0]]} "
                f"{' / '.join(str(v) for v in found[1][1].values())} then meets every check and "
                "limit (the best design there)"
            )
            if best is None or found[0] > best[0]:
                best = (found[0], text)
    if best is None:
        return shown, (
            "no lower acceleration or rapid speed lets a design fit: a limit or a part rating "
            "stands in the way (see the checks missed)"
        )
    return shown, best[1]


def first_design(problem, axis):
    """(drive type, parts) of the best design of ``problem``'s drive-type spaces on ``axis``, the
    first type in the problem's order that has one; None when none has."""
    from .drivebest import best_first
    from .drivedesigns import spaces

    for sp in spaces(problem, axis):
        designs, _, _ = best_first(problem, sp, spec_of(problem), 1)
        if designs:
            return sp.kind, designs[0].parts
    return None


def spec_of(problem):
    from .drivedesigns import objective_of

    return objective_of(problem)[1]


def lowest_change(problem, key: str, deadline: float | None = None):
    """(factor, (drive type, parts)): the largest factor (within 1/2^STEPS) on the axis's ``key``
    ('acceleration' or 'max_speed') at which ``problem``'s drive-type spaces hold a design, found by
    bisection; None when none does at 1/2^STEPS, or ``axis.key`` is 0.  ``deadline`` (a
    time.perf_counter() value): the bisection stops there with what it verified."""
    axis = problem.axis
    if getattr(axis, key) <= 0:
        return None
    lo, hi = 0.0, 1.0
    found = None
    for _ in range(STEPS):
        if deadline is not None and time.perf_counter() >= deadline:
            break
        mid = 0.5 * (lo + hi)
        hit = first_design(problem, scaled(axis, key, mid))
        if hit:
            lo, found = mid, (mid, hit)
        else:
            hi = mid
    return found
