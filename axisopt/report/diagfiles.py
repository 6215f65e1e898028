"""The files a table diagnosis writes (:func:`write_report`: text, JSON, the residual figures) and
its residual figures against each factor, the factors' display names and categories.  Nothing here
prints."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..fileio import tidy_layout
from ..identify.tables.diagnose import split_by_observation as _split
from ..identify.tables.measure import Y_UNIT
from . import save_figure, write_text_atomic
from .diagnosis import diagnosis_dict

# SI factor -> (display unit, scale, offset) for residual plots
FACTOR_DISPLAY = {
    "position": ("mm", 1e3, 0.0),
    "force": ("N", 1.0, 0.0),
    "velocity": ("mm/s", 1e3, 0.0),
    "speed": ("mm/s", 1e3, 0.0),
    "time": ("s", 1.0, 0.0),
    "temperature": ("degC", 1.0, -273.15),
    "frequency": ("Hz", 1.0, 0.0),
    "normal_load": ("N", 1.0, 0.0),
    "axial_load": ("N", 1.0, 0.0),
}


CATEGORICAL = {"direction": {-1.0: "-1", 1.0: "+1"}, "cycle": {}, "mode": {}, "exclude": {}}


def categories(name: str, values) -> list | None:
    """[(value, tick label), ...] when a factor is categorical (direction, cycle, mode, or at most
    three distinct values), else None (plotted on a continuous axis)."""
    u = np.unique(np.asarray(values, dtype=float))
    if name not in CATEGORICAL and len(u) > 3:
        return None
    names = CATEGORICAL.get(name, {})
    return [(float(x), names.get(float(x), f"{x:g}")) for x in u]


def residual_figures(diag, verdict: str):
    """Per observation of ``diag``: (observation, matplotlib Figure of its residuals, model -
    measured, against each recorded factor, before (baseline) and after (with ``verdict``)); a
    category factor one tick each."""
    from ..figure import (
        Figure,  # outside pyplot: no backend is chosen (a notebook's stays as it was)
    )

    before = _split(diag.obs, diag.baseline.prediction - diag.y)
    after = _split(diag.obs, diag.final.prediction - diag.y)
    for o, rb, ra in zip(diag.obs, before, after):
        facs = [(n, v) for n, v in o.factors.items() if np.ptp(v) > 0] or [("row", np.arange(o.n))]
        unit, f = Y_UNIT[o.kind]
        fig = Figure(figsize=(3.6 * len(facs), 3.2))
        axes = fig.subplots(1, len(facs), squeeze=False)
        for ax, (name, v) in zip(axes[0], facs):
            fu, fs, fo = FACTOR_DISPLAY.get(name, ("", 1.0, 0.0))
            v = np.asarray(v) * fs + fo
            cats = categories(name, v)
            if cats is None:
                ax.plot(v, rb * f, ".", ms=3, alpha=0.6, label="baseline")
                ax.plot(v, ra * f, ".", ms=3, alpha=0.8, label=f"with {verdict}")
            # a category per tick, baseline left and extended model right of it, points spread
            else:
                jit = np.random.default_rng(0).uniform(-0.08, 0.08, len(v))
                pos = np.searchsorted([c for c, _ in cats], v).astype(float)
                ax.plot(pos - 0.18 + jit, rb * f, ".", ms=3, alpha=0.6, label="baseline")
                ax.plot(pos + 0.18 + jit, ra * f, ".", ms=3, alpha=0.8, label=f"with {verdict}")
                ax.set_xticks(range(len(cats)), [lab for _, lab in cats])
                ax.set_xlim(-0.6, len(cats) - 0.4)
            ax.axhline(0.0, color="k", lw=0.5)
            ax.set_xlabel(f"{name} [{fu}]" if fu else name)
            ax.set_ylabel(f"model - measured [{unit}]")
        axes[0][0].legend(fontsize=7)
        tidy_layout(fig)
        yield o, fig


def write_report(diag, outdir) -> Path:
    """Markdown report with residual plots before/after; returns the report path."""
    from . import make_output_dir

    out = make_output_dir(outdir)
    d = diagnosis_dict(diag)
    md = [f"# Diagnosis of {d['design']}", "", f"**Verdict: {d['verdict']}**", ""]
    for a in d["accepted"]:
        md.append(
            f"- **{a['effect']}** — {a['finding']}. "
            + "; ".join(f"{p['name']} = {p['text']}" for p in a["parameters"])
            + f". dBIC {a['dBIC']:.1f}, held-out gain {a['gain_percent']:.0f} %"
            + (
                f", beat {a['runner_up']['effect']} by {a['runner_up']['margin']:.1f} BIC"
                if a["runner_up"]
                else ""
            )
        )
        md += [f"  - check: {f}" for f in a["plausibility"]]
    md += ["", "## Data", ""]
    for ds in d["datasets"]:
        md.append(
            f"- `{ds['file']}` ({ds['test']}): {ds['rows']} rows, noise floor "
            f"{ds['noise_floor']:.3g} {ds['unit']}; cross-validation leaves one {ds['cv_groups']} "
            "out"
        )
        md += [f"  - excluded line {e['line']}: {e['reason']}" for e in ds["excluded_rows"]]
    md += ["", "## Baseline fit", "", "| parameter | value |", "|---|---|"]
    md += [f"| {p['name']} | {p['text']} |" for p in d["baseline"]["parameters"]]
    md += [f"\ncheck: {f}" for f in d["baseline"]["plausibility"]]
    md += ["", "## Where the baseline misfits", ""]
    for ds, rows in zip(d["datasets"], d["residuals_baseline"]):
        md += [
            f"`{Path(ds['file']).name}`",
            "",
            "| factor | share of residual variance | worst level | rms there |",
            "|---|---|---|---|",
        ]
        md += [
            f"| {r['factor']} | {100 * r['eta2']:.1f} % | {r['worst_level']} "
            f"| {r['worst_rms']:.3g} {r['unit']} |"
            for r in rows
        ]
        md.append("")
    md += ["## Candidates", ""]
    for i, rnd in enumerate(d["candidates"], start=1):
        md += [
            f"Round {i}",
            "",
            "| effect | dBIC | held-out gain | parameters |",
            "|---|---|---|---|",
        ]
        for c in rnd:
            g = f"{c['cv_gain_percent']:.0f} %" if c["cv_gain_percent"] is not None else "-"
            md.append(
                f"| {c['effect']} | {c['dBIC']:.1f} | {g} | "
                + "; ".join(f"{p['name']} = {p['text']}" for p in c["parameters"])
                + " |"
            )
        md.append("")
    md += ["## Gain", "", "| data | held-out RMSE before | after | gain |", "|---|---|---|---|"]
    md += [
        f"| {Path(h['file']).name} | {h['baseline']:.4g} {h['unit']} | {h['final']:.4g} "
        f"{h['unit']} | {h['gain_percent']:.0f} % |"
        for h in d["holdout_rmse_units"]
    ]
    md += [
        "",
        f"Gain {d['gain_percent']:.0f} % (grouped cross-validation, noise-weighted RMSE "
        f"{d['holdout_rmse_baseline']:.3g} -> {d['holdout_rmse_final']:.3g}; about 1 is the noise "
        "floor).",
        "",
    ]
    md += ["## What the final fit leaves", ""]
    for u in d["unexplained"]:
        name = Path(u["file"]).name
        if u["remaining"]:
            md.append(
                f"- `{name}`: **unexplained** structure (RMS {u['rms_over_noise']:.2g}x the noise "
                "floor)"
            )
            md += [
                f"  - residual {sg['signature']}: {100 * sg['share']:.0f} % of the residual "
                f"variance. Candidates: {sg['causes']}. To separate them: {sg['to_separate']}."
                for sg in u["signatures"]
            ]
        else:
            md.append(
                f"- `{name}`: RMS {u['rms_over_noise']:.2g}x the noise floor, no structure along a "
                "recorded factor"
            )
    md += ["", "## Residual plots", ""]
    for k, (o, fig) in enumerate(residual_figures(diag, d["verdict"])):
        png = out / f"residuals_{k + 1}.png"
        save_figure(fig, png, dpi=90)
        md += [f"![residuals {Path(o.dataset.source).name}]({png.name})", ""]
    path = out / "report.md"
    write_text_atomic(path, "\n".join(md) + "\n", what="report")
    return path
