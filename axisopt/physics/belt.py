r"""A timing-belt reduction stage of two pulleys: geometry, the permissible effective pull,
stiffness, inertia.

The vendors' procedure (ELATECH polyurethane belts, "Drive calculation" and the
technical-data pages: the tooth shear strength FUspez per tooth and cm of width, the allowable
tensile load FTzul and the specific spring rate Cspez per width; ContiTech SYNCHROFLEX pp. 42-43
"basis of calculation" and worked example; Siegling "Timing belts - calculation methods" ref. 202
p. 2) in SI units:

.. math::
    d = p z / \pi                                       (pitch diameter, Gates eq. 1)
    L = 2 C + \pi (d_1 + d_2) / 2 + (d_2 - d_1)^2 / (4 C)  (open belt, pitch length)
    \beta_1 = \pi - 2 \arcsin((d_2 - d_1) / (2 C))      (wrap on the small pulley)
    F_U = F_{U,spez} z_e b,\ z_e \le z_{e,max} = 12      (ELATECH, SYNCHROFLEX: tooth shear)
    F_U = 2 T / d                                       (SYNCHROFLEX, Siegling)
    F_T = F_{TV} + F_U / 2 \le F_{T,zul}                 (tight span of a two-pulley drive, pretension F_TV)
    c = C_{spez} / l                                    (a span of free length l, ELATECH Cspez)

The stage's torsional stiffness at the output with the input held is that of both spans acting on
the output pulley, :math:`2 c (d_2/2)^2`, as long as the slack span keeps tension (F_TV >= F_U / 2,
Siegling's least pretension of a two-pulley drive).  It counts the belt's cords only (the teeth's
own deflection under load is not in these vendors' tables): an upper bound of the stage's stiffness.

Every function works on floats, numpy arrays and CasADi symbols.
"""  # noqa: E501

from __future__ import annotations

from math import pi

from .. import mathx as mx

__all__ = [
    "pitch_diameter",
    "belt_length",
    "span_length",
    "wrap_angle",
    "teeth_in_mesh",
    "span_stiffness",
    "stage_torsional_stiffness",
    "tooth_shear_pull",
    "tension_pull",
    "effective_pull",
    "pulley_inertia",
    "stage_input_inertia",
    "ZE_MAX",
]

ZE_MAX = 12.0  # ELATECH M belts: at most 12 teeth in mesh count (ELATECH "Drive calculation")


def pitch_diameter(pitch, teeth):
    """Pitch diameter d = p z / pi [m] of a pulley of ``teeth`` teeth for the belt pitch ``pitch``
    [m]."""
    return pitch * teeth / pi


def belt_length(d1, d2, centre):
    """Pitch length [m] of an open belt over pulleys of pitch diameters ``d1`` <= ``d2`` at centre
    distance ``centre`` [m] (SYNCHROFLEX p. 43 for equal pulleys: L = 2 a + z t)."""
    return 2.0 * centre + 0.5 * pi * (d1 + d2) + (d2 - d1) ** 2 / (4.0 * centre)


def span_length(d1, d2, centre):
    """Free length [m] of each span between the pulleys (the common tangent)."""
    return mx.sqrt(centre**2 - 0.25 * (d2 - d1) ** 2)


def wrap_angle(d1, d2, centre):
    """Wrap angle [rad] of the belt on the smaller pulley."""
    s = 0.5 * (d2 - d1) / centre
    return pi - 2.0 * mx.atan(s / mx.sqrt(1.0 - s**2))


def teeth_in_mesh(teeth_small, d1, d2, centre, ze_max=ZE_MAX):
    """Teeth in mesh on the small pulley, z1 beta / 2 pi, and at most ``ze_max`` (ELATECH: 12 for M
    belts).  Not rounded down: the catalog rows take the whole teeth (the vendors' z_e is a
    count)."""
    return mx.fmin(teeth_small * wrap_angle(d1, d2, centre) / (2.0 * pi), ze_max)


def span_stiffness(c_spez, span):
    """Axial stiffness [N/m] of a belt span of free length ``span`` [m] from the belt's specific
    spring rate ``c_spez`` [N] (force per unit strain, ELATECH Cspez of the belt's width)."""
    return c_spez / span


def stage_torsional_stiffness(c_spez, span, d_out):
    """Torsional stiffness [N m/rad] of the stage at its output pulley (pitch diameter ``d_out``)
    with the input
    held: both pretensioned spans, 2 c (d/2)^2."""
    return 2.0 * span_stiffness(c_spez, span) * (0.5 * d_out) ** 2


def tooth_shear_pull(fu_spez, teeth_meshed, width):
    """Effective pull [N] the teeth carry: F_U = FUspez z_e b with ``fu_spez`` [N/m] (the vendor's
    N/cm x 100, at the stage's speed), ``teeth_meshed`` z_e, ``width`` b [m]."""
    return fu_spez * teeth_meshed * width


def tension_pull(allowable_tension, pretension_share=1.0):
    """Effective pull [N] the cords allow in a two-pulley drive pretensioned to ``pretension_share``
    x F_U (1: ELATECH's rule for positioning drives, F_TV >= F_U): F_TV + F_U / 2 <= F_Tzul."""
    return allowable_tension / (pretension_share + 0.5)


def effective_pull(fu_spez, teeth_meshed, width, allowable_tension, pretension_share=1.0):
    """Permissible effective pull [N]: the lower of the teeth's shear and the cords' tension."""
    return mx.fmin(
        tooth_shear_pull(fu_spez, teeth_meshed, width),
        tension_pull(allowable_tension, pretension_share),
    )


def pulley_inertia(tip_diameter, width, density, bore=0.0):
    """Inertia [kg m^2] of a pulley as a disc of its tip diameter and ``width`` (Siegling's pulley
    mass m = (dk^2 - d^2) pi b rho / 4) less its ``bore``: m (dk^2 + d^2) / 8."""
    mass = (tip_diameter**2 - bore**2) * pi * width * density / 4.0
    return mass * (tip_diameter**2 + bore**2) / 8.0


def stage_input_inertia(j_in, j_out, belt_mass, d_in, ratio):
    """Inertia [kg m^2] of the stage seen at its input: the input pulley, the output pulley through
    the ratio (J / i^2) and the belt's mass moving at the pitch-line speed (m (d_1/2)^2)."""
    return j_in + j_out / ratio**2 + belt_mass * (0.5 * d_in) ** 2
