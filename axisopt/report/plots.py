"""Plots of evaluations: stiffness and frequency over the stroke, the duty cycle on the motor's
torque-speed plane."""

from __future__ import annotations

import math

import numpy as np

from ..fileio import save_figure, tidy_layout
from ..model import Evaluation
from ..units import N_PER_UM
from .checktext import judged_rows
from .text import RPM


def duty_points(ev: Evaluation) -> dict | None:
    """The duty cycle of an evaluation on the motor's torque-speed plane (None without a motor):
    motor speed [rpm] and torque [N.m] at the start and end of each phase, the RMS torque at the
    mean speed, and the motor's rated, peak and speed limits."""
    from ..physics.motion import phase_speeds

    d, v, a = ev.design, ev.values, ev.design.axis
    if d.motor is None:
        return None
    phases = a.phases
    ratio = a.reduction_ratio if d.reduction is None else float(d.reduction["ratio"])
    to_rpm = 2.0 * math.pi / float(d.screw["lead"]) * ratio * RPM  # table m/s -> motor rpm
    speeds = phase_speeds(phases)
    n, t = [], []
    from ..model import design_params, drive_response

    prm = design_params(d)
    torques = drive_response(prm, d.preload)["duty_torques"]  # per phase; not a Function output
    for (v0, v1), (t0, t1) in zip(speeds, torques):
        n += [v0 * to_rpm, v1 * to_rpm]
        t += [float(t0), float(t1)]
    total = sum(ph.duration for ph in phases)
    mean = (
        sum(ph.duration * 0.5 * (v0 + v1) for ph, (v0, v1) in zip(phases, speeds)) / total
        if total
        else 0.0
    )
    m = d.motor
    estimated = [c for c in ("peak_corner_speed", "peak_torque_at_max_speed") if _missing(m, c)]
    return {
        "speed_rpm": n,
        "torque_Nm": t,
        "rms_torque_Nm": float(v["rms_torque"]),
        "mean_speed_rpm": mean * to_rpm,
        "rated_torque_Nm": float(m["rated_torque"]),
        "peak_torque_Nm": float(m["peak_torque"]),
        "rated_speed_rpm": float(m["rated_speed"]) * RPM,
        "max_speed_rpm": float(m["max_speed"]) * RPM,
        "motor": str(m["id"]),
        # the steady thrusts at feed (no acceleration): the largest axial load against the peak, the
        # mean one with the cycle's RMS against the RMS limit (model.drive)
        "thrust_torque_Nm": float(v["thrust_torque"]),
        "mean_thrust_torque_Nm": float(v["mean_thrust_torque"]),
        # the intermittent zone the check uses (vendor corner points or their estimate) and the RMS
        # bound
        "zone_speed_rpm": [
            0.0,
            float(prm["motor_peak_corner_speed"]) * RPM,
            float(m["max_speed"]) * RPM,
        ],
        "zone_torque_Nm": [
            float(m["peak_torque"]),
            float(m["peak_torque"]),
            float(prm["motor_peak_at_max_speed"]),
        ],
        "zone_estimated": bool(estimated),
        "rms_limit_Nm": float(prm["rms_torque_ratio"]) * float(m["rated_torque"]),
    }


def _missing(row, col) -> bool:
    try:
        val = float(row[col])
    except (KeyError, TypeError, ValueError):
        return True
    return not math.isfinite(val)


def _torque_speed(ax, pts: dict, label: str, color, limits: bool = True) -> None:
    """One design's duty cycle against its motor: every phase's |torque| at its speed, the steady
    thrust at feed (the largest axial load: checked against the peak, a triangle), the RMS torque
    (checked, with the mean thrust, against rated x rms_torque_ratio, a square), and, once per
    motor, its intermittent (peak) zone as the check reads it (dashed), the rated (continuous)
    torque up to the rated speed (thick), the RMS limit (dotted) and the maximum speed (dash-dot).
    The marker and line styles are explained once by :func:`_style_legend`; the labels name the
    design and the motor with their values."""
    rms = max(pts["rms_torque_Nm"], pts["mean_thrust_torque_Nm"])
    ax.plot(
        pts["speed_rpm"],
        np.abs(pts["torque_Nm"]),
        "o-",
        ms=3,
        lw=1,
        color=color,
        label=f"{label}: thrust at feed {pts['thrust_torque_Nm']:.1f}, RMS {rms:.2f} N.m",
    )
    ax.plot([0.0], [pts["thrust_torque_Nm"]], "^", ms=9, color=color, clip_on=False)
    ax.plot([pts["mean_speed_rpm"]], [rms], "s", ms=8, color=color, mfc="none")
    if not limits:  # the motor's limits are drawn once, with the first design that uses it
        return
    nr, nm = pts["rated_speed_rpm"], pts["max_speed_rpm"]
    zs, zt = pts["zone_speed_rpm"], pts["zone_torque_Nm"]
    how = "corner estimated" if pts.get("zone_estimated") else "vendor corner points"
    ax.plot(
        zs,
        zt,
        "--",
        color=color,
        lw=1.5,
        alpha=0.7,
        label=f"{pts['motor']}: peak {pts['peak_torque_Nm']:.3g} N.m ({how}), rated "
        f"{pts['rated_torque_Nm']:.3g} N.m to {nr:.0f} rpm, RMS limit {pts['rms_limit_Nm']:.3g} "
        f"N.m, max {nm:.0f} rpm",
    )
    ax.plot([0, nr], [pts["rated_torque_Nm"]] * 2, "-", color=color, lw=2.5, alpha=0.45)
    ax.plot([nm, nm], [0, zt[-1]], "-.", color=color, lw=1, alpha=0.7)
    ax.plot([0, nm], [pts["rms_limit_Nm"]] * 2, ":", color=color, lw=1.2, alpha=0.8)


def _style_legend(ax) -> list:
    """Legend entries for the marker and line styles of the torque-speed panel (drawn in grey,
    once)."""
    from matplotlib.lines import Line2D

    g = "0.35"
    return [
        Line2D([], [], color=g, marker="o", ms=3, lw=1, label="duty cycle |T| by phase"),
        Line2D(
            [], [], color=g, marker="^", ms=8, ls="", label="steady thrust at feed (axial_load)"
        ),
        Line2D(
            [],
            [],
            color=g,
            marker="s",
            ms=7,
            mfc="none",
            ls="",
            label="RMS checked (cycle or mean thrust)",
        ),
        Line2D([], [], color=g, ls="--", label="intermittent (peak) zone"),
        Line2D([], [], color=g, lw=2.5, alpha=0.45, label="rated torque to rated speed"),
        Line2D([], [], color=g, ls=":", label="RMS limit (rms_torque_ratio x rated)"),
        Line2D([], [], color=g, ls="-.", label="max speed"),
    ]


def distinct_labels(items, prefix=None) -> list:
    """Legend labels that name every part in which the items differ (and only those): ``items`` are
    dicts slot -> part id (or mounting); ``prefix`` an optional list of leading tags (e.g. '#2')."""
    slots = [k for k in (items[0] if items else {}) if len({str(it.get(k)) for it in items}) > 1]
    out = []
    for i, it in enumerate(items):
        body = " / ".join(str(it[k]) for k in slots if it.get(k) not in (None, "")) or "same parts"
        out.append(f"{prefix[i]} {body}" if prefix else body)
    return out


def plot_profiles(evaluations, path: str | None = None, labels=None, limits=None, margins=None):
    """Stiffness and first natural frequency over the stroke, one line per evaluation (its own dash
    pattern, so coinciding curves stay visible; a design that fails a check is marked x and its
    legend entry names the failed checks); with a motor, a torque-speed panel: the duty-cycle points
    against the motor's rated and peak torque and speed limits (the limits the checks use: the
    intermittent zone falling from its corner speed to max speed), each motor's limits drawn once, a
    design without a motor named as such.  ``limits`` (optional) maps 'min_stiffness' [N/m] and
    'min_frequency' [Hz] to the problem's limits, drawn as dashed lines; ``margins`` (optional) a
    problem's least check margins, the failed checks judged against them.  Returns the matplotlib
    Figure (not registered with pyplot; Jupyter shows it as an image); written to ``path`` only when
    one is given."""
    import matplotlib

    from ..figure import Figure

    pts = [duty_points(ev) for ev in evaluations]
    drive = any(p is not None for p in pts)
    if drive:
        fig = Figure(figsize=(13, 8))
        gs = fig.add_gridspec(2, 2, width_ratios=(1, 1))
        ax1 = fig.add_subplot(gs[0, 0])
        ax2 = fig.add_subplot(gs[1, 0], sharex=ax1)
        ax3 = fig.add_subplot(gs[:, 1])
    else:
        fig = Figure(figsize=(7, 6))
        ax1, ax2 = fig.subplots(2, 1, sharex=True)
    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    motors_drawn = set()
    styles = ("-", "--", "-.", ":")
    groups: dict = {}  # designs whose stiffness and frequency curves coincide share one line
    for i, ev in enumerate(evaluations):
        key = (
            np.round(np.asarray(ev["k_total"], float) / N_PER_UM, 3).tobytes(),
            np.round(np.asarray(ev["f1"], float), 3).tobytes(),
            tuple(np.round(ev.x, 6)),
        )
        groups.setdefault(key, []).append(i)
    tags = [labels[i] if labels else ev.design.name for i, ev in enumerate(evaluations)]
    short = [t.split()[0] if t.startswith("#") else t for t in tags]
    for j, members in enumerate(groups.values()):
        i = members[0]
        ev = evaluations[i]
        s = (ev.x - ev.design.axis.start_offset) * 1e3
        col = colors[i % len(colors)]
        failed = sorted(
            {
                r["check"]
                for m in members
                for r in judged_rows(evaluations[m], margins)
                if not r["pass"]
            }
        )
        name = (
            tags[i]
            if len(members) == 1
            else f"{', '.join(short[m] for m in members)}: the same curves ({tags[i]} ...)"
        )
        name += f" - FAILS {', '.join(failed)}" if failed else ""
        # distinct dash patterns: curves that nearly coincide stay visible
        ls = styles[j % len(styles)]
        mk = dict(marker="x", markevery=max(1, len(s) // 8)) if failed else {}
        ax1.plot(s, np.asarray(ev["k_total"]) / N_PER_UM, ls, label=name, color=col, **mk)
        ax2.plot(s, ev["f1"], ls, label=name, color=col, **mk)
    for i in range(len(evaluations)):
        col = colors[i % len(colors)]
        if pts[i] is not None:
            first = pts[i]["motor"] not in motors_drawn
            motors_drawn.add(pts[i]["motor"])
            _torque_speed(ax3, pts[i], short[i], col, limits=first)
        elif drive:  # a design without a motor is named, not silently left out of the drive panel
            ax3.plot([], [], " ", label=f"{short[i]}: no drive (the design has no motor)")
    limits = dict(limits or {})
    if "min_stiffness" in limits:
        ax1.axhline(
            limits["min_stiffness"] / N_PER_UM,
            color="tab:red",
            ls="--",
            lw=1,
            label=f"min_stiffness {limits['min_stiffness'] / N_PER_UM:g} N/um",
        )
    if "min_frequency" in limits:
        ax2.axhline(
            limits["min_frequency"],
            color="tab:red",
            ls="--",
            lw=1,
            label=f"min_frequency {limits['min_frequency']:g} Hz",
        )
        ax2.legend(fontsize=8)
    ax1.set_ylabel("axial stiffness [N/um]")
    ax2.set_ylabel("1st natural frequency [Hz]")
    ax2.set_xlabel("nut position along the stroke [mm]")
    axes = (ax1, ax2)
    if drive:
        ax3.set_xlabel("motor speed [rpm]")
        ax3.set_ylabel("motor torque magnitude [N.m]")
        ax3.set_title("duty cycle against the motor limits", fontsize=10)
        top = max(
            max(p["zone_torque_Nm"] + [p["thrust_torque_Nm"]] + list(np.abs(p["torque_Nm"])))
            for p in pts
            if p is not None
        )
        right = max(p["max_speed_rpm"] for p in pts if p is not None)
        ax3.set_xlim(0, 1.05 * right)
        ax3.set_ylim(0, 1.08 * top)
        # below the panel: the legend never hides a limit line or a duty point
        handles, names = ax3.get_legend_handles_labels()
        ax3.legend(
            handles + _style_legend(ax3),
            names + [h.get_label() for h in _style_legend(ax3)],
            fontsize=7,
            loc="upper center",
            bbox_to_anchor=(0.5, -0.1),
            ncol=1,
            frameon=False,
        )
        axes = (ax1, ax2, ax3)
    for ax in axes:
        ax.grid(True, alpha=0.3)
    if drive:  # the designs' legend (and the problem's limits) below the curves, off the data
        h1, n1 = ax1.get_legend_handles_labels()
        h2, n2 = ax2.get_legend_handles_labels()
        extra = [(h, n) for h, n in zip(h2, n2) if n.startswith("min_frequency")]
        ax2.legend(
            h1 + [h for h, _ in extra],
            n1 + [n for _, n in extra],
            fontsize=7,
            loc="upper center",
            bbox_to_anchor=(0.5, -0.18),
            frameon=False,
        )
    else:
        ax1.legend(fontsize=8)
    tidy_layout(fig)
    if path is not None:
        save_figure(fig, path)
    return fig
