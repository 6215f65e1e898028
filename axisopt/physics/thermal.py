"""Thermal growth of the screw shaft and the pretension that compensates it (vendor catalog forms),
and the steady heat balance of a ball-screw drive as a lumped thermal network (Jungnickel 2010;
SI)."""

from __future__ import annotations

from axisopt import mathx as mx
from axisopt.physics.screw import E_STEEL, screw_axial_rigidity

__all__ = [
    "ALPHA_STEEL",
    "K_STEEL",
    "K_CAST_IRON",
    "thermal_growth",
    "restrained_thermal_force",
    "thermal_force_elastic_ends",
    "thermal_displacement",
    "rotating_shaft_heat_transfer",
    "friction_temperature_rise",
    "free_convection_temperature_rise",
    "horizontal_cylinder_free_film",
    "mixed_convection_film",
    "shaft_end_fraction",
    "screw_heat_network",
]

ALPHA_STEEL = 11.6e-6  # [1/K] HIWIN BS-08-2-EN-1704-K F 3.36 (THK A-715 uses 12e-6)


def thermal_growth(length, temperature_rise, alpha=ALPHA_STEEL):
    r"""Free thermal elongation of a screw length.

    .. math:: \Delta L = \alpha\, \Delta T\, L

    length : L [m];  temperature_rise : Delta T [K];  alpha : [1/K] (11.6e-6 HIWIN F 3.36, 12e-6 THK
        A-715).
    Returns Delta L [m].  Source: HIWIN ballscrew catalog (temperature rise), THK "thermal
    displacement".
    """
    return alpha * temperature_rise * length


def restrained_thermal_force(
    root_diameter, temperature_rise, alpha=ALPHA_STEEL, youngs_modulus=E_STEEL
):
    r"""Axial force that holds a heated screw at its length between rigid ends; the pretension that
    compensates a temperature rise.

    .. math:: P = E A \alpha \Delta T,\ A = \pi d_r^2 / 4

    root_diameter : d_r [m];  temperature_rise : Delta T [K];  alpha [1/K];  youngs_modulus : E
        [Pa].
    Returns P [N].  Source: HIWIN ballscrew catalog (pretension to absorb thermal elongation),
    THK catalog ("pretension" with a negative target lead).
    """
    return screw_axial_rigidity(root_diameter, youngs_modulus) * alpha * temperature_rise


def thermal_force_elastic_ends(
    root_diameter, span, temperature_rise, k_bearing_set, alpha=ALPHA_STEEL, youngs_modulus=E_STEEL
):
    r"""Change of the axial force in a screw held at both ends by elastic bearing sets when it heats
    up.

    .. math:: \Delta F = \alpha \Delta T L / (L/EA + 2/k_B)

    (compressive; the two bearing sets and the shaft in series).  Pretension keeps the bearing sets
    loaded while the force falls by Delta F.  root_diameter : d_r [m];  span : L [m];
    temperature_rise [K]
    k_bearing_set : one set with housing [N/m].  Returns Delta F [N] (<= restrained_thermal_force).
    Source: statics of springs in series; limit k_B -> inf is restrained_thermal_force.
    """
    ea = screw_axial_rigidity(root_diameter, youngs_modulus)
    return alpha * temperature_rise * span / (span / ea + 2.0 / k_bearing_set)


def thermal_displacement(
    x,
    span,
    root_diameter,
    temperature_rise,
    k_bearing_set,
    both_ends_fixed,
    alpha=ALPHA_STEEL,
    youngs_modulus=E_STEEL,
):
    r"""Displacement of the nut position along the screw caused by a uniform temperature rise.

    One fixed end (fixed-free, fixed-supported): the shaft grows freely away from the fixed bearing,

    .. math:: u(x) = \alpha \Delta T x

    Both ends fixed: the restrained growth pushes the bearing sets apart by Delta F / k_B each,

    .. math:: u(x) = -\Delta F / k_B + (\alpha \Delta T - \Delta F / EA)\, x

    x : fixed bearing to nut [m];  span : L [m];  root_diameter : d_r [m];  temperature_rise : Delta
        T [K]
    k_bearing_set : [N/m];  both_ends_fixed : 1.0 for fixed-fixed, 0.0 otherwise (may be symbolic).
    Returns u [m] (positive away from the fixed bearing).
    """
    ea = screw_axial_rigidity(root_diameter, youngs_modulus)
    free = alpha * temperature_rise * x
    df = thermal_force_elastic_ends(
        root_diameter, span, temperature_rise, k_bearing_set, alpha, youngs_modulus
    )
    held = -df / k_bearing_set + (alpha * temperature_rise - df / ea) * x
    return both_ends_fixed * held + (1.0 - both_ends_fixed) * free


# Jungnickel, G. (2010) "Simulation des thermischen Verhaltens von Werkzeugmaschinen", TU Dresden:
# film coefficient of a cylinder rotating in still air, alpha = 3.75 omega^0.7 r^0.4 (as implemented
# in steffenschroe/Thermca, thermca/lib/forced_conv.py, rot_cyl_in_air, cited there as [Jun10]).
JUNGNICKEL_CYLINDER = (3.75, 0.7, 0.4)


def rotating_shaft_heat_transfer(speed, radius, coefficients=JUNGNICKEL_CYLINDER):
    r"""Convective heat-transfer coefficient of a shaft rotating in still air (Jungnickel 2010).

    .. math:: \alpha = 3.75\, \omega^{0.7} r^{0.4}

    speed : omega [rad/s] (sign ignored);  radius : r [m].  Returns alpha [W/(m^2 K)].  E.g. a 40 mm
        shaft at 1000 rpm: 20.3 W/(m^2 K).  Validity: forced convection by the rotation alone (no
        air stream, no coolant).
    """
    c, a, b = coefficients
    return c * (mx.fabs(speed) + 1e-12) ** a * radius**b


def friction_temperature_rise(friction_power, heat_transfer, area):
    r"""Steady temperature rise of a body that turns its friction power into heat and loses it by
    convection from its surface (heat balance: heat generated = heat convected, Newton's law of
    cooling).

    .. math:: \Delta T = P / (\alpha A)

    friction_power : P [W] (drag torque x speed, e.g. the cycle mean: Tian & He's Q = T
        omega);  heat_transfer : alpha [W/(m^2 K)];  area : A [m^2].  Returns Delta T [K].
        Conduction into the bearing housings and nut bracket, and radiation, are left out: the rise
        is an upper estimate for a screw in still air.
    """
    return friction_power / (heat_transfer * area)


# Holman, J.P., Heat Transfer, Table 7-2 "Simplified equations for free convection from various
# surfaces to air at atmospheric pressure": horizontal cylinder, laminar (1e4 < Gr Pr < 1e9): h =
# 1.32 (dT / d)^(1/4) W/(m^2 K), dT [K], d [m].
HOLMAN_HORIZONTAL_CYLINDER = 1.32


def free_convection_temperature_rise(
    friction_power, diameter, area, coefficient=HOLMAN_HORIZONTAL_CYLINDER
):
    r"""Temperature rise of a horizontal cylinder losing ``friction_power`` by free convection to
    still air alone (Holman Table 7-2, laminar: :math:`h = 1.32 (\Delta T/d)^{1/4}`), solved for
    the rise:

    .. math:: \Delta T = \big(P\, d^{1/4} / (1.32 A)\big)^{4/5}

    friction_power : P [W];  diameter : d [m];  area : A [m^2].  Returns Delta T [K].  With the
        rotation's own film (``rotating_shaft_heat_transfer``) acting as well, the true rise is
        below both this and ``friction_temperature_rise`` with the rotating film alone; the smaller
        of the two is an upper estimate that holds at standstill-like mean speeds, where the
        rotating-shaft correlation goes to zero.
    """
    return (friction_power * diameter**0.25 / (coefficient * area)) ** 0.8


# ---- the heat balance as a lumped thermal network
# ------------------------------------------------------------
# Jungnickel, G. (2010) "Simulation des thermischen Verhaltens von Werkzeugmaschinen. Modellierung
# und Parametrierung", TU Dresden: lumped-parameter thermal models of machine-tool components, as
# implemented in steffenschroe/Thermca (thermca/lib/*.py, cited there as [Jun10]): the
# rotating-shaft film (above), free convection on a horizontal cylinder (free_conv.horiz_cyl), mixed
# free and forced convection (combd_film.mix_conv), material conductivities (solids.carbon_steel C45
# 48 W/(m K), solids.cast_iron_gjl_300 47.5 W/(m K)).
K_STEEL = 48.0  # [W/(m K)] screw shaft: C45 (1.0503), [Jun10] via Thermca solids.carbon_steel
# [W/(m K)] nut bracket, table: EN-GJL-300, [Jun10] via Thermca solids.cast_iron_gjl_300
K_CAST_IRON = 47.5


def horizontal_cylinder_free_film(temperature_rise, diameter):
    r"""Free-convection film coefficient of a horizontal cylinder in still air (Jungnickel 2010,
    Thermca ``free_conv.horiz_cyl``).

    .. math:: \alpha = 1.34\, \Delta T^{0.33} + 0.164\, (\Delta T / d^7)^{0.1}

    temperature_rise : Delta T, surface over air [K];  diameter : d [m].  Returns alpha [W/(m^2 K)].
        E.g. a 40 mm shaft 5 K above the air: 4.1 W/(m^2 K) (Holman's laminar 1.32 (dT/d)^0.25 gives
        4.4).
    """
    return 1.34 * temperature_rise**0.33 + 0.164 * (temperature_rise / diameter**7) ** 0.1


def mixed_convection_film(forced, free, exponent=4.0):
    r"""Film coefficient of free and forced convection acting together (Jungnickel 2010, Thermca
    ``combd_film.mix_conv``).

    .. math:: \alpha = (\alpha_{forced}^n + \alpha_{free}^n)^{1/n}

    forced, free : [W/(m^2 K)];  exponent : n = 4 for flows across each other (a horizontal
        rotating shaft: the rotation's flow runs round it, the buoyant one up), 3 for assisting
        flows.  Returns alpha [W/(m^2 K)].
    """
    return (forced**exponent + free**exponent) ** (1.0 / exponent)


def shaft_end_fraction(
    film, nominal_diameter, root_diameter, half_length, end_conductance, conductivity=K_STEEL
):
    r"""How strongly the shaft ends pull the mean temperature of a heated shaft towards theirs: the
    shaft as a fin (conduction along it, convection from its surface) between two ends held through
    ``end_conductance``.

    With heat entering uniformly along the shaft, the mean rise is :math:`\theta_\infty (1 - f)`
    (:math:`\theta_\infty = q'/(\alpha U)`, the rise of an endless shaft); with the ends at
    :math:`\theta_e` and no heat along it, :math:`\theta_e f`, where

    .. math:: f = \frac{G \tanh x}{x\,(k A m \tanh x + G)},\quad m = \sqrt{\alpha U / (k A)},\ x = m\,l

    (the fin equation :math:`k A \theta'' = \alpha U \theta - q'` with
    :math:`k A \theta' = \pm G \theta` at the ends; Incropera & DeWitt, Fundamentals of Heat and
    Mass Transfer, ch. 3.6, extended fins).  U = pi d (nominal diameter: the surface), A = pi d_r^2
    / 4 (root diameter: the conducting section).
    film : alpha [W/(m^2 K)];  nominal_diameter, root_diameter [m];  half_length : l, half the
        bearing span (both ends held) or the whole span (one end held, the other free)
        [m];  end_conductance : G [W/K] per end;
    conductivity : k [W/(m K)].  Returns f [-] in [0, tanh(x)/x] (0: insulated ends; tanh(x)/x: ends
        at theta_e).
    """  # noqa: E501
    area = mx.pi * root_diameter**2 / 4.0
    kam = mx.sqrt(film * mx.pi * nominal_diameter * conductivity * area)  # k A m
    x = kam / (conductivity * area) * half_length
    t = mx.tanh(x)
    return end_conductance * t / (x * (kam * t + end_conductance))


def screw_heat_network(
    nut_power,
    bearing_power,
    film,
    nominal_diameter,
    root_diameter,
    span,
    ends,
    nut_conductance,
    end_conductance,
    housing_conductance,
    conductivity=K_STEEL,
):
    r"""Steady mean temperature rise of the screw shaft of a ball-screw drive: a lumped thermal
    network after Jungnickel (2010) (heat sources at the nut and the support bearings, a film on the
    rotating shaft, conduction through the joints to the machine's structure, which stays at
    ambient).

    Nodes and paths (theta: rise over ambient):

    * the nut's friction power P_n enters the nut and the shaft under it, taken at one temperature
      (the balls' contact conductance taken as infinite, Jungnickel models it finite, Thermca
      ``ball_screw.cont_cond``: a finite one keeps the nut warmer and sends more of P_n into the
      table, so the shaft's rise here is an upper estimate); it leaves through the nut bracket into
      the table, ``nut_conductance`` G_n, and into the shaft;
    * the shaft spreads it along its span (uniformly: the nut sweeps the stroke) and loses it by
      convection, ``film`` alpha over pi d L, and by conduction along the shaft into its ends
      (:func:`shaft_end_fraction`);
    * each held end leads through the support bearing, ``end_conductance`` G_e, into its housing;
      the bearings' friction power P_b heats the housings, ``housing_conductance`` G_h each, to
      theta_e = P_b / (ends G_h) on average.

    .. math::
        R_s = (1 - f) / (\alpha \pi d L),\quad
        Q_s = \frac{P_n - G_n f \theta_e}{1 + G_n R_s},\quad
        \theta_s = Q_s R_s + f \theta_e

    nut_power : P_n [W];  bearing_power : P_b, all fixed support sets [W];  film : alpha [W/(m^2
        K)]; nominal_diameter, root_diameter [m];  span : L, bearing to bearing [m];  ends : held
        shaft ends (2 with a bearing at each end, 1 fixed-free);  conductances [W/K].  Returns
        theta_s [K], the shaft's mean rise (what its growth reads).  It rises linearly with P_n (so
        with the nut preload) and with P_b.  Radiation is left out (an upper estimate).
    """
    f = shaft_end_fraction(
        film, nominal_diameter, root_diameter, span / ends, end_conductance, conductivity
    )
    r_s = (1.0 - f) / (film * mx.pi * nominal_diameter * span)
    theta_end = f * bearing_power / (ends * housing_conductance)
    q_shaft = (nut_power - nut_conductance * theta_end) / (1.0 + nut_conductance * r_s)
    return q_shaft * r_s + theta_end
