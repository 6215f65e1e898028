"""One case of a machine study: its machine built from the base YAML tree and the case's values, its
joint solve and what the record (a plain dict, ``DIR/cases/<case_id>.json``) holds of it.  The
runner's :func:`.record.record_case` makes the record around them, as for an axis case."""

from __future__ import annotations

from pathlib import Path

from ..machine.spec import MACHINE_FILE_SPEC, read_machine
from ..yamlio import Section
from .cases import Case, apply_overrides

OBJECTIVE_UNITS = {
    "cost": ("cost", "EUR", 1.0),
    "tool_stiffness": ("least stiffness at the tool", "N/um", 1e-6),
    "frequency": ("lowest natural frequency", "Hz", 1.0),
    "moving_mass": ("moving masses", "kg", 1.0),
}


def build_machine(context: dict, case: Case):
    """The case's :class:`~axisopt.machine.spec.Machine` (InputError if the combination is invalid,
    or if it pins a nut preload: a machine solve chooses them)."""
    from ..machine.joint import refuse_preloads

    tree = apply_overrides(context["base"], case.overrides)
    machine = read_machine(
        Section(tree, context["base_source"], spec=MACHINE_FILE_SPEC), Path(context["base_source"])
    )
    refuse_preloads(machine)
    return machine


def solve_machine_case(context: dict, machine):
    """The case's joint solve (the runner's :func:`.record.record_case` records a failure)."""
    from ..machine import solve_machine

    return solve_machine(machine, context["method"])


def machine_record(rec: dict, machine, res) -> None:
    """A machine case's answer into its record: status, objective, the joint optimum and the
    sequential sizing, the gain and the certificate."""
    from ..machine.record import design_dict

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


__all__ = ["build_machine", "solve_machine_case", "machine_record", "OBJECTIVE_UNITS"]
