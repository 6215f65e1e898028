"""What to change when no rack-and-pinion or linear-motor design fits: the closest designs (fewest summed
relative misses of the checks and limits) with the checks they miss, and the least change of the axis
(acceleration, then rapid speed, each lowered by bisection) that makes one of them fit, verified by
evaluating those designs at the changed axis."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .drivespace import evaluate_one

STEPS = 10  # bisection steps (a factor resolved to 1/1024)
VERIFY = 20  # closest designs per type a change is verified on


def _fits(problem, space, flats, spec) -> int | None:
    """The first of ``flats`` that meets every check and limit, or None."""
    from .drivetype import _scores

    for i in flats:
        one = evaluate_one(space, i)
        res = {"outputs": {k: np.array([v]) for k, v in one["outputs"].items()},
               "margins": {k: np.array([v]) for k, v in one["margins"].items()}, "cost": np.array([one["cost"]])}
        if _scores(problem, space, res, spec)[1][0]:
            return i
    return None


def design_change(problem, closest: dict, spec):
    """(closest designs, design change text) for an infeasible drive-type problem (see the module)."""
    from .drivetype import _design, spaces

    shown = []
    for kind, (space, flats) in closest.items():
        for i in flats[:1]:
            d = _design(space, i, evaluate_one(space, i), spec)
            d.margins = {k: v for k, v in d.margins.items() if v < 1.0}
            shown.append(d)
    if not closest:
        return shown, ""
    best = None
    axis = problem.axis
    for key, label, unit, scale in (("acceleration", "acceleration", "m/s^2", 1.0),
                                    ("max_speed", "rapid speed", "m/min", 60.0)):
        if getattr(axis, key) <= 0 or axis.duty_cycle:
            continue
        lo, hi = 0.0, 1.0
        found = None
        for _ in range(STEPS):
            mid = 0.5 * (lo + hi)
            ax = replace(axis, **{key: getattr(axis, key) * mid})
            hit = None
            for sp in spaces(problem, ax):
                near = closest.get(sp.kind, (None, []))[1]
                j = _fits(problem, sp, near[:VERIFY], spec)
                if j is not None:
                    hit = (sp.kind, sp.parts(j))
                    break
            if hit:
                lo, found = mid, (mid, hit)
            else:
                hi = mid
        if found is not None:
            value = getattr(axis, key) * found[0]
            text = (f"lower {label} to {value * scale:.3g} {unit} (from {getattr(axis, key) * scale:.3g}): "
                    f"verified, {found[1][0].replace('_', ' ')} {' / '.join(str(v) for v in found[1][1].values())} "
                    "then meets every check and limit")
            if best is None or found[0] > best[0]:
                best = (found[0], text)
    if best is None:
        return shown, ("no lower acceleration or rapid speed lets the closest designs fit: a limit or a part "
                       "rating stands in the way (see the checks missed)")
    return shown, best[1]
