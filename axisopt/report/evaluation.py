"""The evaluation of one design as a text table and a JSON dict, in vendor units (N/um, Hz, mm, N*m).
Nothing here prints."""

from __future__ import annotations

import math
import textwrap

import numpy as np

from ..design import PRETENSION_RISE, TEMPERATURE_RISE, rotating_nut
from ..display import fmt
from ..model import CHECKS, Evaluation, passes
from ..model.checks import DN_RULE_OTHER, DN_RULES
from ..model.function import NOT_APPLICABLE, check_rows, drive_dict  # noqa: F401  (one per check; drive values: in model)
from ..model.limits import CHECK_TABLE, check_name, margin_output
from ..model.loads import balance_summary
from ..model.motorrule import DEFAULT_RULE, rule_text
from ..model.params import axis_params
from ..model.servo import servo_response
from ..units import N_PER_UM
from .accuracy import budget_dict, budget_lines, reduction_lost_motion
from .gantry import twin_dict, twin_lines
from .lifeloads import life_dict, life_lines
from .servo import servo_dict, servo_lines

RPM = 60.0 / (2.0 * math.pi)  # rad/s -> rpm
WIDTH = 100  # terminal columns the text tables fit

# Each check's physical values in the unit vendors quote them in: (unit, factor from SI), DN in mm x rpm; and
# short names for tables with one column per design (both declared with the check in model.limits).
CHECK_UNITS = {c.name: (c.unit, c.factor) for c in CHECK_TABLE}
CHECK_SHORT = {c.name: c.short for c in CHECK_TABLE}
# a horizontal screw's own-weight sag shown in the text from this [m] (long screws; the JSON always has it)
SAG_SHOWN = 1e-4


def fmt_value(x) -> str:
    """A physical value at sensible precision: whole numbers from 100 up (with thousands separators), else
    three significant digits; '-' for a missing or non-finite value."""
    if x is None or not math.isfinite(x):
        return "-"
    if abs(x) >= 100:
        return f"{x:,.0f}"
    return f"{x:.3g}"


def judged_rows(ev: Evaluation, margins: dict | None = None) -> list:
    """:func:`check_rows`, each judged against the least margin a problem sets for it (``margins``: check ->
    margin, the problem's ``limits.margins``; 0 switches a check off): where that is not 1, ``pass`` reads the
    margin against it and ``allowed`` holds it (a table must not say FAIL for a margin the problem allowed)."""
    from ..model.checks import MARGIN_RTOL

    out = []
    for r in check_rows(ev):
        m = (margins or {}).get(r["check"], 1.0)
        if m != 1.0:
            r = {**r, "allowed": m,
                 "pass": m == 0 or r["margin"] is None and r["pass"] or r["margin"] is not None
                 and r["margin"] >= m * (1.0 - MARGIN_RTOL)}
        out.append(r)
    return out


def allowed_list(rows) -> str:
    """'bearing life 0.5, critical speed 1.2': the rows :func:`judged_rows` judged on another margin than 1, with
    that margin ('off' for 0); '' when none."""
    return ", ".join(f"{r['check'].replace('_', ' ')} " + ("off" if r["allowed"] == 0 else f"{r['allowed']:g}")
                     for r in rows if "allowed" in r)


def allowed_note(rows) -> str:
    """'* against the problem's least margin (limits.margins): ...' (:func:`allowed_list`; '' when none)."""
    judged = allowed_list(rows)
    return f"* against the problem's least margin (limits.margins): {judged}" if judged else ""


# checks whose needed value means nothing when the check does not apply (a rotating nut's screw stands still)
NOT_LOADED = ("critical_speed", "dn_limit", "bearing_speed", "coupling_speed")
# THK A-715: "set a negative target value for the reference travel distance assuming a temperature increase of 2
# to 5 degC (-0.02 mm to -0.06 mm/m)": growth beyond 0.06 mm per metre (a rise beyond 5 K) leaves that practice
PRACTICE_GROWTH = 0.06e-3  # [m/m]
PRACTICE_RISE_MAX = 5.0  # [K]
# Schneeberger ball screws, permissible speed: "if Ln/d0 > 50 an intermediate support is needed; consult the maker
# above 40" (tech-doc pages, docs/assumptions.md)
SLENDERNESS_SUPPORT, SLENDERNESS_CONSULT = 50.0, 40.0


def check_lines(ev: Evaluation, margins: dict | None = None) -> list:
    """The checks block of ``evaluate``: available, needed and margin with units (fits 100 columns); with a
    problem's ``margins`` (check -> least margin), pass or FAIL against them (:func:`judged_rows`)."""
    lines = [f"{'checks (margin = available / needed, >= 1 passes)':<50}{'available':>15}{'needed':>15}{'margin':>8}"]
    rows = judged_rows(ev, margins)
    for r in rows:
        unit = f" {r['unit']}" if r["unit"] else ""
        if r["check"] == "bearing_fit":
            have = f"{fmt_value(r['available_min'])}-{fmt_value(r['available'])}{unit}"
            label = "bearing bore / bores the screw end takes"
        else:
            have = fmt_value(r["available"]) + unit if r["available"] is not None else "n/a"
            label = r["label"]
        need = fmt_value(r["needed"]) + unit if r["needed"] else "none"
        margin = "n/a" if r["margin"] is None else f"{r['margin']:.2f}"
        verdict = "pass" if r["pass"] else "FAIL"
        if r["margin"] is None:  # the check does not apply (a standing screw's critical speed, a single nut's
            # preload): no values compared, no verdict
            have, verdict = "n/a", "does not apply"
            need = "-" if r["check"] in NOT_LOADED else need
        lines.append(f"  {label:<48}{have:>15}{need:>15}{margin:>8}  {verdict}" + ("*" if "allowed" in r else ""))
    lines.extend(textwrap.wrap("  rules: " + "; ".join(rule_notes(ev)), WIDTH, subsequent_indent="    "))
    note = allowed_note(rows)
    if note:
        lines.extend(textwrap.wrap(note, WIDTH, initial_indent="  ", subsequent_indent="    "))
    return lines


def rule_notes(ev: Evaluation) -> list:
    """Whose rule each vendor-dependent check applies: the DN by the screw's vendor, the nut lift-off's load
    cases (model.loads.lift_off_load)."""
    d = ev.design
    out = ["DN " + DN_RULES.get(str(d.screw["vendor"]), DN_RULE_OTHER),
           "buckling with the nut a " + ("fixed end (THK A-726)" if d.axis.buckling_nut_end == "fixed" else
                                        "supported end (MiSUMi Selection of Ball Screws 2)")]
    if d.nut["type"] == "double":
        out.append("lift-off: the cut and the inertia at once (axis.cut_while_accelerating)"
                   if d.axis.cut_while_accelerating else
                   "lift-off: each load case its own load (THK A-725: the cut at feed speed, the inertia in the "
                   + ("duty cycle's phases)" if d.axis.duty_cycle else "rapid)"))
    return out

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
    s = (ev.x - axis.start_offset)
    return {
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
        "chain_at_minimum_N_per_um": {k: (_finite(c / N_PER_UM) if math.isfinite(c) else "rigid")
                                      for k, c in ev.components().items()},
        "nut_backlash_um": v["backlash"] * 1e6,
        "pretension_N": v["pretension"],
        "friction_power_W": v["friction_power"], "temperature_rise_K": v["temperature_rise"],
        "heat_balance_rise_K": v["heat_balance_rise"], "heat_transfer_W_per_m2K": v["heat_transfer"],
        "thermal_growth_um": v["thermal_growth"] * 1e6,
        "thermal_displacement_mm": (np.asarray(v["thermal_displacement"]) * 1e3).tolist(),
        "drive_train_modes_Hz": [np.asarray(v["f_axial_torsional"]).tolist(),
                                 np.asarray(v["f_axial_torsional_2"]).tolist()],
        "damping_parts": {k: np.asarray(v[f"zeta_{k}"]).tolist() for k in ("guides", "nut", "bearings", "structure")},
        "bearing_stiffness_N_per_um": v["k_bearing"] / N_PER_UM,
        "table_mode_Hz": v["f_table"],
        "moving_mass_kg": v["moving_mass"],
        "total_mass_kg": v["total_mass"],
        "cost": v["cost"],
        "cost_currency": "EUR",
        "screw_sag_mm": float(v["screw_sag"]) * 1e3,
        "drag_torque_Nm": v["drag_torque"],
        "drag_torque_parts_Nm": {"nut": v["drag_nut"], "bearings": v["drag_bearings"],
                                 "guides": v["drag_guides"]},
        "checks": {r["check"]: {k: x for k, x in r.items() if k not in ("check", "label")} | {"label": r["label"]}
                   for r in check_rows(ev)},
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
        "load_factor": axis.load_factor_eff,  # the fw the life checks read (given, or THK A-704 Table 19)
        # carriage
        "min_tool_stiffness_N_per_um": ev.minimum("k_tool")[0] / N_PER_UM,
        "tool_stiffness_N_per_um": (np.asarray(v["k_tool"]) / N_PER_UM).tolist(),
        "guide_rocking_compliance_um_per_kN": v["c_rocking"] * 1e9,
        "pitch_mode_Hz": v["f_pitch"], "yaw_mode_Hz": v["f_yaw"],
        "guide_max_block_load_N": v["guide_max_load"], "guide_static_safety": v["guide_static_safety"],
        "guide_mean_block_load_N": v["guide_mean_load"], "nut_static_safety": v["nut_static_safety"],
        "servo": servo_dict(servo_response(ev), v["kv"]),
        "positioning_budget": budget_dict(ev),
        "estimated": [e.to_dict() | {"moves": w} for e, w in estimates(ev) if w],
    } | ({"counterbalance": counterbalance_dict(ev)} if axis.counterbalance is not None else {}) | twin_dict(ev)


def _balance(ev: Evaluation) -> dict:
    d = ev.design
    p = axis_params(d.axis, d.screw, d.nut, d.bearing, d.guide, d.motor, d.coupling, d.reduction)
    return {k: float(x) for k, x in balance_summary(p, float(ev.values["moving_mass"])).items()}


def counterbalance_dict(ev: Evaluation) -> dict:
    """A counterbalance's kind and sizes and what it takes off the head [N] (JSON)."""
    cb = ev.design.axis.counterbalance
    b = _balance(ev)
    sizes = ({"mass_kg": cb.mass, "efficiency": cb.efficiency, "chain_mass_kg": cb.chain_mass}
             if cb.kind == "counterweight" else
             {"force_N": cb.force, "force_at_end_N": cb.force_end, "tolerance": cb.tolerance,
              "piston_mass_kg": cb.piston_mass})
    return {"kind": cb.kind, **sizes, "force_at_rest_N": b["rest"], "force_rising_N": b["rising"],
            "force_lowering_N": b["lowering"], "head_weight_N": b["weight"], "net_weight_on_screw_N": b["net"]}


def counterbalance_lines(ev: Evaluation) -> list:
    """``evaluate``'s counterbalance line: what it is and the weight it leaves on the screw."""
    cb = ev.design.axis.counterbalance
    if cb is None:
        return []
    b = _balance(ev)
    if cb.kind == "counterweight":
        what = (f"counterweight {cb.mass:,.0f} kg (chain efficiency {cb.efficiency:g}"
                + (f", chain {cb.chain_mass:g} kg" if cb.chain_mass else "") + f"): {b['rest']:,.0f} N up at rest, "
                f"{b['rising']:,.0f} N rising, {b['lowering']:,.0f} N lowering")
    else:
        what = (f"cylinder {cb.force:,.0f}..{cb.force_end:,.0f} N over the stroke +/- {cb.tolerance * 100:g} %: "
                f"{b['rest']:,.0f} N taken (the end that loads the drive most)")
    text = (f"counterbalance: {what}; the screw carries {b['net']:,.0f} N of the head's {b['weight']:,.0f} N "
            "at rest")
    return textwrap.wrap(text, WIDTH, initial_indent="  ", subsequent_indent="    ")


def _finite(x):
    return float(x) if math.isfinite(x) and abs(x) < 1e8 else None


def evaluation_table(ev: Evaluation, margins: dict | None = None) -> str:
    """The text table ``axisopt evaluate`` prints; ``margins``: a problem's least check margins (``axisopt solve``:
    the checks pass or fail against them, :func:`judged_rows`)."""
    d = ev.design
    v = ev.values
    a = d.axis
    lines = []
    ids = d.part_ids()
    lines.append(f"design {d.name}")
    lines.append(f"  {a.mounting}, stroke {a.stroke * 1e3:.0f} mm, span {a.span * 1e3:.0f} mm, "
                 f"moving mass {a.moving_mass:,.0f} kg (+ nut and blocks)")
    lines.extend(counterbalance_lines(ev))
    grade = f" grade {d.screw_grade}" if d.screw_grade is not None else ""
    parts = [f"screw {ids['screw']}{grade}", f"nut {ids['nut']} (preload {d.preload:.0f} N)",
             f"bearings {ids['bearing']}", f"guides {ids['guide']} x{a.guide_blocks}"]
    parts += [f"{slot} {ids[slot]}" for slot in ("motor", "coupling", "reduction") if slot in ids]
    glued = "  ".join(p.replace(" ", "\0") for p in parts)  # break between parts, never inside one
    lines.extend(w.replace("\0", " ") for w in textwrap.wrap(glued, WIDTH, initial_indent="  ",
                                                             subsequent_indent="  ", break_on_hyphens=False))
    assumed = [k for k in d.assumed if not ((k == "motor_inertia" and d.motor is not None)
                                            or (k.startswith("coupling_") and d.coupling is not None)
                                            or (k.startswith("reduction_") and d.reduction is not None))]
    if assumed:
        shown = [_default_shown(a, k) for k in assumed]
        glued = ", ".join(x.replace(" ", "\0") for x in shown)
        lines.extend(w.replace("\0", " ") for w in textwrap.wrap(
            f"defaults used for: {glued}", WIDTH, initial_indent="  ", subsequent_indent="    ",
            break_on_hyphens=False))
    lines.append("")
    i_min = ev.i_min
    k_tot = float(v["k_total"][i_min])
    comps = ev.components(i_min)
    weakest = ev.weakest
    sets = 2 if a.mounting == "fixed-fixed" else 1
    housing = "housing rigid" if v["c_housing"] == 0 else f"housing {1 / v['c_housing'] / N_PER_UM:,.0f} N/um"
    housing = "housing estimated" if a.bearing_housing_stiffness is None else housing
    labels = {"bearings": f"bearings ({sets} set{'s' if sets > 1 else ''}, {housing})",
              "screw": "screw tension", "screw torsion": "screw torsion (lead)",
              "coupling": "coupling (lead)" if d.reduction is None else "coupling + reduction (lead)",
              "nut": f"nut at {v['max_axial_force'] / 1e3:.1f} kN",
              "unit bearing": "rotating-nut unit bearing" + (" (estimate)" if _unit_rigidity_estimated(d) else ""),
              "nut bracket": "nut bracket (estimate)" if a.nut_bracket_stiffness is None else "nut bracket"}
    lines.append(f"axial stiffness chain at its softest point ({(ev.x[i_min] - a.start_offset) * 1e3:.0f} mm "
                 f"along the stroke)")
    lines.append(f"  {'component':<34}{'N/um':>10}{'um/kN':>9}{'share':>8}")
    for name, k in comps.items():
        mark = "  <- weakest link" if name == weakest else ""
        if not np.isfinite(k):
            lines.append(f"  {labels[name]:<34}{'rigid':>10}{'0':>9}{'':>8}  (not given)")
            continue
        lines.append(f"  {labels[name]:<34}{k / N_PER_UM:>10,.1f}{1e9 / k:>9.2f}{k_tot / k * 100:>7.0f}%{mark}")
    if a.mounting == "fixed-fixed":
        k_sb = float(v["k_screw_bearings"][i_min])
        lines.append(f"  {'screw + bearings, two paths':<34}{k_sb / N_PER_UM:>10,.1f}{1e9 / k_sb:>9.2f}"
                     f"{k_tot / k_sb * 100:>7.0f}%  (in place of the two rows above)")
    lines.append(f"  {'total':<34}{k_tot / N_PER_UM:>10,.1f}{1e9 / k_tot:>9.2f}")
    lines.append(f"  {'table on guides':<34}{'':>10}  (table mode {v['f_table']:.0f} Hz)")
    # the stiffness at the cutting point: the chain in series with the table rocking on its blocks
    k_tool = float(np.asarray(v["k_tool"])[i_min])
    c_rock = float(v["c_rocking"])
    rock = f"{1 / c_rock / N_PER_UM:>10,.1f}{c_rock * 1e9:>9.2f}" if c_rock > 0 else f"{'rigid':>10}{'0':>9}"
    lines.append(f"  {'guides pitch/yaw x lever^2':<34}{rock}  (tool {a.tool_height_eff * 1e3:.0f} mm up, "
                 f"{a.tool_offset * 1e3:.0f} mm across)")
    lines.append(f"  {'stiffness at the tool':<34}{k_tool / N_PER_UM:>10,.1f}{1e9 / k_tool:>9.2f}  (pitch "
                 f"{v['f_pitch']:.0f} Hz, yaw {v['f_yaw']:.0f} Hz)")
    lines.extend(textwrap.wrap(
        f"carriage: largest block load {v['guide_max_load'] / 1e3:.2f} kN, guide static safety f_S "
        f"{v['guide_static_safety']:.1f} (least {a.guide_static_safety:g}); mean block load "
        f"{v['guide_mean_load'] / 1e3:.2f} kN; nut static safety {v['nut_static_safety']:.1f} "
        f"(least {a.nut_static_safety:g})", WIDTH, initial_indent="  ", subsequent_indent="    "))
    lines.append("")
    lines.append(f"{'over the stroke':<22}{'start':>10}{'middle':>10}{'end':>10}{'minimum':>10}{'at [mm]':>9}")
    s = ev.x - a.start_offset
    idx = [0, int(np.argmin(np.abs(s - a.stroke / 2))), len(s) - 1]
    rows = (("k_total", "axial stiffness N/um", N_PER_UM), ("k_tool", "tool stiffness N/um", N_PER_UM),
            ("f1", "1st frequency Hz", 1.0),
            ("f_axial_torsional", "axial-torsional Hz", 1.0), ("damping_ratio", "damping ratio %", 0.01))
    for key, label, scale in rows:
        arr = np.asarray(v[key])
        m, pos = ev.minimum(key)
        lines.append(f"  {label:<20}" + "".join(f"{arr[i] / scale:>10.1f}" for i in idx)
                     + f"{m / scale:>10.1f}{pos * 1e3:>9.0f}")
    lines.append("")
    lines.append(f"drag torque {v['drag_torque']:.3f} N.m  (nut {v['drag_nut']:.3f}, bearings "
                 f"{v['drag_bearings']:.3f}, guides {v['drag_guides']:.3f}) at {a.max_speed * 60:.0f} m/min")
    lines.append(f"moving mass {v['moving_mass']:,.1f} kg   total mass {v['total_mass']:,.1f} kg   "
                 f"cost {v['cost']:,.0f} EUR (illustrative prices)")
    sag = float(v["screw_sag"])
    if sag >= SAG_SHOWN:
        lines.extend(textwrap.wrap(
            f"screw sag under its own weight {sag * 1e3:.2f} mm between the supports {a.span * 1e3:.0f} mm apart "
            "(a beam; the nut carries the shaft where it stands, and a pretension, gone when warm, is not "
            "counted; no vendor gives a limit: limits.max_screw_sag)", WIDTH, subsequent_indent="  "))
    slender = float(v["screw_slenderness"])
    if slender > SLENDERNESS_SUPPORT:
        lines.extend(textwrap.wrap(
            f"warning: the screw is {slender:.0f} diameters long between its supports (span {a.span * 1e3:.0f} mm): "
            f"Schneeberger asks an intermediate support above {SLENDERNESS_SUPPORT:g} (consult the maker above "
            f"{SLENDERNESS_CONSULT:g}); limits.max_slenderness bounds it", WIDTH, subsequent_indent="  "))
    lines.extend(twin_lines(ev))
    lines.append(_thermal_line(ev))
    lines.extend(budget_lines(ev))
    z = {k: float(np.asarray(v[k])[i_min]) * 100
         for k in ("zeta_guides", "zeta_nut", "zeta_bearings", "zeta_structure")}
    lines.append(f"damping of the axial mode {float(np.asarray(v['damping_ratio'])[i_min]) * 100:.1f} %  (guides "
                 f"{z['zeta_guides']:.1f}, nut {z['zeta_nut']:.2f}, bearings {z['zeta_bearings']:.2f}, structure "
                 f"{z['zeta_structure']:.1f}; seed T. 5-7)")
    lines.extend(textwrap.wrap(
        f"drive-train modes (motor free) {float(np.asarray(v['f_axial_torsional'])[i_min]):.0f} and "
        f"{float(np.asarray(v['f_axial_torsional_2'])[i_min]):.0f} Hz;  " + _lost_motion_text(ev),
        WIDTH, subsequent_indent="  "))
    lines.append("")
    lines.extend(drive_lines(ev))
    lines.extend(servo_lines(servo_response(ev)))
    lines.extend(life_lines(ev))
    lines.append("")
    lines.extend(check_lines(ev, margins))
    lines.extend(estimate_lines(ev))
    return "\n".join(lines)


# outputs an evaluation names the estimates of (besides the checks near their limit)
_EST_OUTPUTS = (("k_total", "min stiffness"), ("f1", "min frequency"), ("drag_torque", "drag torque"),
                ("life", "nut life"))
NEAR_LIMIT = 1.1  # a check with margin below this counts as near its limit


# defaults the life, torque and heat checks read, shown with their value: (axis attribute, display unit, SI per unit)
# (the temperature rise has its own line: the thermal block says where it comes from)
_DEFAULT_VALUES = {"mean_axial_load": ("mean_axial_load_eff", "N", 1.0),
                   "mean_speed": ("mean_speed_eff", "m/min", 1 / 60),
                   "required_life": ("required_life", "h", 3600.0), "load_factor": ("load_factor_eff", "", 1.0)}


def _default_shown(axis, key: str) -> str:
    """A defaulted axis key as the evaluation names it: with its value where the checks read it."""
    if key not in _DEFAULT_VALUES:
        return key
    attr, unit, factor = _DEFAULT_VALUES[key]
    value = getattr(axis, attr, None)
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        return key
    from ..model.estimates import axis_value_text

    return f"{key} {axis_value_text(value / factor, unit)}"


def estimates(ev: Evaluation) -> list:
    """[(Estimate, [what it moves])] for the design's estimated part values except prices (which move only the
    cost and are always illustrative): the key outputs and the checks within 10 % of their limit."""
    from ..model.estimates import design_estimates, resting_on

    est = [e for e in design_estimates(ev.design) if "price" not in e.column]
    if not est:
        return []
    near = [margin_output(c) for c in CHECKS if float(ev.values[margin_output(c)]) < NEAR_LIMIT]
    names = dict(_EST_OUTPUTS) | {m: f"check {check_name(m).replace('_', ' ')}" for m in near}
    moved = resting_on(ev.design, list(names), est)
    return [(e, [names[o] for o in names if any(x is e for x in moved.get(o, ()))]) for e in est]


def estimate_lines(ev: Evaluation) -> list:
    rows = [(e, w) for e, w in estimates(ev) if w]
    if not rows:
        return []
    out = ["", "estimated values (not in the vendor's table; catalogs/SOURCES.md) and what they move:"]
    for e, what in rows:
        out.extend(textwrap.wrap(f"{e.text()} moves "
                                 f"{', '.join(what)}", WIDTH, initial_indent="  ", subsequent_indent="      "))
    return out




def drive_lines(ev: Evaluation) -> list:
    """The drive block of ``evaluate``: motor, coupling, duty cycle, torques, speed, inertia, brake."""
    d, v, a = ev.design, ev.values, ev.design.axis
    if d.motor is None:
        return ["drive: no motor given (parts.motor); rotor inertia "
                f"{fmt(a.motor_inertia, 'kg.m^2')} assumed for the drive-train modes", ""]
    m = d.motor
    r = d.reduction
    ratio = a.reduction_ratio if r is None else float(r["ratio"])
    if r is not None:
        red = (f"reduction {r['id']} ({r['vendor']} {r['kind']}; {ratio:g}:1, efficiency {float(r['efficiency']):g}, "
               f"{float(r['inertia']) * 1e4:.3g} kg.cm^2 at the input, {float(r['torsional_stiffness']):,.0f} "
               f"N.m/rad, backlash {float(r['backlash']) * 10800 / math.pi:g} arcmin"
               + (f", {fmt(float(r['mass']), 'kg')}" if math.isfinite(float(r["mass"])) else "") + ")")
    else:
        red = "direct" if ratio == 1 else f"reduction {ratio:g}:1, efficiency {a.reduction_efficiency:g}"
    cpl = f"coupling {d.coupling['id']}" if d.coupling is not None else "coupling from the axis values"
    cycle = (f"{len(a.duty_cycle)}-entry duty cycle" if a.duty_cycle
             else "rapid move over the stroke and back, no dwell (default)")
    lines = [*textwrap.wrap(f"drive: motor {m['id']} ({m['vendor']}; rated {fmt(m['rated_torque'], 'N.m')}, peak "
                            f"{fmt(m['peak_torque'], 'N.m')}, max {m['max_speed'] * RPM:,.0f} rpm)", WIDTH,
                            subsequent_indent="    "),
             *textwrap.wrap(f"{cpl}, {red}", WIDTH, initial_indent="  ", subsequent_indent="    "),
             *textwrap.wrap(f"{cycle}: {v['duty_time']:.2f} s;  friction {v['friction_torque']:.3f} N.m"
                            + (f", gravity {v['gravity_torque']:.3f} N.m" if a.orientation == "vertical" else ""),
                            WIDTH, initial_indent="  ", subsequent_indent="    ")]
    scaled = abs(v["needed_motor_peak_torque"] - v["peak_torque"]) > 1e-9 * v["peak_torque"]
    rms_ratio = float(v["available_motor_rated_torque"]) / float(m["rated_torque"])
    unb_ratio = _row_number(m, "unbalance_ratio", DEFAULT_RULE.unbalance)
    peak = float(v["available_motor_peak_torque"])
    limited = "" if a.torque_limit is None else f", axis.torque_limit {fmt(a.torque_limit, 'N.m')}"
    # the needed column holds what the check compares: the cycle's peak scaled to the flat peak where the motor's
    # zone falls at speed (the cycle's own peak on the line below)
    rows = [("peak torque (cycle, thrust)", f"{v['needed_motor_peak_torque']:.3f} N.m" + (" *" if scaled else ""),
             f"{fmt(peak, 'N.m')} (motor peak, zone by speed{limited})"),
            ("RMS torque, mean thrust", f"{v['rms_torque']:.3f}, {v['mean_thrust_torque']:.3f} N.m",
             f"{rms_ratio:g} x {fmt(m['rated_torque'], 'N.m')} (rated)"),
            ("motor speed", f"{v['motor_speed'] * RPM:,.0f} rpm", f"{m['max_speed'] * RPM:,.0f} rpm (max)"),
            ("inertia ratio load/rotor", f"{v['inertia_ratio']:.2f} ({fmt(v['load_inertia'] * 1e4, 'kg.cm^2')})",
             f"{a.max_inertia_ratio:g} (axis.max_inertia_ratio)")]
    if a.orientation == "vertical":
        rows.append(("unbalanced load torque", f"{v['unbalance_torque']:.3f} N.m",
                     f"{unb_ratio:g} x {fmt(m['rated_torque'], 'N.m')} (rated)"))
        brake = float(m["brake_torque"]) if math.isfinite(float(m["brake_torque"])) else 0.0
        rows.append(("holding torque at a stop", f"{v['holding_torque']:.3f} N.m",
                     f"{fmt(brake, 'N.m')} brake / {a.brake_safety:g}" if brake else "no brake listed"))
    if d.coupling is not None:
        rows.append(("coupling torque", f"{fmt(peak * ratio, 'N.m')} (motor peak)",
                     f"{fmt(d.coupling['rated_torque'], 'N.m')} (rated)"))
    if r is not None:
        rows.append(("output torque peak (cycle)", fmt(v["output_peak_torque"], "N.m"),
                     f"{fmt(float(r['accel_torque']), 'N.m')} (T2B)"))
        rows.append(("output torque RMS, thrust", fmt(v["output_rms_torque"], "N.m"),
                     f"{fmt(float(r['rated_torque']), 'N.m')} (T2N)"))
        stop = "T2Stop" if math.isfinite(_row_number(r, "emergency_torque", math.nan)) else "T2B, no T2Stop listed"
        rows.append(("E-stop: motor peak x ratio", fmt(v["needed_reduction_emergency_torque"], "N.m"),
                     f"{fmt(v['available_reduction_emergency_torque'], 'N.m')} ({stop})"))
    lines.append(f"  {'':<28}{'needed':>26}   available")
    for name, need, have in rows:
        lines.extend(textwrap.wrap(f"  {name:<28}{need:>26}   {have}", WIDTH, subsequent_indent=" " * 59))
    if scaled:
        lines.extend(textwrap.wrap(f"    * the cycle's peak {v['peak_torque']:.3f} N.m scaled to the motor's flat "
                                   "peak (its zone falls at the speed of that peak): what the check compares",
                                   WIDTH, subsequent_indent="      "))
    lines.extend(textwrap.wrap("motor rule: " + rule_text(str(m["vendor"]), rms_ratio, unb_ratio,
                                                          a.rms_torque_ratio),
                               WIDTH, initial_indent="  ", subsequent_indent="    "))
    lines.extend(textwrap.wrap(
        f"regeneration {v['regen_energy']:,.0f} J per cycle back from the motor, {v['regen_power']:,.0f} W mean "
        "(braking" + (", lowering" if a.orientation == "vertical" else "") + "; before winding and drive losses): "
        "what the drive's regenerative resistor must take (Yaskawa 12.8.6), not checked", WIDTH,
        initial_indent="  ", subsequent_indent="    "))
    lines.append("")
    return lines


def _lost_motion_text(ev) -> str:
    """The lost motion at the table by its cause: the nut's play and a reduction's backlash, each named."""
    red = reduction_lost_motion(ev.design)
    nut = float(ev.values["backlash"]) - red
    if ev.design.reduction is None:
        return f"nut backlash {nut * 1e6:.0f} um"
    return f"lost motion: nut {nut * 1e6:.0f} um, reduction {red * 1e6:.0f} um"


def _row_number(row, col: str, default: float) -> float:
    """A part row's number in ``col``; ``default`` where it is empty or the table has no such column."""
    try:
        v = float(row[col])
    except (KeyError, TypeError, ValueError):
        return default
    return v if math.isfinite(v) else default


def _unit_rigidity_estimated(design) -> bool:
    """A rotating-nut unit whose row lists no bearing rigidity (the model's estimate stands in)."""
    v = design.nut.get("unit_bearing_rigidity", math.nan) if hasattr(design.nut, "get") else math.nan
    return not (isinstance(v, float) and math.isfinite(v))


def thermal_warning(ev: Evaluation) -> str:
    """A warning where the thermal growth at the nut exceeds THK A-715's planning range (a negative target
    travel of -0.02 to -0.06 mm/m for a 2-5 degC rise: PRACTICE_GROWTH per metre from the fixed bearing), or
    where the practice rise is used but the heat balance of the default cycle would exceed it ('' if neither)."""
    a, v = ev.design.axis, ev.values
    x_far = a.start_offset + a.stroke
    allowed = PRACTICE_GROWTH * x_far
    growth = float(v["thermal_growth"])
    out = []
    if growth > allowed * (1 + 1e-9):
        out.append(f"thermal growth {growth * 1e6:.0f} um exceeds THK A-715's planning range (0.06 mm/m, a "
                   f"5 degC rise: {allowed * 1e6:.0f} um at {x_far * 1e3:.0f} mm from the fixed bearing); "
                   "limits.max_thermal_growth bounds it, a cooled screw (axis.heat_transfer), a lower preload "
                   "or a scale (feedback) takes it out")
    balance = float(v["heat_balance_rise"])
    if not a.rise_from_balance and a.temperature_rise is None and balance > PRACTICE_RISE_MAX:
        out.append(f"the heat balance of continuous rapids gives +{balance:.3g} K, above THK A-715's 2-5 degC "
                   "planning range the practice rise assumes (axis.rise_without_cycle: balance uses it)")
    return ("warning: " + "; ".join(out)) if out else ""


def _thermal_line(ev: Evaluation) -> str:
    a, v = ev.design.axis, ev.values
    u = np.asarray(v["thermal_displacement"])
    text = (f"thermal: +{float(v['temperature_rise']):.3g} K moves the nut up to {np.max(np.abs(u)) * 1e3:.3f} mm "
            f"(alpha 11.6e-6/K, HIWIN F 3.36)")
    used = a.rise_from_balance
    how = ("rise from the heat balance of the duty cycle" if used and a.duty_cycle else
           f"rise from the heat balance of the default cycle (axis.rise_without_cycle: balance; the practice rise "
           f"would be {TEMPERATURE_RISE:g} K), continuous rapids" if used else
           "rise as given; the heat balance" if a.temperature_rise is not None else
           "rise: THK A-715's practice rise (axis.rise_without_cycle: practice), no duty cycle; the heat balance "
           "of continuous rapids")
    film = ("axis.heat_transfer" if a.heat_transfer is not None else
            "free convection: a standing screw under a rotating nut" if rotating_nut(ev.design.nut) else
            "Jungnickel rotating shaft over the cycle, with free convection")
    rise = "" if used else f" would give +{float(v['heat_balance_rise']):.3g} K"
    balance = (f"{how}: friction power {float(v['friction_power']):.3g} W (nut and bearings at the cycle's mean "
               f"screw speed) through a lumped network (Jungnickel 2010): shaft film "
               f"{float(v['heat_transfer']):.3g} W/(m^2.K) ({film}), conduction through the nut bracket and the "
               f"shaft ends (estimated conductances, docs/assumptions.md){rise}")
    text += "\n" + "\n".join(textwrap.wrap(balance, WIDTH, initial_indent="  ", subsequent_indent="    "))
    warn = thermal_warning(ev)
    if warn:
        text += "\n" + "\n".join(textwrap.wrap(warn, WIDTH, initial_indent="  ", subsequent_indent="    "))
    if a.mounting == "fixed-fixed":
        pre, push = float(v["pretension"]), float(v["thermal_force"])
        design = PRETENSION_RISE if a.pretension_rise is None else a.pretension_rise
        how_pre = f"absorbs a design rise of {design:g} K, THK A-715" if a.pretension is None else "as given"
        rest = (f"{(push - pre) / 1e3:.1f} kN beyond it compresses the screw" if push > pre
                else "the screw stays in tension")
        pre_line = (f"pretension {pre / 1e3:.1f} kN ({how_pre}); the rise pushes the elastic ends with "
                    f"{push / 1e3:.1f} kN: {rest}; bearing static load {v['bearing_static_load'] / 1e3:.1f} kN")
        text += "\n" + "\n".join(textwrap.wrap(pre_line, WIDTH, initial_indent="  ", subsequent_indent="    "))
    return text


def fit_lines(text: str, width: int = 100) -> str:
    """Wrap each line longer than ``width`` at spaces, its continuation indented under it (tables are built
    to fit; this catches prose: notes, misses, messages)."""
    out = []
    for line in text.split("\n"):
        if len(line) <= width:
            out.append(line)
            continue
        lead = " " * (len(line) - len(line.lstrip(" ")))
        out.extend(textwrap.wrap(line, width, initial_indent="", subsequent_indent=lead + "    ",
                                 break_on_hyphens=False, drop_whitespace=True) or [line])
    return "\n".join(out)
