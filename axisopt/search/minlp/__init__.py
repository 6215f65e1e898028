"""The reference MINLP methods: the whole sizing problem as one mixed-integer nonlinear program.

One formulation (:mod:`.formulation`: one-hot binaries per slot, part parameters as binary-weighted
catalog columns, the recovery of a design from a solver's point) and one scaling of the limits
(:mod:`.scaling`), solved by

* :func:`solve_bonmin` (:mod:`.bonmin`): CasADi + Bonmin, nonlinear branch-and-bound; a heuristic on
  this nonconvex problem (never a proof, one design);
* :func:`solve_scip` (:mod:`.scip`): the CasADi model translated to SCIP (:mod:`.translate`),
  spatial branch-and-bound; the optimum proven up to SCIP's tolerances and cross-checked (one
  design; optional extra ``axisopt[scip]``).

Neither computes a Pareto front.  Every design they report is re-evaluated with the project's own
model.
"""

from __future__ import annotations

from .bonmin import solve_bonmin
from .scip import solve_scip

__all__ = ["solve_bonmin", "solve_scip"]
