"""One case of a study solved into its record (a plain dict, saved as ``DIR/cases/<case_id>.json``).

:func:`solve_case` builds the case's problem, solves it and records the status, the reason of a
failure, the best design, where its minima lie, its drive values and check margins and the
certificate; it never raises for a case-level failure.  The record holds data only: the table, plots
and report are made from it (:mod:`.table`).
"""

from __future__ import annotations

import math
import os
import socket
import threading
import time

from ..errors import InputError
from .cases import Case, build_problem, short_message
from .store import OK_STATUSES, RECORD_VERSION

# failures of the machinery, not of the case: not a result, solved again by a resumed run
INFRA_STATUSES = ("worker_died",)
# how versions before worker_died recorded a case whose worker died twice (status "error")
LEGACY_WORKER_DIED = "worker process died twice while solving this case"
# A solve is not thread-safe (per-process CasADi solver caches): a Dask worker with several threads
# runs its cases one at a time.
_SOLVE_LOCK = threading.Lock()


def solve_case(context: dict, case: Case) -> dict:
    """Build and solve one case; never raises for a case-level failure (the reason is recorded).  A
    machine study's case (``context['kind'] == 'machine'``) is a joint machine solve
    (:mod:`.machinecase`)."""
    if context.get("kind") == "machine":
        from .machinecase import build_machine, machine_record, solve_machine_case

        with _SOLVE_LOCK:
            return record_case(
                case,
                lambda: build_machine(context, case),
                lambda machine: solve_machine_case(context, machine),
                machine_record,
            )
    return record_case(
        case, lambda: build_problem(context, case), lambda p: _solve(context, p), _axis_record
    )


def record_case(case: Case, build, solve, fill) -> dict:
    """One case's record: ``build()`` (an InputError is the case's input_error), ``solve(built)``
    (any exception is the case's error: a failure is this case's result, not the end of the study),
    then ``fill(rec, built, solved)`` records the answer; the time taken last."""
    t0 = time.perf_counter()
    rec = {
        "version": RECORD_VERSION,
        "case_id": case.case_id,
        "index": case.index,
        "inputs": {k: v for k, v in case.overrides},
        "status": "",
        "reason": "",
        "worker": f"{socket.gethostname()}:{os.getpid()}",
    }
    try:
        built = build()
    except InputError as exc:
        status, reason = "input_error", short_message(exc)
    else:
        try:
            solved = solve(built)
        except InputError as exc:  # a problem the solve refuses (a drive type it cannot take)
            status, reason = "input_error", short_message(exc)
        except Exception as exc:  # a solver failure is a result of this case
            status, reason = "error", f"{type(exc).__name__}: {exc}"
        else:
            fill(rec, built, solved)
            rec["time_s"] = time.perf_counter() - t0
            return rec
    rec.update(status=status, reason=reason.replace("\n", " "), time_s=time.perf_counter() - t0)
    return rec


def _solve(context: dict, problem) -> tuple:
    """The case's solve and its best design's evaluation (None without one); a problem with
    search.drive_types solved over its types (the evaluation None)."""
    from ..model import evaluate
    from ..search import solve

    if problem.drives is not None:
        from ..search.drivetype import solve_drive_types

        with _SOLVE_LOCK:
            res = solve_drive_types(
                problem, context["method"], top=1, time_limit=context.get("time_limit", 100.0)
            )
        return res, None
    with _SOLVE_LOCK:
        res = solve(
            problem,
            context["method"],
            top=1,
            sensitivities=False,
            time_limit=context.get("time_limit", 100.0),
        )
        # on numpy: the CasADi Function of a case's duty cycle would be built for this one
        # evaluation
        ev = (
            evaluate(res.best.design, use_casadi=False)
            if res.best is not None and res.best.design is not None
            else None
        )
    return res, ev


def _axis_record(rec: dict, problem, solved: tuple) -> None:
    """An axis case's answer into its record: status, objective, the reason of a failure, the best
    design, where its minima lie, its drive values and check margins, the certificate."""
    from ..model.function import check_rows, drive_dict

    res, ev = solved
    if problem.drives is not None:
        _drive_types_record(rec, res)
        return
    rec["status"] = res.status
    rec["objective"] = {
        "label": res.objective_label,
        "unit": res.objective_unit,
        "value": _num(res.objective),
    }
    reason = res.message
    if res.infeasibility is not None:  # the misses that decide first, the notes after
        reason = res.infeasibility.deciding(most=len(res.infeasibility.unmeetable) or 3) + (
            f"; {reason}" if reason else ""
        )
    rec["reason"] = reason if res.status not in OK_STATUSES else ""
    rec["note"] = res.message if res.status in OK_STATUSES else ""
    if res.best is not None:
        best = res.best.to_dict()
        best.pop("misses", None)
        rec["best"] = best
    if ev is not None:
        k, kpos = ev.minimum("k_total")
        f, fpos = ev.minimum("f1")
        rec["profile"] = {
            "min_stiffness_position_mm": kpos * 1e3,
            "min_frequency_position_mm": fpos * 1e3,
            "weakest_link": ev.weakest,
            "all_checks_pass": bool(min(ev.checks().values()) >= 1.0),
        }
        drv = drive_dict(ev)
        if drv is not None:  # the motor's needs and its torque margins
            rec["drive"] = {
                k: (_num(float(v)) if isinstance(v, (int, float)) else v) for k, v in drv.items()
            }
        rec["checks"] = {
            r["check"]: {k: r[k] for k in ("available", "needed", "unit", "margin", "pass")}
            for r in check_rows(ev)
        }
    c = res.certificate
    rec["certificate"] = {
        "proven": bool(c.proven),
        "gap": _num(c.gap),
        "combinations": int(c.combinations),
        "feasible": None if c.feasible is None else int(c.feasible),
        "pruned_by_bound": int(c.pruned_by_bound),
        "exact_evaluations": int(c.exact_evaluations),
        "nlps": int(c.nlps_solved),
        "nlp_failures": int(c.nlp_failures),
    }
    if res.pareto is not None:
        rec["pareto"] = res.pareto.to_dict()


def _drive_types_record(rec: dict, res) -> None:
    """A case of a problem with search.drive_types (solved by search.drivetype.solve_drive_types)
    into its
    record: the best design of any type with its drive type, parts, the values every type has
    (objective, least stiffness, first frequency, cost, moving mass) and its margins; a screw design
    also with its checks as a screw case records them."""
    best = res.best
    rec["status"] = res.status
    rec["objective"] = {
        "label": res.objective_label,
        "unit": res.objective_unit,
        "value": None if best is None else _num(best.objective),
    }
    rec["reason"] = "" if best is not None else (res.change or "no design of any drive type fits")
    rec["note"] = "; ".join(res.notes) if best is not None else ""
    if best is not None:
        if best.drive_type == "screw":
            b = best.candidate.to_dict()
            b.pop("misses", None)
        else:
            b = {
                **{k: (int(v) if k == "forcers" else v) for k, v in best.parts.items()},
                "objective": _num(best.objective),
                "min_stiffness": _num(best.stiffness),
                "min_frequency": _num(best.frequency),
                "cost": _num(best.cost),
                "moving_mass": _num(best.moving_mass),
            }
            rec["drive_margins"] = {k: _num(float(v)) for k, v in best.margins.items()}
        rec["best"] = {"drive_type": best.drive_type, **b}
    rec["certificate"] = {
        "proven": res.status == "optimal",
        "gap": 0.0 if res.status == "optimal" else None,
        "combinations": int(sum(t.combinations for t in res.types)),
        "feasible": None
        if any(t.feasible is None for t in res.types)
        else int(sum(t.feasible for t in res.types)),
    }


def run_batch(context: dict, cases) -> list:
    """Solve several cases (one task of a pool or Dask cluster)."""
    return [solve_case(context, c) for c in cases]


def _num(v):
    return float(v) if v is not None and math.isfinite(v) else None


__all__ = ["solve_case", "record_case", "run_batch", "INFRA_STATUSES", "LEGACY_WORKER_DIED"]
