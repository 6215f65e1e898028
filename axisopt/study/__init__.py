"""Compare designs and run batch trade studies (local process pool by default, Dask when asked).

* :mod:`.compare`: the designs ``axisopt compare`` puts side by side, problems solved to their best
  design (the table itself: :mod:`axisopt.report.compare`).
* :mod:`.spec`: study files (a base problem plus sweeps over its fields) expanded into cases.
* :mod:`.run`: one solve per case in worker processes or on a Dask cluster, saved as each completes,
  resumable; one case's solve and record in :mod:`.record`, the back-ends in :mod:`.pool`, the
  directory's lock in :mod:`.lock`, the case files in :mod:`.store`.
* :mod:`.table`: the results table (CSV, Parquet), summary plots and the Markdown report.
"""

from __future__ import annotations

import sys
import types

from .cases import Case, Study, Sweep, apply_overrides, build_problem
from .outputs import write_outputs
from .run import Progress, RunSummary, run_study, solve_case
from .spec import load_study
from .store import OK_STATUSES, CaseStore
from .table import results_table

__all__ = [
    "load_study",
    "run_study",
    "results_table",
    "write_outputs",
    "Study",
    "Sweep",
    "Case",
    "Progress",
    "RunSummary",
    "CaseStore",
    "solve_case",
    "build_problem",
    "apply_overrides",
    "OK_STATUSES",
]


class _CallablePackage(types.ModuleType):
    """``axisopt.study`` names both this package and the notebook function that runs a study
    (:func:`axisopt.api.study`): once the package is imported it is the attribute, so the package
    itself runs a study when called,
    ``axisopt.study("problems/studies/teaching_random.yaml", "out")``."""

    def __call__(
        self,
        spec,
        out=None,
        *,
        workers: int | None = 0,
        resume: bool = False,
        overwrite: bool = False,
        scheduler=None,
        time_limit: float = 100.0,
    ):
        from .result import run_spec

        return run_spec(
            spec,
            out,
            workers=workers,
            resume=resume,
            overwrite=overwrite,
            scheduler=scheduler,
            time_limit=time_limit,
        )


sys.modules[__name__].__class__ = _CallablePackage
