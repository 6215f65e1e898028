"""Machine studies: a base machine file and sweeps over any of its keys, each case a joint machine
solve, run by the axis study's runner (the same case store, lock, resume, local pool and Dask
back-ends, :mod:`.run`).

.. code-block:: yaml

    name: vmc-masses
    base: ../machines/vmc_machine.yaml   # a machine YAML (relative to this file)
    method: default                      # default | exhaustive (the joint search's method)
    combine: product                     # product | zip, as in an axis study
    sweep:                               # dotted paths into the machine YAML
      axes.Z.problem.axis.moving_mass: {from: 300 kg, to: 500 kg, steps: 5}
      machine.limits.min_frequency: [50 Hz, 60 Hz]

The sweeps are an axis study's (:mod:`.spec`: lists, ranges, seeded random samples, zip or product),
the case ids the same hash of the base and the inputs, so a changed base never reuses a stale
result.  Each case's record (``DIR/cases/<case_id>.json``, written atomically as it finishes) holds
the joint optimum, the sequential sizing beside it and the stiffness chain at the tool;
``DIR/machines.csv`` is the table of every case in case order, made from the records only, so it is
the same whatever ran them (one process, N local workers, a Dask cluster).
"""

from __future__ import annotations

import csv
import json
from dataclasses import dataclass, replace
from pathlib import Path

from ..errors import InputError
from ..machine.spec import DIRECTIONS
from ..yamlio import Key, Section, Spec, read_yaml
from .cases import Case, Study, expand, short_message
from .machinecase import build_machine, solve_machine_case
from .spec import COMBINE, SWEEP_SPEC, read_sweep
from .store import CaseStore, refuse_inputs_in

METHODS = ("default", "exhaustive")
TABLE = "machines.csv"

MACHINE_STUDY_SPEC = Spec(
    "machine study",
    "a machine study: a base machine and sweeps over its keys",
    {
        "name": Key("string", "the study's name (default: the file name)"),
        "description": Key("string", "free text"),
        "base": Key(
            "string",
            "path of a machine YAML (top-level 'axes:'), relative to this file",
            required=True,
        ),
        "method": Key(
            "choice", "the joint search's method for every case", choices=METHODS, default="default"
        ),
        "combine": Key(
            "choice",
            "product: every combination; zip: the n-th value of each key",
            choices=COMBINE,
            default="product",
        ),
        "sweep": Key(
            "section",
            "the swept keys: dotted paths into the machine YAML (e.g. "
            "axes.Z.problem.axis.moving_mass)",
            required=True,
            spec=SWEEP_SPEC,
        ),
    },
)


@dataclass(frozen=True)
class MachineStudy(Study):
    """A study whose base is a machine file: its cases are machine solves
    (:func:`solve_machine_case`)."""

    def context(self) -> dict:
        return {**super().context(), "kind": "machine"}


def load_machine_study(path) -> MachineStudy:
    """Read a machine study YAML with its expanded cases; the base and each distinct swept value are
    read at once, so a typo or a bad value is one InputError naming the study key."""
    path = Path(path)
    src = str(path)
    root = Section(read_yaml(path), src, spec=MACHINE_STUDY_SPEC)
    name = root.read("name", path.stem)
    description = root.read("description", "") or ""
    method, combine = root.read("method"), root.read("combine")
    rel = root.read("base")
    bpath = path.parent / rel
    if not bpath.is_file():
        raise root.error("base", f"base machine '{rel}' not found (relative to the study file)")
    base = read_yaml(bpath)
    if not (isinstance(base.value, dict) and "axes" in base.value):
        raise root.error(
            "base",
            f"'{rel}' is not a machine file (no top-level 'axes:'); an axis problem's "
            "study is `axisopt study`",
        )
    sweep_sec = root.read("sweep")
    sweeps = tuple(read_sweep(sweep_sec, k) for k in sweep_sec.keys())
    if not sweeps:
        raise root.error("sweep", "list at least one key to sweep")
    root.done()
    study = MachineStudy(
        name=name,
        description=description,
        source=src,
        base=base,
        base_source=str(bpath),
        base_dir=str(bpath.parent),
        method=method,
        combine=combine,
        sweeps=sweeps,
    )
    study = replace(study, cases=expand(study, sweep_sec))
    _check(study, root)
    return study


def _check(study: MachineStudy, root: Section) -> None:
    ctx = study.context()
    try:
        build_machine(ctx, Case("base", -1, ()))
    except InputError as exc:
        raise InputError(
            f"base machine: {exc}", source=study.source, where=root.where("base")
        ) from None
    for s in study.sweeps:
        for v in s.checked:
            try:
                build_machine(ctx, Case("check", -1, ((s.key, v),)))
            except InputError as exc:
                raise InputError(
                    f"sweep '{s.key}' value {json.dumps(v, default=str)}: {short_message(exc)}",
                    source=study.source,
                    where=f"line {s.line}",
                ) from None


def table_rows(study: MachineStudy, out) -> list:
    """One row per case in case order (from the records only; a missing case has status
    'missing')."""
    store = CaseStore(out)
    rows = []
    for c in study.cases:
        rec = store.read(c.case_id) or {"status": "missing", "inputs": c.inputs(), "reason": ""}
        row = {
            "case_id": c.case_id,
            **{k: json.dumps(v) if isinstance(v, (list, dict)) else v for k, v in c.overrides},
            "status": rec["status"],
        }
        best = rec.get("best")
        obj = rec.get("objective") or {}
        row[f"objective [{obj.get('unit', '')}]"] = _g(obj.get("value"))
        if best:
            row["cost [EUR]"] = _g(best["cost_eur"])
            for d in DIRECTIONS:
                row[f"k_{d} [N/um]"] = _g(best["k_tool_n_per_um"][d])
            for d in DIRECTIONS:
                w = best["most_compliant"][d]
                row[f"softest {d}"] = f"{w['axis']} {w['part']}"
            row["f1 [Hz]"] = _g(best["lowest_frequency_hz"])
            row["Dunkerley [Hz]"] = _g(best["dunkerley_hz"])
            row["moving [kg]"] = _g(best["moving_mass_kg"])
            for a in best["axes"]:
                for part in ("screw", "guide", "motor"):
                    row[f"{a['name']} {part}"] = a.get(part) or "-"
        seq = rec.get("sequential")
        row["sequential [EUR]"] = _g(seq["cost_eur"]) if seq else ""
        row["sequential feasible"] = "" if not seq else ("yes" if seq["feasible"] else "no")
        row["gain"] = _g(rec.get("gain"))
        row["reason"] = rec.get("reason", "")
        rows.append(row)
    return rows


def _g(v) -> str:
    return "" if v is None else f"{v:.6g}"


def write_table(study: MachineStudy, out) -> Path:
    """``DIR/machines.csv``: every case's row (:func:`table_rows`), written atomically."""
    import io

    from ..fileio import write_text_atomic

    rows = table_rows(study, out)
    cols: list = []
    for r in rows:
        cols += [k for k in r if k not in cols]
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=cols, restval="", lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    path = Path(out) / TABLE
    write_text_atomic(path, buf.getvalue(), what="machine study table")
    return path


def run_machine_study(
    study: MachineStudy,
    out_dir,
    *,
    workers: int | None = None,
    scheduler=None,
    resume: bool = False,
    progress=None,
    batch: int | None = None,
):
    """Run every case not yet in ``out_dir`` (:func:`.run.run_study`: resumable, streamed to disk,
    local pool or Dask) and write the table; the :class:`.run.RunSummary`."""
    from .run import run_study

    refuse_inputs_in(out_dir, [study.source, study.base_source], ("study.json", TABLE))
    summary = run_study(
        study,
        out_dir,
        workers=workers,
        scheduler=scheduler,
        resume=resume,
        progress=progress,
        batch=batch,
        report=False,
    )
    summary.files = {"table": str(write_table(study, out_dir))}
    return summary


__all__ = [
    "MachineStudy",
    "MACHINE_STUDY_SPEC",
    "load_machine_study",
    "build_machine",
    "solve_machine_case",
    "run_machine_study",
    "table_rows",
    "write_table",
]
