"""Plots of evaluations: stiffness and frequency over the stroke, the duty cycle on the motor's
torque-speed plane."""

from __future__ import annotations

import math

import numpy as np

from ..fileio import save_figure, tidy_layout
from ..model import Evaluation
from ..units import N_PER_UM
from .evaluation import RPM


def duty_points(ev: Evaluation) -> dict | None:
    """The duty cycle of an evaluation on the motor's torque-speed plane (None without a motor): motor speed
    [rpm] and torque [N.m] at the start and end of each phase, the RMS torque at the mean speed, and the
    motor's rated, peak and speed limits."""
    from ..physics.motion import phase_speeds

    d, v, a = ev.design, ev.values, ev.design.axis
    if d.motor is None:
        return None
    phases = a.phases
    to_rpm = 2.0 * math.pi / float(d.screw["lead"]) * a.reduction_ratio * RPM  # table m/s -> motor rpm
    speeds = phase_speeds(phases)
    n, t = [], []
    from ..model import design_params, drive_response

    prm = design_params(d)
    torques = drive_response(prm, d.preload)["duty_torques"]  # per phase; not a Function output
    for (v0, v1), (t0, t1) in zip(speeds, torques):
        n += [v0 * to_rpm, v1 * to_rpm]
        t += [float(t0), float(t1)]
    total = sum(ph.duration for ph in phases)
    mean = sum(ph.duration * 0.5 * (v0 + v1) for ph, (v0, v1) in zip(phases, speeds)) / total if total else 0.0
    m = d.motor
    return {"speed_rpm": n, "torque_Nm": t, "rms_torque_Nm": float(v["rms_torque"]),
            "mean_speed_rpm": mean * to_rpm, "rated_torque_Nm": float(m["rated_torque"]),
            "peak_torque_Nm": float(m["peak_torque"]), "rated_speed_rpm": float(m["rated_speed"]) * RPM,
            "max_speed_rpm": float(m["max_speed"]) * RPM, "motor": str(m["id"]),
            # the intermittent zone the check uses (vendor corner points or their estimate) and the RMS bound
            "zone_speed_rpm": [0.0, float(prm["motor_peak_corner_speed"]) * RPM, float(m["max_speed"]) * RPM],
            "zone_torque_Nm": [float(m["peak_torque"]), float(m["peak_torque"]), float(prm["motor_peak_at_max_speed"])],
            "rms_limit_Nm": float(prm["rms_torque_ratio"]) * float(m["rated_torque"])}


def _torque_speed(ax, pts: dict, label: str, color) -> None:
    ax.plot(pts["speed_rpm"], np.abs(pts["torque_Nm"]), "o-", ms=3, lw=1, color=color,
            label=f"{label}: duty cycle |T|")
    ax.plot([pts["mean_speed_rpm"]], [pts["rms_torque_Nm"]], "s", ms=7, color=color, mfc="none",
            label=f"{label}: RMS at mean speed")
    nr, nm = pts["rated_speed_rpm"], pts["max_speed_rpm"]
    ax.plot([0, nr, nr], [pts["rated_torque_Nm"], pts["rated_torque_Nm"], 0], "-", color=color, lw=2, alpha=0.5,
            label=f"{pts['motor']}: rated torque to rated speed")
    zs, zt = pts["zone_speed_rpm"], pts["zone_torque_Nm"]
    ax.plot(zs + [nm], zt + [0], "--", color=color, lw=1.5, alpha=0.5,
            label=f"{pts['motor']}: intermittent zone, max speed (checked)")
    ax.axhline(pts["rms_limit_Nm"], color=color, lw=1, ls=":", alpha=0.6,
               label=f"{pts['motor']}: RMS limit (rms_torque_ratio x rated)")


def distinct_labels(items, prefix=None) -> list:
    """Legend labels that name every part in which the items differ (and only those): ``items`` are
    dicts slot -> part id (or mounting); ``prefix`` an optional list of leading tags (e.g. '#2')."""
    slots = [k for k in (items[0] if items else {}) if len({str(it.get(k)) for it in items}) > 1]
    out = []
    for i, it in enumerate(items):
        body = " / ".join(str(it[k]) for k in slots if it.get(k) not in (None, "")) or "same parts"
        out.append(f"{prefix[i]} {body}" if prefix else body)
    return out


def plot_profiles(evaluations, path: str | None = None, labels=None, limits=None):
    """Stiffness and first natural frequency over the stroke, one line per evaluation; with a motor, a
    torque-speed panel: the duty-cycle points against the motor's rated and peak torque and speed limits
    (the limits the checks use: the intermittent zone falling from its corner speed to max speed).  ``limits``
    (optional) maps 'min_stiffness' [N/m] and 'min_frequency' [Hz] to the problem's limits, drawn as
    dashed lines.  Returns the matplotlib Figure (not registered with pyplot); written to ``path`` only when
    one is given."""
    import matplotlib
    from matplotlib.figure import Figure

    pts = [duty_points(ev) for ev in evaluations]
    drive = any(p is not None for p in pts)
    if drive:
        fig = Figure(figsize=(13, 6))
        gs = fig.add_gridspec(2, 2, width_ratios=(1, 1))
        ax1 = fig.add_subplot(gs[0, 0])
        ax2 = fig.add_subplot(gs[1, 0], sharex=ax1)
        ax3 = fig.add_subplot(gs[:, 1])
    else:
        fig = Figure(figsize=(7, 6))
        ax1, ax2 = fig.subplots(2, 1, sharex=True)
    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, ev in enumerate(evaluations):
        s = (ev.x - ev.design.axis.start_offset) * 1e3
        lab = labels[i] if labels else ev.design.name
        col = colors[i % len(colors)]
        ax1.plot(s, np.asarray(ev["k_total"]) / N_PER_UM, label=lab, color=col)
        ax2.plot(s, ev["f1"], label=lab, color=col)
        if pts[i] is not None:
            _torque_speed(ax3, pts[i], lab, col)
    limits = dict(limits or {})
    if "min_stiffness" in limits:
        ax1.axhline(limits["min_stiffness"] / N_PER_UM, color="tab:red", ls="--", lw=1,
                    label=f"min_stiffness {limits['min_stiffness'] / N_PER_UM:g} N/um")
    if "min_frequency" in limits:
        ax2.axhline(limits["min_frequency"], color="tab:red", ls="--", lw=1,
                    label=f"min_frequency {limits['min_frequency']:g} Hz")
        ax2.legend(fontsize=8)
    ax1.set_ylabel("axial stiffness [N/um]")
    ax2.set_ylabel("1st natural frequency [Hz]")
    ax2.set_xlabel("nut position along the stroke [mm]")
    axes = (ax1, ax2)
    if drive:
        ax3.set_xlabel("motor speed [rpm]")
        ax3.set_ylabel("motor torque magnitude [N.m]")
        ax3.set_title("duty cycle against the motor limits", fontsize=10)
        ax3.set_xlim(left=0)
        ax3.set_ylim(bottom=0)
        ax3.legend(fontsize=7, loc="upper right")
        axes = (ax1, ax2, ax3)
    for ax in axes:
        ax.grid(True, alpha=0.3)
    ax1.legend(fontsize=8)
    tidy_layout(fig)
    if path is not None:
        save_figure(fig, path)
    return fig
