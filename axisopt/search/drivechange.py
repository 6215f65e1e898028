"""What to change when no rack-and-pinion or linear-motor design fits: the closest designs (fewest
summed relative misses of the checks and limits) with the checks they miss, and the least change of
the axis (acceleration, then rapid speed, each lowered by bisection to 1/256 of it) at which the
default search finds a design -- verified, the design is named."""

from __future__ import annotations

from dataclasses import replace

from .drivespace import evaluate_one

STEPS = 8  # bisection steps (a factor resolved to 1/256)
TYPE_LABELS = {"rack_pinion": "rack and pinion", "linear_motor": "linear motor"}


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
    from .drivebest import best_first
    from .drivedesigns import design_of, spaces

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
    for key, label, unit, scale in (
        ("acceleration", "acceleration", "m/s^2", 1.0),
        ("max_speed", "rapid speed", "m/min", 60.0),
    ):
        if getattr(axis, key) <= 0:
            continue
        lo, hi = 0.0, 1.0
        found = None
        for _ in range(STEPS):
            mid = 0.5 * (lo + hi)
            ax = scaled(axis, key, mid)
            hit = None
            for sp in spaces(problem, ax):
                designs, _, _ = best_first(problem, sp, spec, 1)
                if designs:
                    hit = (sp.kind, designs[0].parts)
                    break
            if hit:
                lo, found = mid, (mid, hit)
            else:
                hi = mid
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
