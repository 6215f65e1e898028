"""A machine solve as a self-contained HTML report (:class:`axisopt.report.html.Page`): key figures
first, the stiffness chain at the tool with every link (the axis part along or across its travel and
the frame under it, each link's share of the compliance), the per-axis designs, the lumped chain's
frequencies, the sequential sizing beside the joint optimum, and the printed result."""

from __future__ import annotations

from ..machine.spec import DIRECTIONS
from . import html as H

_UNITS = {
    "cost": ("EUR", 1.0),
    "tool_stiffness": ("N/um", 1e-6),
    "frequency": ("Hz", 1.0),
    "moving_mass": ("kg", 1.0),
}


def link_rows(md) -> list:
    """Per axis and direction: (axis, direction, role, axis part, frame, link [N/um], share of the
    compliance at the tool [%]); the frame marked '(estimate)' where the machine file gives none."""
    rows = []
    for i, d in enumerate(DIRECTIONS):
        for a in md.axes:
            share = 100.0 * md.k_tool[i] / a.k_link[i]  # (1/k_link) / (1/k_tool)
            frame = f"{a.k_frame[i] * 1e-6:,.0f}" + (" (estimate)" if a.frame_estimated else "")
            rows.append(
                [
                    a.name,
                    d,
                    a.roles[i],
                    f"{a.k_axis[i] * 1e-6:,.1f}",
                    frame,
                    f"{a.k_link[i] * 1e-6:,.1f}",
                    f"{share:.1f} %",
                ]
            )
        rows.append(["tool", d, "all in series", "", "", f"{md.k_tool[i] * 1e-6:,.1f}", "100.0 %"])
    return rows


def axis_rows(md) -> list:
    rows = []
    for a in md.axes:
        c = a.candidate
        rows.append(
            [
                a.name,
                c.screw,
                c.nut,
                c.bearing,
                c.guide,
                c.motor or "-",
                c.coupling or "-",
                c.reduction or "-",
                c.arrangement or "-",
                f"{c.nut_preload:,.0f} N",
                f"{a.carried:,.1f} kg",
                f"{a.lumped:,.1f} kg",
                f"{a.cost:,.0f} EUR",
            ]
        )
    return rows


AXIS_HEAD = [
    "axis",
    "screw",
    "nut",
    "bearing",
    "guide",
    "motor",
    "coupling",
    "reduction",
    "arrangement",
    "preload",
    "carries",
    "moves",
    "cost",
]
LINK_HEAD = [
    "axis",
    "direction",
    "link",
    "axis part [N/um]",
    "frame [N/um]",
    "link [N/um]",
    "share",
]


def compliance_figure(md):
    """The compliance at the tool per direction, stacked by link (axis part and frame of every axis)
    [um/kN]."""
    from ..figure import Figure
    from ..fileio import tidy_layout

    fig = Figure(figsize=(7, 3.2))
    ax = fig.subplots()
    left = [0.0, 0.0, 0.0]
    for a in md.axes:
        for part, ks in (("axis", a.k_axis), ("frame", a.k_frame)):
            c = [1e9 / k for k in ks]
            ax.barh(list(DIRECTIONS), c, left=left, label=f"{a.name} {part}")
            left = [x + y for x, y in zip(left, c)]
    ax.invert_yaxis()
    ax.set_xlabel("compliance at the tool [um/kN], each link (axis part, frame under it)")
    ax.legend(fontsize=7, ncol=3, loc="lower right")
    ax.grid(True, axis="x", alpha=0.3)
    tidy_layout(fig)
    return fig


def _compliance_plotly(md):
    import plotly.graph_objects as go

    fig = go.Figure()
    for a in md.axes:
        for part, ks in (("axis", a.k_axis), ("frame", a.k_frame)):
            fig.add_bar(
                y=list(DIRECTIONS),
                x=[1e9 / k for k in ks],
                orientation="h",
                name=f"{a.name} {part}",
            )
    fig.update_layout(barmode="stack", xaxis_title="compliance at the tool [um/kN]")
    return fig


def _design_sections(page, md, label: str) -> None:
    page.section(f"{label}: every axis's design").append(H.table(AXIS_HEAD, axis_rows(md)))
    page.section(f"{label}: stiffness at the tool, each link").append(
        H.table(LINK_HEAD, link_rows(md))
    )
    freq = [
        [f"{'/'.join(md.branches[b])}", d, ", ".join(f"{x:,.1f}" for x in f)]
        for (b, d), f in md.frequencies.items()
    ]
    body = page.section(f"{label}: natural frequencies of the lumped chains")
    body.append(H.table(["chain", "direction", "frequencies [Hz]"], freq))
    d, who, role = md.lowest_at
    body.append(
        H.para(
            f"lowest {md.f_lowest:.1f} Hz ({d}-direction mode, most strain energy in {who}'s "
            f"{role} link); Dunkerley's lower bound {md.f_dunkerley:.1f} Hz"
        )
    )
    if md.misses:
        body.append(
            H.para(
                "misses: " + "; ".join(f"{k} {v:.4g} against {b:.4g} (SI)" for k, v, b in md.misses)
            )
        )


def machine_page(res, text: str, interactive: bool = False):
    """The report of a :class:`axisopt.machine.joint.MachineResult`; ``text`` is the printed
    result."""
    m = res.machine
    unit, f = _UNITS[m.objective]
    page = H.Page(
        f"Machine: {m.name}",
        f"objective {m.objective}; method {res.method}",
        interactive=interactive,
    )
    page.card("status", res.status, "ok" if res.status == "optimal" else "bad")
    if res.best is not None:
        page.card("joint optimum", f"{res.best.value(m.objective) * f:,.1f} {unit}", "ok")
        for i, d in enumerate(DIRECTIONS):
            page.card(f"k_{d} at the tool", f"{res.best.k_tool[i] * 1e-6:,.1f} N/um")
        page.card("lowest frequency", f"{res.best.f_lowest:,.1f} Hz")
    seq = res.sequential
    if seq is not None:
        page.card(
            "sequential sizing",
            f"{seq.value(m.objective) * f:,.1f} {unit}" + ("" if seq.feasible else " (misses)"),
            "" if seq.feasible else "bad",
        )
    page.card("nominal combinations", f"{res.nominal_combinations:.3g}")
    page.card("time", f"{res.time:.1f} s")
    if res.best is not None:
        best = res.best
        page.figure(
            "Compliance at the tool, each link",
            lambda: _compliance_plotly(best),
            lambda: compliance_figure(best),
            320,
        )
        _design_sections(page, best, "Joint optimum")
    if seq is not None:
        _design_sections(page, seq, "Sequential sizing")
    if res.notes:
        page.section("Notes").extend(H.para(n) for n in res.notes)
    page.section("Result (as printed)").append(H.pre(text))
    return page


def evaluation_page(ev, text: str, interactive: bool = False):
    """The report of a machine of chosen parts
    (:class:`axisopt.machine.evaluate.MachineEvaluation`)."""
    m = ev.machine
    page = H.Page(f"Machine: {m.name}", "its parts as chosen", interactive=interactive)
    md = ev.design
    if md is None:
        page.card("status", "an axis misses its own limits", "bad")
    else:
        page.card(
            "machine limits", "met" if md.feasible else "missed", "ok" if md.feasible else "bad"
        )
        for i, d in enumerate(DIRECTIONS):
            page.card(f"k_{d} at the tool", f"{md.k_tool[i] * 1e-6:,.1f} N/um")
        page.card("lowest frequency", f"{md.f_lowest:,.1f} Hz")
        page.card("cost", f"{md.cost:,.0f} EUR")
        page.figure(
            "Compliance at the tool, each link",
            lambda: _compliance_plotly(md),
            lambda: compliance_figure(md),
            320,
        )
        _design_sections(page, md, "The machine")
    page.section("Result (as printed)").append(H.pre(text))
    return page


__all__ = ["machine_page", "evaluation_page", "link_rows", "axis_rows", "compliance_figure"]
