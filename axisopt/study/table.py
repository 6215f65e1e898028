"""The study's results: one table row per case (CSV and Parquet), summary plots, a Markdown report.

The table is always assembled from the case files (``DIR/cases/*.json``), so it is the same whether
the study ran in one go, was resumed, or ran on a Dask cluster.  Columns: ``case_id``, ``index``, the
swept inputs (a quantity sweep becomes a number column with its unit in the name, e.g.
``axis.stroke [mm]``; a list value such as a set of mountings is joined with ``+``), ``status``,
``reason``, the objective, the chosen parts and preload, the design's minima over the stroke and where
they occur, cost, masses, drag torque, life, the certificate, and the solve time.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from ..fileio import (
    atomic_file,
    csv_safe,
    make_output_dir,
    save_figure,
    tidy_layout,
    write_text_atomic,
)
from ..model.goals import GOALS
from ..search.reported import REPORTED
from .store import OK_STATUSES, CaseStore

_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")

RESULT_COLUMNS = (
    ("objective", ("objective", "value")), ("objective_unit", ("objective", "unit")),
    ("mounting", ("best", "mounting")), ("screw", ("best", "screw")), ("nut", ("best", "nut")),
    ("bearing", ("best", "bearing")), ("guide", ("best", "guide")),
    ("motor", ("best", "motor")), ("coupling", ("best", "coupling")), ("reduction", ("best", "reduction")),
    ("nut_preload [N]", ("best", "nut_preload")),
    # the values a result reports of its best design (search.result.REPORTED), each with its profile columns
    *((col, key) for r in REPORTED for col, key in ((r.column, ("best", r.field)), *r.profile)),
    ("peak_torque [N.m]", ("drive", "peak_torque_Nm")), ("rms_torque [N.m]", ("drive", "rms_torque_Nm")),
    ("motor_speed [rpm]", ("drive", "motor_speed_rpm")), ("inertia_ratio", ("drive", "inertia_ratio")),
    ("proven", ("certificate", "proven")), ("gap", ("certificate", "gap")),
    ("combinations", ("certificate", "combinations")), ("feasible", ("certificate", "feasible")),
    ("nlps", ("certificate", "nlps")),
)
TIME_COLUMNS = ("solve_time [s]", "worker")  # differ between runs of the same study
CSV_FLOAT = "%.10g"  # ten significant digits: no float noise (999.9999999999999) in the CSV files


def check_columns() -> list:
    """(column, check, field) for each check of the chosen design: margin, available and needed in the
    vendor unit (e.g. ``critical_speed available [rpm]``); empty where the check does not apply."""
    from ..model import CHECKS
    from ..model.limits import CHECK_RECORDS

    out = []
    for c in CHECKS:
        unit = CHECK_RECORDS[c].unit
        u = f" [{unit}]" if unit else ""
        out += [(f"{c} margin", c, "margin"), (f"{c} available{u}", c, "available"),
                (f"{c} needed{u}", c, "needed")]
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
            out[s.key] = (name, _number)
        else:
            out[s.key] = (s.key, _text)
    return out


def _number(v):
    if isinstance(v, (int, float)):
        return float(v)
    return float(_QTY.match(str(v)).group(1))


def _text(v):
    if isinstance(v, list):
        return "+".join(_text(x) for x in v)
    if isinstance(v, dict):
        return ", ".join(f"{k}={_text(x)}" for k, x in v.items())
    return str(v)


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
    rows = []
    for r in records(study, out_dir):
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
        pareto = r.get("pareto")
        row["pareto_points"] = len(pareto["points"]) if pareto else None
        row["solve_time [s]"] = r.get("time_s")
        row["worker"] = r.get("worker", "")
        rows.append(row)
    columns = ["case_id", "index"] + [n for n, _ in cols.values()] + ["status", "reason"] \
        + [n for n, _ in RESULT_COLUMNS] + [n for n, _, _ in chk] + ["pareto_points"] \
        + list(TIME_COLUMNS)
    df = pd.DataFrame(rows, columns=columns)
    for n in [n for n, _ in RESULT_COLUMNS] + [n for n, _, _ in chk]:
        if df[n].dropna().map(lambda x: isinstance(x, (int, float)) and not isinstance(x, bool)).all() \
                and n not in ("proven",):
            df[n] = pd.to_numeric(df[n], errors="coerce")
    df["proven"] = df["proven"].astype("boolean")
    df["pareto_points"] = df["pareto_points"].astype("Int64")
    return df


def write_outputs(study, out_dir, summary=None) -> dict:
    """Write ``results.csv``, ``results.parquet`` (when pyarrow is installed), the plots and
    ``report.md`` into ``out_dir``; returns {name: path}.

    Each file is replaced atomically (:func:`axisopt.report.atomic_file`): a run stopped or out of disk
    space while writing leaves the previous file whole.  A file that cannot be written is an InputError
    naming it."""
    out = Path(out_dir)
    df = results_table(study, out)
    files = {}
    files["csv"] = str(out / "results.csv")
    with atomic_file(files["csv"], "w", what="results table") as fh:
        csv_safe(df).to_csv(fh, index=False, float_format=CSV_FLOAT)  # text cells escaped (CSV injection)
    try:
        import pyarrow  # noqa: F401
    except ImportError:
        parquet_note = "Parquet not written: install pyarrow (pip install 'axisopt[parquet]')"
    else:
        files["parquet"] = str(out / "results.parquet")
        with atomic_file(files["parquet"], "wb", what="results table") as fh:
            df.to_parquet(fh, index=False)
        parquet_note = ""
    plots = summary_plots(study, df, out / "plots", out)
    files.update(plots)
    files["report"] = str(out / "report.md")
    write_text_atomic(files["report"], markdown_report(study, df, files, summary, parquet_note), what="report")
    return files


# ------------------------------------------------------------------------------------------- plots

def _group_column(study, df, cols):
    """The column that separates lines in the summary plots: the first non-numeric swept input,
    else the chosen mounting."""
    for name, conv in cols.values():
        if conv is _text and df[name].nunique() > 1:
            return name
    return "mounting"


MAX_LINES = 10  # lines per plot; with more combinations the lines follow the plain grouping (text input or mounting)


def _line_groups(df, cols, name, fallback):
    """Columns whose combinations make the lines of a plot against swept input ``name``: every other
    swept input (cases that differ in them are different designs questions and are not joined), or the
    fallback grouping when nothing else is swept or the combinations are too many to draw."""
    others = [n for k, (n, _c) in cols.items() if n != name and df[n].nunique() > 1]
    if others and df.groupby(others, dropna=False).ngroups <= MAX_LINES:
        return others
    return [fallback]


def _machine_columns(df, cols) -> list:
    """Swept inputs that change the axis itself (axis.*: stroke, masses, ...): cases that differ in them
    are different machines, so a cost / stiffness staircase is drawn within each, never across."""
    return [n for k, (n, _c) in cols.items() if k.startswith("axis.") and df[n].nunique() > 1]


def _group_label(g, by) -> str:
    """'max_cost = 4000 EUR, mountings = fixed-fixed': each swept input with the unit of its column."""
    g = g if isinstance(g, tuple) else (g,)
    out = []
    for b, v in zip(by, g):
        name, _, unit = b.partition(" [")
        val = f"{v:g}" if isinstance(v, (int, float)) and not isinstance(v, bool) else str(v)
        out.append(f"{name.split('.')[-1]} = {val}" + (f" {unit.rstrip(']')}" if unit else ""))
    return ", ".join(out)


_LINE_STYLES = ("-", "--", "-.", ":")
SHADED_INPUTS = 20  # distinct inputs without a design shaded as bands; more are marked as a rug of ticks
_MARKERS = ("o", "s", "^", "v", "D", "P", "X", "*")


def summary_plots(study, df, plot_dir: Path, out_dir: Path) -> dict:
    """Best minimum stiffness and frequency against each numeric swept input (one line per combination of
    the other swept inputs, infeasible cases marked), and the cost / stiffness trade-off of all cases with
    its non-dominated cases joined within each machine (cases of different axis inputs are not joined)."""
    import matplotlib

    from ..figure import (
        Figure,  # outside pyplot: no backend is chosen (a notebook's stays as it was)
    )

    files = {}
    ok = df[df["status"].isin(OK_STATUSES)]
    bad = df[~df["status"].isin(OK_STATUSES)]
    if ok.empty:
        return files
    make_output_dir(plot_dir)
    cols = input_columns(study)
    group = _group_column(study, ok, cols)
    for key, (name, conv) in cols.items():
        if conv is not _number or df[name].nunique() < 2:
            continue
        by = _line_groups(df, cols, name, group)
        fig = Figure(figsize=(7, 6))
        a1, a2 = fig.subplots(2, 1, sharex=True)
        for j, (g, sub) in enumerate(ok.groupby(by, dropna=False, sort=True)):
            # best over the cases that share this x and this line's inputs; each line its own dash pattern and
            # marker, so lines that coincide stay visible
            k = sub.groupby(name)["min_stiffness [N/um]"].max()
            f = sub.groupby(name)["min_frequency [Hz]"].max()
            style = dict(ls=_LINE_STYLES[j % len(_LINE_STYLES)], marker=_MARKERS[j % len(_MARKERS)] if len(k) < 40
                         else ".", ms=4 + 1.5 * (j % 3), mfc="none", label=_group_label(g, by))
            a1.plot(k.index, k.values, **style)
            a2.plot(f.index, f.values, **style)
        if len(bad):
            # cases without a design have no value to draw: their inputs are shaded, not drawn as zeros (a
            # sweep of many distinct inputs, e.g. random: a rug of ticks along the bottom of the panel, one artist)
            xs = sorted(set(bad[name].dropna()))
            what = f"for {len(bad)} cases ({', '.join(sorted(set(bad['status'])))})"
            short = key.split(".")[-1]
            # with other inputs swept, the mark says where such a case sits, not that this input is the cause
            text = (f"no design at this {short} {what}" if len(cols) == 1 else
                    f"{short} of a case without a design {what}; the cause may be another input (its reason)")
            for ax in (a1, a2):
                if len(xs) > SHADED_INPUTS:
                    ax.plot(xs, [0.0] * len(xs), "|", color="tab:red", ms=10, alpha=0.6,
                            transform=ax.get_xaxis_transform(), label=text)
                    continue
                for i, x in enumerate(xs):
                    ax.axvline(x, color="tab:red", alpha=0.25, lw=4, label=text if i == 0 else None)
        a1.set_ylabel("best min. axial stiffness [N/um]")
        a2.set_ylabel("best min. 1st frequency [Hz]")
        a2.set_xlabel(name.replace(" [", " [", 1))
        for ax in (a1, a2):
            ax.grid(True, alpha=0.3)
        a1.legend(fontsize=7)
        fig.suptitle(f"{study.name}: best design against {key}", fontsize=10)
        tidy_layout(fig)
        fname = plot_dir / f"best_vs_{_slug(key)}.png"
        save_figure(fig, fname, dpi=100)
        files[f"plot {key}"] = str(fname)
    # trade-off over all cases: cost against minimum stiffness, non-dominated cases joined per machine
    pts = ok[["cost [EUR]", "min_stiffness [N/um]"]].dropna()
    if len(pts) >= 2:
        fig = Figure(figsize=(7, 4.5))
        ax = fig.subplots()
        machines = _machine_columns(df, cols)
        by = machines or [group]
        colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
        for i, (g, sub) in enumerate(ok.groupby(by, dropna=False, sort=True)):
            col = colors[i % len(colors)]
            sub = sub[["cost [EUR]", "min_stiffness [N/um]"]].dropna()
            ax.scatter(sub["cost [EUR]"], sub["min_stiffness [N/um]"], s=12, alpha=0.7, color=col,
                       label=_group_label(g, by))
            if machines and len(sub) >= 2:
                front = pareto_mask(sub["cost [EUR]"].to_numpy(), sub["min_stiffness [N/um]"].to_numpy())
                fr = sub[front].sort_values("cost [EUR]")
                ax.step(fr["cost [EUR]"], fr["min_stiffness [N/um]"], "-", color=col, where="post", lw=1)
        if not machines:
            front = pareto_mask(pts["cost [EUR]"].to_numpy(), pts["min_stiffness [N/um]"].to_numpy())
            fr = pts[front].sort_values("cost [EUR]")
            ax.step(fr["cost [EUR]"], fr["min_stiffness [N/um]"], "k-", where="post", lw=1,
                    label="non-dominated cases")
        if len(bad):
            ax.text(0.01, 0.01, f"not shown: {len(bad)} cases without a design", transform=ax.transAxes,
                    fontsize=8, color="tab:red", va="bottom")
        ax.set_xlabel("cost [EUR]")
        ax.set_ylabel("min. axial stiffness [N/um]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, title="non-dominated cases joined per machine" if machines else None,
                  title_fontsize=7)
        ax.set_title(f"{study.name}: stiffness against cost of every case's best design", fontsize=10)
        tidy_layout(fig)
        fname = plot_dir / "tradeoff_cost_stiffness.png"
        save_figure(fig, fname, dpi=100)
        files["plot trade-off"] = str(fname)
    # Pareto fronts of the cases (pareto-mode problems), overlaid on their first two objectives
    fronts = [r for r in records(study, out_dir) if r.get("pareto")]
    if fronts:
        p0 = fronts[0]["pareto"]
        kx, ky = p0["keys"][:2]
        fig = Figure(figsize=(7, 4.5))
        ax = fig.subplots()
        for r in fronts[:12]:
            # each point's objective values in the front's key order (a record written before they were stored:
            # the Candidate field of the goal)
            if not {kx, ky} <= set(r["pareto"]["keys"]):  # a case with other objectives: not on these axes
                continue
            at = [r["pareto"]["keys"].index(k) for k in (kx, ky)]
            vals = [p["objectives"] if "objectives" in p else [p[GOALS[k].field] for k in r["pareto"]["keys"]]
                    for p in r["pareto"]["points"]]
            xs, ys = [v[at[0]] for v in vals], [v[at[1]] for v in vals]
            ax.plot(xs, ys, ".", label=_label(r, cols))
        ax.set_xlabel(f"{kx} [{p0['units'][0]}]")
        ax.set_ylabel(f"{ky} [{p0['units'][1]}]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
        ax.set_title(f"{study.name}: Pareto fronts" + (" (first 12 cases)" if len(fronts) > 12 else ""),
                     fontsize=10)
        tidy_layout(fig)
        fname = plot_dir / "pareto_fronts.png"
        save_figure(fig, fname, dpi=100)
        files["plot Pareto fronts"] = str(fname)
    return files


def _label(rec, cols) -> str:
    return ", ".join(f"{k.split('.')[-1]}={_text(rec['inputs'][k])}" for k in cols if k in rec["inputs"])


def pareto_mask(cost, stiffness):
    """Non-dominated points: lower cost and higher stiffness are better."""
    import numpy as np

    order = np.lexsort((-stiffness, cost))
    mask = np.zeros(len(cost), bool)
    best = -math.inf
    for i in order:
        if stiffness[i] > best:
            mask[i] = True
            best = stiffness[i]
    return mask


def _slug(key: str) -> str:
    return re.sub(r"[^A-Za-z0-9]+", "_", key).strip("_")


# ------------------------------------------------------------------------------------------ report

def markdown_report(study, df, files, summary=None, parquet_note="") -> str:
    out_dir = Path(files["csv"]).parent

    def rel(p):
        return Path(p).relative_to(out_dir).as_posix()

    n = len(study.cases)
    ok = df[df["status"].isin(OK_STATUSES)]
    L = [f"# Study: {study.name}", ""]
    if study.description:
        L += [study.description.strip(), ""]
    L += [f"- study file: `{study.source}`", f"- base problem: `{study.base_source}`",
          f"- method: {study.method}; cases: {n} ({study.combine} of {len(study.sweeps)} swept keys)"]
    if summary is not None:
        L.append(f"- last run: {summary.solved} cases solved in {summary.time:.1f} s on {summary.backend}"
                 + (f" ({summary.workers} workers)" if summary.workers else "")
                 + (f", {summary.resumed} kept from an earlier run" if summary.resumed else ""))
        if summary.lost:
            L.append(f"- **{summary.lost} cases not run** ({summary.lost_reason}); rerun with `--resume`")
    missing = n - len(df)
    L.append(f"- finished: {len(df)} of {n}; solved: {len(ok)}; failed: {len(df) - len(ok)}"
             + (f"; **missing: {missing}** (rerun with `--resume`)" if missing else ""))
    L += ["", "## Sweeps", "", "| key | values | kind |", "|---|---|---|"]
    for s in study.sweeps:
        vals = [_text(v) for v in s.values]
        shown = ", ".join(vals[:6]) + (f", ... ({len(vals)} values)" if len(vals) > 6 else "")
        L.append(f"| `{s.key}` | {shown} | {s.kind} |")
    L += ["", "## Results", "", f"- table: [results.csv]({rel(files['csv'])})"
          + (f", [results.parquet]({rel(files['parquet'])})" if "parquet" in files else f" ({parquet_note})"),
          "- one JSON file per case: `cases/<case_id>.json`", ""]
    counts = df["status"].value_counts()
    if len(counts):
        L += ["| status | cases |", "|---|---|"] + [f"| {s} | {c} |" for s, c in counts.items()] + [""]
    for name, p in files.items():
        if name.startswith("plot"):
            L += [f"### {name[5:]}", "", f"![{name[5:]}]({rel(p)})", ""]
    if not ok.empty:
        unit = ok["objective_unit"].dropna().iloc[0] if ok["objective_unit"].notna().any() else ""
        cols = input_columns(study)
        top = ok.sort_values("objective", ascending=False).head(10)
        L += ["## Best cases", "", "| case | " + " | ".join(n for n, _ in cols.values())
              + f" | objective [{unit}] | mounting | nut | bearing | guide | k [N/um] | f [Hz] | cost [EUR] |",
              "|" + "---|" * (len(cols) + 9)]
        for _, r in top.iterrows():
            L.append(f"| {r['case_id']} | " + " | ".join(_cell(r[n]) for n, _ in cols.values())
                     + f" | {_cell(r['objective'])} | {r['mounting']} | {r['nut']} | {r['bearing']} | {r['guide']}"
                     f" | {_cell(r['min_stiffness [N/um]'])} | {_cell(r['min_frequency [Hz]'])}"
                     f" | {_cell(r['cost [EUR]'], 0)} |")
        L.append("")
        L += ["## Parts chosen", ""]
        for slot in ("mounting", "screw", "nut", "bearing", "guide", "motor", "coupling", "reduction"):
            vc = ok[slot].replace("", None).dropna().value_counts().head(5)
            if slot in ("motor", "coupling", "reduction") and vc.empty:
                continue
            L.append(f"- {slot}: " + ", ".join(f"{k} ({v})" for k, v in vc.items()))
        L.append("")
    bad = df[~df["status"].isin(OK_STATUSES)]
    if not bad.empty:
        L += ["## Failed cases", "", "| case | status | reason |", "|---|---|---|"]
        for _, r in bad.head(50).iterrows():
            L.append(f"| {r['case_id']} | {r['status']} | {str(r['reason']).replace('|', '/')[:300]} |")
        if len(bad) > 50:
            L.append(f"| ... | | {len(bad) - 50} more in the table |")
        L.append("")
    return "\n".join(L)


def _cell(v, nd=1):
    if isinstance(v, float):
        return "-" if not math.isfinite(v) else f"{v:,.{nd}f}"
    return str(v)


__all__ = ["results_table", "write_outputs", "records", "input_columns", "pareto_mask"]
