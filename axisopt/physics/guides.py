"""Linear guides: normal/tangential stiffness (seed 3.4, Table 1, eq. 31-35) and block friction
(Table 9)."""

from __future__ import annotations

from axisopt import mathx as mx

__all__ = [
    "TANGENTIAL_NORMAL_RATIO",
    "guide_tangential_stiffness",
    "guide_ball_stiffness",
    "guide_normal_stiffness_hertz",
    "guide_tangential_stiffness_hertz",
    "guide_friction_force",
]

TANGENTIAL_NORMAL_RATIO = 0.71  # seed Table 1 / sec. 3.1.3 (Wang et al. [27]): k_t / k_n


def guide_tangential_stiffness(normal_stiffness, ratio=TANGENTIAL_NORMAL_RATIO):
    r"""Tangential (lateral) stiffness of a rolling guide block from its catalog normal stiffness.

    .. math:: k_t = 0.71\, k_n                                   (seed Table 1, text of sec. 3.1.3)

    normal_stiffness : k_n [N/m];  ratio : k_t/k_n [-].  Returns k_t [N/m].
    Empirical, from three computed guides in [27] (ratios 0.718-0.720).
    """
    return ratio * normal_stiffness


def guide_ball_stiffness(preload_per_ball, deflection_constant):
    r"""Tangent stiffness of one preloaded ball along its contact normal (both contacts).

    .. math:: \delta = c_h P^{2/3} \Rightarrow k_b = dP/d\delta = \tfrac32 P_0^{1/3} / c_h     (seed eq. 12)

    preload_per_ball    : P_0 [N]
    deflection_constant : c_h [m/N^(2/3)], e.g. nut.hertz_point_deflection(1.0, ...) summed over
        both contacts
    Returns k_b [N/m].
    """  # noqa: E501
    return 1.5 * mx.cbrt(preload_per_ball) / deflection_constant


def guide_normal_stiffness_hertz(preload_per_ball, deflection_constant, n_balls, contact_angle):
    r"""Normal stiffness of a preloaded guide block from the linearised Hertz row model (seed eq.
    31-34).

    A normal displacement delta_n changes each ball approach by delta_n sin(beta) (eq. 33): loaded
    rows compress, opposing rows relax, each ball contributes k_b sin^2(beta):

    .. math:: K_n = z\, k_b \sin^2\beta

    preload_per_ball : P_0 [N] (eq. 32: F_0 = sqrt(2) z P_0 sin beta);  deflection_constant : c_h
        [m/N^(2/3)]
    n_balls : z, loaded balls of all rows [-];  contact_angle : beta [rad].  Returns K_n [N/m].
    Valid below lift-off of the relaxing rows (external load < ~2.8 x preload).
    """
    return (
        n_balls
        * guide_ball_stiffness(preload_per_ball, deflection_constant)
        * mx.sin(contact_angle) ** 2
    )


def guide_tangential_stiffness_hertz(preload_per_ball, deflection_constant, n_balls, contact_angle):
    r"""Tangential stiffness of a preloaded guide block, linearised Hertz row model (seed eq. 35).

    Lateral displacement delta_t changes each ball approach by delta_t cos(beta):

    .. math:: K_t = z\, k_b \cos^2\beta

    Arguments as guide_normal_stiffness_hertz.  Returns K_t [N/m].  K_t/K_n = cot^2(beta); the
    empirical 0.71 of Table 1 corresponds to beta = 50 deg in this idealised model (real blocks
    differ by row layout).
    """
    return (
        n_balls
        * guide_ball_stiffness(preload_per_ball, deflection_constant)
        * mx.cos(contact_angle) ** 2
    )


def guide_friction_force(
    friction_force, friction_coefficient, friction_viscous, normal_load, speed
):
    r"""Friction force of one guide block against block load and speed.

    .. math:: F = F_0 + \mu |N| + c_v |v|

    friction_force       : F_0, seal and preload friction at zero load [N]
    friction_coefficient : mu [-] (rolling, 0.001-0.005)
    friction_viscous     : c_v [N*s/m]
    normal_load          : N, block load in addition to preload [N]
    speed                : v [m/s]
    Returns F [N] (magnitude; the force opposes motion).  Source: linear-in-load reading of seed
    Table 9 (after [16]); the table's growth above 20 kN is steeper than linear.  Valid 0.08-0.7 m/s
    (Table 9 range).
    """
    return (
        friction_force
        + friction_coefficient * mx.fabs(normal_load)
        + friction_viscous * mx.fabs(speed)
    )
