"""A study's output files: the results table as CSV (and Parquet), the summary figures and the
Markdown report that lists them (:func:`write_outputs`).  Nothing here prints."""

from __future__ import annotations

import math
from pathlib import Path

from ..fileio import (
    atomic_file,
    csv_safe,
    write_text_atomic,
)
from .plots import (
    summary_plots,
)
from .store import OK_STATUSES
from .table import (
    CSV_FLOAT,
    as_text,
    input_columns,
    results_table,
)


def write_outputs(study, out_dir, summary=None) -> dict:
    """Write ``results.csv``, ``results.parquet`` (when pyarrow is installed), the plots and
    ``report.md`` into ``out_dir``; returns {name: path}.

    Each file is replaced atomically (:func:`axisopt.report.atomic_file`): a run stopped or out of
    disk space while writing leaves the previous file whole.  A file that cannot be written is an
    InputError naming it."""
    out = Path(out_dir)
    df = results_table(study, out)
    files = {}
    files["csv"] = str(out / "results.csv")
    with atomic_file(files["csv"], "w", what="results table") as fh:
        # text cells escaped (CSV injection)
        csv_safe(df).to_csv(fh, index=False, float_format=CSV_FLOAT)
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
    write_text_atomic(
        files["report"], markdown_report(study, df, files, summary, parquet_note), what="report"
    )
    return files


def markdown_report(study, df, files, summary=None, parquet_note="") -> str:
    out_dir = Path(files["csv"]).parent

    def rel(p):
        return Path(p).relative_to(out_dir).as_posix()

    n = len(study.cases)
    ok = df[df["status"].isin(OK_STATUSES)]
    L = [f"# Study: {study.name}", ""]
    if study.description:
        L += [study.description.strip(), ""]
    L += [
        f"- study file: `{study.source}`",
        f"- base problem: `{study.base_source}`",
        f"- method: {study.method}; cases: {n} ({study.combine} of {len(study.sweeps)} swept keys)",
    ]
    if summary is not None:
        L.append(
            f"- last run: {summary.solved} cases solved in {summary.time:.1f} s on "
            f"{summary.backend}"
            + (f" ({summary.workers} workers)" if summary.workers else "")
            + (f", {summary.resumed} kept from an earlier run" if summary.resumed else "")
        )
        if summary.lost:
            L.append(
                f"- **{summary.lost} cases not run** ({summary.lost_reason}); rerun with `--resume`"
            )
    missing = n - len(df)
    L.append(
        f"- finished: {len(df)} of {n}; solved: {len(ok)}; failed: {len(df) - len(ok)}"
        + (f"; **missing: {missing}** (rerun with `--resume`)" if missing else "")
    )
    L += ["", "## Sweeps", "", "| key | values | kind |", "|---|---|---|"]
    for s in study.sweeps:
        vals = [as_text(v) for v in s.values]
        shown = ", ".join(vals[:6]) + (f", ... ({len(vals)} values)" if len(vals) > 6 else "")
        L.append(f"| `{s.key}` | {shown} | {s.kind} |")
    L += [
        "",
        "## Results",
        "",
        f"- table: [results.csv]({rel(files['csv'])})"
        + (
            f", [results.parquet]({rel(files['parquet'])})"
            if "parquet" in files
            else f" ({parquet_note})"
        ),
        "- one JSON file per case: `cases/<case_id>.json`",
        "",
    ]
    counts = df["status"].value_counts()
    if len(counts):
        L += (
            ["| status | cases |", "|---|---|"]
            + [f"| {s} | {c} |" for s, c in counts.items()]
            + [""]
        )
    for name, p in files.items():
        if name.startswith("plot"):
            L += [f"### {name[5:]}", "", f"![{name[5:]}]({rel(p)})", ""]
    if not ok.empty:
        unit = ok["objective_unit"].dropna().iloc[0] if ok["objective_unit"].notna().any() else ""
        cols = input_columns(study)
        top = ok.sort_values("objective", ascending=False).head(10)
        # a study over drive types (search.drive_types): each case's drive type, and a rack or
        # linear motor where the screw's nut and bearing are
        types = "drive_type" in ok.columns
        L += [
            "## Best cases",
            "",
            "| case | "
            + " | ".join(n for n, _ in cols.values())
            + f" | objective [{unit}] | "
            + ("drive | rack or linear motor | " if types else "")
            + "mounting | nut | bearing | guide | k [N/um] | f [Hz] | cost [EUR] |",
            "|" + "---|" * (len(cols) + 9 + 2 * types),
        ]
        for _, r in top.iterrows():
            drive = (
                f"{_cell(r['drive_type'])} | "
                f"{_cell(r['rack'] if _given(r['rack']) else r['linear_motor'])} | "
                if types
                else ""
            )
            L.append(
                f"| {r['case_id']} | "
                + " | ".join(_cell(r[n]) for n, _ in cols.values())
                + f" | {_cell(r['objective'])} | {drive}{_cell(r['mounting'])} | {_cell(r['nut'])}"
                f" | {_cell(r['bearing'])} | {_cell(r['guide'])}"
                f" | {_cell(r['min_stiffness [N/um]'])} | {_cell(r['min_frequency [Hz]'])}"
                f" | {_cell(r['cost [EUR]'], 0)} |"
            )
        L.append("")
        L += ["## Parts chosen", ""]
        for slot in (
            "mounting",
            "screw",
            "nut",
            "bearing",
            "guide",
            "motor",
            "coupling",
            "reduction",
            "rack",
            "linear_motor",
        ):
            if slot not in ok.columns:
                continue
            vc = ok[slot].replace("", None).dropna().value_counts().head(5)
            if vc.empty and (
                types or slot in ("motor", "coupling", "reduction", "rack", "linear_motor")
            ):
                continue
            L.append(f"- {slot}: " + ", ".join(f"{k} ({v})" for k, v in vc.items()))
        L.append("")
    bad = df[~df["status"].isin(OK_STATUSES)]
    if not bad.empty:
        L += ["## Failed cases", "", "| case | status | reason |", "|---|---|---|"]
        for _, r in bad.head(50).iterrows():
            L.append(
                f"| {r['case_id']} | {r['status']} | {str(r['reason']).replace('|', '/')[:300]} |"
            )
        if len(bad) > 50:
            L.append(f"| ... | | {len(bad) - 50} more in the table |")
        L.append("")
    return "\n".join(L)


def _given(v) -> bool:
    """Whether a table cell holds a value (not empty, None or NaN)."""
    return not (v is None or v == "" or (isinstance(v, float) and not math.isfinite(v)))


def _cell(v, nd=1):
    if isinstance(v, float):
        return "-" if not math.isfinite(v) else f"{v:,.{nd}f}"
    return str(v)
