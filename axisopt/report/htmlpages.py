"""The HTML pages of the commands that report more than one design or a diagnosis: a solve (its best
design, the runners-up and the Pareto front), designs side by side, a study and a table diagnosis;
each built from :mod:`.html`'s ``Page``, tables and figures."""

from __future__ import annotations

import math

from ..search.reported import REPORTED_BY_FIELD
from ..search.result import OPTIMAL
from ..study.store import OK_STATUSES
from ..units import N_PER_UM
from . import interactive as ifig  # plotly itself is imported only when a figure is drawn
from .html import MARGIN_KEY, Page, checks_table, margin_class, parts_table, pre, table


def solve_page(res, problem, text: str, interactive: bool = False) -> Page:
    """A solve: status and certificate first, the best design's profile (with the runners-up) or the
    Pareto front as a scatter matrix, the checks of the best design, and the printed result."""
    from ..model import evaluate
    from . import static
    from .plots import distinct_labels, plot_profiles
    from .solve import plot_pareto

    page = Page(
        f"Sizing: {res.problem}",
        f"{res.objective_label}; method {res.method}",
        interactive=interactive,
    )
    page.card("status", res.status, "ok" if res.status == OPTIMAL else "bad")
    page.card(
        "proven", "yes" if res.certificate.proven else "no", "ok" if res.certificate.proven else ""
    )
    page.card("combinations", f"{res.certificate.combinations:,}")
    page.card("time", f"{res.time:.2f} s")
    if res.pareto is not None:
        page.card("Pareto points", str(len(res.pareto.points)))
        page.figure(
            "Pareto front",
            lambda: ifig.pareto_figure(res.pareto),
            lambda: plot_pareto(res.pareto),
            560,
        )
        page.section(f"Every point of the front ({len(res.pareto.points)})").append(
            pareto_table(res.pareto)
        )
    elif res.best is not None and res.best.design is not None:
        page.card("objective", f"{res.best.objective:,.3f} {res.objective_unit}")
        cands = [res.best] + list(res.runners_up)
        parts = [{"mounting": c.mounting, **c.parts()} for c in cands]
        labels = (
            distinct_labels(parts, [f"#{c.rank}" for c in cands]) if len(cands) > 1 else ["best"]
        )
        evs = [evaluate(c.design) for c in cands]
        limits = {k: v for k, v in problem.limits if k in ("min_stiffness", "min_frequency")}
        page.figure(
            "Best designs over the stroke"
            + (
                "; drive against the motor"
                if evs[0].design.motor is not None and not interactive
                else ""
            ),
            lambda: ifig.profiles_figure(evs, labels, limits),
            lambda: plot_profiles(evs, labels=labels, limits=limits, margins=problem.margin_map),
        )
        # the winning design as the evaluate report shows it: its stiffness chain, drive and FRF
        best = evs[0]
        page.figure(
            "Stiffness chain of the best design",
            lambda: ifig.chain_figure(best),
            lambda: static.chain_figure(best),
            300,
        )
        if interactive and best.design.motor is not None:
            page.figure(
                "Drive of the best design: duty cycle against the motor",
                lambda: ifig.drive_figure(best),
                None,
                460,
            )
        page.figure(
            "Dynamic compliance of the best design's table (FRF)",
            lambda: ifig.frf_figure(best),
            lambda: static.frf_figure(best),
            560,
        )
        page.section("Checks of the best design").append(checks_table(evs[0], problem.margin_map))
        page.section("Parts of the best design to order").append(
            parts_table(evs[0].design, problem)
        )
    page.section("Result (as printed)").append(pre(text))
    return page


def pareto_table(front) -> str:
    """Every point of a Pareto front: its objective values and its parts."""
    from ..search.pareto import FIELD

    head = (
        ["#"]
        + [f"{k.replace('_', ' ')} [{u}]" if u else k for k, u in zip(front.keys, front.units)]
        + ["mounting", "parts: screw / nut / bearing / guide / motor ...", "preload [N]"]
    )
    rows = []
    for i, pt in enumerate(front.points, start=1):
        rows.append(
            [str(i)]
            + [f"{float(getattr(pt, FIELD[k])):,.4g}" for k in front.keys]
            + [pt.mounting, list(pt.parts().values()), f"{pt.nut_preload:,.0f}"]
        )
    return table(head, rows)


def compare_page(items, text: str, interactive: bool = False) -> Page:
    from .checktext import judged_rows
    from .drivetype import LABELS
    from .plots import distinct_labels, plot_profiles

    page = Page("Comparison", ", ".join(c.label for c in items), interactive=interactive)
    evs = [c.evaluation for c in items if c.evaluation is not None]
    head = [
        "design",
        "min stiffness [N/um]",
        "min 1st frequency [Hz]",
        "drag [N.m]",
        "total mass [kg]",
        "cost [EUR]",
        "motor",
        "least margin",
        "failed checks",
    ]
    rows, classes = [], []

    def judged(label, stiffness, frequency, drag, mass, cost, motor, least, failed, kind=""):
        """One design's card and its row of the side-by-side table (values in display units)."""
        page.card(
            label,
            kind
            + f"{stiffness:,.1f} N/um, {frequency:,.1f} Hz"
            + (f"; FAILS {', '.join(failed)}" if failed else ""),
            "bad" if failed else "ok",
        )
        rows.append(
            [label, f"{stiffness:,.1f}", f"{frequency:,.1f}", drag, mass, f"{cost:,.0f}", motor]
            + ["n/a" if least is None else f"{least:.2f}", ", ".join(failed) or "none"]
        )
        classes.append(
            ["wrap"] + [""] * 6 + [margin_class(least, not failed), "bad wrap" if failed else "ok"]
        )

    for c in items:
        e = c.evaluation
        if e is None and getattr(c, "drive", None) is not None:  # a rack or linear-motor design
            d = c.drive
            failed = [k for k, v in d.margins.items() if v < 1.0]
            least = min(d.margins.values()) if d.margins else None
            motor = str(d.parts.get("motor", d.parts.get("linear_motor", "-")))
            kind = f"{LABELS[d.drive_type]}: "
            judged(c.label, d.stiffness, d.frequency, "-", "-", d.cost, motor, least, failed, kind)
            continue
        if e is None:
            page.card(c.label, c.solve["status"] if c.solve else "-", "bad")
            rows.append(
                [c.label] + ["-"] * 7 + [f"no design ({c.solve['status'] if c.solve else '-'})"]
            )
            classes.append(["wrap"] + [""] * 7 + ["bad wrap"])
            continue
        checks = judged_rows(e, c.margins)  # a solved problem's checks against its limits.margins
        failed = [r["check"] for r in checks if not r["pass"]]
        margins = [r["margin"] for r in checks if r["margin"] is not None]
        motor = str(e.design.motor["id"]) if e.design.motor is not None else "no drive"
        judged(
            c.label,
            e.minimum("k_total")[0] / N_PER_UM,
            e.minimum("f1")[0],
            f"{float(e['drag_torque']):.3f}",
            f"{float(e['total_mass']):,.1f}",
            float(e["cost"]),
            motor,
            min(margins) if margins else None,
            failed,
        )
    page.section("Side by side").append(table(head, rows, classes=classes) + MARGIN_KEY)
    if evs:
        labels = [c.label for c in items if c.evaluation is not None]
        parts = [{"mounting": e.design.axis.mounting, **e.design.part_ids()} for e in evs]
        if len(set(labels)) < len(labels):
            labels = distinct_labels(parts)
        page.figure(
            "Stiffness and frequency over the stroke",
            lambda: ifig.profiles_figure(evs, labels),
            lambda: plot_profiles(evs, labels=labels),
        )
    page.section("Side by side (as printed)").append(pre(text))
    return page


def study_page(study, df, text: str, interactive: bool = False) -> Page:
    """A study: counts by status, the objective against each numeric swept input, the results
    table."""
    import pandas as pd

    from ..study.table import input_columns
    from .static import objective_figure

    page = Page(f"Trade study: {study.name}", f"{len(df)} cases", interactive=interactive)
    for status, n in df["status"].value_counts().items():
        page.card(str(status), str(int(n)), "ok" if status == OPTIMAL else "bad")
    unit = df["objective_unit"].dropna().iloc[0] if df["objective_unit"].notna().any() else ""
    for key, (name, _) in input_columns(study).items():
        if name not in df or not pd.api.types.is_numeric_dtype(df[name]):
            continue
        ok = df["status"] == OPTIMAL
        page.figure(
            f"Objective against {key}",
            lambda n=name, k=key, o=ok: ifig.objective_figure(df, n, k, unit, o),
            lambda n=name, k=key, o=ok: objective_figure(df, n, k, unit, o),
            380,
        )
    slots = [c for c in ("screw", "nut", "bearing", "guide", "motor", "coupling") if c in df]
    shown = [
        c
        for c in (
            "case_id",
            *[n for n, _ in input_columns(study).values()],
            "status",
            "reason",
            "objective",
            "parts",
            *(REPORTED_BY_FIELD[f].column for f in ("min_stiffness", "min_frequency", "cost")),
        )
        if c in df or c == "parts" and slots
    ]
    sub = df.head(200)
    # the parts in one column (each id unbroken, wrapping between ids): a 1280 px window shows every
    # column
    rows = [
        [
            [str(x) for x in r[slots] if isinstance(x, str) and x] or "-"
            if c == "parts"
            else _cell(r[c])
            for c in shown
        ]
        for _, r in sub.iterrows()
    ]
    classes = [
        [
            "wrap" if c == "reason" else ("bad" if c == "status" and st not in OK_STATUSES else "")
            for c in shown
        ]
        for st in sub["status"]
    ]
    head = [f"parts: {' / '.join(slots)}" if c == "parts" else c for c in shown]
    page.section("Cases" + (" (first 200; all in results.csv)" if len(df) > 200 else "")).append(
        table(head, rows, classes=classes)
    )
    # no image links
    summary = "\n".join(ln for ln in text.splitlines() if not ln.lstrip().startswith("!["))
    page.section("Summary (as written to report.md, figures above)").append(pre(summary))
    return page


def diagnose_page(diag, text: str, interactive: bool = False) -> Page:
    """A diagnosis: the verdict first (an effect named and confirmed on held-out data is the
    diagnosis's
    success: green, never red), then residuals against each factor before and after, and the
    text."""
    from ..identify.tables.diagnose import split_by_observation as _split
    from .diagfiles import residual_figures
    from .diagnosis import diagnosis_dict

    d = diagnosis_dict(diag)
    page = Page(
        f"Diagnosis: {d['design']}", "what the model gets wrong and why", interactive=interactive
    )
    page.card("verdict", d["verdict"], "ok" if d["accepted"] else "")
    page.card("held-out gain", f"{d['gain_percent']:.0f} %")
    for a in d["accepted"]:
        page.card(a["effect"], "; ".join(p["text"] for p in a["parameters"]) or a["finding"])
    before = _split(diag.obs, diag.baseline.prediction - diag.y)
    after = _split(diag.obs, diag.final.prediction - diag.y)
    static = residual_figures(diag, d["verdict"]) if not interactive else None
    for o, rb, ra in zip(diag.obs, before, after):
        name = str(o.dataset.source).replace("\\", "/").rsplit("/", 1)[-1]
        page.figure(
            f"Residuals: {name}",
            lambda o=o, rb=rb, ra=ra: ifig.residuals_figure(o, rb, ra, d["verdict"]),
            lambda: next(static)[1],
            360,
        )
    page.section("Diagnosis (as printed)").append(pre(text))
    return page


def _cell(v) -> str:
    if isinstance(v, float):
        return "-" if not math.isfinite(v) else f"{v:,.4g}"
    return str(v)
