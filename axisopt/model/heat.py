"""Heat balance of the screw: friction power over the duty cycle and the temperature rise it causes.

The nut's preload drag and the support bearings' drag turn into heat in the screw at the cycle's mean screw
speed (Tian & He: Q = T omega); the shaft loses it by convection from its surface, with the film coefficient of a
cylinder rotating in still air (Jungnickel 2010), bounded by free convection from a horizontal cylinder (Holman)
at low speed, unless the axis gives one (``axis.heat_transfer``).  The rise
replaces the fixed ``temperature_rise`` when the axis has a duty cycle and sets none; thermal growth at the nut,
the pretension of a fixed-fixed screw and the checks that read them use it.  It rises with the nut preload
(through the drag), so do the outputs that read it (model.limits.OUTPUT_PRELOAD).
"""

from __future__ import annotations

import math

from .. import mathx as mx
from ..physics import nut as pn
from ..physics import thermal as pt
from ..physics.motion import phase_speeds


def heat_balance(p, preload) -> dict:
    """Friction power [W] (nut and bearings, cycle mean), film coefficient [W/(m^2 K)], the heat-balance rise
    [K] and the temperature rise the model uses [K] (the balance when ``temperature_rise_auto``)."""
    phases = p.get("duty", ())
    v_mean = pt.mean_cycle_speed(phases, phase_speeds(phases)) if phases else p["mean_speed"]
    omega = 2.0 * math.pi * v_mean / p["lead"]
    t_screw = pn.nut_preload_drag_torque(preload, p["lead"], p["nominal_diameter"]) \
        + p["bearing_sets"] * p["bearing_torque"]
    power = t_screw * omega
    d = p["nominal_diameter"]
    area = math.pi * d * p["span"]
    # film: the axis's, else the rotating shaft's (Jungnickel) bounded by free convection alone (Holman); each
    # alone overstates the rise, so the smaller is an upper estimate of it
    h_rot = pt.rotating_shaft_heat_transfer(omega, 0.5 * d)
    rise_auto = mx.fmin(pt.friction_temperature_rise(power, h_rot, area),
                        pt.free_convection_temperature_rise(power, d, area))
    given = p["heat_transfer"] > 0.0
    rise = mx.if_else(given, pt.friction_temperature_rise(power, mx.fmax(p["heat_transfer"], 1e-12), area),
                      rise_auto)
    h = power / (area * mx.fmax(rise, 1e-12))  # the effective film
    # the axis says in Python whether the balance sets the rise (motion.Phases.heat), so that a model without it
    # carries no preload-dependent thermal terms (the global reference solvers see the same algebra as before)
    flag = getattr(phases, "heat", None)
    if flag is None:  # a bare parameter dict: the parameter decides
        used = p["temperature_rise_auto"] * rise + (1.0 - p["temperature_rise_auto"]) * p["temperature_rise"]
    else:
        used = rise if flag else p["temperature_rise"]
    return {"friction_power": power, "heat_transfer": h, "heat_balance_rise": rise, "temperature_rise": used,
            "cycle_mean_screw_speed": omega}


def with_temperature(p, heat) -> dict:
    """``p`` with the temperature rise the model uses (loads, chain)."""
    q = dict(p)
    q["temperature_rise"] = heat["temperature_rise"]
    return q
