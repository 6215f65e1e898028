r"""Independent check of an axis by the part vendors' own selection procedures (issue 38, done-when
item 2).

Usage::

    python tools/vendor_check.py problems/teaching_problem.yaml      # solves it, then checks the optimum
    python tools/vendor_check.py problems/vmc_x_design.yaml          # checks a design as it is
    python tools/vendor_check.py P.yaml --json out.json              # the rows as JSON too

Written apart from axisopt's physics on purpose: nothing here imports ``axisopt``.  axisopt is
called only as a program (``python -m axisopt solve|evaluate ... --json``); the design's keys are
read from its YAML, the chosen parts' rows straight from ``catalogs/*.csv`` (units from the
headers), and every number is recomputed here by the vendor's printed procedure (the source of each
is in its function's docstring and in the printed table).  For each check the table shows the
vendor's value and limit, the vendor's margin with PASS/FAIL by the vendor's criterion, axisopt's
margin and their ratio; ``AGREE`` where both use the same method and agree within :data:`TOLERANCE`,
``DIFF`` where they differ by more, ``CONV`` where the two use different conventions on purpose (the
note says which; docs/validation.md lists them).

Vendor texts (git mirror ArtemFilin1990/Mar, see /work/research/38_conventions.md for the paths):
T-GC THK General Catalog (ball screw A15, LM guide A1); H-BS HIWIN Ballscrews BS-08-2-EN-1704-K;
H-LG HIWIN Linear Guideway G99TE20-1808; NSK-SP NSK super-precision bearings; IBC TI-I-5010.2/E; IKO
CAT-1578E.

Estimates of this checker (no vendor figure; printed in the notes): the screw axis at the rail
mounting plane under the table centre (the block loads); the cross and normal cutting components
scale with a phase's feed force; screw length for the inertia = bearing span (journals not known);
trapezoidal moves (jerk ignored); with a gearbox, the feed thrust (axis.axial_load) and the mean
thrust (axis.mean_axial_load) as steady output torques beside the cycle's (T2B, T2N rows).
"""  # noqa: E501

from __future__ import annotations

import argparse
import csv
import json
import math
import re
import subprocess
import sys
import tempfile
from dataclasses import asdict, dataclass, replace
from pathlib import Path

import numpy as np
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))
import vendor_procedures as vp  # noqa: E402  (this checker's own formulas, no axisopt)
import vendor_rules as vr  # noqa: E402  (the per-vendor rules: servo, lift-off load cases, gearbox E-stop)
from vendor_procedures import UNITS, Row, quantity  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TOLERANCE = 0.02  # agreement of vendor and axisopt margins where both use the same method
G = 9.80665


def catalog_row(kind: str, part) -> dict:
    """A part's row from catalogs/<kind>.csv in SI (units from the headers), or an inline
    mapping."""
    # an inline part: vendor and series default to 'custom' (as axisopt reads it)
    if isinstance(part, dict):
        row = {
            k: (quantity(v) if not isinstance(v, str) or re.match(r"^[-0-9.]", v) else v)
            for k, v in part.items()
        }
        return {"vendor": "custom", "series": "custom"} | row
    with open(ROOT / "catalogs" / f"{kind}.csv", newline="", encoding="utf-8") as fh:
        for row in csv.DictReader(fh):
            if row["id"] != part:
                continue
            out = {}
            for head, text in row.items():
                m = re.fullmatch(r"(\w+) \[(.+)\]", head)
                name, unit = (m.group(1), m.group(2)) if m else (head, None)
                out[name] = (float(text) * UNITS[unit] if text else None) if unit else text
            return out
    raise KeyError(f"{part} not in catalogs/{kind}.csv")


# --- axisopt as a program
# -------------------------------------------------------------------------------------
def run_axisopt(path: Path, workdir: Path) -> tuple[Path | None, dict]:
    """Solve a problem (saving its optimum as a design) or take a design; evaluate it.  Returns the
    design file and the evaluate JSON; where the optimum is not a screw drive (a linear motor,
    a rack: --save-design then writes its drive_design, not a screw design), (None, the solve's
    JSON) for the drive checker."""
    text = path.read_text(encoding="utf-8")
    design = path
    cmd = [sys.executable, "-m", "axisopt"]
    if re.search(r"^objective:", text, re.M):
        design = workdir / "optimum.yaml"
        run = subprocess.run(
            cmd + ["solve", str(path), "--no-sensitivity", "--save-design", str(design)],
            check=True,
            capture_output=True,
            text=True,
        )
        saved = yaml.safe_load(design.read_text(encoding="utf-8")) if design.exists() else None
        # the optimum is another drive type: said on stderr, and --save-design writes its
        # drive_design section (not a screw design)
        if "beats the screw drive" in run.stderr or (
            isinstance(saved, dict) and "drive_design" in saved
        ):
            solved = workdir / "solve.json"
            subprocess.run(
                cmd + ["solve", str(path), "--no-sensitivity", "--top", "1", "--json", str(solved)],
                check=True,
                capture_output=True,
                text=True,
            )
            res = json.loads(solved.read_text(encoding="utf-8"))
            if (res.get("best") or {}).get("drive_type", "screw") != "screw":
                return None, res
    out = workdir / "evaluate.json"
    subprocess.run(
        cmd + ["evaluate", str(design), "--json", str(out)],
        check=True,
        capture_output=True,
        text=True,
    )
    return design, json.loads(out.read_text(encoding="utf-8"))


# --- the axis as the vendor's procedure needs it
# ------------------------------------------------------------
@dataclass
class Axis:
    stroke: float
    start: float
    span: float
    mounting: str
    vertical: bool
    wall: bool
    v_max: float
    a_max: float
    axial_load: float
    mean_load: float
    mean_speed: float
    mean_speed_given: bool
    life_h: float
    load_factor: float | None
    blocks: int
    normal: float
    cross: float
    h_tool: float
    y_tool: float
    h_cg: float
    y_cg: float
    block_spacing: float
    rail_spacing: float
    rails: int
    housing_k: float | None
    bracket_k: float | None
    temp_rise: float | None
    ratio: float
    red_eff: float
    red_inertia: float
    max_inertia_ratio: float
    brake: str
    duty: list
    table_mass: float
    rms_asked: float | None = None  # axis.rms_torque_ratio (None: the motor vendor's rule)
    torque_limit: float | None = None  # axis.torque_limit [N.m]
    cut_while_accelerating: bool = False


def read_axis(design: dict) -> Axis:
    """The design's axis keys, with the defaults docs/files.md states for those not given."""
    a = design["axis"]

    def q(key, default=None):
        return quantity(a[key]) if key in a else default

    stroke, table_len = q("stroke"), q("table_length", 0.5)
    start = q("start_offset", 0.130)
    width = q("table_width", table_len)
    axial = q("axial_load")
    return Axis(
        stroke=stroke,
        start=start,
        span=start + stroke + q("end_margin", 0.150),
        mounting=a["mounting"],
        vertical=a.get("orientation") == "vertical",
        wall=a.get("orientation") == "wall",
        v_max=q("max_speed"),
        a_max=q("acceleration", 0.0),
        axial_load=axial,
        mean_load=q("mean_axial_load", axial / 3.0),
        mean_speed=q("mean_speed", q("max_speed") / 2.0),
        mean_speed_given="mean_speed" in a,
        life_h=q("required_life", 20000 * 3600.0) / 3600.0,
        load_factor=float(a["load_factor"]) if "load_factor" in a else None,
        blocks=int(a.get("guide_blocks", 4)),
        normal=q("normal_load", 0.0),
        cross=q("cross_load", 0.0),
        h_tool=q("tool_height", 0.4 * table_len),
        y_tool=q("tool_offset", 0.0),
        h_cg=q("cg_height", 0.2 * table_len),
        y_cg=q("cg_offset", 0.0),
        block_spacing=q("block_spacing", 0.6 * table_len),
        rail_spacing=q("rail_spacing", 0.6 * width),
        rails=int(a.get("rails", 2)),
        housing_k=q("bearing_housing_stiffness"),
        bracket_k=q("nut_bracket_stiffness"),
        # the rise the pretension is designed for: axis.pretension_rise where given (the shaft's
        # design rise), else axis.temperature_rise, else THK's 3 K
        temp_rise=(
            q("pretension_rise")
            if "pretension_rise" in a
            else q("temperature_rise")
            if "temperature_rise" in a
            else None
        ),
        ratio=float(a.get("reduction_ratio", 1.0)),
        red_eff=float(a.get("reduction_efficiency", 1.0)),
        red_inertia=q("reduction_inertia", 0.0),
        max_inertia_ratio=float(a.get("max_inertia_ratio", 5.0)),
        brake=str(a.get("brake", "auto")),
        duty=list(a.get("duty_cycle") or []),
        table_mass=q("moving_mass"),
        rms_asked=float(a["rms_torque_ratio"]) if "rms_torque_ratio" in a else None,
        torque_limit=vr.torque_limit(a),
        cut_while_accelerating=a.get("cut_while_accelerating") is True,
    )


def compare(vendor, theirs, same_method=True) -> str:
    if theirs is None or vendor is None:
        return "INFO"
    if not same_method:
        return "CONV"
    return "AGREE" if abs(vendor / theirs - 1.0) <= TOLERANCE else "DIFF"


def check_design(design: dict, ev: dict) -> list[Row]:
    """Every vendor check of one evaluated design."""
    ax = read_axis(design)
    parts = design["parts"]
    screw, nut = catalog_row("screws", parts["screw"]), catalog_row("nuts", parts["nut"])
    brg, guide = catalog_row("bearings", parts["bearing"]), catalog_row("guides", parts["guide"])
    motor = catalog_row("motors", parts["motor"]) if "motor" in parts else None
    coupling = catalog_row("couplings", parts["coupling"]) if "coupling" in parts else None
    red = catalog_row("reductions", parts["reduction"]) if parts.get("reduction") else None
    if red:  # the part's row takes the place of the axis keys (ratio, efficiency, input inertia)
        ax.ratio, ax.red_eff, ax.red_inertia = red["ratio"], red["efficiency"], red["inertia"]
    rotating = str(nut.get("rotating") or "").strip() in ("1", "1.0")
    preload = quantity(parts["nut_preload"]) if "nut_preload" in parts else ev["nut_preload_N"]
    chk = ev["checks"]
    rows: list[Row] = []

    def theirs(name, field="available", scale=1.0):
        c = chk.get(name)
        return None if c is None or c.get(field) is None else c[field] * scale

    def their_margin(name):
        c = chk.get(name)
        return None if c is None else c["margin"]

    # masses and loads (THK A-725: Fa = mu m g + f + m alpha, + m g on a vertical axis, A-739)
    moving = ax.table_mass + nut["mass"] + ax.blocks * guide["block_mass"]

    # the guides' resistance under a moving mass (THK A-725: mu (m g + N) + f)
    def guide_friction(mass):
        on_rails = 0.0 if (ax.vertical or ax.wall) else mass * G
        return (
            guide["friction_coefficient"] * (on_rails + ax.normal)
            + ax.blocks * guide["friction_force"]
        )

    friction = guide_friction(moving)
    # what the guides carry
    ax_guides, moving_guides, friction_guides = replace(ax), moving, friction
    tw = design["axis"].get("twin_drive")
    # each drive checked as its governing side: its share of the mass, friction and process force
    if tw:
        r, side, whole = vp.twin_side(
            tw, ax.table_mass, nut["mass"], ax.blocks * guide["block_mass"]
        )
        moving_guides = whole
        friction_guides = guide_friction(whole)
        ax_guides = replace(
            ax, table_mass=whole - 2 * nut["mass"] - ax.blocks * guide["block_mass"]
        )
        moving, friction = side, friction_guides * side / whole
        ax.axial_load, ax.mean_load, ax.force_share = r * ax.axial_load, r * ax.mean_load, r
    weight = moving * G if ax.vertical else 0.0
    # the weight on the screw by direction; the mass the drive accelerates
    weights, accel = weight, moving
    cb = design["axis"].get("counterbalance")
    if cb and cb.get("kind", "none") != "none" and ax.vertical:
        weights, extra = vp.counterbalance_weights(cb, weight)
        accel = moving + extra
        weight = weights(0)  # at rest: the holding torque
    phases, cycle_given = vp.duty_phases(ax, accel, friction, weights)
    a_peak = max([ax.a_max] + [abs(p.acc) for p in phases])
    net = max(abs(weights(1)), abs(weights(-1))) if callable(weights) else weight
    f_max = ax.axial_load + accel * a_peak + friction + net
    lead, d1, d0 = (
        screw["lead"] * 1e3,
        screw["root_diameter"] * 1e3,
        screw["nominal_diameter"] * 1e3,
    )
    n_max = ax.v_max * 60.0 / (lead * 1e-3)  # [rpm]
    svendor = screw["vendor"]
    ff = ax.mounting == "fixed-fixed"
    x_far = (ax.start + ax.stroke) * 1e3
    span = ax.span * 1e3

    # 1 permissible rotational speed (critical speed, mounting factor) and DN; a rotating nut: the
    # nut's DN only
    if rotating:
        n_nut, dp = vp.nut_rotation_speed_limit(d0, screw["dn_limit"])
        rows.append(
            Row(
                "rotating nut permissible speed",
                "rpm",
                n_nut,
                n_max,
                n_nut / n_max,
                theirs("unit_speed"),
                their_margin("unit_speed"),
                "",
                "T-GC A-697 DN <= 70 000 on the nut's rotation; "
                "A-772..A-774: standing screw, no critical speed",
                f"ball centre diameter {dp:.2f} mm",
            )
        )
    else:
        n1, src = vp.critical_speed(svendor, d1, span, ax.mounting)
        rows.append(
            Row(
                "critical speed",
                "rpm",
                n1,
                n_max,
                n1 / n_max,
                theirs("critical_speed"),
                their_margin("critical_speed"),
                "",
                src,
                f"l_b = bearing span {span:.0f} mm",
            )
        )
        dn_lim, dn, src, note = vp.dn_check(
            svendor, d0, d1, screw["ball_diameter"] * 1e3, n_max, screw["dn_limit"]
        )
        rows.append(
            Row(
                "DN value",
                "mm.rpm",
                dn_lim,
                dn,
                dn_lim / dn,
                theirs("dn"),
                their_margin("dn"),
                "",
                src,
                note,
            )
        )
    # 2 buckling and 3 permissible tensile/compressive load (147 MPa)
    la = max(x_far, span - ax.start * 1e3) if ff else x_far
    if design["axis"].get("buckling_nut_end") == "supported":
        p1, src = vr.misumi_buckling(d1, la)
    else:
        p1, src = vp.buckling_load(svendor, d1, la)
    rows.append(
        Row(
            "buckling",
            "kN",
            p1 / 1e3,
            f_max / 1e3,
            p1 / f_max,
            theirs("buckling"),
            their_margin("buckling"),
            "",
            src,
            f"l_a = thrust bearing to nut at the far end {la:.0f} mm, nut as fixed end (THK A-726);"
            " load: feed force + m a + friction (+ weight)",
        )
    )
    pre_vendor = vp.thermal_pretension(d1, ax.temp_rise, svendor) if ff else 0.0
    p2 = vp.permissible_tension(d1)
    tension = f_max + pre_vendor
    rows.append(
        Row(
            "tensile/compressive load",
            "kN",
            p2 / 1e3,
            tension / 1e3,
            p2 / tension,
            theirs("screw_yield"),
            their_margin("screw_yield"),
            "",
            "T-GC A-694 eq. 7: P2 = 116 d1^2 (147 MPa)",
            "max axial force" + (" + thermal pretension" if ff else ""),
        )
    )
    if ff:
        rows.append(
            Row(
                "thermal pretension",
                "kN",
                pre_vendor / 1e3,
                None,
                None,
                ev.get("pretension_N", 0.0) / 1e3,
                None,
                "",
                "T-GC A-715 eq. 38, H-BS F 3.36 (alpha) x E A: stretch for a "
                f"{ax.temp_rise or vp.DESIGN_RISE:.0f} K rise",
                "axis.pretension_rise, else axis.temperature_rise if given, else 3 K",
            )
        )
    # 4 nut: static safety, lift-off, preload ceiling, L10 life
    fs_nut = vp.NUT_STATIC_SAFETY
    rows.append(
        Row(
            "nut static safety C0a/Famax",
            "-",
            nut["static_load_rating"] / f_max,
            fs_nut,
            nut["static_load_rating"] / f_max / fs_nut,
            ev.get("nut_static_safety"),
            None,
            "",
            "T-GC A-703 Table 18 (machine tool, vibration/impact: 2.5-7), H-BS F 3.3",
            f"criterion f_S >= {fs_nut} (vendor's lower bound; axisopt's default 5)",
        )
    )
    double = nut["type"] == "double"
    if double:
        lift = 2**1.5 * preload
        rapid = [] if cycle_given else vp.default_drive_phases(ax, accel, friction, weights)
        dwell_force = max(
            [
                quantity(st.get("force", 0.0)) * getattr(ax, "force_share", 1.0)
                for st in ax.duty
                if "dwell" in st
            ]
            + [0.0]
        )
        lift_need, how = vr.lift_off_need(
            ax, phases, rapid, friction, net, f_max, ax.cut_while_accelerating
        )
        lift_need = max(lift_need, abs(weights(0) if callable(weights) else weight) + dwell_force)
        rows.append(
            Row(
                "nut lift-off",
                "kN",
                lift / 1e3,
                lift_need / 1e3,
                lift / lift_need,
                theirs("nut_lift_off"),
                their_margin("nut_lift_off"),
                "",
                "H-BS F 3.6 / T-GC A-687: F_lim = 2^(3/2) F_pr",
                how,
            )
        )
        ceiling = 0.1 * nut["dynamic_load_rating"]
        rows.append(
            Row(
                "nut preload ceiling",
                "kN",
                ceiling / 1e3,
                preload / 1e3,
                ceiling / preload,
                theirs("nut_preload"),
                their_margin("nut_preload"),
                "",
                "T-GC A-687, H-BS F 3.5: <= 10 % Ca",
            )
        )
    # the life's mean speed: the designer's stated one (the machine's hours include time off the
    # cycle), else the cycle's (THK A-705: the phases' speeds and times), else half the rapid speed
    # (docs/files.md's default)
    use_cycle = cycle_given and not ax.mean_speed_given
    nm = vp.mean_speed_rpm(phases, lead) if use_cycle else ax.mean_speed * 60 / (lead * 1e-3)
    fw_nut, fw_src = vp.nut_load_factor(nut["vendor"], ax.v_max, ax.load_factor)
    life, src = vp.nut_life_h(
        nut["dynamic_load_rating"], preload if double else 0.0, phases, fw_nut, nm
    )
    # the fw axisopt's life checks read (its output), for the same-basis rows
    fw_ax = float(ev["load_factor"])
    life_ax = vp.nut_life_h(
        nut["dynamic_load_rating"], preload if double else 0.0, phases, fw_ax, nm
    )[0]
    rows.append(
        Row(
            "nut L10 life",
            "h",
            life,
            ax.life_h,
            life / ax.life_h,
            theirs("nut_life"),
            their_margin("nut_life"),
            "",
            src,
            f"{fw_src}; mean speed {nm:.0f} rpm"
            + ("" if cycle_given else "; loads: axis.mean_axial_load + friction each way")
            + f"; at axisopt's fw {fw_ax}: {life_ax:,.0f} h",
            same_basis=life_ax,
        )
    )
    # the unit's own support bearing carries the nut's load and turns with it (T-GC A-776, B-721)
    if rotating:
        ca_u = nut["unit_bearing_dynamic_load"]
        u_life = vp.unit_bearing_life_h(ca_u, phases, fw_nut, nm)
        u_ax = vp.unit_bearing_life_h(ca_u, phases, fw_ax, nm)
        rows.append(
            Row(
                "unit support bearing L10 life",
                "h",
                u_life,
                ax.life_h,
                u_life / ax.life_h,
                theirs("unit_bearing_life"),
                their_margin("unit_bearing_life"),
                "",
                "T-GC A-730: L = (Ca/(fw Fm))^3 x 10^6 rev, Ca of the DIR/BLR table (B-721)",
                f"Ca {ca_u / 1e3:.1f} kN; {fw_src}; mean nut speed {nm:.0f} rpm; at axisopt's fw "
                f"{fw_ax}: {u_ax:,.0f} h",
                same_basis=u_ax,
            )
        )
    # 5 support bearings: life per direction by the rows carrying it, static safety
    n_sets = 2 if ff else 1
    blife, src, bnote = vp.bearing_life_h(brg, phases, pre_vendor, nm)
    b_ax = vp.bearing_life_h(brg, phases, pre_vendor, nm, fw_ax)[0]
    bnote += f"; with axisopt's fw {fw_ax} on the loads: {b_ax:,.0f} h"
    # each set by its own maker's rule (issue 53): NSK rates its TAC B sets by the rows loaded with
    # the groups' Hertz split (NSK-SP pp. 110-111); HIWIN WBK, THK BK and Schaeffler ZKLF print one
    # set rating and state no set rule: IBC TI-I-5010.2's per-bearing reading.  The other reading of
    # an NSK set is shown, not judged.  A standing screw's end bearings do not turn: no rolling life
    # (T-GC A-772..A-774).
    nsk = str(brg.get("vendor")) == "NSK"
    if not rotating and nsk:
        nlife, nsrc, nnote = vp.nsk_set_life_h(brg, phases, pre_vendor, nm, fw_ax)
        rows.append(
            Row(
                "support bearing L10 life",
                "h",
                nlife,
                ax.life_h,
                nlife / ax.life_h,
                theirs("bearing_life"),
                their_margin("bearing_life"),
                compare(nlife / ax.life_h, their_margin("bearing_life")),
                nsrc + " (the set maker's own rule)",
                nnote + f"; axisopt's fw {fw_ax} on the loads; axisopt applies the same rule to an "
                "NSK set (its static set load: the pretension and the thermal force of the rise "
                "beyond the pretension's design rise)",
            )
        )
        rows.append(
            Row(
                "support bearing L10 life (IBC per bearing, not NSK's rule)",
                "h",
                blife,
                ax.life_h,
                None,
                None,
                None,
                "INFO",
                src,
                bnote + f"; shown, not judged: an NSK set by NSK's rule above (IBC's margin "
                f"{blife / ax.life_h:.3g})",
            )
        )
    elif not rotating:
        rows.append(
            Row(
                "support bearing L10 life",
                "h",
                blife,
                ax.life_h,
                blife / ax.life_h,
                theirs("bearing_life"),
                their_margin("bearing_life"),
                "",
                src,
                bnote + f"; {brg.get('vendor')} states no rule for its set: IBC's",
            )
        )
    avail, need, m_lift, lnote = vp.bearing_lift_off(brg, f_max, pre_vendor)
    rows.append(
        Row(
            "support bearing lift-off",
            "kN",
            avail / 1e3,
            need / 1e3,
            m_lift,
            theirs("bearing_lift_off"),
            their_margin("bearing_lift_off"),
            "",
            "IBC Table 2.2: unloading at Fae > X Fv",
            lnote
            + "; load: max axial force"
            + (" (+ pretension on the rows facing it)" if ff else ""),
        )
    )
    perm, src, generic = vp.bearing_permissible_load(brg)
    load_b = f_max + pre_vendor
    n_a, n_b = vp.ROWS[brg["arrangement"]]
    how = "weaker direction's rows; load: max axial force" + (" + pretension" if ff else "")
    # a 3:1 set: its stronger rows face the pretension, the single the force alone
    if n_a != n_b and ff:
        strong = perm * max(n_a, n_b) / min(n_a, n_b)
        if strong / load_b <= perm / f_max:
            perm = strong
        else:
            load_b = f_max
        how = (
            "the stronger rows against max axial force + pretension, the weaker against the force "
            "alone"
        )
    # generic: a plain C0a without its vendor's factor, where each side picks a general S0
    rows.append(
        Row(
            "support bearing static",
            "kN",
            perm / 1e3,
            load_b / 1e3,
            perm / load_b,
            theirs("bearing_static"),
            their_margin("bearing_static"),
            "CONV" if generic else "",
            src,
            how
            + (
                "; convention: no vendor factor for this rating: this checker IBC's S0 2.5, "
                "axisopt Rexroth's S0 4 for machine tools"
                if generic
                else ""
            ),
        )
    )
    # the lead band over the thread the nut travels (issue 53): JIS B 1192 / THK A-678 Table 1's
    # e_p + v_u of the band holding stroke + nut length (ISO 3408-3's useful travel), the nut's
    # length from its vendor's table (nuts.csv `length`); read here from
    # catalogs/lead_tolerances.csv
    budget = ev.get("positioning_budget") or {}
    lead_ax = next(
        (v for k, v in budget.get("rows_um", {}).items() if k.startswith("lead error")), None
    )
    axis_yaml = design.get("axis", {})
    plain = not axis_yaml.get("pitch_compensation") and axis_yaml.get("feedback") != "linear_scale"
    if lead_ax is not None and plain and nut.get("length"):
        travel = ax.stroke + nut["length"]
        band = vp.lead_band_um(budget.get("grade", "C5"), travel)
        if band is not None:
            rows.append(
                Row(
                    "lead band over stroke + nut length",
                    "um",
                    band,
                    None,
                    None,
                    lead_ax,
                    None,
                    "",
                    "T-GC A-678 Table 1 (JIS B 1192): e_p + v_u of the band of the travelled "
                    "thread",
                    f"grade {budget.get('grade', 'C5')}, {ax.stroke * 1e3:.0f} mm stroke + "
                    f"{nut['length'] * 1e3:.0f} mm nut (its vendor's table) = {travel * 1e3:.0f} "
                    "mm",
                )
            )
    # 6 guides: static safety and travel life at the vendor's rating distance
    if tw:  # the guides carry the whole gantry and the whole force
        ph_guides = vp.duty_phases(ax_guides, moving_guides, friction_guides, 0.0)[0]
    else:
        ph_guides = phases
    ends = [ax_guides]
    # the cross carriage at either end of its stroke: its weight and inertia there, as separate
    # forces
    if tw:
        ends = [
            vr.cross_carriage_at(ax_guides, moving_guides, quantity(tw.get("cross_mass", 0.0)), y)
            for y in (0.5 * quantity(tw["cross_stroke"]), -0.5 * quantity(tw["cross_stroke"]))
        ]
    blocks = max(vp.block_loads_max(a, moving_guides, a_peak) for a in ends)
    fs_g, src = vp.guide_static_safety(guide["vendor"], guide["type"])
    rows.append(
        Row(
            "guide static safety C0/P",
            "-",
            guide["static_load_rating"] / blocks,
            fs_g,
            guide["static_load_rating"] / blocks / fs_g,
            ev.get("guide_static_safety"),
            None,
            "",
            src,
            f"largest block load {blocks / 1e3:.2f} kN (axisopt "
            f"{ev.get('guide_max_block_load_N', float('nan')) / 1e3:.2f} kN)",
        )
    )
    travel_speed = vp.mean_travel_speed(phases) if use_cycle else ax.mean_speed
    need_km = ax.life_h * 3600 * travel_speed / 1e3
    g_km, src, gnote = min(
        (vp.guide_life_km(guide, a, ph_guides, cycle_given, moving_guides) for a in ends),
        key=lambda t: t[0],
    )
    g_ax = min(
        vp.guide_life_km(guide, a, ph_guides, cycle_given, moving_guides, fw_ax)[0] for a in ends
    )
    rows.append(
        Row(
            "guide L10 travel",
            "km",
            g_km,
            need_km,
            g_km / need_km,
            theirs("guide_life"),
            their_margin("guide_life"),
            "",
            src,
            gnote + f"; at axisopt's fw {fw_ax}: {g_ax:,.0f} km",
            same_basis=g_ax,
        )
    )
    # 7 axial rigidity of the feed system (THK A-707 eq. 32)
    k_v, src, knote = vp.feed_rigidity(ax, screw, nut, brg, preload, f_max)
    # the unit's bearing is in series with the nut (A-707's K_B of the nut's own support)
    if rotating:
        k_u = nut.get("unit_bearing_rigidity")
        k_v = 1 / (1 / k_v + 1e6 / k_u) if k_u else k_v
        knote += (
            f"; unit bearing {k_u / 1e6:.0f} N/um in series"
            if k_u
            else "; unit bearing rigidity not printed (THK A-707: ask the maker): left out"
        )
    chain = ev.get("chain_at_minimum_N_per_um", {})
    k_them = None
    if chain:
        parts_k = [
            v for k, v in chain.items() if k not in ("screw torsion", "coupling") and v != "rigid"
        ]
        k_them = 1.0 / sum(1.0 / v for v in parts_k)
    rows.append(
        Row(
            "axial rigidity (screw, nut, bearing, K_H)",
            "N/um",
            k_v,
            None,
            None,
            k_them,
            None,
            "",
            src,
            knote,
        )
    )
    # 8 drive: inertia ratio, RMS torque, holding torque
    if motor is not None:
        rows += vp.drive_rows(
            ax,
            screw,
            nut,
            brg,
            motor,
            coupling,
            accel,
            friction,
            weights,
            phases,
            preload,
            n_sets,
            ev,
            cycle_given,
            red,
            nut["unit_inertia"] if rotating else None,
        )
    # 9 own-weight sag of a horizontal screw (beam formula, INFO: no vendor limit)
    if not (ax.vertical or ax.wall) and screw.get("mass_per_length"):
        sag = vp.screw_sag(screw["mass_per_length"], screw["root_diameter"], ax.span, ax.mounting)
        rows.append(
            Row(
                "screw sag (own weight)",
                "um",
                sag * 1e6,
                None,
                None,
                None,
                None,
                "INFO",
                "AISC Table 3-23: delta = q L^4 / (k E I), I = pi d1^4/64, k by the mounting",
                f"q = {screw['mass_per_length'] * G:.1f} N/m over the span {span:.0f} mm; no "
                "vendor limit",
            )
        )
    for r in rows:
        if r.kind in ("CONV", "AGREE", "DIFF"):  # set where the row is made (this design's parts)
            continue
        same = not any(r.check.startswith(c) for c in vp.CONVENTIONS)
        if r.same_basis is not None:
            r.kind = compare(r.same_basis, r.axisopt, same)
        else:
            r.kind = compare(
                r.margin if r.margin is not None and r.axis_margin is not None else r.vendor,
                r.axis_margin if r.margin is not None and r.axis_margin is not None else r.axisopt,
                same,
            )
        if r.kind == "CONV":
            r.note = (
                (r.note + "; " if r.note else "")
                + "convention: "
                + vp.CONVENTIONS[next(c for c in vp.CONVENTIONS if r.check.startswith(c))]
            )
    return rows


def fmt(x) -> str:
    if x is None:
        return "-"
    if isinstance(x, float) and not math.isfinite(x):
        return "inf"
    a = abs(x)
    return f"{x:,.0f}" if a >= 1000 else f"{x:.3g}" if a >= 0.01 else f"{x:.2e}"


def table(rows: list[Row]) -> str:
    head = (
        f"{'check':<42} {'unit':>6} {'vendor':>10} {'limit':>10} {'margin':>7} {'':4} "
        f"{'axisopt':>10} {'ax.marg':>7} {'ratio':>6} {'':5}"
    )
    lines = [head, "-" * len(head)]
    for r in rows:
        ratio = (
            r.margin / r.axis_margin
            if r.margin is not None and r.axis_margin
            else r.vendor / r.axisopt
            if r.axisopt
            else None
        )
        verdict = "" if r.margin is None else ("PASS" if r.passes else "FAIL")
        lines.append(
            f"{r.check:<42} {r.unit:>6} {fmt(r.vendor):>10} {fmt(r.limit):>10} {fmt(r.margin):>7} "
            f"{verdict:4} {fmt(r.axisopt):>10} {fmt(r.axis_margin):>7} {fmt(ratio):>6} {r.kind:5}"
        )
        lines.append(f"    {r.source}" + (f"  [{r.note}]" if r.note else ""))
    return "\n".join(lines)


# the results table of docs/validation.md: (short label, the checker's check name)
SUMMARY = (
    ("crit. speed", "critical speed"),
    ("DN", "DN value"),
    ("buckling", "buckling"),
    ("P2 147 MPa", "tensile/compressive load"),
    ("nut C0a/F", "nut static safety C0a/Famax"),
    ("lift-off", "nut lift-off"),
    ("preload<=10%Ca", "nut preload ceiling"),
    ("nut life", "nut L10 life"),
    ("brg life", "support bearing L10 life"),
    ("brg static", "support bearing static"),
    ("guide C0/P", "guide static safety C0/P"),
    ("guide km", "guide L10 travel"),
    ("K axial", "axial rigidity (screw, nut, bearing, K_H)"),
    ("J ratio", "inertia ratio load/rotor"),
    ("T rms", "RMS torque"),
    ("T hold", "holding torque at a stop"),
    ("LM Fp", "peak force (HIWIN Fp)"),
    ("LM Fe<=0.7Fc", "effective force (HIWIN Fe <= 0.7 Fc)"),
)


def summary_cell(r: dict | None) -> str:
    """One cell of the results table from a row's JSON: 'margin PASS (axisopt's margin) KIND'; for
    the rigidity 'vendor / axisopt' N/um."""
    if r is None:
        return "\u2013"
    if r["margin"] is None:
        return f"{fmt(r['vendor'])} / {fmt(r['axisopt'])} {r['kind']}"
    verdict = "PASS" if r["passes"] else "**FAIL**"
    theirs = f" ({fmt(r['axis_margin'])})" if r["axis_margin"] is not None else ""
    return f"{fmt(r['margin'])} {verdict}{theirs} {r['kind']}"


def summary_table(results: dict) -> str:
    """The Markdown results table of docs/validation.md from {column name: the rows' JSON}."""
    names = list(results)
    lines = ["| check | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
    for label, check in SUMMARY:
        cells = [
            summary_cell(next((r for r in results[n] if r["check"] == check), None)) for n in names
        ]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def lowest_margin(rows: list[dict]) -> dict | None:
    """The row with the lowest vendor margin (the check an engineer signing the design looks at
    first) among the rows the vendor's criterion judges, from the rows' JSON."""
    judged = [r for r in rows if r["margin"] is not None]
    return min(judged, key=lambda r: r["margin"]) if judged else None


def signoff_cells(label: str, rows: list[dict]) -> str:
    """The first cells of a row of docs/validation.md's sign-off table: the optimum's column name,
    its lowest vendor margin with PASS/FAIL, the check, and the vendor rule that judges it (the
    row's source)."""
    r = lowest_margin(rows)
    if r is None:
        return f"| {label} | \u2013 | \u2013 | \u2013 |"
    verdict = "PASS" if r["passes"] else "**FAIL**"
    return (
        f"| {label} | {fmt(r['margin'])} {verdict} | {r['check']} | "
        + r["source"].replace("|", "/")
        + " |"
    )


# the drive checker's rows: (source of the vendor's rule, unit) by check name's start
DRIVE_SOURCES = (
    ("peak force", "H-LMS Appendix A: Fp = M a + (M g + Fa) mu below the peak force (about 1 s)"),
    ("effective force (HIWIN Fe <= 0.7", "H-LMS Appendix A: Fe (RMS over the cycle), Ie/Ic < 0.7"),
    (
        "effective force (HIWIN Fe <= Fc",
        "H-LMS definitions: Fc at 20 degC ambient, 80 degC winding",
    ),
    ("acceleration time", "H-LMS definitions: the peak force for about 1 s, then cooling"),
    ("peak current", "H-LMS Appendix A: Ip = Fp / Kf below Ip"),
    ("effective current", "H-LMS Appendix A: Ie = Fe / Kf below Ic"),
    (
        "magnet attraction",
        "H-LMS: the attraction 'must be taken up by the guide' (in both guide rows)",
    ),
    ("guide", "T-GC A-10/A-32 (fw THK A-704 Table 19), C0/P; the attraction in the block load"),
    ("pinion", "THK A-241 GSR-R: thrust <= capacity / overload factor"),
    ("motor", "Yaskawa Sigma-7 11.2.4: rack load torque, RMS"),
    ("gearbox", "Beckhoff AG2400: T2B, T2N, n1Max"),
    ("inertia", "Yaskawa Sigma-7: load / rotor inertia"),
)


def drive_rows(path: Path, res: dict) -> list[Row]:
    """A linear-motor or rack-and-pinion optimum by its vendors' steps
    (tools/vendor_check_drives.py: the duty cycle sampled in time, trapezoids or S-curves where the
    axis gives a jerk) as this checker's rows."""
    import vendor_check_drives as vcd

    lines, _ = vcd.check(path, res)
    out = []
    for name, value, limit, margin, verdict, model, agree in lines:
        label, _, unit = name.rpartition(" [")
        src = next((s for k, s in DRIVE_SOURCES if label.startswith(k)), "vendor_check_drives.py")
        info = verdict == "INFO"
        kind = "INFO" if info or agree == "ONLY" else agree
        out.append(
            Row(
                label,
                unit.rstrip("]"),
                value,
                None if info else limit,
                None if info else margin,
                None,
                model if (model is not None and math.isfinite(model)) else None,
                kind,
                src,
                "no axisopt margin of its own: this checker's rule" if agree == "ONLY" else "",
            )
        )
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("file", help="problem or design YAML")
    ap.add_argument("--json", help="write the rows as JSON")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        design_path, ev = run_axisopt(Path(args.file), Path(tmp))
        design = None if design_path is None else yaml.safe_load(design_path.read_text("utf-8"))
    if design is None:  # a linear motor or a rack: their vendors' steps (vendor_check_drives.py)
        rows = drive_rows(Path(args.file), ev)
        print(
            f"{args.file}: {ev['best']['drive_type']}, parts "
            + "  ".join(f"{k} {v}" for k, v in ev["best"]["parts"].items())
        )
    else:
        rows = check_design(design, ev)
        print(
            f"{args.file}: design {ev['design']}, {ev['mounting']}, parts "
            + "  ".join(f"{k} {v}" for k, v in ev["parts"].items())
        )
    print(table(rows))
    fails = [r.check for r in rows if not r.passes]
    diffs = [r.check for r in rows if r.kind == "DIFF"]
    print(
        f"vendor criterion: {'all pass' if not fails else 'FAIL ' + ', '.join(fails)};  "
        f"disagreements > {TOLERANCE:.0%} (same method): {', '.join(diffs) or 'none'}"
    )
    if args.json:
        Path(args.json).write_text(
            json.dumps([asdict(r) | {"passes": r.passes} for r in rows], indent=1)
        )
    return 0


if __name__ == "__main__":
    np.seterr(all="raise")
    raise SystemExit(main())
