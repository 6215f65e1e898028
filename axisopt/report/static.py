"""Static figures of the HTML reports: matplotlib drawn to SVG and written into the page.

A report's default figures (``--plotly no``): the page opens offline, needs no plotly and stays
small (the plotly script alone is about 4.7 MB).  The figures are the ones the command line's
``--plot`` draws (:func:`axisopt.report.plots.plot_profiles`,
:func:`axisopt.report.methods.plot_frf`, :func:`axisopt.report.solve.plot_pareto`, the diagnosis's
residual plots) plus the two only a report shows (the stiffness chain, a study's objective against a
swept input).  Text stays text in the SVG (the browser's sans-serif), dense point clouds are raster,
so a figure weighs tens of kB.
"""

from __future__ import annotations

import io
import math

import numpy as np

from ..fileio import tidy_layout

_COUNT = [0]


def svg(fig, alt: str = "") -> str:
    """``fig`` (a matplotlib Figure) as an inline SVG element, drawn at its own size (so every
    figure's text is the same size) and scaled down, aspect kept, where the page is narrower;
    ``alt`` is its accessible name."""
    import matplotlib

    _COUNT[0] += 1
    buf = io.StringIO()
    # text as text (small, selectable); ids salted per figure: two SVGs in one page never share an
    # id
    with matplotlib.rc_context(
        {
            "svg.fonttype": "none",
            "svg.hashsalt": f"axisopt-fig-{_COUNT[0]}",
            "font.family": "sans-serif",
        }
    ):
        fig.savefig(buf, format="svg", bbox_inches="tight")
    text = buf.getvalue()
    text = text[text.index("<svg") :]  # no XML declaration or doctype inside HTML
    label = f' role="img" aria-label="{_attr(alt)}"' if alt else ""
    text = text.replace("<svg", f"<svg{label}", 1)
    return f'<div class="fig static">{text}</div>'


def _attr(text: str) -> str:
    import html

    return html.escape(str(text), quote=True)


def chain_figure(ev):
    """The axial stiffness chain at the softest point: compliance per component [um/kN], the weakest
    in red."""
    from ..figure import Figure

    comps = {k: v for k, v in ev.components().items() if math.isfinite(v) and v > 0}
    names = list(comps)
    c = [1e9 / comps[n] for n in names]
    fig = Figure(figsize=(7, 0.45 * len(names) + 1.0))
    ax = fig.subplots()
    ax.barh(names, c, color=["#c62828" if n == ev.weakest else "#1f77b4" for n in names])
    for y, v in enumerate(c):
        ax.text(v, y, f" {v:.2f}", va="center", fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("compliance at the softest point [um/kN] (weakest link in red)")
    ax.set_xlim(0, 1.15 * max(c))
    ax.grid(True, axis="x", alpha=0.3)
    tidy_layout(fig)
    return fig


def frf_figure(ev):
    """Table compliance over frequency at stroke start, middle and end: motor held, motor free, with
    the servo (as ``axisopt evaluate --frf`` draws it)."""
    from ..model.frf import frf
    from .methods import closed_loop_frf, plot_frf

    free = frf(ev)
    f = np.asarray(free["frequency_Hz"], float)
    return plot_frf(free, None, frf(ev, f, motor_held=True), closed_loop_frf(ev, f))


def objective_figure(df, name: str, key: str, unit: str, ok):
    """A study's objective against one numeric swept input: the optimal cases as points, the inputs
    of the cases without a design as red ticks along the bottom (their reasons are in the cases
    table)."""
    from ..figure import Figure

    fig = Figure(figsize=(7, 3.6))
    ax = fig.subplots()
    ax.plot(df.loc[ok, name], df.loc[ok, "objective"], "o", ms=4, label="optimal")
    if (~ok).any():
        xs = sorted(set(df.loc[~ok, name].dropna()))
        ax.plot(
            xs,
            [0.0] * len(xs),
            "|",
            color="#c62828",
            ms=12,
            transform=ax.get_xaxis_transform(),
            label=f"input of a case without a design ({int((~ok).sum())} cases; reasons in the "
            "table)",
        )
    ax.set_xlabel(name)
    ax.set_ylabel(f"objective [{unit}]" if unit else "objective")
    ax.set_title(f"objective against {key}", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    tidy_layout(fig)
    return fig


__all__ = ["svg", "chain_figure", "frf_figure", "objective_figure"]
