"""Heat balance of the screw: friction power over the duty cycle and the temperature rise it causes.

The nut's preload drag and the support bearings' drag turn into heat at the cycle's mean screw speed
(Tian & He: Q = T omega).  The heat leaves through a lumped thermal network after Jungnickel (2010)
(:func:`axisopt.physics.thermal.screw_heat_network`): the nut's heat through the nut bracket into
the table and into the shaft; the shaft loses it by convection (Jungnickel's film of a shaft
rotating in still air, averaged over the cycle's phases, mixed with free convection from a
horizontal cylinder) and by conduction along itself into the support bearings and their housings,
which the bearings' own heat warms.  ``axis.heat_transfer`` replaces the shaft's film (a cooled
screw).  The rise replaces the fixed ``temperature_rise`` when the axis has a duty cycle and sets
none; the thermal growth at the nut and the thermal force of a fixed-fixed screw read it.  It rises
linearly with the nut preload (through the drag), and so do the outputs that read it
(model.limits.OUTPUT_PRELOAD).

The network's conductances are estimates (no vendor or paper publishes them for a general axis;
measured check: tests/physics/test_thermal.py against THK's heat-generation tests A-821 and A-671;
docs/assumptions.md):

* ``NUT_BRACKET_SHAPE``: the nut bracket conducts like a cast-iron block whose section over length
  equals the screw's nominal diameter (e.g. 40 x 80 mm over 80 mm for a 40 mm screw: 1.9 W/K), the
  table beyond it at ambient;
* ``END_CONDUCTANCE``: shaft end -> support bearing -> housing, 2 W/K per end (Schaeffler's radial
  conductance of a rolling bearing, Thermca ``bearing.cond``, gives 1.5-1.8 W/K per row of a 7206 at
  230-1000 rpm; a DF pair in series with its housing joint about 2 W/K);
* ``HOUSING_CONDUCTANCE``: a support-bearing housing to the bed, 5 W/K (a bolted cast-iron unit on
  the bed);
* ``FREE_CONVECTION_RISE``: the free-convection film is taken at a 5 K rise (THK plans for 2-5 degC,
  A-715; the film moves by -15 % / +15 % between 2.5 and 10 K).
"""

from __future__ import annotations

import math

from .. import mathx as mx
from ..physics import nut as pn
from ..physics import thermal as pt
from ..physics.motion import mean_speed, phase_travel
from .loads import unit

NUT_BRACKET_SHAPE = 1.0  # bracket section / length per metre of screw diameter [-] (estimate)
END_CONDUCTANCE = 2.0  # [W/K] per held shaft end (estimate)
HOUSING_CONDUCTANCE = 5.0  # [W/K] per support-bearing housing (estimate)
FREE_CONVECTION_RISE = 5.0  # [K] at which the free-convection film is taken (estimate)


def cycle_film(phases, lead, radius):
    """Jungnickel's rotating-shaft film averaged over the duty cycle's phases by time [W/(m^2 K)],
    each phase at its mean screw speed (travel over duration; a dwell adds nothing): the film grows
    as omega^0.7, so the film at the cycle's mean speed would overstate it."""
    total = sum(ph.duration for ph in phases)
    if total <= 0.0:
        return 0.0
    film = 0.0
    for ph in phases:
        if ph.duration > 0.0:
            omega = 2.0 * math.pi * phase_travel(ph) / ph.duration / lead
            film = film + ph.duration / total * pt.rotating_shaft_heat_transfer(omega, radius)
    return film


def heat_balance(p, preload) -> dict:
    """Friction power [W] (nut and bearings, cycle mean), the shaft's film coefficient [W/(m^2 K)],
    the heat-balance rise [K] and the temperature rise the model uses [K] (the balance when
    ``temperature_rise_auto``)."""
    phases = p.get("duty", ())
    v_mean = mean_speed(phases) if phases else p["mean_speed"]
    omega = 2.0 * math.pi * v_mean / p["lead"]
    d, d_r = p["nominal_diameter"], p["root_diameter"]
    r = unit(p, "nut_rotating")  # a bare parameter dict without the unit: a nut on a turning screw
    # a driven rotating nut: the unit's bearing heats the nut housing (its heat takes the nut's
    # path), the end bearings and the shaft stand still (no drag, no rotating film: free convection
    # alone)
    p_nut = (
        pn.nut_preload_drag_torque(preload, p["lead"], d) + r * unit(p, "unit_bearing_torque")
    ) * omega
    p_bearings = (1.0 - r) * p["bearing_sets"] * p["bearing_torque"] * omega
    h_rot = (
        cycle_film(phases, p["lead"], 0.5 * d)
        if phases
        else pt.rotating_shaft_heat_transfer(omega, 0.5 * d)
    )
    h_rot = (1.0 - r) * h_rot
    h_mixed = pt.mixed_convection_film(
        h_rot, pt.horizontal_cylinder_free_film(FREE_CONVECTION_RISE, d)
    )
    given = p["heat_transfer"] > 0.0
    h = mx.if_else(given, mx.fmax(p["heat_transfer"], 1e-12), h_mixed)
    rise = pt.screw_heat_network(
        p_nut,
        p_bearings,
        h,
        d,
        d_r,
        p["span"],
        p["shaft_ends"],
        NUT_BRACKET_SHAPE * pt.K_CAST_IRON * d,
        END_CONDUCTANCE,
        HOUSING_CONDUCTANCE,
    )
    # the axis says in Python whether the balance sets the rise (motion.Phases.heat), so that a
    # model without it carries no preload-dependent thermal terms (the global reference solvers see
    # the same algebra as before)
    flag = getattr(phases, "heat", None)
    if flag is None:  # a bare parameter dict: the parameter decides
        used = (
            p["temperature_rise_auto"] * rise
            + (1.0 - p["temperature_rise_auto"]) * p["temperature_rise"]
        )
    else:
        used = rise if flag else p["temperature_rise"]
    return {
        "friction_power": p_nut + p_bearings,
        "heat_transfer": h,
        "heat_balance_rise": rise,
        "temperature_rise": used,
        "cycle_mean_screw_speed": omega,
    }


def with_temperature(p, heat) -> dict:
    """``p`` with the temperature rise the model uses (loads, chain)."""
    q = dict(p)
    q["temperature_rise"] = heat["temperature_rise"]
    return q
