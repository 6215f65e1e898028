"""The task a solve works on, and the vocabulary every stage of the search reads: the search space
(the part arrays and the combination numbering, :mod:`.space`), the constraints (each limit with its
preload structure and scaling, :mod:`.constraints`) and the objective (:mod:`.objective`).  The
stages (:mod:`axisopt.search`) build it once (:func:`axisopt.search.front.build_task`) and pass it
on; nothing here runs a stage.  A long stage writes its progress to :data:`LOG` every
:data:`PROGRESS` seconds.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

from ...problem import Problem
from .objective import ObjectiveSpec
from .space import Space

__all__ = ["LOG", "PROGRESS", "Task"]

LOG = logging.getLogger("axisopt")  # a long search's progress records (a terminal shows them)
PROGRESS = 2.0  # [s] between progress records of a long search (the search, the explanation)


@dataclass(frozen=True)
class Task:
    """What every stage of a solve works on: the problem, its search space, its constraints and the
    scalar objective (the Pareto front: the stiffness, whose exact solve gives every front
    value)."""

    problem: Problem
    space: Space
    constraints: tuple
    objective: ObjectiveSpec
    # an infeasible answer explained (closest designs, what to relax): False where only the status
    # and optimum are read (the arrangements' relaxed re-solves)
    explain: bool = True
