"""The summary figures of a study: each result column against each swept input, one line per group
of the other inputs (machines, mountings, text inputs), inputs without a design shaded or marked,
and the cost-stiffness Pareto mask.  Nothing here prints."""

from __future__ import annotations

import math
from pathlib import Path

from ..fileio import (
    make_output_dir,
    save_figure,
    tidy_layout,
)
from ..model.goals import GOALS
from .store import OK_STATUSES
from .table import as_number, as_text, case_label, input_columns, records, slug


def _group_column(study, df, cols):
    """The column that separates lines in the summary plots: the first non-numeric swept input,
    else the chosen mounting."""
    for name, conv in cols.values():
        if conv is as_text and df[name].nunique() > 1:
            return name
    return "mounting"


# lines per plot; with more combinations the lines follow the plain grouping (text input or
# mounting)
MAX_LINES = 10


def _line_groups(df, cols, name, fallback):
    """Columns whose combinations make the lines of a plot against swept input ``name``: every other
    swept input (cases that differ in them are different designs questions and are not joined), or
    the fallback grouping when nothing else is swept or the combinations are too many to draw."""
    others = [n for k, (n, _c) in cols.items() if n != name and df[n].nunique() > 1]
    if others and df.groupby(others, dropna=False).ngroups <= MAX_LINES:
        return others
    return [fallback]


def _machine_columns(df, cols) -> list:
    """Swept inputs that change the axis itself (axis.*: stroke, masses, ...): cases that differ in
    them are different machines, so a cost / stiffness staircase is drawn within each, never
    across."""
    return [n for k, (n, _c) in cols.items() if k.startswith("axis.") and df[n].nunique() > 1]


def _group_label(g, by) -> str:
    """'max_cost = 4000 EUR, mountings = fixed-fixed': each swept input with the unit of its
    column."""
    g = g if isinstance(g, tuple) else (g,)
    out = []
    for b, v in zip(by, g):
        name, _, unit = b.partition(" [")
        val = f"{v:g}" if isinstance(v, (int, float)) and not isinstance(v, bool) else str(v)
        out.append(f"{name.split('.')[-1]} = {val}" + (f" {unit.rstrip(']')}" if unit else ""))
    return ", ".join(out)


_LINE_STYLES = ("-", "--", "-.", ":")


# distinct inputs without a design shaded as bands; more are marked as a rug of ticks
SHADED_INPUTS = 20


_MARKERS = ("o", "s", "^", "v", "D", "P", "X", "*")


def summary_plots(study, df, plot_dir: Path, out_dir: Path) -> dict:
    """Best minimum stiffness and frequency against each numeric swept input (one line per
    combination of the other swept inputs, infeasible cases marked), and the cost / stiffness
    trade-off of all cases with its non-dominated cases joined within each machine (cases of
    different axis inputs are not joined)."""
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
        if conv is not as_number or df[name].nunique() < 2:
            continue
        by = _line_groups(df, cols, name, group)
        fig = Figure(figsize=(7, 6))
        a1, a2 = fig.subplots(2, 1, sharex=True)
        for j, (g, sub) in enumerate(ok.groupby(by, dropna=False, sort=True)):
            # best over the cases that share this x and this line's inputs; each line its own dash
            # pattern and marker, so lines that coincide stay visible
            k = sub.groupby(name)["min_stiffness [N/um]"].max()
            f = sub.groupby(name)["min_frequency [Hz]"].max()
            style = dict(
                ls=_LINE_STYLES[j % len(_LINE_STYLES)],
                marker=_MARKERS[j % len(_MARKERS)] if len(k) < 40 else ".",
                ms=4 + 1.5 * (j % 3),
                mfc="none",
                label=_group_label(g, by),
            )
            a1.plot(k.index, k.values, **style)
            a2.plot(f.index, f.values, **style)
        if len(bad):
            # cases without a design have no value to draw: their inputs are shaded, not drawn as
            # zeros (a sweep of many distinct inputs, e.g. random: a rug of ticks along the bottom
            # of the panel, one artist)
            xs = sorted(set(bad[name].dropna()))
            what = f"for {len(bad)} cases ({', '.join(sorted(set(bad['status'])))})"
            short = key.split(".")[-1]
            # with other inputs swept, the mark says where such a case sits, not that this input is
            # the cause
            text = (
                f"no design at this {short} {what}"
                if len(cols) == 1
                else f"{short} of a case without a design {what}; the cause may be another input "
                "(its reason)"
            )
            for ax in (a1, a2):
                if len(xs) > SHADED_INPUTS:
                    ax.plot(
                        xs,
                        [0.0] * len(xs),
                        "|",
                        color="tab:red",
                        ms=10,
                        alpha=0.6,
                        transform=ax.get_xaxis_transform(),
                        label=text,
                    )
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
        fname = plot_dir / f"best_vs_{slug(key)}.png"
        save_figure(fig, fname, dpi=100)
        files[f"plot {key}"] = str(fname)
    # trade-off over all cases: cost against minimum stiffness, non-dominated cases joined per
    # machine
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
            ax.scatter(
                sub["cost [EUR]"],
                sub["min_stiffness [N/um]"],
                s=12,
                alpha=0.7,
                color=col,
                label=_group_label(g, by),
            )
            if machines and len(sub) >= 2:
                front = pareto_mask(
                    sub["cost [EUR]"].to_numpy(), sub["min_stiffness [N/um]"].to_numpy()
                )
                fr = sub[front].sort_values("cost [EUR]")
                ax.step(
                    fr["cost [EUR]"], fr["min_stiffness [N/um]"], "-", color=col, where="post", lw=1
                )
        if not machines:
            front = pareto_mask(
                pts["cost [EUR]"].to_numpy(), pts["min_stiffness [N/um]"].to_numpy()
            )
            fr = pts[front].sort_values("cost [EUR]")
            ax.step(
                fr["cost [EUR]"],
                fr["min_stiffness [N/um]"],
                "k-",
                where="post",
                lw=1,
                label="non-dominated cases",
            )
        if len(bad):
            ax.text(
                0.01,
                0.01,
                f"not shown: {len(bad)} cases without a design",
                transform=ax.transAxes,
                fontsize=8,
                color="tab:red",
                va="bottom",
            )
        ax.set_xlabel("cost [EUR]")
        ax.set_ylabel("min. axial stiffness [N/um]")
        ax.grid(True, alpha=0.3)
        ax.legend(
            fontsize=7,
            title="non-dominated cases joined per machine" if machines else None,
            title_fontsize=7,
        )
        ax.set_title(
            f"{study.name}: stiffness against cost of every case's best design", fontsize=10
        )
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
            # each point's objective values in the front's key order (a record written before they
            # were stored: the Candidate field of the goal) a case with other objectives: not on
            # these axes
            if not {kx, ky} <= set(r["pareto"]["keys"]):
                continue
            at = [r["pareto"]["keys"].index(k) for k in (kx, ky)]
            vals = [
                p["objectives"]
                if "objectives" in p
                else [p[GOALS[k].field] for k in r["pareto"]["keys"]]
                for p in r["pareto"]["points"]
            ]
            xs, ys = [v[at[0]] for v in vals], [v[at[1]] for v in vals]
            ax.plot(xs, ys, ".", label=case_label(r, cols))
        ax.set_xlabel(f"{kx} [{p0['units'][0]}]")
        ax.set_ylabel(f"{ky} [{p0['units'][1]}]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
        ax.set_title(
            f"{study.name}: Pareto fronts" + (" (first 12 cases)" if len(fronts) > 12 else ""),
            fontsize=10,
        )
        tidy_layout(fig)
        fname = plot_dir / "pareto_fronts.png"
        save_figure(fig, fname, dpi=100)
        files["plot Pareto fronts"] = str(fname)
    return files


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
