"""Drive torque losses: screw efficiency, torque from axial force, total drag torque at the
motor."""

from __future__ import annotations

from axisopt import mathx as mx

__all__ = ["screw_efficiency", "axial_force_torque", "motor_drag_torque"]


def screw_efficiency(lead_angle, friction_coefficient=0.003):
    r"""Forward efficiency of a ball screw (rotation -> translation).

    .. math:: \eta = \tan\phi / \tan(\phi + \rho),\ \rho = \arctan\mu

    lead_angle : phi [rad];  friction_coefficient : mu [-] (0.003-0.01 for ball screws, THK).
    Returns eta [-].
    """
    return mx.tan(lead_angle) / mx.tan(lead_angle + mx.atan(friction_coefficient))


def axial_force_torque(axial_force, lead, efficiency=0.9):
    r"""Motor torque to drive an axial force, T = F P_h / (2 pi eta).

    Source: THK "studying the rotational torque".

    axial_force : F [N] (sign kept);  lead : P_h [m];  efficiency : eta [-].  Returns T [N*m].
    """
    return axial_force * lead / (2.0 * mx.pi * efficiency)


def motor_drag_torque(
    preload_torque, bearing_torque, guide_force, lead, efficiency=0.9, seal_torque=0.0
):
    r"""Total no-load drag torque seen by the motor.

    .. math:: T = T_p + T_{brg} + T_{seal} + F_{guide} P_h / (2\pi\eta)

    preload_torque : T_p, nut preload drag (nut.nut_preload_drag_torque) [N*m]
    bearing_torque : T_brg, support bearings (bearings.bearing_friction_torque, all bearings) [N*m]
    guide_force    : F_guide, sum of guide block friction (guides.guide_friction_force) [N]
    lead : P_h [m];  efficiency : eta [-];  seal_torque : T_seal [N*m].  Returns T [N*m].
    Source: THK General Catalog, ball screw torque calculation (A-743..A-746): the drive torque at
    constant speed is the preload drag, the bearings' and seals' torques and the guide friction
    through the lead.
    """
    return (
        preload_torque
        + bearing_torque
        + seal_torque
        + axial_force_torque(guide_force, lead, efficiency)
    )
