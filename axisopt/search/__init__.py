"""Sizing search over the catalogs: ``solve(problem, method=...) -> SolveResult``.

Methods (:data:`.front.METHOD_TABLE`, with what each can do): ``'default'`` (block bounds,
screening, exact preload solve in bound order, IPOPT polish; proves the optimum), ``'exhaustive'``
(every combination; the ground truth), ``'bonmin'`` (CasADi Bonmin MINLP with one-hot part
selection; a heuristic reference) and ``'scip'`` (the same MINLP solved globally by SCIP; optional
extra ``axisopt[scip]``).  All use the same model position grid (``model.positions``) for the
minimum over the stroke, the same limits and the same tie rule, so their objectives compare.

The stages of a default solve, one module each: :mod:`.front` (entry, task, methods, the result) ->
:mod:`.parts` (the filtered part tables as a :mod:`.task.space`) -> :mod:`.bounds` (block bounds) ->
:mod:`.screen` -> :mod:`.preload` (exact 1-D preload solve) -> :mod:`.polish` (IPOPT) ->
:mod:`.candidates` -> :mod:`.result`; :mod:`.bestfirst` drives the middle stages.  Every stage reads
the :mod:`.task` (the space, the constraints, the objective).  Beside them: :mod:`.exhaustive`,
:mod:`.pareto`, :mod:`.explain` and :mod:`.relax` (infeasible problems), :mod:`.interval`.

``solve`` is a pure function of the problem (no printing, no global state besides per-process solver
caches), so a trade study may call it in worker processes.
"""

from __future__ import annotations

from dataclasses import replace

from .certificate import Certificate
from .front import METHOD_TABLE, METHODS, solve
from .infeasible.answer import Infeasibility, Relaxation
from .result import Binding, Candidate, ParetoFront, SolveResult
from .sensitivity import estimated_at_optimum, limit_sensitivities

__all__ = [
    "solve",
    "METHODS",
    "METHOD_TABLE",
    "SolveResult",
    "Candidate",
    "Certificate",
    "Binding",
    "Infeasibility",
    "ParetoFront",
    "Relaxation",
    "replace",
    "estimated_at_optimum",
    "limit_sensitivities",
]
