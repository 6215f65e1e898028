"""axisopt in a notebook: the commands as functions that return result objects.

>>> import axisopt
>>> ev = axisopt.evaluate("problems/teaching_design.yaml")       # an Evaluation
>>> ev                                                           # one line in N/um, Hz, N.m, EUR
>>> ev.to_frame()                                                # stiffness and frequency over the stroke
>>> ev.check_table()                                             # available / needed / unit / margin
>>> res = axisopt.solve("problems/teaching_problem.yaml")        # a SolveResult
>>> res.to_frame()                                               # best design and runners-up
>>> fig = axisopt.plot_profiles([ev])                            # a matplotlib Figure (a file only with path=)

Each function takes a file path or the object it would read (a Design, a Problem, a Study); each
result has ``to_frame()`` (pandas, units in the column names), a short ``repr`` in engineering units
and an HTML table for Jupyter.  ``import axisopt`` imports none of this until a name is used
(``axisopt.__getattr__``).  Bad input raises :class:`axisopt.errors.InputError` (file and key in the
message), as the command line reports.
"""  # noqa: E501

from __future__ import annotations

import time
from os import PathLike

from .design import Design, load_design
from .problem import Problem, load_problem

__all__ = [
    "load_design",
    "load_problem",
    "evaluate",
    "solve",
    "compare",
    "study",
    "diagnose",
    "plot_profiles",
    "plot_pareto",
]


def _design(design) -> Design:
    return design if isinstance(design, Design) else load_design(design)


def evaluate(
    design: Design | str | PathLike,
    *,
    calibration: str | PathLike | None = None,
    n_positions: int | None = None,
):
    """Evaluate a design (a :class:`Design` or a design YAML path) over the stroke ->
    :class:`Evaluation`.

    calibration : a calibration YAML saved by ``diagnose`` (as
        ``axisopt evaluate DESIGN --calibration FILE`` takes it)
    n_positions : nut positions on the stroke (default: the model grid the search uses)
    """
    from .model import evaluate as _evaluate

    d = _design(design)
    if calibration is not None:
        from .identify.calibration import apply_calibration

        d = apply_calibration(d, calibration)
    return _evaluate(d, n_positions)


def solve(
    problem: Problem | str | PathLike,
    method: str = "default",
    *,
    top: int = 5,
    time_limit: float = 100.0,
    sensitivities: bool = True,
):
    """Solve a sizing problem (a :class:`Problem` or a problem YAML path) -> :class:`SolveResult`.

    method : 'default' (proven optimum) | 'exhaustive' | 'bonmin' | 'scip'; ``top`` designs
        returned; ``sensitivities`` re-solves with each limit relaxed by 10 % (``res.binding``).
    ``res.best.design`` is the best :class:`Design` (``evaluate`` it for the full evaluation).  A
    problem with ``search.drive_types`` returns the drive types' answer
    (:class:`axisopt.search.drivetype.DriveTypeResult`, method 'default' or 'exhaustive'); so does
    one without, when a rack-and-pinion or linear-motor design the catalogs offer by default beats
    the screw drive (:mod:`axisopt.search.drivedefault`).
    """
    from .search import solve as _solve

    p = problem if isinstance(problem, Problem) else load_problem(problem)
    if p.drives is not None:
        from .search.drivetype import solve_drive_types

        return solve_drive_types(p, method, top=top, time_limit=time_limit)
    started = time.perf_counter()
    res = _solve(p, method, top=top, time_limit=time_limit, sensitivities=sensitivities)
    if res.pareto is None:  # the drive types the catalogs offer by default (search.drivedefault)
        from .search.drivedefault import offer

        other = offer(p, res, method, top=top, deadline=started + time_limit).result
        if other is not None:
            return other
    return res


def compare(*files, method: str = "default", time_limit: float = 100.0):
    """Designs side by side -> :class:`axisopt.report.compare.Comparison`.  Each argument is a
    design or problem YAML path (a problem is solved to its best design, within ``time_limit``
    seconds) or a :class:`Design`."""
    from .report.compare import Comparison
    from .study.compare import compare_designs

    return Comparison(compare_designs(files, method=method, time_limit=time_limit))


def study(
    spec,
    out: str | PathLike | None = None,
    *,
    workers: int | None = 0,
    resume: bool = False,
    overwrite: bool = False,
    scheduler=None,
    time_limit: float = 100.0,
):
    """Run a trade study (a study YAML path or a loaded :class:`Study`) -> :class:`StudyResult` (its
    ``to_frame()`` is the results table, one row per case).

    out       : output directory (default ``<study file stem>-results`` as on the command line)
    workers   : local worker processes; 0 (the default here) solves in this process, None uses every
                core
    resume    : continue a run in ``out`` (its finished cases are kept)
    overwrite : solve every case again (the case results in ``out`` are deleted first); a re-run
                with neither is an error that names both
    time_limit: [s] of each case's solve (the study command's --time-limit option)

    ``axisopt.study`` is also the package :mod:`axisopt.study`; the package is callable with these
    arguments, so ``axisopt.study(spec)`` works before and after the package is imported.
    """
    from .study.result import run_spec

    return run_spec(
        spec,
        out,
        workers=workers,
        resume=resume,
        overwrite=overwrite,
        scheduler=scheduler,
        time_limit=time_limit,
    )


def diagnose(
    data,
    design: Design | str | PathLike,
    *,
    effects=None,
    max_effects: int = 3,
    gain: str | None = None,
):
    """Diagnose measured data of an axis -> :class:`axisopt.identify.Diagnosis` (time records:
    ``TimeDiagnosis``).

    data    : a measured CSV path or a list of them (a first file with a ``time`` column is a time
              record)
    design  : the measured axis's design (a :class:`Design` or a design YAML path)
    effects : only consider these effect names (default: the whole library)
    gain    : time records with a current column: torque or force per ampere, e.g. '0.85 N.m/A'
    """
    from .errors import InputError
    from .identify import plant_from_design

    paths = [data] if isinstance(data, (str, PathLike)) else list(data)
    if not paths:
        raise InputError("diagnose needs at least one measured data file")
    names = list(effects) if effects is not None else None
    plant = plant_from_design(_design(design))
    from .identify.records.record import is_time_record

    if is_time_record(paths[0]):
        from .identify.records.idim import diagnose_time_files

        return diagnose_time_files(
            paths, plant=plant, gain=gain, candidates=names, max_effects=max_effects
        )
    from .identify import diagnose as _diagnose
    from .identify import read_dataset
    from .identify.effects import library

    if names:
        unknown = [n for n in names if n not in library()]
        if unknown:
            raise InputError(
                f"effects: unknown effect '{unknown[0]}'; known: {', '.join(library())}"
            )
    if max_effects < 0:
        raise InputError("max_effects must not be negative")
    return _diagnose(
        [read_dataset(p) for p in paths], plant, candidates=names, max_effects=max_effects
    )


def plot_profiles(evaluations, path: str | PathLike | None = None, *, labels=None, limits=None):
    """Stiffness and first natural frequency over the stroke (and the duty cycle against the motor
    limits) of one :class:`Evaluation` or a list -> matplotlib Figure; written to ``path`` only when
    given."""
    from .report.plots import plot_profiles as _plot

    evs = [evaluations] if not isinstance(evaluations, (list, tuple)) else list(evaluations)
    return _plot(evs, None if path is None else str(path), labels=labels, limits=limits)


def plot_pareto(front, path: str | PathLike | None = None):
    """Scatter matrix of a Pareto front (a :class:`ParetoFront` or a :class:`SolveResult` that has
    one) -> matplotlib Figure; written to ``path`` only when given."""
    from .report.solve import plot_pareto as _plot

    front = getattr(front, "pareto", None) or front
    return _plot(front, None if path is None else str(path))
