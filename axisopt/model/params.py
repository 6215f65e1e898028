"""The flat SI parameter vector of the axis model, built from an Axis and its four part rows."""

from __future__ import annotations

import numpy as np

from ..catalog.columns import ARRANGEMENT_ROWS
from ..catalog.grades import SCALE_GRADES, lead_errors, price_factors, scale_error
from ..design import PRETENSION_RISE, TEMPERATURE_RISE
from ..physics import counterbalance as pcb
from ..physics.bearings import (
    STATIC_SAFETY_MACHINE_TOOL,
    housing_stiffness_default,
    support_starting_torque_envelope,
)
from ..physics.nut import bracket_stiffness_default, nut_length_estimate, nut_stiffness_catalog
from .driveparams import drive_params
from .gantry import gantry_params
from .paramnames import (
    PARAM_NAMES,
    PART_PARAMS,
    column_value,
    listed_or,
    optional_column,
)

# A guide row without a rating basis: 50 km, the shorter of the vendors' two bases (a C defined for
# 100 km and read as a 50 km rating halves the life, never doubles it)
GUIDE_RATING_DISTANCE = 50e3  # [m]
# a screw row without a grade: the grade its catalog price is for (catalogs/SOURCES.md)
DEFAULT_GRADE = "C5"


def axis_params(
    axis, screw, nut, bearing, guide, motor=None, coupling=None, reduction=None, grade=None
) -> dict:
    """Flat SI parameter dict for :func:`axisopt.model.axis_response` from an Axis and its part
    rows.

    Part rows may be pandas Series (one design) or DataFrames / dicts of arrays (many designs).
    Without a motor (or coupling) row the axis's ``motor_inertia`` (``coupling_*``) values stand in
    and the drive checks do not apply.  ``grade``: the screw's lead accuracy grade (a name, or an
    array of names like the rows; default the screw row's ``grade`` where it has one, else C5, the
    grade of the catalog price).  ``p["duty"]`` holds the axis's duty-cycle phases (not a parameter:
    the same for every design).
    """
    col = column_value
    mounting = axis.mounting
    torque = col(bearing, "starting_torque")
    p = {
        "stroke": axis.stroke,
        "start_offset": axis.start_offset,
        "span": axis.span,
        "acceleration": axis.top_acceleration,
        "max_speed": axis.top_speed,
        "mean_speed": axis.mean_speed_eff,
        "required_life": axis.required_life,
        "load_factor": axis.load_factor_eff,
        "guide_blocks": float(axis.guide_blocks),
        "rails": float(axis.rails),
        "rail_length": axis.stroke + axis.table_length,
        "normal_load": axis.normal_load,
        "viscosity": axis.lubricant_viscosity,
        "bearing_sets": 2.0 if mounting == "fixed-fixed" else 1.0,
        "gravity_axial": 1.0 if axis.orientation == "vertical" else 0.0,
        # a duty cycle and no temperature_rise given: the heat balance (model.heat) sets the rise
        "temperature_rise": TEMPERATURE_RISE
        if axis.temperature_rise is None
        else axis.temperature_rise,
        "temperature_rise_auto": 1.0 if axis.rise_from_balance else 0.0,
        "heat_transfer": 0.0 if axis.heat_transfer is None else axis.heat_transfer,
        "pretension": 0.0 if axis.pretension is None else axis.pretension,
        "pretension_auto": 1.0 if (axis.pretension is None and mounting == "fixed-fixed") else 0.0,
        # the vendor's design rise the auto pretension absorbs; the shaft ends a support bearing
        # holds (heat)
        "pretension_rise": PRETENSION_RISE
        if axis.pretension_rise is None
        else axis.pretension_rise,
        "shaft_ends": 1.0 if mounting == "fixed-free" else 2.0,
    }
    # every column that feeds a parameter as it is (catalog.COLUMNS), then the ones read through a
    # rule
    for table, row in (("screws", screw), ("nuts", nut), ("bearings", bearing), ("guides", guide)):
        for column, param in PART_PARAMS[table]:
            p[param] = col(row, column)
    dm = 0.5 * (col(bearing, "bore") + col(bearing, "outer_diameter"))
    p.update(
        {
            "nut_double": _is_type(nut, "double"),
            "bearing_mean_diameter": dm,
            # starting torque of the support unit where its vendor lists it; else the upper envelope
            # of the vendor values per preload and mean diameter
            # (physics.bearings.support_starting_torque_envelope)
            "bearing_torque": listed_or(
                torque, support_starting_torque_envelope(p["bearing_preload"], dm)
            ),
            "bearing_torque_listed": np.isfinite(torque) * 1.0,
            "guide_roller": _is_type(guide, "roller"),
            # rows of the bearing set that carry each load direction (catalog.ARRANGEMENT_ROWS)
            "bearing_rows_strong": _arrangement_rows(bearing, 0),
            "bearing_rows_weak": _arrangement_rows(bearing, 1),
            # each set by its maker's rule (issue 53): NSK rates its sets' row groups with their
            # Hertz load split (NSK-SP pp. 110-111); a maker that states no set rule: IBC's linear
            # split (model.checks.bearing_life_load)
            "bearing_hertz_split": _is_vendor(bearing, HERTZ_SPLIT_VENDORS),
            # the screw's dangerous speed by its vendor's rule: HIWIN's (H-BS F 3.27/3.28) for its
            # screws, THK's lambda for the others (model.checks)
            "screw_hiwin_rule": _is_vendor(screw, ("HIWIN",)),
            # the lift-off load of the stronger direction where the catalog lists one (a 3-against-1
            # set), else the set's one lift-off load (the weaker direction's)
            "bearing_lift_off_strong": listed_or(
                col(bearing, "lift_off_load_strong"), p["bearing_lift_off"]
            ),
            # the guide's rating basis where its vendor states it, else 50 km (the shorter basis:
            # conservative)
            "guide_rating_distance": listed_or(
                col(guide, "rating_distance"), GUIDE_RATING_DISTANCE
            ),
            # the least static safety of the set on its static rating: the axis's, else the rating's
            # vendor's (catalog column static_safety), else Rexroth's machine-tool S0
            # (physics.bearings)
            "bearing_static_safety": listed_or(
                col(bearing, "static_safety"), STATIC_SAFETY_MACHINE_TOOL
            )
            if axis.bearing_static_safety is None
            else axis.bearing_static_safety,
            "nut_lift_off_safety": axis.nut_lift_off_safety,
            "cut_while_accelerating": 1.0 if axis.cut_while_accelerating else 0.0,
            "buckling_nut_fixed": 1.0 if axis.buckling_nut_end == "fixed" else 0.0,
        }
    )
    # the nut's length where its vendor lists it, else the catalog envelope (physics.nut): the lead
    # band is read over the thread the nut travels, stroke + nut length
    p["nut_length"] = nut_length(screw, nut)
    p.update(grade_params(axis, screw, grade, p["nut_length"]))
    p.update(rotating_nut_params(p, nut))
    p.update(mount_compliances(axis, p))
    p.update(carriage_params(axis))
    p.update(drive_params(axis, motor, coupling, reduction))
    p.update(counterbalance_params(axis))
    # a twin drive (model.gantry): the guides carry bridge and cross carriage; each drive the
    # governing side's share of the process force (as the duty cycle's phases, design.Axis.phases)
    p.update(gantry_params(axis))
    p["table_mass"] = axis.moving_mass + p["cross_mass"]
    p["axial_load"] = p["force_share"] * axis.axial_load
    p["mean_axial_load"] = p["force_share"] * axis.mean_axial_load_eff
    p["duty"] = axis.phases
    return p


def grade_params(axis, screw, grade=None, nut_length=0.0) -> dict:
    """The lead accuracy grade's parameters: the lead error over the thread the nut travels,
    stroke + ``nut_length`` [m] (ISO 3408-3's useful travel: the band of the length the nut's balls
    run over), the price factor on the screw shaft [-] (:mod:`axisopt.catalog.grades`; the catalog
    price is the C5 price), and the guides' running pitch and yaw [rad].  ``grade``: a name or an
    array of names (default: the screw row's ``grade``, else C5); ``nut_length`` a float or an array
    like the rows."""
    if grade is None:
        try:
            grade = screw["grade"]
        except (KeyError, IndexError, ValueError):
            grade = DEFAULT_GRADE
    travel = axis.stroke + np.asarray(nut_length, dtype=float)
    err = lead_errors(grade, travel if np.ndim(travel) else float(travel), axis.pitch_compensation)
    factor = price_factors(grade)
    scale = axis.feedback == "linear_scale"
    return {
        "lead_error": err if np.ndim(err) else float(err),
        "grade_price_factor": factor if np.ndim(factor) else float(factor),
        "guide_pitch": axis.guide_pitch,
        "guide_yaw": axis.guide_yaw,
        # a linear scale on the table (closed loop): its grade's error over the stroke and its read
        # head's repeatability (grades.SCALE_GRADES) take the place of the screw's lead and thermal
        # rows
        "scale_feedback": 1.0 if scale else 0.0,
        "scale_error": scale_error(axis.scale_grade, axis.stroke) if scale else 0.0,
        "scale_repeatability": SCALE_GRADES[axis.scale_grade].repeatability if scale else 0.0,
    }


def counterbalance_params(axis) -> dict:
    """The counterbalance's parameters (SI; model.loads.balance_force): a counterweight's mass m_c
    and its chain's efficiency, the mass that moves with the head besides it (the counterweight and
    its chain, a cylinder's piston), and a balance cylinder's force at the end of its range (over
    the stroke, with the pressure tolerance, physics.counterbalance.cylinder_force_range) that
    leaves the screw the largest net weight (physics.counterbalance.cylinder_worst_force), chosen
    with the head's weight from axis.moving_mass (table + workpiece; nut and blocks, a few per cent,
    left out of the choice).  Without a counterbalance: 0, 1, 0, 0."""
    cb = axis.counterbalance
    if cb is None:
        return {
            "balance_mass": 0.0,
            "balance_efficiency": 1.0,
            "balance_moving_mass": 0.0,
            "balance_force": 0.0,
        }
    if cb.kind == "counterweight":
        return {
            "balance_mass": cb.mass,
            "balance_efficiency": cb.efficiency,
            "balance_moving_mass": cb.mass + cb.chain_mass,
            "balance_force": 0.0,
        }
    lo, hi = pcb.cylinder_force_range(cb.force, cb.force_end, cb.tolerance)
    worst = pcb.cylinder_worst_force(axis.moving_mass * pcb.G, lo, hi)
    return {
        "balance_mass": 0.0,
        "balance_efficiency": 1.0,
        "balance_moving_mass": cb.piston_mass,
        "balance_force": float(worst),
    }


# Estimates for a rotating-nut unit whose vendor prints no figure (catalogs/SOURCES.md,
# docs/assumptions.md): the built-in bearing's axial rigidity per kN of its dynamic rating, the
# lowest ratio of the Schaeffler ZKLF rows HIWIN reprints (H-BS 8.8.2: ZKLF50140 1 400 N/um at Cdyn
# 125 kN); its preload as the ZKLN/ZKLF rule of catalogs/SOURCES.md (5 % Cdyn); its mean diameter as
# 2.5 x the screw's nominal diameter (the THK DIR/BLR unit housings D are 2.4-3.0 d, T-GC
# B-721/B-723; the bearing sits inside D, so the drag read from it is high)
UNIT_RIGIDITY_PER_RATING = 1400e6 / 125e3  # [N/m per N] = 11.2 N/um per kN
UNIT_PRELOAD_FRACTION = 0.05  # [-] of the unit bearing's Ca
UNIT_MEAN_DIAMETER_RATIO = 2.5  # [-] of the screw's nominal diameter


def rotating_nut_params(p: dict, nut) -> dict:
    """The driven rotating-nut unit's parameters (SI), one part or arrays: ``nut_rotating`` 1.0 for
    a unit (the nut row's ``rotating`` flag), else 0.0 with neutral finite values (so one formula
    evaluates a mix of rows on floats, arrays and CasADi without NaN).  Where the unit's vendor
    prints no figure the estimates above stand
    in: max speed = the screw's DN limit / d (THK A-697, H-BS 3.7.6: the balls run at the nut's
    speed relative to the screw, the same on a turning nut); the bearing's rigidity, preload and
    starting torque (:func:`axisopt.physics.bearings.support_starting_torque_envelope`).  Needs
    ``p``'s screw and nut values."""
    col = optional_column
    flag = listed_or(col(nut, "rotating"), 0.0)
    r = np.where(flag == 1.0, 1.0, 0.0)
    r = r if np.ndim(r) else float(r)
    on = r == 1.0
    ca = np.where(on, listed_or(col(nut, "unit_bearing_dynamic_load"), 1.0), 1.0)
    c0 = np.where(on, listed_or(col(nut, "unit_bearing_static_load"), 1.0), 1.0)
    preload = UNIT_PRELOAD_FRACTION * ca
    dm = UNIT_MEAN_DIAMETER_RATIO * p["nominal_diameter"]
    q = {
        "nut_rotating": r,
        "unit_inertia": np.where(on, listed_or(col(nut, "unit_inertia"), 0.0), 0.0),
        "unit_max_speed": np.where(
            on, listed_or(col(nut, "unit_max_speed"), p["dn_limit"] / p["nominal_diameter"]), 1.0
        ),
        "unit_bearing_dynamic_load": ca,
        "unit_bearing_static_load": c0,
        "unit_bearing_preload": preload,
        "unit_bearing_stiffness": np.where(
            on, listed_or(col(nut, "unit_bearing_rigidity"), UNIT_RIGIDITY_PER_RATING * ca), 1.0
        ),
        "unit_bearing_torque": np.where(
            on,
            listed_or(
                col(nut, "unit_starting_torque"), support_starting_torque_envelope(preload, dm)
            ),
            0.0,
        ),
    }
    return {k: (v if np.ndim(v) else float(v)) for k, v in q.items()}


def one_design(p: dict, i: int = 0) -> dict:
    """Design ``i`` of a flat parameter dict as floats (the duty cycle carried along)."""
    out = {k: float(np.asarray(p[k]).ravel()[i] if np.ndim(p[k]) else p[k]) for k in PARAM_NAMES}
    out["duty"] = p.get("duty", ())
    return out


def carriage_params(axis) -> dict:
    """Carriage geometry, load and safety parameters (SI), with the defaults of
    :class:`axisopt.design.Axis`.  The rocking inertias default to a uniform box of the axis's
    moving mass (table + workpiece): table_length long, table_width wide, 2 x cg_height high, its
    centre at cg_height (pitch about the cross axis in the mounting plane; yaw about the normal axis
    through the carriage centre, cg_offset away)."""
    from ..physics.carriage import box_inertia

    length, width, h = axis.table_length, axis.table_width_eff, axis.cg_height_eff
    pitch = (
        box_inertia(axis.moving_mass, length, 2.0 * h, h)
        if axis.pitch_inertia is None
        else axis.pitch_inertia
    )
    yaw = (
        box_inertia(axis.moving_mass, length, width, axis.cg_offset)
        if axis.yaw_inertia is None
        else axis.yaw_inertia
    )
    return {
        "cross_load": axis.cross_load,
        "tool_height": axis.tool_height_eff,
        "tool_offset": axis.tool_offset,
        "cg_height": h,
        "cg_offset": axis.cg_offset,
        "block_spacing": axis.block_spacing_eff,
        "rail_spacing": axis.rail_spacing_eff,
        "gravity_cross": 1.0 if axis.orientation == "wall" else 0.0,
        "pitch_inertia": pitch,
        "yaw_inertia": yaw,
        "guide_static_safety": axis.guide_static_safety,
        "nut_static_safety": axis.nut_static_safety,
        "duty_process": 1.0 if axis.duty_cycle else 0.0,
    }


def mount_compliances(axis, p) -> dict:
    """Compliance [m/N] of one bearing housing and of the nut bracket: the axis's values, else the
    published estimates (never rigid): the housing 26 x its bearing set (IBC TI-I-5010.2 units
    against their bare sets, :func:`axisopt.physics.bearings.housing_stiffness_default`), the
    bracket 4 x its nut at the catalog's reference preload (THK A-709's 80 % nut-mounting allowance
    once more, :func:`axisopt.physics.nut.bracket_stiffness_default`).  Floats or arrays (one per
    part)."""
    housing = (
        housing_stiffness_default(p["bearing_stiffness"])
        if axis.bearing_housing_stiffness is None
        else axis.bearing_housing_stiffness
    )
    nut = nut_stiffness_catalog(
        p["nut_stiffness"],
        p["nut_stiffness_preload"],
        p["nut_dynamic_load"],
        reference_preload=p["nut_stiffness_preload"],
    )
    bracket = (
        bracket_stiffness_default(nut)
        if axis.nut_bracket_stiffness is None
        else axis.nut_bracket_stiffness
    )
    return {"housing_compliance": 1.0 / housing, "bracket_compliance": 1.0 / bracket}


def _arrangement_rows(row, i):
    """Rows of the set carrying the stronger (i = 0) or the other (1) load direction, one part or an
    array."""
    a = np.asarray(row["arrangement"])
    rows = np.select(
        [a == k for k in ARRANGEMENT_ROWS], [v[i] for v in ARRANGEMENT_ROWS.values()], np.nan
    )
    return float(rows) if rows.ndim == 0 else rows


def nut_length(screw, nut):
    """The nut's length [m] (one part or arrays of parts): its ``length`` column where its vendor
    lists one, else the catalog envelope :func:`axisopt.physics.nut.nut_length_estimate` on the
    screw's lead and diameter.  The lead band reads stroke + this length (:func:`grade_params`; the
    search's grade rows likewise)."""
    return listed_or(
        optional_column(nut, "length"),
        nut_length_estimate(
            column_value(screw, "lead"),
            column_value(screw, "nominal_diameter"),
            _is_type(nut, "double"),
        ),
    )


# the bearing makers that state their own rule for a set's row-group loads (NSK super-precision
# bearings: the rows' ratings pp. 110-111, the split of DB and DBB sets pp. 140-141, the Hertz law
# it rests on for the others); the others print one set rating and state no rule for the split
HERTZ_SPLIT_VENDORS = ("NSK",)


def _is_vendor(row, vendors):
    """1.0 where the part's ``vendor`` is one of ``vendors`` (one part or an array of parts); 0
    where the row names none (a part written inline without a vendor)."""
    try:
        v = row["vendor"]
    except (KeyError, IndexError):
        return 0.0
    if isinstance(v, str):
        return 1.0 if v in vendors else 0.0
    return np.isin(np.asarray(v).astype(str), vendors).astype(float)


def _is_type(row, value):
    """1.0 where the part's ``type`` column is ``value`` (one part or an array of parts)."""
    t = row["type"]
    if isinstance(t, str):
        return 1.0 if t == value else 0.0
    return (np.asarray(t) == value).astype(float)


def positions(axis, n: int | None = None) -> np.ndarray:
    """Nut positions x (fixed bearing to nut) [m] over the stroke: an even grid plus, for
    fixed-fixed, the mid-span point where the screw is softest (when it lies on the stroke)."""
    n = n or axis.positions
    x = axis.start_offset + np.linspace(0.0, axis.stroke, n)
    if axis.mounting == "fixed-fixed":
        mid = 0.5 * axis.span
        if axis.start_offset < mid < axis.start_offset + axis.stroke:
            x = np.unique(np.append(x, mid))
    return x
