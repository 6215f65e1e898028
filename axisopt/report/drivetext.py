"""The drive block of an evaluation's text: motor, coupling or reduction, duty cycle, torques,
speeds, inertia, brake, lost motion, and the thermal warning (growth at the nut against THK's
planning range).  Nothing here prints."""

from __future__ import annotations

import math
import textwrap

import numpy as np

from ..design import PRETENSION_RISE, TEMPERATURE_RISE, rotating_nut
from ..display import fmt
from ..model import Evaluation
from ..model.motorrule import DEFAULT_RULE, rule_text
from .accuracy import reduction_lost_motion
from .text import RPM, WIDTH

# THK A-715: "set a negative target value for the reference travel distance assuming a temperature
# increase of 2 to 5 degC (-0.02 mm to -0.06 mm/m)": growth beyond 0.06 mm per metre (a rise beyond
# 5 K) leaves that practice
PRACTICE_GROWTH = 0.06e-3  # [m/m]


PRACTICE_RISE_MAX = 5.0  # [K]


def drive_lines(ev: Evaluation) -> list:
    """The drive block of ``evaluate``: motor, coupling, duty cycle, torques, speed, inertia,
    brake."""
    d, v, a = ev.design, ev.values, ev.design.axis
    if d.motor is None:
        return [
            "drive: no motor given (parts.motor); rotor inertia "
            f"{fmt(a.motor_inertia, 'kg.m^2')} assumed for the drive-train modes",
            "",
        ]
    m = d.motor
    r = d.reduction
    ratio = a.reduction_ratio if r is None else float(r["ratio"])
    if r is not None:
        red = (
            f"reduction {r['id']} ({r['vendor']} {r['kind']}; {ratio:g}:1, efficiency "
            f"{float(r['efficiency']):g}, {float(r['inertia']) * 1e4:.3g} kg.cm^2 at the input, "
            f"{float(r['torsional_stiffness']):,.0f} N.m/rad, backlash "
            f"{float(r['backlash']) * 10800 / math.pi:g} arcmin"
            + (f", {fmt(float(r['mass']), 'kg')}" if math.isfinite(float(r["mass"])) else "")
            + ")"
        )
    else:
        red = (
            "direct"
            if ratio == 1
            else f"reduction {ratio:g}:1, efficiency {a.reduction_efficiency:g}"
        )
    cpl = (
        f"coupling {d.coupling['id']}"
        if d.coupling is not None
        else "coupling from the axis values"
    )
    cycle = (
        f"{len(a.duty_cycle)}-entry duty cycle"
        if a.duty_cycle
        else "rapid move over the stroke and back, no dwell (default)"
    )
    lines = [
        *textwrap.wrap(
            f"drive: motor {m['id']} ({m['vendor']}; rated {fmt(m['rated_torque'], 'N.m')}, peak "
            f"{fmt(m['peak_torque'], 'N.m')}, max {m['max_speed'] * RPM:,.0f} rpm)",
            WIDTH,
            subsequent_indent="    ",
        ),
        *textwrap.wrap(f"{cpl}, {red}", WIDTH, initial_indent="  ", subsequent_indent="    "),
        *textwrap.wrap(
            f"{cycle}: {v['duty_time']:.2f} s;  friction {v['friction_torque']:.3f} N.m"
            + (f", gravity {v['gravity_torque']:.3f} N.m" if a.orientation == "vertical" else ""),
            WIDTH,
            initial_indent="  ",
            subsequent_indent="    ",
        ),
    ]
    scaled = abs(v["needed_motor_peak_torque"] - v["peak_torque"]) > 1e-9 * v["peak_torque"]
    rms_ratio = float(v["available_motor_rated_torque"]) / float(m["rated_torque"])
    unb_ratio = _row_number(m, "unbalance_ratio", DEFAULT_RULE.unbalance)
    peak = float(v["available_motor_peak_torque"])
    limited = "" if a.torque_limit is None else f", axis.torque_limit {fmt(a.torque_limit, 'N.m')}"
    # the needed column holds what the check compares: the cycle's peak scaled to the flat peak
    # where the motor's zone falls at speed (the cycle's own peak on the line below)
    rows = [
        (
            "peak torque (cycle, thrust)",
            f"{v['needed_motor_peak_torque']:.3f} N.m" + (" *" if scaled else ""),
            f"{fmt(peak, 'N.m')} (motor peak, zone by speed{limited})",
        ),
        (
            "RMS torque, mean thrust",
            f"{v['rms_torque']:.3f}, {v['mean_thrust_torque']:.3f} N.m",
            f"{rms_ratio:g} x {fmt(m['rated_torque'], 'N.m')} (rated)",
        ),
        (
            "motor speed",
            f"{v['motor_speed'] * RPM:,.0f} rpm",
            f"{m['max_speed'] * RPM:,.0f} rpm (max)",
        ),
        (
            "inertia ratio load/rotor",
            f"{v['inertia_ratio']:.2f} ({fmt(v['load_inertia'] * 1e4, 'kg.cm^2')})",
            f"{a.max_inertia_ratio:g} (axis.max_inertia_ratio)",
        ),
    ]
    if a.orientation == "vertical":
        rows.append(
            (
                "unbalanced load torque",
                f"{v['unbalance_torque']:.3f} N.m",
                f"{unb_ratio:g} x {fmt(m['rated_torque'], 'N.m')} (rated)",
            )
        )
        brake = float(m["brake_torque"]) if math.isfinite(float(m["brake_torque"])) else 0.0
        rows.append(
            (
                "holding torque at a stop",
                f"{v['holding_torque']:.3f} N.m",
                f"{fmt(brake, 'N.m')} brake / {a.brake_safety:g}" if brake else "no brake listed",
            )
        )
    if d.coupling is not None:
        rows.append(
            (
                "coupling torque",
                f"{fmt(peak * ratio, 'N.m')} (motor peak)",
                f"{fmt(d.coupling['rated_torque'], 'N.m')} (rated)",
            )
        )
    if r is not None:
        rows.append(
            (
                "output torque peak (cycle)",
                fmt(v["output_peak_torque"], "N.m"),
                f"{fmt(float(r['accel_torque']), 'N.m')} (T2B)",
            )
        )
        rows.append(
            (
                "output torque RMS, thrust",
                fmt(v["output_rms_torque"], "N.m"),
                f"{fmt(float(r['rated_torque']), 'N.m')} (T2N)",
            )
        )
        stop = (
            "T2Stop"
            if math.isfinite(_row_number(r, "emergency_torque", math.nan))
            else "T2B, no T2Stop listed"
        )
        rows.append(
            (
                "E-stop: motor peak x ratio",
                fmt(v["needed_reduction_emergency_torque"], "N.m"),
                f"{fmt(v['available_reduction_emergency_torque'], 'N.m')} ({stop})",
            )
        )
    lines.append(f"  {'':<28}{'needed':>26}   available")
    for name, need, have in rows:
        lines.extend(
            textwrap.wrap(f"  {name:<28}{need:>26}   {have}", WIDTH, subsequent_indent=" " * 59)
        )
    if scaled:
        lines.extend(
            textwrap.wrap(
                f"    * the cycle's peak {v['peak_torque']:.3f} N.m scaled to the motor's flat "
                "peak (its zone falls at the speed of that peak): what the check compares",
                WIDTH,
                subsequent_indent="      ",
            )
        )
    lines.extend(
        textwrap.wrap(
            "motor rule: " + rule_text(str(m["vendor"]), rms_ratio, unb_ratio, a.rms_torque_ratio),
            WIDTH,
            initial_indent="  ",
            subsequent_indent="    ",
        )
    )
    lines.extend(
        textwrap.wrap(
            f"regeneration {v['regen_energy']:,.0f} J per cycle back from the motor, "
            f"{v['regen_power']:,.0f} W mean (braking"
            + (", lowering" if a.orientation == "vertical" else "")
            + "; before winding and drive losses): "
            "what the drive's regenerative resistor must take (Yaskawa 12.8.6), not checked",
            WIDTH,
            initial_indent="  ",
            subsequent_indent="    ",
        )
    )
    lines.append("")
    return lines


def lost_motion_text(ev) -> str:
    """The lost motion at the table by its cause: the nut's play and a reduction's backlash, each
    named."""
    red = reduction_lost_motion(ev.design)
    nut = float(ev.values["backlash"]) - red
    if ev.design.reduction is None:
        return f"nut backlash {nut * 1e6:.0f} um"
    return f"lost motion: nut {nut * 1e6:.0f} um, reduction {red * 1e6:.0f} um"


def _row_number(row, col: str, default: float) -> float:
    """A part row's number in ``col``; ``default`` where it is empty or the table has no such
    column."""
    try:
        v = float(row[col])
    except (KeyError, TypeError, ValueError):
        return default
    return v if math.isfinite(v) else default


def unit_rigidity_estimated(design) -> bool:
    """A rotating-nut unit whose row lists no bearing rigidity (the model's estimate stands in)."""
    v = (
        design.nut.get("unit_bearing_rigidity", math.nan)
        if hasattr(design.nut, "get")
        else math.nan
    )
    return not (isinstance(v, float) and math.isfinite(v))


def thermal_warning(ev: Evaluation) -> str:
    """A warning where the thermal growth at the nut exceeds THK A-715's planning range (a negative
    target travel of -0.02 to -0.06 mm/m for a 2-5 degC rise: PRACTICE_GROWTH per metre from the
    fixed bearing), or where the practice rise is used but the heat balance of the default cycle
    would exceed it ('' if neither)."""
    a, v = ev.design.axis, ev.values
    x_far = a.start_offset + a.stroke
    allowed = PRACTICE_GROWTH * x_far
    growth = float(v["thermal_growth"])
    out = []
    if growth > allowed * (1 + 1e-9):
        out.append(
            f"thermal growth {growth * 1e6:.0f} um exceeds THK A-715's planning range (0.06 mm/m, "
            f"a 5 degC rise: {allowed * 1e6:.0f} um at {x_far * 1e3:.0f} mm from the fixed "
            "bearing); limits.max_thermal_growth bounds it, a cooled screw (axis.heat_transfer), a "
            "lower preload or a scale (feedback) takes it out"
        )
    balance = float(v["heat_balance_rise"])
    if not a.rise_from_balance and a.temperature_rise is None and balance > PRACTICE_RISE_MAX:
        out.append(
            f"the heat balance of continuous rapids gives +{balance:.3g} K, above THK A-715's 2-5 "
            "degC planning range the practice rise assumes (axis.rise_without_cycle: balance uses "
            "it)"
        )
    return ("warning: " + "; ".join(out)) if out else ""


def thermal_line(ev: Evaluation) -> str:
    a, v = ev.design.axis, ev.values
    u = np.asarray(v["thermal_displacement"])
    text = (
        f"thermal: +{float(v['temperature_rise']):.3g} K moves the nut up to "
        f"{np.max(np.abs(u)) * 1e3:.3f} mm (alpha 11.6e-6/K, HIWIN F 3.36)"
    )
    used = a.rise_from_balance
    how = (
        "rise from the heat balance of the duty cycle"
        if used and a.duty_cycle
        else "rise from the heat balance of the default cycle (axis.rise_without_cycle: balance; "
        f"the practice rise would be {TEMPERATURE_RISE:g} K), continuous rapids"
        if used
        else "rise as given; the heat balance"
        if a.temperature_rise is not None
        else "rise: THK A-715's practice rise (axis.rise_without_cycle: practice), no duty cycle; "
        "the heat balance of continuous rapids"
    )
    film = (
        "axis.heat_transfer"
        if a.heat_transfer is not None
        else "free convection: a standing screw under a rotating nut"
        if rotating_nut(ev.design.nut)
        else "Jungnickel rotating shaft over the cycle, with free convection"
    )
    rise = "" if used else f" would give +{float(v['heat_balance_rise']):.3g} K"
    balance = (
        f"{how}: friction power {float(v['friction_power']):.3g} W (nut and bearings at the "
        "cycle's mean screw speed) through a lumped network (Jungnickel 2010): shaft film "
        f"{float(v['heat_transfer']):.3g} W/(m^2.K) ({film}), conduction through the nut bracket "
        f"and the shaft ends (estimated conductances, docs/assumptions.md){rise}"
    )
    text += "\n" + "\n".join(
        textwrap.wrap(balance, WIDTH, initial_indent="  ", subsequent_indent="    ")
    )
    warn = thermal_warning(ev)
    if warn:
        text += "\n" + "\n".join(
            textwrap.wrap(warn, WIDTH, initial_indent="  ", subsequent_indent="    ")
        )
    if a.mounting == "fixed-fixed":
        pre, push = float(v["pretension"]), float(v["thermal_force"])
        design = PRETENSION_RISE if a.pretension_rise is None else a.pretension_rise
        how_pre = (
            f"absorbs a design rise of {design:g} K, THK A-715"
            if a.pretension is None
            else "as given"
        )
        rest = (
            f"{(push - pre) / 1e3:.1f} kN beyond it compresses the screw"
            if push > pre
            else "the screw stays in tension"
        )
        pre_line = (
            f"pretension {pre / 1e3:.1f} kN ({how_pre}); the rise pushes the elastic ends with "
            f"{push / 1e3:.1f} kN: {rest}; bearing static load "
            f"{v['bearing_static_load'] / 1e3:.1f} kN"
        )
        text += "\n" + "\n".join(
            textwrap.wrap(pre_line, WIDTH, initial_indent="  ", subsequent_indent="    ")
        )
    return text
