"""The drive's parameters from its part rows: motor and coupling (:func:`drive_params`) and a
reduction stage (:func:`reduction_params`), each a dict of SI values the model's drive checks
read."""

from __future__ import annotations

import numpy as np

from ..physics.drive import PEAK_CORNER_FRACTION
from .motorrule import DEFAULT_RULE
from .paramnames import (
    PART_PARAMS,
    column_value,
    listed_or,
    optional_column,
)


def drive_params(axis, motor, coupling, reduction=None) -> dict:
    """Motor, coupling and reduction parameters (SI).  Missing parts: the axis values, checks off.

    ``reduction``: a reductions row (or arrays of them); a row whose ``ratio`` is NaN stands for no
    reduction (the search's direct-drive choice beside the catalog's reductions): the axis's
    reduction values then."""
    col = column_value
    q = {
        "max_inertia_ratio": axis.max_inertia_ratio,
        "brake_safety": axis.brake_safety,
        "rms_torque_ratio": DEFAULT_RULE.rms
        if axis.rms_torque_ratio is None
        else axis.rms_torque_ratio,
        "unbalance_torque_ratio": DEFAULT_RULE.unbalance,
    }
    q.update(reduction_params(axis, reduction))
    ratio = q["reduction_ratio"]
    if motor is None:
        rotor = axis.motor_inertia
        q.update(
            {
                "has_motor": 0.0,
                "motor_rated_torque": 1.0,
                "motor_peak_torque": 1.0,
                "motor_max_speed": 1.0,
                "motor_brake_torque": 0.0,
                "motor_price": 0.0,
                "motor_peak_corner_speed": 1.0,
                "motor_peak_at_max_speed": 1.0,
            }
        )
    else:
        rotor = col(motor, "rotor_inertia")
        # the brake adds its inertia (catalog value; the plain rotor where none is listed)
        if axis.brake_used:
            rotor = listed_or(col(motor, "rotor_inertia_brake"), rotor)
        brake = listed_or(col(motor, "brake_torque"), 0.0)
        q.update({"has_motor": 1.0, "motor_brake_torque": brake})
        q.update({param: col(motor, column) for column, param in PART_PARAMS["motors"]})
        # the intermittent zone's corner points where the vendor lists them, else the conservative
        # estimate
        q["motor_peak_corner_speed"] = listed_or(
            col(motor, "peak_corner_speed"),
            np.minimum(col(motor, "rated_speed"), PEAK_CORNER_FRACTION * col(motor, "max_speed")),
        )
        q["motor_peak_at_max_speed"] = listed_or(
            col(motor, "peak_torque_at_max_speed"), col(motor, "rated_torque")
        )
        # the motor vendor's selection rule (model.motorrule; a row without one: the harshest),
        # unless the problem asks its own RMS ratio
        if axis.rms_torque_ratio is None:
            q["rms_torque_ratio"] = listed_or(optional_column(motor, "rms_ratio"), DEFAULT_RULE.rms)
        q["unbalance_torque_ratio"] = listed_or(
            optional_column(motor, "unbalance_ratio"), DEFAULT_RULE.unbalance
        )
        # the drive's torque limit caps what the motor gives at every speed
        if axis.torque_limit is not None:
            q["motor_peak_torque"] = np.minimum(q["motor_peak_torque"], axis.torque_limit)
            q["motor_peak_at_max_speed"] = np.minimum(
                q["motor_peak_at_max_speed"], axis.torque_limit
            )
    if coupling is None:
        q.update(
            {
                "has_coupling": 0.0,
                "coupling_stiffness": axis.coupling_stiffness,
                "coupling_inertia": axis.coupling_inertia,
                "coupling_rated_torque": 1.0,
                "coupling_max_speed": 1.0,
                "coupling_price": 0.0,
            }
        )
    else:
        q.update(
            {
                "has_coupling": 1.0,
                "coupling_stiffness": col(coupling, "torsional_stiffness"),
                "coupling_inertia": col(coupling, "inertia"),
            }
        )
        q.update({param: col(coupling, column) for column, param in PART_PARAMS["couplings"]})
    q["rotor_inertia"] = rotor
    # motor side of the drive-train model, seen from the screw through the reduction
    q["motor_inertia"] = (rotor + q["reduction_inertia"]) * ratio**2
    return q


def reduction_params(axis, reduction) -> dict:
    """The reduction's parameters (SI): its catalog row where there is one (a NaN ratio: none), else
    the axis's ratio, efficiency and input inertia with a rigid stage (compliance 0) and the
    reduction checks off."""
    none = {
        "has_reduction": 0.0,
        "reduction_ratio": axis.reduction_ratio,
        "reduction_efficiency": axis.reduction_efficiency,
        "reduction_inertia": axis.reduction_inertia,
        "reduction_rated_torque": 1.0,
        "reduction_accel_torque": 1.0,
        "reduction_compliance": 0.0,
        "reduction_max_speed": 1.0,
        "reduction_price": 0.0,
        "reduction_backlash": 0.0,
        "reduction_emergency_torque": 1.0,
    }
    if reduction is None:
        return none
    col = column_value
    has = np.isfinite(col(reduction, "ratio"))
    q = {
        param: listed_or(col(reduction, column), none[param])
        for column, param in PART_PARAMS["reductions"]
    }
    q["has_reduction"] = has * 1.0 if np.ndim(has) else float(has)
    # the emergency-stop torque where the vendor lists it, else T2B (never above it)
    q["reduction_emergency_torque"] = listed_or(
        optional_column(reduction, "emergency_torque"), q["reduction_accel_torque"]
    )
    # the stage's torsional stiffness (output side) as a compliance, in series with the coupling's
    # (model.chain)
    q["reduction_compliance"] = listed_or(1.0 / col(reduction, "torsional_stiffness"), 0.0)
    return q
