"""A design of the search space as a :class:`.result.Candidate`: its parts, preload and the model's
values (:func:`make_candidate`, :func:`candidate_values`)."""

from __future__ import annotations

import numpy as np

from .. import model
from ..design import Design
from ..model.goals import RESULT_GOALS
from ..model.limits import LIMITS
from .reported import REPORTED
from .result import CANDIDATE_FIELDS, Candidate
from .task.objective import ObjectiveSpec
from .task.space import Space


def make_candidate(
    space: Space,
    combo: int,
    preload: float,
    objective: ObjectiveSpec,
    rank: int = 0,
    name: str = "",
) -> Candidate:
    """The candidate of combination ``combo`` at ``preload`` (clipped to its range), ranked
    ``rank``."""
    return candidate_values(space, combo, preload, objective, rank, name)[0]


def candidate_values(
    space: Space,
    combo: int,
    preload: float,
    objective: ObjectiveSpec,
    rank: int = 0,
    name: str = "",
) -> tuple:
    """(:func:`make_candidate`'s Candidate, the model's values of its design:
    ``Evaluation.values``)."""
    mi, n, b, g = (int(v) for v in space.unravel(combo))
    mounting = space.mountings[mi]
    screw, nut, bearing, guide, motor, coupling, reduction = part_rows(space, n, b, g)
    lo, hi = float(space.preload_lo[n]), float(space.preload_hi[n])
    preload = float(min(max(preload, lo), hi))
    design = Design(
        axis=space.problem.axis_for(mounting),
        screw=screw,
        nut=nut,
        bearing=bearing,
        guide=guide,
        motor=motor,
        coupling=coupling,
        reduction=reduction,
        nut_preload=preload,
        screw_grade=None if space.grades is None else str(space.grades[n]),
        name=name or f"{space.problem.name}-{rank or 'design'}",
        source=space.problem.source,
        assumed=space.problem.assumed,
    )
    # the model on numpy: the same formula as the CasADi Function (tests/model/test_function.py
    # holds them to 1e-10) without building that Function for every new axis (a study's cases, the
    # closest designs)
    ev = model.evaluate(design, use_casadi=False)
    v = ev.values
    J = float(objective.value({k: np.asarray(v[k]) for k, _ in objective.terms}))
    outputs = {
        lim.output: float(np.min(v[lim.output])) for lim in LIMITS.values() if lim.output in v
    }
    # the goals' values that are Candidate fields (the others the Candidate reads from ``outputs``)
    goals = {g.field: g.value(outputs) for g in RESULT_GOALS if g.field in CANDIDATE_FIELDS}
    # the reported values read from a model output (the others are goals' fields)
    reported = {r.field: float(np.min(v[r.output])) / r.per for r in REPORTED if r.output}
    return Candidate(
        rank=rank,
        combination=int(combo),
        mounting=mounting,
        screw=str(screw["id"]),
        nut=str(nut["id"]),
        bearing=str(bearing["id"]),
        guide=str(guide["id"]),
        nut_preload=preload,
        motor="" if motor is None else str(motor["id"]),
        coupling="" if coupling is None else str(coupling["id"]),
        reduction="" if reduction is None else str(reduction["id"]),
        screw_grade="" if space.grades is None else str(space.grades[n]),
        objective=J,
        design=design,
        outputs=outputs,
        **goals,
        **reported,
    ), v


def part_rows(space: Space, n, b, g):
    """(screw, nut, bearing, guide, motor, coupling, reduction) rows of part-axis numbers; ``g`` is
    the guide- and-drive index (motor, coupling and reduction None where the axis values stand
    in)."""
    gi, di = divmod(int(g), space.n_drives)
    mi, ci, ri = space.drives[di]
    return (
        space.screws.row(n),
        space.nuts.row(n),
        space.bearings.row(b),
        space.guides.row(gi),
        None if mi is None else space.motors.row(mi),
        None if ci is None else space.couplings.row(ci),
        None if ri is None else space.reductions.row(ri),
    )
