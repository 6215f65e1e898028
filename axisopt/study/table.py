"""The study's results: one table row per case (CSV and Parquet), summary plots, a Markdown report.

The table is always assembled from the case files (``DIR/cases/*.json``), so it is the same whether
the study ran in one go, was resumed, or ran on a Dask cluster.  Columns: ``case_id``, ``index``,
the swept inputs (a quantity sweep becomes a number column with its unit in the name, e.g.
``axis.stroke [mm]``; a list value such as a set of mountings is joined with ``+``), ``status``,
``reason``, the objective, the chosen parts and preload, the design's minima over the stroke and
where they occur, cost, masses, drag torque, life, the certificate, and the solve time.
"""

from __future__ import annotations

import re

from ..search.reported import REPORTED
from .store import CaseStore

_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")

RESULT_COLUMNS = (
    ("objective", ("objective", "value")),
    ("objective_unit", ("objective", "unit")),
    ("mounting", ("best", "mounting")),
    ("screw", ("best", "screw")),
    ("nut", ("best", "nut")),
    ("bearing", ("best", "bearing")),
    ("guide", ("best", "guide")),
    ("motor", ("best", "motor")),
    ("coupling", ("best", "coupling")),
    ("reduction", ("best", "reduction")),
    ("nut_preload [N]", ("best", "nut_preload")),
    # the values a result reports of its best design (search.result.REPORTED), each with its profile
    # columns
    *((col, key) for r in REPORTED for col, key in ((r.column, ("best", r.field)), *r.profile)),
    ("peak_torque [N.m]", ("drive", "peak_torque_Nm")),
    ("rms_torque [N.m]", ("drive", "rms_torque_Nm")),
    ("motor_speed [rpm]", ("drive", "motor_speed_rpm")),
    ("inertia_ratio", ("drive", "inertia_ratio")),
    ("proven", ("certificate", "proven")),
    ("gap", ("certificate", "gap")),
    ("combinations", ("certificate", "combinations")),
    ("feasible", ("certificate", "feasible")),
    ("nlps", ("certificate", "nlps")),
)
TIME_COLUMNS = ("solve_time [s]", "worker")  # differ between runs of the same study
CSV_FLOAT = "%.10g"  # ten significant digits: no float noise (999.9999999999999) in the CSV files


def check_columns() -> list:
    """(column, check, field) for each check of the chosen design: margin, available and needed in
    the vendor unit (e.g. ``critical_speed available [rpm]``); empty where the check does not
    apply."""
    from ..model import CHECKS
    from ..model.limits import CHECK_RECORDS

    out = []
    for c in CHECKS:
        unit = CHECK_RECORDS[c].unit
        u = f" [{unit}]" if unit else ""
        out += [
            (f"{c} margin", c, "margin"),
            (f"{c} available{u}", c, "available"),
            (f"{c} needed{u}", c, "needed"),
        ]
    return out


def input_columns(study) -> dict:
    """sweep key -> (column name, converter) so that quantity sweeps become numeric columns."""
    out = {}
    for s in study.sweeps:
        units = set()
        numeric = True
        for v in s.values:
            if isinstance(v, bool) or isinstance(v, (list, dict)):
                numeric = False
                break
            if isinstance(v, (int, float)):
                units.add("")
                continue
            m = _QTY.match(str(v))
            if not m:
                numeric = False
                break
            units.add(m.group(2))
        if numeric and len(units) == 1:
            unit = units.pop()
            name = f"{s.key} [{unit}]" if unit else s.key
            out[s.key] = (name, as_number)
        else:
            out[s.key] = (s.key, as_text)
    return out


def as_number(v):
    if isinstance(v, (int, float)):
        return float(v)
    return float(_QTY.match(str(v)).group(1))


def as_text(v):
    if isinstance(v, list):
        return "+".join(as_text(x) for x in v)
    if isinstance(v, dict):
        return ", ".join(f"{k}={as_text(x)}" for k, x in v.items())
    return str(v)


# a study whose cases choose among drive types (search.drive_types): the best design's type and the
# part slots of the rack-and-pinion and linear-motor types, beside the screw's
DRIVE_PART_COLUMNS = ("rack", "twin_pinion", "linear_motor", "forcers")


def drive_columns(recs) -> tuple:
    """((column, best key), ...) of the drive type and its parts, and ((column, margin), ...) of the
    rack-and-pinion and linear-motor designs' margins, when any record holds such a design
    (else empty: a screw study's table keeps its columns)."""
    if not any("drive_type" in (r.get("best") or {}) for r in recs):
        return [], []
    parts = [("drive_type", "drive_type")] + [(k, k) for k in DRIVE_PART_COLUMNS]
    keys = sorted({k for r in recs for k in (r.get("drive_margins") or {})})
    return parts, [(f"drive {k} margin", k) for k in keys]


def records(study, out_dir) -> list:
    """The case records of the study's current cases that are present, in case order."""
    store = CaseStore(out_dir)
    out = []
    for c in study.cases:
        r = store.read(c.case_id)
        if r is not None:
            out.append(r)
    return out


def results_table(study, out_dir):
    """pandas DataFrame, one row per finished case."""
    import pandas as pd

    cols = input_columns(study)
    chk = check_columns()
    recs = records(study, out_dir)
    drive_cols, margin_cols = drive_columns(recs)
    rows = []
    for r in recs:
        row = {"case_id": r["case_id"], "index": r["index"]}
        for key, (name, conv) in cols.items():
            row[name] = conv(r["inputs"].get(key))
        row["status"] = r["status"]
        row["reason"] = r.get("reason", "")
        for name, (a, b) in RESULT_COLUMNS:
            row[name] = (r.get(a) or {}).get(b)
        checks = r.get("checks") or {}
        for name, c, f in chk:
            row[name] = (checks.get(c) or {}).get(f)
        for name, key in drive_cols:
            row[name] = (r.get("best") or {}).get(key)
        for name, key in margin_cols:
            row[name] = (r.get("drive_margins") or {}).get(key)
        pareto = r.get("pareto")
        row["pareto_points"] = len(pareto["points"]) if pareto else None
        row["solve_time [s]"] = r.get("time_s")
        row["worker"] = r.get("worker", "")
        rows.append(row)
    columns = (
        ["case_id", "index"]
        + [n for n, _ in cols.values()]
        + ["status", "reason"]
        + [n for n, _ in RESULT_COLUMNS]
        + [n for n, _, _ in chk]
        + [n for n, _ in drive_cols + margin_cols]
        + ["pareto_points"]
        + list(TIME_COLUMNS)
    )
    df = pd.DataFrame(rows, columns=columns)
    for n in [n for n, _ in RESULT_COLUMNS] + [n for n, _, _ in chk]:
        if df[n].dropna().map(
            lambda x: isinstance(x, (int, float)) and not isinstance(x, bool)
        ).all() and n not in ("proven",):
            df[n] = pd.to_numeric(df[n], errors="coerce")
    df["proven"] = df["proven"].astype("boolean")
    df["pareto_points"] = df["pareto_points"].astype("Int64")
    return df


# ------------------------------------------------------------------------------------------- plots


def case_label(rec, cols) -> str:
    return ", ".join(
        f"{k.split('.')[-1]}={as_text(rec['inputs'][k])}" for k in cols if k in rec["inputs"]
    )


def slug(key: str) -> str:
    return re.sub(r"[^A-Za-z0-9]+", "_", key).strip("_")


# ------------------------------------------------------------------------------------------ report


__all__ = ["results_table", "records", "input_columns"]
