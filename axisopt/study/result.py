"""A study run from Python (:func:`axisopt.study`): the run's summary and its results table."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..display import html_table, one_line
from .cases import Study
from .lock import StudyLock
from .run import RunSummary, run_study
from .store import CaseStore, refuse_inputs_in
from .table import results_table

# columns of the notebook's HTML view (the table itself has every column)
SHOWN = (
    "case_id",
    "status",
    "objective",
    "objective_unit",
    "mounting",
    "screw",
    "nut",
    "min_stiffness [N/um]",
    "min_frequency [Hz]",
    "cost [EUR]",
)


@dataclass(repr=False)
class StudyResult:
    """A finished study: ``summary`` (cases solved, failed, files written) and the output directory;
    the results table, one row per case, is read from the case files by :meth:`to_frame`."""

    study: Study
    out_dir: str
    summary: RunSummary

    def to_frame(self):
        """pandas DataFrame, one row per finished case: the swept inputs (quantities as numbers, the
        unit in the column name, e.g. ``axis.stroke [mm]``), status, objective, chosen parts,
        ``min_stiffness [N/um]``, ``cost [EUR]``, each check's margin, available and needed (the
        study's ``results.csv``)."""
        return results_table(self.study, self.out_dir)

    @property
    def files(self) -> dict:
        """name -> path of the table, plots and report written."""
        return dict(self.summary.files)

    def __repr__(self) -> str:
        s = self.summary
        return one_line(
            "StudyResult",
            repr(self.study.name),
            {
                "cases": s.total,
                "solved now": s.solved,
                "kept": s.resumed or None,
                "failed": s.failed,
                "not run": s.lost or None,
                "time": f"{s.time:.1f} s",
                "out": self.out_dir,
            },
        )

    def _repr_html_(self) -> str:
        df = self.to_frame()
        cols = [c for c in SHOWN if c in df.columns]
        return html_table(df[cols].to_dict("records"), repr(self), columns=cols)


# what an axis study writes in its output directory (study/run.py, study/outputs.py)
OUTPUT_FILES = ("study.json", "results.csv", "results.parquet", "report.md")


def run_spec(
    spec,
    out=None,
    *,
    workers: int | None = 0,
    resume: bool = False,
    overwrite: bool = False,
    scheduler=None,
    progress=None,
    time_limit: float = 100.0,
) -> StudyResult:
    """Run a study (a study YAML path or a loaded :class:`Study`) -> :class:`StudyResult`.

    out       : output directory (default ``<study file stem>-results``, as on the command line)
    workers   : local worker processes; 0 (the default here) solves in this process, None uses every
                core
    resume    : continue a run in ``out`` (its finished cases are kept)
    overwrite : solve every case again: the case results already in ``out`` are deleted first
    time_limit: [s] of each case's solve (the study command's --time-limit option, default 100)

    An ``out`` that holds case results, with neither ``resume`` nor ``overwrite``, is an InputError
    that says so in these words (``axisopt.study(..., resume=True)``), not in the command line's.
    """
    import math
    from dataclasses import replace
    from os import PathLike

    from ..errors import InputError
    from .spec import load_study

    if resume and overwrite:
        raise InputError(
            "resume=True continues a run, overwrite=True starts it again: give one of them"
        )
    path = isinstance(spec, (str, PathLike))
    study = load_study(spec) if path else spec
    if not (math.isfinite(time_limit) and time_limit > 0):
        raise InputError(f"time_limit must be positive, got {time_limit}")
    study = replace(study, time_limit=float(time_limit))
    if out is None:
        out = f"{Path(spec).stem if path else study.name}-results"
    refuse_inputs_in(
        Path(out), [str(spec) if path else study.source, study.base_source], OUTPUT_FILES
    )
    store = CaseStore(out)
    have = store.existing()
    if have and overwrite:
        clear_cases(out)
    elif have and not resume:
        raise InputError(
            f"already holds {len(have)} case results; call axisopt.study(..., resume=True) to "
            "continue that study, overwrite=True to solve it again, or give another out",
            source=str(out),
        )
    return run(study, out, workers=workers, resume=resume, scheduler=scheduler, progress=progress)


def clear_cases(out) -> int:
    """Delete the case results in ``out`` (a study run again from the start: ``--overwrite``); their
    count."""
    store = CaseStore(out)
    have = store.existing()
    if have:
        with StudyLock(out):
            for case_id in have:
                (store.dir / f"{case_id}.json").unlink(missing_ok=True)
    return len(have)


def run(
    study: Study,
    out_dir,
    *,
    workers: int | None = 0,
    resume: bool = False,
    scheduler=None,
    progress=None,
) -> StudyResult:
    """Run ``study`` into ``out_dir`` (:func:`axisopt.study.run.run_study`) and return its
    result."""
    if scheduler is not None:
        workers = None
    summary = run_study(
        study, out_dir, workers=workers, scheduler=scheduler, resume=resume, progress=progress
    )
    return StudyResult(study, str(out_dir), summary)


__all__ = ["StudyResult", "clear_cases", "run", "run_spec"]
