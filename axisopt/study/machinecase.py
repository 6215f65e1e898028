"""One case of a machine study: its machine built from the base YAML tree and the case's values, and its joint
solve recorded as a plain dict (``DIR/cases/<case_id>.json``; the runner's :func:`.record.solve_case` calls it
for a machine study's context)."""

from __future__ import annotations

import os
import socket
import time
from pathlib import Path

from ..errors import InputError
from ..machine.spec import MACHINE_FILE_SPEC, read_machine
from ..yamlio import Section
from .cases import Case, apply_overrides, short_message
from .store import RECORD_VERSION

OBJECTIVE_UNITS = {
    "cost": ("cost", "EUR", 1.0),
    "tool_stiffness": ("least stiffness at the tool", "N/um", 1e-6),
    "frequency": ("lowest natural frequency", "Hz", 1.0),
    "moving_mass": ("moving masses", "kg", 1.0),
}


def build_machine(context: dict, case: Case):
    """The case's :class:`~axisopt.machine.spec.Machine` (InputError if the combination is invalid)."""
    tree = apply_overrides(context["base"], case.overrides)
    return read_machine(
        Section(tree, context["base_source"], spec=MACHINE_FILE_SPEC), Path(context["base_source"])
    )


def solve_machine_case(context: dict, case: Case) -> dict:
    """Build and solve one machine case into its record; never raises for a case-level failure."""
    from ..machine import solve_machine
    from ..machine.record import design_dict

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
        machine = build_machine(context, case)
    except InputError as exc:
        rec.update(
            status="input_error",
            reason=short_message(exc).replace("\n", " "),
            time_s=time.perf_counter() - t0,
        )
        return rec
    try:
        res = solve_machine(machine, context["method"])
    except Exception as exc:  # a failure is this case's result, not the end of the study
        rec.update(
            status="error",
            reason=f"{type(exc).__name__}: {exc}".replace("\n", " "),
            time_s=time.perf_counter() - t0,
        )
        return rec
    label, unit, f = OBJECTIVE_UNITS[machine.objective]
    rec["status"] = res.status
    rec["objective"] = {
        "label": label,
        "unit": unit,
        "value": None if res.best is None else res.best.value(machine.objective) * f,
    }
    if res.best is None:
        rec["reason"] = "no combination of the axes' designs meets every machine and axis limit"
    else:
        rec["best"] = design_dict(res.best)
    if res.sequential is not None:
        rec["sequential"] = design_dict(res.sequential)
    rec["gain"] = None if res.gain is None else res.gain * f
    rec["certificate"] = {
        "proven": True,
        "combinations": res.nominal_combinations,
        "axis_solves": res.axis_solves,
        "offers_kept": dict(res.offers),
    }
    rec["note"] = "; ".join(res.notes)
    rec["time_s"] = time.perf_counter() - t0
    return rec


__all__ = ["build_machine", "solve_machine_case", "OBJECTIVE_UNITS"]
