"""The evaluation of one design as a text table and a JSON dict, in vendor units (N/um, Hz, mm,
N*m).  Nothing here prints."""

from __future__ import annotations

import math
import textwrap

import numpy as np

from ..model import CHECKS, Evaluation, passes
from ..model.function import NOT_APPLICABLE, check_rows, drive_dict  # noqa: F401  (one per check; drive values: in model)
from ..model.limits import CHECK_TABLE, margin_output
from ..model.servo import servo_response
from ..units import N_PER_UM
from .accuracy import budget_dict, budget_lines
from .checktext import check_lines
from .drivetext import (
    drive_lines,
    lost_motion_text,
    thermal_line,
    unit_rigidity_estimated,
)
from .estimatetext import (
    counterbalance_dict,
    counterbalance_lines,
    default_shown,
    estimate_lines,
    estimates,
)
from .gantry import twin_dict, twin_lines
from .lifeloads import life_dict, life_lines
from .servo import servo_dict, servo_lines
from .text import WIDTH

# Each check's physical values in the unit vendors quote them in: (unit, factor from SI), DN in mm x
# rpm; and short names for tables with one column per design (both declared with the check in
# model.limits).
CHECK_UNITS = {c.name: (c.unit, c.factor) for c in CHECK_TABLE}
CHECK_SHORT = {c.name: c.short for c in CHECK_TABLE}
# a horizontal screw's own-weight sag shown in the text from this [m] (long screws; the JSON always
# has it)
SAG_SHOWN = 1e-4


# Schneeberger ball screws, permissible speed: "if Ln/d0 > 50 an intermediate support is needed;
# consult the maker above 40" (tech-doc pages, docs/assumptions.md)
SLENDERNESS_SUPPORT, SLENDERNESS_CONSULT = 50.0, 40.0


def _fmt(v, nd=1):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    return f"{v:,.{nd}f}"


def evaluation_dict(ev: Evaluation) -> dict:
    """JSON-ready summary of an evaluation (vendor units in key names)."""
    v = ev.values
    axis = ev.design.axis
    kmin, kpos = ev.minimum("k_total")
    fmin, fpos = ev.minimum("f1")
    s = ev.x - axis.start_offset
    return (
        {
            "design": ev.design.name,
            "parts": ev.design.part_ids(),
            "screw_grade": ev.design.grade,
            "mounting": axis.mounting,
            "nut_preload_N": ev.design.preload,
            "min_axial_stiffness_N_per_um": kmin / N_PER_UM,
            "min_axial_stiffness_position_mm": kpos * 1e3,
            "min_natural_frequency_Hz": fmin,
            "min_natural_frequency_position_mm": fpos * 1e3,
            "weakest_link": ev.weakest,
            "nut_stiffness_N_per_um": v["k_nut"] / N_PER_UM,
            "chain_at_minimum_N_per_um": {
                k: (_finite(c / N_PER_UM) if math.isfinite(c) else "rigid")
                for k, c in ev.components().items()
            },
            "nut_backlash_um": v["backlash"] * 1e6,
            "pretension_N": v["pretension"],
            "friction_power_W": v["friction_power"],
            "temperature_rise_K": v["temperature_rise"],
            "heat_balance_rise_K": v["heat_balance_rise"],
            "heat_transfer_W_per_m2K": v["heat_transfer"],
            "thermal_growth_um": v["thermal_growth"] * 1e6,
            "thermal_displacement_mm": (np.asarray(v["thermal_displacement"]) * 1e3).tolist(),
            "drive_train_modes_Hz": [
                np.asarray(v["f_axial_torsional"]).tolist(),
                np.asarray(v["f_axial_torsional_2"]).tolist(),
            ],
            "damping_parts": {
                k: np.asarray(v[f"zeta_{k}"]).tolist()
                for k in ("guides", "nut", "bearings", "structure")
            },
            "bearing_stiffness_N_per_um": v["k_bearing"] / N_PER_UM,
            "table_mode_Hz": v["f_table"],
            "moving_mass_kg": v["moving_mass"],
            "total_mass_kg": v["total_mass"],
            "cost": v["cost"],
            "cost_currency": "EUR",
            "screw_sag_mm": float(v["screw_sag"]) * 1e3,
            "drag_torque_Nm": v["drag_torque"],
            "drag_torque_parts_Nm": {
                "nut": v["drag_nut"],
                "bearings": v["drag_bearings"],
                "guides": v["drag_guides"],
            },
            "checks": {
                r["check"]: {k: x for k, x in r.items() if k not in ("check", "label")}
                | {"label": r["label"]}
                for r in check_rows(ev)
            },
            "drive": drive_dict(ev),
            "life_loads": life_dict(ev),
            "all_checks_pass": bool(all(passes(v[margin_output(c)]) for c in CHECKS)),
            "positions_mm": (s * 1e3).tolist(),
            "axial_stiffness_N_per_um": (np.asarray(v["k_total"]) / N_PER_UM).tolist(),
            "screw_stiffness_N_per_um": (np.asarray(v["k_screw"]) / N_PER_UM).tolist(),
            "natural_frequency_Hz": np.asarray(v["f1"]).tolist(),
            "axial_frequency_Hz": np.asarray(v["f_axial"]).tolist(),
            "axial_torsional_frequency_Hz": np.asarray(v["f_axial_torsional"]).tolist(),
            "damping_ratio": np.asarray(v["damping_ratio"]).tolist(),
            "assumed_defaults": list(ev.design.assumed),
            # the fw the life checks read (given, or THK A-704 Table 19)
            "load_factor": axis.load_factor_eff,
            # carriage
            "min_tool_stiffness_N_per_um": ev.minimum("k_tool")[0] / N_PER_UM,
            "tool_stiffness_N_per_um": (np.asarray(v["k_tool"]) / N_PER_UM).tolist(),
            "guide_rocking_compliance_um_per_kN": v["c_rocking"] * 1e9,
            "pitch_mode_Hz": v["f_pitch"],
            "yaw_mode_Hz": v["f_yaw"],
            "guide_max_block_load_N": v["guide_max_load"],
            "guide_static_safety": v["guide_static_safety"],
            "guide_mean_block_load_N": v["guide_mean_load"],
            "nut_static_safety": v["nut_static_safety"],
            "servo": servo_dict(servo_response(ev), v["kv"]),
            "positioning_budget": budget_dict(ev),
            "estimated": [e.to_dict() | {"moves": w} for e, w in estimates(ev) if w],
        }
        | ({"counterbalance": counterbalance_dict(ev)} if axis.counterbalance is not None else {})
        | twin_dict(ev)
    )


def _finite(x):
    return float(x) if math.isfinite(x) and abs(x) < 1e8 else None


def evaluation_table(ev: Evaluation, margins: dict | None = None) -> str:
    """The text table ``axisopt evaluate`` prints; ``margins``: a problem's least check margins
    (``axisopt solve``: the checks pass or fail against them, :func:`judged_rows`)."""
    d = ev.design
    v = ev.values
    a = d.axis
    lines = []
    ids = d.part_ids()
    lines.append(f"design {d.name}")
    lines.append(
        f"  {a.mounting}, stroke {a.stroke * 1e3:.0f} mm, span {a.span * 1e3:.0f} mm, "
        f"moving mass {a.moving_mass:,.0f} kg (+ nut and blocks)"
    )
    lines.extend(counterbalance_lines(ev))
    grade = f" grade {d.screw_grade}" if d.screw_grade is not None else ""
    parts = [
        f"screw {ids['screw']}{grade}",
        f"nut {ids['nut']} (preload {d.preload:.0f} N)",
        f"bearings {ids['bearing']}",
        f"guides {ids['guide']} x{a.guide_blocks}",
    ]
    parts += [f"{slot} {ids[slot]}" for slot in ("motor", "coupling", "reduction") if slot in ids]
    glued = "  ".join(p.replace(" ", "\0") for p in parts)  # break between parts, never inside one
    lines.extend(
        w.replace("\0", " ")
        for w in textwrap.wrap(
            glued, WIDTH, initial_indent="  ", subsequent_indent="  ", break_on_hyphens=False
        )
    )
    assumed = [
        k
        for k in d.assumed
        if not (
            (k == "motor_inertia" and d.motor is not None)
            or (k.startswith("coupling_") and d.coupling is not None)
            or (k.startswith("reduction_") and d.reduction is not None)
        )
    ]
    if assumed:
        shown = [default_shown(a, k) for k in assumed]
        glued = ", ".join(x.replace(" ", "\0") for x in shown)
        lines.extend(
            w.replace("\0", " ")
            for w in textwrap.wrap(
                f"defaults used for: {glued}",
                WIDTH,
                initial_indent="  ",
                subsequent_indent="    ",
                break_on_hyphens=False,
            )
        )
    lines.append("")
    i_min = ev.i_min
    k_tot = float(v["k_total"][i_min])
    comps = ev.components(i_min)
    weakest = ev.weakest
    sets = 2 if a.mounting == "fixed-fixed" else 1
    housing = (
        "housing rigid"
        if v["c_housing"] == 0
        else f"housing {1 / v['c_housing'] / N_PER_UM:,.0f} N/um"
    )
    housing = "housing estimated" if a.bearing_housing_stiffness is None else housing
    labels = {
        "bearings": f"bearings ({sets} set{'s' if sets > 1 else ''}, {housing})",
        "screw": "screw tension",
        "screw torsion": "screw torsion (lead)",
        "coupling": "coupling (lead)" if d.reduction is None else "coupling + reduction (lead)",
        "nut": f"nut at {v['max_axial_force'] / 1e3:.1f} kN",
        "unit bearing": "rotating-nut unit bearing"
        + (" (estimate)" if unit_rigidity_estimated(d) else ""),
        "nut bracket": "nut bracket (estimate)"
        if a.nut_bracket_stiffness is None
        else "nut bracket",
    }
    lines.append(
        f"axial stiffness chain at its softest point ({(ev.x[i_min] - a.start_offset) * 1e3:.0f} "
        "mm along the stroke)"
    )
    lines.append(f"  {'component':<34}{'N/um':>10}{'um/kN':>9}{'share':>8}")
    for name, k in comps.items():
        mark = "  <- weakest link" if name == weakest else ""
        if not np.isfinite(k):
            lines.append(f"  {labels[name]:<34}{'rigid':>10}{'0':>9}{'':>8}  (not given)")
            continue
        lines.append(
            "  "
            f"{labels[name]:<34}{k / N_PER_UM:>10,.1f}{1e9 / k:>9.2f}{k_tot / k * 100:>7.0f}%{mark}"
        )
    if a.mounting == "fixed-fixed":
        k_sb = float(v["k_screw_bearings"][i_min])
        lines.append(
            f"  {'screw + bearings, two paths':<34}{k_sb / N_PER_UM:>10,.1f}{1e9 / k_sb:>9.2f}"
            f"{k_tot / k_sb * 100:>7.0f}%  (in place of the two rows above)"
        )
    lines.append(f"  {'total':<34}{k_tot / N_PER_UM:>10,.1f}{1e9 / k_tot:>9.2f}")
    lines.append(f"  {'table on guides':<34}{'':>10}  (table mode {v['f_table']:.0f} Hz)")
    # the stiffness at the cutting point: the chain in series with the table rocking on its blocks
    k_tool = float(np.asarray(v["k_tool"])[i_min])
    c_rock = float(v["c_rocking"])
    rock = (
        f"{1 / c_rock / N_PER_UM:>10,.1f}{c_rock * 1e9:>9.2f}"
        if c_rock > 0
        else f"{'rigid':>10}{'0':>9}"
    )
    lines.append(
        f"  {'guides pitch/yaw x lever^2':<34}{rock}  (tool {a.tool_height_eff * 1e3:.0f} mm up, "
        f"{a.tool_offset * 1e3:.0f} mm across)"
    )
    lines.append(
        f"  {'stiffness at the tool':<34}{k_tool / N_PER_UM:>10,.1f}{1e9 / k_tool:>9.2f}  (pitch "
        f"{v['f_pitch']:.0f} Hz, yaw {v['f_yaw']:.0f} Hz)"
    )
    lines.extend(
        textwrap.wrap(
            f"carriage: largest block load {v['guide_max_load'] / 1e3:.2f} kN, guide static safety "
            f"f_S {v['guide_static_safety']:.1f} (least {a.guide_static_safety:g}); mean block "
            f"load {v['guide_mean_load'] / 1e3:.2f} kN; nut static safety "
            f"{v['nut_static_safety']:.1f} (least {a.nut_static_safety:g})",
            WIDTH,
            initial_indent="  ",
            subsequent_indent="    ",
        )
    )
    lines.append("")
    lines.append(
        f"{'over the stroke':<22}{'start':>10}{'middle':>10}{'end':>10}{'minimum':>10}"
        f"{'at [mm]':>9}"
    )
    s = ev.x - a.start_offset
    idx = [0, int(np.argmin(np.abs(s - a.stroke / 2))), len(s) - 1]
    rows = (
        ("k_total", "axial stiffness N/um", N_PER_UM),
        ("k_tool", "tool stiffness N/um", N_PER_UM),
        ("f1", "1st frequency Hz", 1.0),
        ("f_axial_torsional", "axial-torsional Hz", 1.0),
        ("damping_ratio", "damping ratio %", 0.01),
    )
    for key, label, scale in rows:
        arr = np.asarray(v[key])
        m, pos = ev.minimum(key)
        lines.append(
            f"  {label:<20}"
            + "".join(f"{arr[i] / scale:>10.1f}" for i in idx)
            + f"{m / scale:>10.1f}{pos * 1e3:>9.0f}"
        )
    lines.append("")
    lines.append(
        f"drag torque {v['drag_torque']:.3f} N.m  (nut {v['drag_nut']:.3f}, bearings "
        f"{v['drag_bearings']:.3f}, guides {v['drag_guides']:.3f}) at {a.max_speed * 60:.0f} m/min"
    )
    lines.append(
        f"moving mass {v['moving_mass']:,.1f} kg   total mass {v['total_mass']:,.1f} kg   "
        f"cost {v['cost']:,.0f} EUR (illustrative prices)"
    )
    sag = float(v["screw_sag"])
    if sag >= SAG_SHOWN:
        lines.extend(
            textwrap.wrap(
                f"screw sag under its own weight {sag * 1e3:.2f} mm between the supports "
                f"{a.span * 1e3:.0f} mm apart (a beam; the nut carries the shaft where it stands, "
                "and a pretension, gone when warm, is not counted; no vendor gives a limit: "
                "limits.max_screw_sag)",
                WIDTH,
                subsequent_indent="  ",
            )
        )
    slender = float(v["screw_slenderness"])
    if slender > SLENDERNESS_SUPPORT:
        lines.extend(
            textwrap.wrap(
                f"warning: the screw is {slender:.0f} diameters long between its supports (span "
                f"{a.span * 1e3:.0f} mm): Schneeberger asks an intermediate support above "
                f"{SLENDERNESS_SUPPORT:g} (consult the maker above {SLENDERNESS_CONSULT:g}); "
                "limits.max_slenderness bounds it",
                WIDTH,
                subsequent_indent="  ",
            )
        )
    lines.extend(twin_lines(ev))
    lines.append(thermal_line(ev))
    lines.extend(budget_lines(ev))
    z = {
        k: float(np.asarray(v[k])[i_min]) * 100
        for k in ("zeta_guides", "zeta_nut", "zeta_bearings", "zeta_structure")
    }
    lines.append(
        f"damping of the axial mode {float(np.asarray(v['damping_ratio'])[i_min]) * 100:.1f} %  "
        f"(guides {z['zeta_guides']:.1f}, nut {z['zeta_nut']:.2f}, bearings "
        f"{z['zeta_bearings']:.2f}, structure {z['zeta_structure']:.1f}; seed T. 5-7)"
    )
    lines.extend(
        textwrap.wrap(
            "drive-train modes (motor free) "
            f"{float(np.asarray(v['f_axial_torsional'])[i_min]):.0f} and "
            f"{float(np.asarray(v['f_axial_torsional_2'])[i_min]):.0f} Hz;  "
            + lost_motion_text(ev),
            WIDTH,
            subsequent_indent="  ",
        )
    )
    lines.append("")
    lines.extend(drive_lines(ev))
    lines.extend(servo_lines(servo_response(ev)))
    lines.extend(life_lines(ev))
    lines.append("")
    lines.extend(check_lines(ev, margins))
    lines.extend(estimate_lines(ev))
    return "\n".join(lines)
