"""The names of the model's flat SI parameter vector (:data:`PARAM_NAMES`, in the vector's order)
and which part columns feed which parameter (:data:`PART_PARAMS`, the motor rule's
:data:`RULE_PARAMS`, :func:`columns_read`): the declaration the parameter builders (:mod:`.params`)
and the catalog readers share."""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from ..catalog.columns import COLUMNS
from .gantry import TWIN_PARAMS

PARAM_NAMES = (
    # axis
    "stroke",
    "start_offset",
    "span",
    "table_mass",
    "acceleration",
    "max_speed",
    "mean_speed",
    "axial_load",
    "mean_axial_load",
    "required_life",
    "load_factor",
    "guide_blocks",
    "rails",
    "rail_length",
    "normal_load",
    "viscosity",
    "motor_inertia",
    "bearing_sets",
    "gravity_axial",
    "housing_compliance",
    "bracket_compliance",
    "coupling_stiffness",
    "coupling_inertia",
    "temperature_rise",
    "pretension",
    "pretension_auto",
    # screw
    "root_diameter",
    "nominal_diameter",
    "lead",
    "screw_max_length",
    "screw_mass_per_length",
    "dn_limit",
    "screw_price_per_length",
    "screw_price_fixed",
    "support_bore_min",
    "support_bore_max",
    # nut
    "nut_stiffness",
    "nut_stiffness_preload",
    "nut_double",
    "nut_dynamic_load",
    "nut_static_load",
    "nut_mass",
    "nut_price",
    "nut_preload_min",
    "nut_preload_max",
    "nut_axial_play",
    # bearing arrangement (per screw end)
    "bearing_stiffness",
    "bearing_lift_off",
    "bearing_lift_off_strong",
    "bearing_preload",
    "bearing_f0",
    "bearing_f1",
    "bearing_mean_diameter",
    "bearing_limiting_speed",
    "bearing_mass",
    "bearing_price",
    "bearing_dynamic_load",
    "bearing_bore",
    "bearing_torque",
    "bearing_torque_listed",
    # guide block and rail
    "guide_normal_stiffness",
    "guide_tangential_stiffness",
    "guide_friction_force",
    "guide_friction_coefficient",
    "guide_friction_viscous",
    "guide_damping",
    "guide_block_mass",
    "guide_rail_mass_per_length",
    "guide_block_price",
    "guide_rail_price_per_length",
    "guide_dynamic_load",
    "guide_preload",
    "guide_roller",
    "guide_rating_distance",
    "bearing_rows_strong",
    "bearing_rows_weak",
    "bearing_hertz_split",
    "screw_hiwin_rule",
    "bearing_static_load",
    "bearing_static_safety",
    "nut_lift_off_safety",
    # drive: motor, coupling, reduction (rotor_inertia at the motor; motor_inertia above is the
    # motor side reflected to the screw for the drive-train modes)
    "rotor_inertia",
    "has_motor",
    "motor_rated_torque",
    "motor_peak_torque",
    "motor_max_speed",
    "motor_brake_torque",
    "motor_price",
    "has_coupling",
    "coupling_rated_torque",
    "coupling_max_speed",
    "coupling_price",
    "reduction_ratio",
    "reduction_efficiency",
    "reduction_inertia",
    "max_inertia_ratio",
    "brake_safety",
    # carriage: the guide's static rating and moment ratings, the cutting force's cross component,
    # the lever arms, the block pattern, gravity across the rails (wall mounting), the table's
    # rocking inertias, the least static safety of guide and nut, and whether the duty cycle's
    # phases carry the process force
    "guide_static_load",
    "guide_moment_roll",
    "guide_moment_pitch",
    "guide_moment_yaw",
    "cross_load",
    "tool_height",
    "tool_offset",
    "cg_height",
    "cg_offset",
    "block_spacing",
    "rail_spacing",
    "gravity_cross",
    "pitch_inertia",
    "yaw_inertia",
    "guide_static_safety",
    "nut_static_safety",
    "duty_process",
    "rms_torque_ratio",
    "motor_peak_corner_speed",
    "motor_peak_at_max_speed",
    "temperature_rise_auto",
    "heat_transfer",
    "shaft_ends",
    "pretension_rise",
    # the motor vendor's rule on an unbalanced axis's load torque (model.motorrule), a reduction's
    # emergency-stop torque, the nut lift-off check's load case (1: the cut while accelerating)
    "unbalance_torque_ratio",
    "reduction_emergency_torque",
    "cut_while_accelerating",
    "buckling_nut_fixed",
    # accuracy: the screw's lead error over the stroke by its grade and the grade's price factor on
    # the shaft; the guides' running pitch and yaw (model.accuracy)
    "lead_error",
    "nut_length",
    "grade_price_factor",
    "guide_pitch",
    "guide_yaw",
    "scale_feedback",
    "scale_error",
    "scale_repeatability",
    # reduction: a catalog part, or none (the axis's reduction_* values above, its checks off); its
    # output-side ratings, its torsional compliance (in series with the coupling) and its input
    # speed limit
    "has_reduction",
    "reduction_rated_torque",
    "reduction_accel_torque",
    "reduction_compliance",
    "reduction_max_speed",
    "reduction_price",
    "reduction_backlash",
    # driven rotating-nut unit (model.rotnut; 0 / neutral values for a nut on a rotating screw)
    "nut_rotating",
    "unit_inertia",
    "unit_max_speed",
    "unit_bearing_dynamic_load",
    "unit_bearing_static_load",
    "unit_bearing_stiffness",
    "unit_bearing_torque",
    "unit_bearing_preload",
    # counterbalance of a vertical axis (model.loads.balance_force): the counterweight and its
    # chain's efficiency, the mass moving with the head besides it, a balance cylinder's force at
    # its worst end
    "balance_mass",
    "balance_efficiency",
    "balance_moving_mass",
    "balance_force",
    # twin-drive gantry (model.gantry; neutral values for one drive)
) + TWIN_PARAMS


# part table -> ((column, parameter), ...): the columns that feed a model parameter as they are,
# from the one declaration of the part columns (axisopt.catalog.columns.COLUMNS).  A new part column
# the model reads needs its ``param`` there and its name in PARAM_NAMES above.
PART_PARAMS = MappingProxyType(
    {t: tuple((c.name, c.param) for c in cols if c.param) for t, cols in COLUMNS.items()}
)


# columns the model reads through a rule in axis_params / drive_params (a fallback, a mean, a
# choice; the text columns type and arrangement as the numbers they stand for)
_RULE_COLUMNS = MappingProxyType(
    {
        # the screw's vendor: its critical-speed rule (HIWIN's or THK's, model.checks)
        "screws": ("vendor",),
        "nuts": (
            "type",
            "length",
            "rotating",
            "unit_inertia",
            "unit_max_speed",
            "unit_bearing_dynamic_load",
            "unit_bearing_static_load",
            "unit_bearing_rigidity",
            "unit_starting_torque",
        ),
        "bearings": (
            "vendor",
            "bore",
            "outer_diameter",
            "starting_torque",
            "arrangement",
            "static_safety",
            "lift_off_load_strong",
        ),
        "guides": ("type", "rating_distance"),
        "motors": (
            "rotor_inertia",
            "rotor_inertia_brake",
            "brake_torque",
            "rated_speed",
            "rated_torque",
            "peak_corner_speed",
            "peak_torque_at_max_speed",
            "rms_ratio",
            "unbalance_ratio",
        ),
        "couplings": ("torsional_stiffness", "inertia"),
        "reductions": ("torsional_stiffness", "emergency_torque"),
    }
)


# rule columns and the parameter each one ends in (for naming the estimates a result rests on,
# model.estimates)
RULE_PARAMS = MappingProxyType(
    {
        ("bearings", "starting_torque"): "bearing_torque",
        ("nuts", "length"): "nut_length",
        ("nuts", "unit_max_speed"): "unit_max_speed",
        ("nuts", "unit_bearing_rigidity"): "unit_bearing_stiffness",
        ("nuts", "unit_starting_torque"): "unit_bearing_torque",
        ("bearings", "static_safety"): "bearing_static_safety",
        ("guides", "rating_distance"): "guide_rating_distance",
        ("motors", "peak_corner_speed"): "motor_peak_corner_speed",
        ("motors", "peak_torque_at_max_speed"): "motor_peak_at_max_speed",
        ("bearings", "lift_off_load_strong"): "bearing_lift_off_strong",
        ("reductions", "torsional_stiffness"): "reduction_compliance",
    }
)


def columns_read(table: str) -> tuple:
    """The columns of a part table the model reads (what a vectorized search keeps as arrays)."""
    direct = tuple(c for c, _ in PART_PARAMS[table])
    return direct + tuple(c for c in _RULE_COLUMNS[table] if c not in direct)


def listed_or(value, fallback):
    """A catalog column where it is listed (finite), ``fallback`` where it is empty; float or
    array."""
    out = np.where(np.isfinite(value), value, fallback)
    return out if np.ndim(out) else float(out)


def column_value(row, name):
    v = row[name]
    return float(v) if np.ndim(v) == 0 else np.asarray(v, dtype=float)


def optional_column(row, name):
    """An optional column of one part or of arrays of parts; NaN (empty) where the table has no such
    column (a table written before the column existed; a scalar, which broadcasts against arrays of
    parts)."""
    try:
        return column_value(row, name)
    except KeyError:
        return float("nan")
