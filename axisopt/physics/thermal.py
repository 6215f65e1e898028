"""Thermal growth of the screw shaft and the pretension that compensates it (vendor catalog forms, SI)."""

from __future__ import annotations

from axisopt.physics.screw import E_STEEL, screw_axial_rigidity

__all__ = [
    "ALPHA_STEEL", "thermal_growth", "restrained_thermal_force", "thermal_force_elastic_ends",
    "thermal_displacement",
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
