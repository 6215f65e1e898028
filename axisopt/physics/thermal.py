"""Thermal growth of the screw shaft and the pretension that compensates it (vendor catalog forms, SI)."""

from __future__ import annotations

from axisopt import mathx as mx
from axisopt.physics.screw import E_STEEL, screw_axial_rigidity

__all__ = [
    "ALPHA_STEEL", "thermal_growth", "restrained_thermal_force", "thermal_force_elastic_ends",
    "thermal_displacement", "rotating_shaft_heat_transfer", "friction_temperature_rise",
    "free_convection_temperature_rise",
]

ALPHA_STEEL = 11.6e-6  # [1/K] HIWIN BS-08-2-EN-1704-K F 3.36 (THK A-715 uses 12e-6)


def thermal_growth(length, temperature_rise, alpha=ALPHA_STEEL):
    r"""Free thermal elongation of a screw length.

    .. math:: \Delta L = \alpha\, \Delta T\, L

    length : L [m];  temperature_rise : Delta T [K];  alpha : [1/K] (11.6e-6 HIWIN F 3.36, 12e-6 THK A-715).
    Returns Delta L [m].  Source: HIWIN ballscrew catalog (temperature rise), THK "thermal displacement".
    """
    return alpha * temperature_rise * length


def restrained_thermal_force(root_diameter, temperature_rise, alpha=ALPHA_STEEL, youngs_modulus=E_STEEL):
    r"""Axial force that holds a heated screw at its length between rigid ends; the pretension that
    compensates a temperature rise.

    .. math:: P = E A \alpha \Delta T,\ A = \pi d_r^2 / 4

    root_diameter : d_r [m];  temperature_rise : Delta T [K];  alpha [1/K];  youngs_modulus : E [Pa].
    Returns P [N].  Source: HIWIN ballscrew catalog (pretension to absorb thermal elongation),
    THK catalog ("pretension" with a negative target lead).
    """
    return screw_axial_rigidity(root_diameter, youngs_modulus) * alpha * temperature_rise


def thermal_force_elastic_ends(root_diameter, span, temperature_rise, k_bearing_set, alpha=ALPHA_STEEL,
                               youngs_modulus=E_STEEL):
    r"""Change of the axial force in a screw held at both ends by elastic bearing sets when it heats up.

    .. math:: \Delta F = \alpha \Delta T L / (L/EA + 2/k_B)

    (compressive; the two bearing sets and the shaft in series).  Pretension keeps the bearing sets loaded
    while the force falls by Delta F.  root_diameter : d_r [m];  span : L [m];  temperature_rise [K]
    k_bearing_set : one set with housing [N/m].  Returns Delta F [N] (<= restrained_thermal_force).
    Source: statics of springs in series; limit k_B -> inf is restrained_thermal_force.
    """
    ea = screw_axial_rigidity(root_diameter, youngs_modulus)
    return alpha * temperature_rise * span / (span / ea + 2.0 / k_bearing_set)


def thermal_displacement(x, span, root_diameter, temperature_rise, k_bearing_set, both_ends_fixed,
                         alpha=ALPHA_STEEL, youngs_modulus=E_STEEL):
    r"""Displacement of the nut position along the screw caused by a uniform temperature rise.

    One fixed end (fixed-free, fixed-supported): the shaft grows freely away from the fixed bearing,

    .. math:: u(x) = \alpha \Delta T x

    Both ends fixed: the restrained growth pushes the bearing sets apart by Delta F / k_B each,

    .. math:: u(x) = -\Delta F / k_B + (\alpha \Delta T - \Delta F / EA)\, x

    x : fixed bearing to nut [m];  span : L [m];  root_diameter : d_r [m];  temperature_rise : Delta T [K]
    k_bearing_set : [N/m];  both_ends_fixed : 1.0 for fixed-fixed, 0.0 otherwise (may be symbolic).
    Returns u [m] (positive away from the fixed bearing).
    """
    ea = screw_axial_rigidity(root_diameter, youngs_modulus)
    free = alpha * temperature_rise * x
    df = thermal_force_elastic_ends(root_diameter, span, temperature_rise, k_bearing_set, alpha, youngs_modulus)
    held = -df / k_bearing_set + (alpha * temperature_rise - df / ea) * x
    return both_ends_fixed * held + (1.0 - both_ends_fixed) * free


# Jungnickel, G. (2010) "Simulation des thermischen Verhaltens von Werkzeugmaschinen", TU Dresden: film
# coefficient of a cylinder rotating in still air, alpha = 3.75 omega^0.7 r^0.4 (as implemented in
# steffenschroe/Thermca, thermca/lib/forced_conv.py, rot_cyl_in_air, cited there as [Jun10]).
JUNGNICKEL_CYLINDER = (3.75, 0.7, 0.4)


def rotating_shaft_heat_transfer(speed, radius, coefficients=JUNGNICKEL_CYLINDER):
    r"""Convective heat-transfer coefficient of a shaft rotating in still air (Jungnickel 2010).

    .. math:: \alpha = 3.75\, \omega^{0.7} r^{0.4}

    speed : omega [rad/s] (sign ignored);  radius : r [m].  Returns alpha [W/(m^2 K)].  E.g. a 40 mm shaft at
    1000 rpm: 20.3 W/(m^2 K).  Validity: forced convection by the rotation alone (no air stream, no coolant).
    """
    c, a, b = coefficients
    return c * (mx.fabs(speed) + 1e-12) ** a * radius**b


def friction_temperature_rise(friction_power, heat_transfer, area):
    r"""Steady temperature rise of a body that turns its friction power into heat and loses it by convection
    from its surface (heat balance: heat generated = heat convected, Newton's law of cooling).

    .. math:: \Delta T = P / (\alpha A)

    friction_power : P [W] (drag torque x speed, e.g. the cycle mean: Tian & He's Q = T omega);  heat_transfer :
    alpha [W/(m^2 K)];  area : A [m^2].  Returns Delta T [K].  Conduction into the bearing housings and nut
    bracket, and radiation, are left out: the rise is an upper estimate for a screw in still air.
    """
    return friction_power / (heat_transfer * area)


# Holman, J.P., Heat Transfer, Table 7-2 "Simplified equations for free convection from various surfaces to air
# at atmospheric pressure": horizontal cylinder, laminar (1e4 < Gr Pr < 1e9): h = 1.32 (dT / d)^(1/4) W/(m^2 K),
# dT [K], d [m].
HOLMAN_HORIZONTAL_CYLINDER = 1.32


def free_convection_temperature_rise(friction_power, diameter, area, coefficient=HOLMAN_HORIZONTAL_CYLINDER):
    r"""Temperature rise of a horizontal cylinder losing ``friction_power`` by free convection to still air alone
    (Holman Table 7-2, laminar: :math:`h = 1.32 (\Delta T/d)^{1/4}`), solved for the rise:

    .. math:: \Delta T = \big(P\, d^{1/4} / (1.32 A)\big)^{4/5}

    friction_power : P [W];  diameter : d [m];  area : A [m^2].  Returns Delta T [K].  With the rotation's own
    film (``rotating_shaft_heat_transfer``) acting as well, the true rise is below both this and
    ``friction_temperature_rise`` with the rotating film alone; the smaller of the two is an upper estimate
    that holds at standstill-like mean speeds, where the rotating-shaft correlation goes to zero.
    """
    return (friction_power * diameter**0.25 / (coefficient * area)) ** 0.8


def mean_cycle_speed(phases, speeds):
    """Mean table speed over a duty cycle [m/s]: distance over cycle time, each phase's distance from its start
    and end speeds (``motion.phase_speeds``) as (v0 + v1) t / 2 (exact at constant acceleration)."""
    total = sum(ph.duration for ph in phases)
    if total <= 0.0:
        return 0.0
    return sum(0.5 * (v0 + v1) * ph.duration for ph, (v0, v1) in zip(phases, speeds)) / total
