"""HTML pages of rack-and-pinion and linear-motor answers: a solve over drive types
(``axisopt solve --report``) and one saved drive design (``axisopt evaluate --report``): cards of
the best design, a table of the designs with their parts and what every drive type has, each
design's margins coloured by how close they are to failing, the margins figure (:mod:`.driveplot`)
and the text answer."""

from __future__ import annotations

from .drivetype import LABELS, MARGIN_LABELS
from .html import MARGIN_KEY, Page, margin_class, pre, table
from .static import svg


def _designs_table(designs, unit: str) -> str:
    head = [
        "#",
        "drive",
        "parts",
        f"objective [{unit}]",
        "stiffness [N/um]",
        "1st frequency [Hz]",
        "cost [EUR]",
        "moving mass [kg]",
        "least margin",
    ]
    rows, classes = [], []
    for i, d in enumerate(designs, start=1):
        least = min(d.margins.values()) if d.margins else None
        rows.append(
            [
                str(i),
                LABELS[d.drive_type],
                ", ".join(f"{k} {v}" for k, v in d.parts.items()),
                f"{d.objective:,.6g}",
                f"{d.stiffness:,.1f}",
                f"{d.frequency:,.1f}",
                f"{d.cost:,.0f}",
                f"{d.moving_mass:,.1f}",
                "n/a" if least is None else f"{least:.2f}",
            ]
        )
        classes.append(["", "", "wrap"] + [""] * 5 + [margin_class(least)])
    return table(head, rows, classes=classes)


def _margins_table(d) -> str:
    rows, states = [], []
    for k, v in sorted(d.margins.items(), key=lambda kv: kv[1]):
        rows.append([MARGIN_LABELS.get(k, k), f"{v:.3f}", "PASS" if v >= 1.0 else "FAIL"])
        states.append("ok" if v >= 1.0 else "bad")
    return table(["check or limit", "margin", ""], rows, states=states) + MARGIN_KEY


def drive_types_page(res, text: str, interactive: bool = False) -> Page:
    """The page of a drive types' answer (:class:`axisopt.search.drivedesigns.DriveTypeResult`)."""
    from .driveplot import plot_drive_designs

    page = Page("Solve over drive types", res.objective_label, interactive=interactive)
    page.card("status", res.status, "ok" if res.best is not None else "bad")
    for t in res.types:
        best = "-" if t.best is None else f"{t.best:,.6g} {res.objective_unit}"
        page.card(LABELS[t.drive_type], f"{t.status}: {best}", "ok" if t.best is not None else "")
    designs = [res.best] + list(res.runners_up) if res.best is not None else list(res.closest)
    heading = "Designs" if res.best is not None else "Closest designs (no design fits)"
    page.section(heading).append(_designs_table(designs, res.objective_unit))
    if designs:
        page.section("Margins of the first design").append(_margins_table(designs[0]))
        fig = plot_drive_designs(res, None, top=len(designs))
        page.section("Margins and objective against cost").append(svg(fig, heading))
    page.section("Answer").append(pre(text))
    return page


def drive_design_page(d, problem, text: str, interactive: bool = False) -> Page:
    """The page of one evaluated rack-and-pinion or linear-motor design."""
    page = Page(f"Design {problem.name}", LABELS[d.drive_type], interactive=interactive)
    failed = [k for k, v in d.margins.items() if v < 1.0]
    page.card(
        "checks", "FAIL: " + ", ".join(failed) if failed else "all pass", "bad" if failed else "ok"
    )
    page.card("stiffness", f"{d.stiffness:,.1f} N/um")
    page.card("1st frequency", f"{d.frequency:,.1f} Hz")
    page.card("cost", f"{d.cost:,.0f} EUR")
    page.section("Design").append(_designs_table([d], "display units"))
    page.section("Checks and limits").append(_margins_table(d))
    page.section("Answer").append(pre(text))
    return page
