"""Interactive figures of the HTML reports (``--plotly inline|cdn``): plotly twins of the static
figures (:mod:`axisopt.report.static`), with zoom and hover for values and part ids.  Needs plotly
(``pip install 'axisopt[html]'``); imported only for an interactive page."""

from __future__ import annotations

import html
import math

import numpy as np

from ..units import N_PER_UM


def _e(text) -> str:
    return html.escape(str(text))


def profiles_figure(evaluations, labels, limits=None):
    """Axial stiffness and first natural frequency over the stroke, one line per evaluation."""
    from plotly.subplots import make_subplots

    fig = make_subplots(
        rows=1, cols=2, subplot_titles=("axial stiffness [N/um]", "1st natural frequency [Hz]")
    )
    for i, (ev, lab) in enumerate(zip(evaluations, labels)):
        s = (ev.x - ev.design.axis.start_offset) * 1e3
        color = _COLORS[i % len(_COLORS)]
        fig.add_scatter(
            x=s,
            y=np.asarray(ev["k_total"]) / N_PER_UM,
            name=lab,
            line=dict(color=color),
            legendgroup=lab,
            row=1,
            col=1,
            hovertemplate="%{x:.0f} mm: %{y:.1f} N/um<extra>" + _e(lab) + "</extra>",
        )
        fig.add_scatter(
            x=s,
            y=np.asarray(ev["f1"]),
            name=lab,
            line=dict(color=color),
            legendgroup=lab,
            showlegend=False,
            row=1,
            col=2,
            hovertemplate="%{x:.0f} mm: %{y:.1f} Hz<extra>" + _e(lab) + "</extra>",
        )
    for key, col, scale, unit in (
        ("min_stiffness", 1, N_PER_UM, "N/um"),
        ("min_frequency", 2, 1.0, "Hz"),
    ):
        if limits and limits.get(key) is not None:
            fig.add_hline(
                y=limits[key] / scale,
                line=dict(dash="dash", color="#c62828"),
                row=1,
                col=col,
                annotation_text=f"limit {limits[key] / scale:g} {unit}",
            )
    fig.update_xaxes(title_text="nut position from stroke start [mm]")
    return fig


_COLORS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2")


def chain_figure(ev):
    """The axial stiffness chain at the softest point: compliance per component [um/kN]."""
    import plotly.graph_objects as go

    comps = {k: v for k, v in ev.components().items() if math.isfinite(v) and v > 0}
    names = list(comps)
    c = [1e9 / comps[n] for n in names]
    fig = go.Figure(
        go.Bar(
            x=c,
            y=names,
            orientation="h",
            marker_color=["#c62828" if n == ev.weakest else "#1f77b4" for n in names],
            hovertemplate="%{y}: %{x:.2f} um/kN<extra></extra>",
        )
    )
    fig.update_layout(
        title="compliance at the softest point [um/kN] (weakest link in red)",
        xaxis_title="um/kN",
        yaxis=dict(autorange="reversed"),
    )
    return fig


def drive_figure(ev):
    """The duty cycle on the motor's torque-speed plane (plotly twin of report.plots' panel), or
    None."""
    import plotly.graph_objects as go

    from .plots import duty_points

    pts = duty_points(ev)
    if pts is None:
        return None
    fig = go.Figure()
    rms = max(pts["rms_torque_Nm"], pts["mean_thrust_torque_Nm"])
    nr, nm = pts["rated_speed_rpm"], pts["max_speed_rpm"]
    how = "corner estimated" if pts["zone_estimated"] else "vendor corner points"
    fig.add_scatter(
        x=pts["zone_speed_rpm"],
        y=pts["zone_torque_Nm"],
        mode="lines",
        line=dict(dash="dash"),
        name=f"{pts['motor']} peak zone ({how})",
    )
    fig.add_scatter(
        x=[0, nr],
        y=[pts["rated_torque_Nm"]] * 2,
        mode="lines",
        line=dict(width=4),
        opacity=0.5,
        name=f"rated {pts['rated_torque_Nm']:.3g} N.m to {nr:.0f} rpm",
    )
    fig.add_scatter(
        x=[0, nm],
        y=[pts["rms_limit_Nm"]] * 2,
        mode="lines",
        line=dict(dash="dot"),
        name=f"RMS limit {pts['rms_limit_Nm']:.3g} N.m",
    )
    fig.add_scatter(
        x=[nm, nm],
        y=[0, pts["zone_torque_Nm"][-1]],
        mode="lines",
        line=dict(dash="dashdot"),
        name=f"max speed {nm:.0f} rpm",
    )
    fig.add_scatter(
        x=pts["speed_rpm"],
        y=np.abs(pts["torque_Nm"]),
        mode="lines+markers",
        name="duty cycle |T| by phase",
    )
    fig.add_scatter(
        x=[0.0],
        y=[pts["thrust_torque_Nm"]],
        mode="markers",
        marker=dict(symbol="triangle-up", size=12),
        name=f"steady thrust at feed {pts['thrust_torque_Nm']:.1f} N.m",
    )
    fig.add_scatter(
        x=[pts["mean_speed_rpm"]],
        y=[rms],
        mode="markers",
        marker=dict(symbol="square-open", size=11),
        name=f"RMS checked {rms:.2f} N.m",
    )
    fig.update_layout(
        title="duty cycle against the motor limits",
        xaxis_title="motor speed [rpm]",
        yaxis_title="motor torque magnitude [N.m]",
    )
    return fig


def frf_figure(ev):
    """Table compliance over frequency at stroke start, middle and end: motor held (the headline
    first frequency's model), motor free and with the tuned servo."""
    from plotly.subplots import make_subplots

    from ..model.frf import frf
    from .methods import closed_loop_frf

    free = frf(ev)
    f = np.asarray(free["frequency_Hz"], float)
    held = frf(ev, f, motor_held=True)
    closed = closed_loop_frf(ev, f)
    fig = make_subplots(
        rows=2, cols=1, shared_xaxes=True, subplot_titles=("compliance [um/N]", "phase [deg]")
    )
    sets = ((held, "solid", "motor held"), (free, "dash", "motor free"), (closed, "dot", "servo"))
    for j, q0 in enumerate(free["positions"]):
        color = _COLORS[j % len(_COLORS)]
        for res, dash, what in sets:
            q = res["positions"][j]
            name = f"{q0['position_mm']:.0f} mm, {what}"
            fig.add_scatter(
                x=f,
                y=q["magnitude_um_per_N"],
                mode="lines",
                line=dict(color=color, dash=dash),
                name=name,
                legendgroup=name,
                row=1,
                col=1,
            )
            fig.add_scatter(
                x=f,
                y=q["phase_deg"],
                mode="lines",
                line=dict(color=color, dash=dash),
                name=name,
                legendgroup=name,
                showlegend=False,
                row=2,
                col=1,
            )
    fig.update_xaxes(type="log", title_text="frequency [Hz]", row=2, col=1)
    fig.update_xaxes(type="log", row=1, col=1)
    fig.update_yaxes(type="log", row=1, col=1)
    return fig


def pareto_figure(front):
    """Scatter matrix of the chosen objectives: sampled feasible designs in grey, the front in
    colour."""
    import plotly.graph_objects as go

    from ..search.pareto import FIELD

    dims_front = [
        dict(
            label=f"{k.replace('_', ' ')} [{u}]" if u else k,
            values=[float(getattr(p, FIELD[k])) for p in front.points],
        )
        for k, u in zip(front.keys, front.units)
    ]
    fig = go.Figure()
    if front.cloud is not None and len(front.cloud):
        cloud = np.asarray(front.cloud)
        fig.add_trace(
            go.Splom(
                dimensions=[
                    dict(label=d["label"], values=cloud[:, i]) for i, d in enumerate(dims_front)
                ],
                name="feasible designs (sample)",
                marker=dict(size=3, color="#b0b7c3", opacity=0.4),
                diagonal_visible=False,
            )
        )
    fig.add_trace(
        go.Splom(
            dimensions=dims_front,
            name="Pareto front",
            diagonal_visible=False,
            marker=dict(size=7, color="#d62728", line=dict(width=0.5, color="white")),
            text=[f"{p.screw} / {p.nut} / {p.bearing} / {p.guide}" for p in front.points],
        )
    )
    fig.update_layout(title="objectives pairwise (front in red, hover for parts)")
    return fig


def objective_figure(df, name: str, key: str, unit: str, ok):
    """A study's objective against one swept input (the twin of
    :func:`axisopt.report.static.objective_figure`)."""
    import plotly.graph_objects as go

    fig = go.Figure()
    fig.add_scatter(
        x=df.loc[ok, name],
        y=df.loc[ok, "objective"],
        mode="markers",
        name="optimal",
        text=df.loc[ok, "case_id"]
        + ": "
        + df.loc[ok, "screw"].astype(str)
        + " / "
        + df.loc[ok, "nut"].astype(str),
        hovertemplate="%{text}<br>%{x}: %{y:.4g}<extra></extra>",
    )
    if (~ok).any():  # no objective to draw: the inputs of the cases without a design are shaded
        for x in sorted(set(df.loc[~ok, name].dropna())):
            fig.add_vline(x=x, line=dict(color="#c62828", width=6), opacity=0.2)
        fig.add_scatter(
            x=[None],
            y=[None],
            mode="lines",
            line=dict(color="#c62828", width=6),
            opacity=0.3,
            name=f"input of a case without a design ({int((~ok).sum())} cases; reasons in the "
            "table)",
        )
    fig.update_layout(
        title=f"objective against {key}", xaxis_title=name, yaxis_title=f"objective [{unit}]"
    )
    return fig


def residuals_figure(o, rb, ra, verdict: str):
    """Residuals of one observation against each recorded factor, baseline and final (plotly)."""
    from plotly.subplots import make_subplots

    from .diagfiles import FACTOR_DISPLAY
    from .diagnosis import Y_UNIT

    facs = [(n, v) for n, v in o.factors.items() if np.ptp(v) > 0] or [("row", np.arange(o.n))]
    unit, f = Y_UNIT[o.kind]
    fig = make_subplots(rows=1, cols=len(facs), shared_yaxes=True)
    for j, (name, v) in enumerate(facs, start=1):
        fu, fs, fo = FACTOR_DISPLAY.get(name, ("", 1.0, 0.0))
        x = np.asarray(v) * fs + fo
        fig.add_scatter(
            x=x,
            y=rb * f,
            mode="markers",
            name="baseline",
            marker=dict(size=4, color="#9aa3b2"),
            showlegend=j == 1,
            row=1,
            col=j,
        )
        fig.add_scatter(
            x=x,
            y=ra * f,
            mode="markers",
            name=f"with {verdict}",
            showlegend=j == 1,
            marker=dict(size=4, color="#d62728"),
            row=1,
            col=j,
        )
        fig.update_xaxes(title_text=f"{name} [{fu}]" if fu else name, row=1, col=j)
    fig.update_yaxes(title_text=f"model - measured [{unit}]", row=1, col=1)
    return fig


__all__ = [
    "profiles_figure",
    "chain_figure",
    "drive_figure",
    "frf_figure",
    "pareto_figure",
    "objective_figure",
    "residuals_figure",
]
