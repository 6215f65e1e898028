"""The drive type as a search choice (``search.drive_types``): the screw drive (the usual search,
its proof), rack and pinion and linear motors (every combination of their parts,
:mod:`.drivespace`), the best design of any type wins.  The default method evaluates each new type's
whole space at once on numpy arrays; the exhaustive method evaluates every combination alone in
floats (the ground truth the tests compare with); both take the screw drive from the screw search
with the same method.  Ties: lower cost, then lower moving mass, then the type listed first.

The objective is one of stiffness, frequency (maximised), cost, moving mass, positioning error
(minimised); the limits on those outputs and min_life hold for every type; a limit on an output only
the screw drive has (drag torque, screw sag, ...) binds the screw drive alone (noted in the answer).
When no type has a design, the answer names the checks the closest designs miss and a design change
verified by evaluating the closest designs again (the acceleration, then the rapid speed lowered by
bisection)."""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from ..errors import InputError
from .drivedesigns import (  # noqa: F401  (the vocabulary, read from here too)
    CLOSEST,
    HANDLED,
    LIMIT_FLOOR,
    LIMITS,
    OBJECTIVES,
    DriveDesign,
    DriveTypeResult,
    TypeSummary,
    design_of,
    limit_arrays,
    objective_of,
    part_tables,
    rank_designs,
    rank_key,
    scores,
    screw_designs,
    spaces,
    subset,
)
from .drivespace import evaluate_one, evaluate_space
from .result import INFEASIBLE, OPTIMAL, STATUSES


def search_space(problem, space, spec, method: str, top: int):
    """The best ``top`` designs of one space, the number of combinations evaluated (exhaustive: the
    feasible count) and, when none is feasible, the closest combinations."""
    if method != "exhaustive":
        from .drivebest import best_first

        designs, _, near = best_first(problem, space, spec, top)
        return designs, None, near
    res = evaluate_space(space)
    objs, oks, misses = scores(problem, space, res, spec)
    sense = spec[3]
    sign = -1.0 if sense == "max" else 1.0
    idx = np.flatnonzero(oks)
    if idx.size:
        cost = np.asarray(res["cost"]).ravel()
        mass = np.asarray(res["outputs"]["moving_mass"]).ravel()
        keys = sorted((rank_key(objs[i], cost[i], mass[i], sign), int(i)) for i in idx)[:top]
        designs = rank_designs(
            [design_of(space, i, evaluate_one(space, i), spec) for _, i in keys], sense
        )
        return designs[:top], int(idx.size), []
    order = np.argsort(misses, kind="stable")[:CLOSEST]
    return [], 0, [int(i) for i in order]


def scalar_search(problem, space, spec, top: int):
    """Every combination alone in floats (the tests' ground truth for small spaces): (designs,
    feasible)."""
    sign = -1.0 if spec[3] == "max" else 1.0
    found = []
    for i in range(space.size):
        one = evaluate_one(space, i)
        res = {
            "outputs": {k: np.array([v]) for k, v in one["outputs"].items()},
            "margins": {k: np.array([v]) for k, v in one["margins"].items()},
            "cost": np.array([one["cost"]]),
        }
        o, k, _ = scores(problem, space, res, spec)
        if k[0]:
            found.append((rank_key(o[0], one["cost"], one["outputs"]["moving_mass"], sign), i))
    found.sort()
    return rank_designs(
        [design_of(space, i, evaluate_one(space, i), spec) for _, i in found[:top]], spec[3]
    ), len(found)


def _screw(problem, method: str, top: int, time_limit: float, spec):
    from .front import solve

    res = solve(
        replace(problem, drives=None), method, top=top, time_limit=time_limit, sensitivities=False
    )
    return res, screw_designs(res)


def solve_drive_types(problem, method: str = "default", *, top: int = 5, time_limit: float = 100.0):
    """Solve ``problem`` over its drive types (see the module); a :class:`DriveTypeResult`."""
    t0 = time.perf_counter()
    if method not in ("default", "exhaustive"):
        raise InputError(
            f"method '{method}': a search over drive types runs the default or exhaustive method",
            source=problem.source,
            where="method",
        )
    mode, spec = objective_of(problem)
    unit, sense = spec[2], spec[3]
    designs, types, notes, closest = [], [], [], {}
    status = OPTIMAL
    for kind in problem.drives.types:
        if kind == "screw":
            res, ds = _screw(
                problem, method, top, max(time_limit - (time.perf_counter() - t0), 1.0), spec
            )
            designs += ds
            types.append(
                TypeSummary(
                    "screw",
                    res.status,
                    res.certificate.combinations,
                    res.certificate.feasible,
                    ds[0].objective if ds else None,
                )
            )
            if not STATUSES[res.status].proven:
                status = res.status
            continue
        for space in spaces(problem):
            if space.kind != kind:
                continue
            ds, nfeas, near = search_space(problem, space, spec, method, top)
            designs += ds
            closest[kind] = (space, near)
            types.append(
                TypeSummary(
                    kind,
                    OPTIMAL if ds else INFEASIBLE,
                    space.size,
                    nfeas,
                    ds[0].objective if ds else None,
                )
            )
    left = sorted(k for k, _ in problem.limits if k not in HANDLED)
    if left and any(t != "screw" for t in problem.drives.types):
        notes.append(f"limits on screw-drive outputs bind the screw drive only: {', '.join(left)}")
    sign = -1.0 if sense == "max" else 1.0
    ranked = sorted(
        designs,
        key=lambda d: (
            rank_key(d.objective, d.cost, d.moving_mass, sign),
            problem.drives.types.index(d.drive_type),
        ),
    )
    out = DriveTypeResult(
        status if ranked else INFEASIBLE,
        method,
        f"{'maximise' if sense == 'max' else 'minimise'} {mode.replace('_', ' ')}",
        unit,
        ranked[0] if ranked else None,
        ranked[1:top],
        types,
        0.0,
        tuple(notes),
    )
    if not ranked:
        from .drivechange import design_change

        out.closest, out.change = design_change(problem, closest, spec)
    out.time = time.perf_counter() - t0
    return out
