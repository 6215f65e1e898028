r"""Counterbalance of a vertical axis: a counterweight on a chain or cable over a sprocket or
pulley, or a pneumatic / hydraulic balance cylinder, takes part of the head's weight off the screw.

The servo vendors' selection formulas for a vertical ball screw with a counterweight (SI, lead P_h
in m):

.. math::
    T_U = (W_1 - W_2)\,g\,P_h / (2\pi\eta)            (Mitsubishi MR-J2S-A Instruction Manual sec. 11, eq. 11-20,
                                                       "unbalanced torque")
    T_F = \mu (W_1 + W_2)\,g\,P_h / (2\pi\eta)        (eq. 11-21, friction torque of the moving part)
    T_L = T_U + T_F \text{ (rising)},\quad T_L = -T_U\eta^2 + T_F \text{ (lowering)}   (eq. 11-18, 11-19)
    T_L = 9.8 (M - M_c) P_B / (2\pi R \eta),\quad J_{L1} = (M + M_c)(P_B / 2\pi R)^2
                                                      (Yaskawa Sigma-7 manual 11.2.1, vertical axis)
    T_L = ((\mu + 1) W_1 - W_2)\,9.81\,B_P / (2\pi\eta)   hoisting,
    T_L = ((\mu - 1) W_1 - W_2)\,9.81\,B_P / (2\pi\eta)   descending,
    T_L = (W_1 - W_2)\,9.81\,B_P / (2\pi\eta)             at a stop   (Fuji ALPHA5 Smart manual 15, "Capacity
                                                                       Selection Calculation")

W_1 / M the head, W_2 / M_c the counterweight [kg].  So the counterweight's weight is subtracted
from the head's and its mass is added to the mass the motor accelerates (it moves the other way at
the same speed).  None of these texts gives a worked example with numbers (searched 2026-11:
Mitsubishi MR-J2S-A / MELDAS MDS-R, Yaskawa Sigma-7 / Junma, Fuji ALPHA5 Smart); the tests check
these functions against the formulas as printed and, where the counterweight is 0, against THK's and
Yaskawa's worked examples.

The chain's friction over its sprocket (:func:`counterweight_force`) is written as an efficiency of
the pulley stage, as the vendors write the screw's: the counterweight's pull arrives at the head
reduced when it drives (the head rising) and must be exceeded when the head drives it (the head
lowering).  A cylinder (:func:`cylinder_force`) pushes with a force that varies over the stroke (the
gas compressed as the head rises or falls, or a pressure regulator keeping it constant) within a
pressure tolerance; no vendor sizing text for balance cylinders was found, so the checks take the
force at the end of its range that loads the drive most (:func:`cylinder_worst_force`).  Floats,
numpy arrays and CasADi symbols (``direction`` is a plain float).
"""  # noqa: E501

from __future__ import annotations

from .. import mathx as mx

G = 9.80665


def counterweight_force(mass, efficiency, direction, g=G):
    r"""Force of a counterweight's chain on the head, along the axis upwards [N], with the head
    moving in ``direction`` (+1 up, -1 down, 0 at rest):

    .. math:: F_c = m_c\,g\,\eta_p^{s}

    mass       : m_c, the counterweight [kg]
    efficiency : η_p, of the chain or cable over its sprocket or pulley, in (0, 1] [-]
    direction  : s, +1 the head rising (the counterweight drives, its pull arrives reduced), -1 the
                 head lowering (the head lifts the counterweight: its weight and the chain's
                 friction), 0 at rest (no friction credited)
    The friction opposes the motion both ways, as Mitsubishi's T_F adds to the torque rising and
    lowering (MR-J2S-A eq. 11-18, 11-19); its size as an efficiency is the pulley's (a roller chain
    over a sprocket about 0.95-0.98, our reading of the chain vendors' drive efficiency, an estimate
    when not given)."""
    return mass * g * efficiency**direction


def cylinder_force(force_start, force_end, position, stroke):
    r"""Force of a balance cylinder on the head [N], linear over the stroke:

    .. math:: F(x) = F_0 + (F_1 - F_0)\,x / l

    force_start : F_0 at the stroke's start (x = 0) [N];  force_end : F_1 at its end [N] (equal: a
        pressure regulator keeps the force constant);  position : x [m];  stroke : l [m].  A gas
        spring or an accumulator with a small volume change is near linear over the stroke (an
        estimate; no vendor law was found)."""
    return force_start + (force_end - force_start) * position / stroke


def cylinder_force_range(force_start, force_end, tolerance):
    r"""Least and largest force of a balance cylinder over its stroke with its pressure tolerance
    [N]:

    .. math:: F_{lo} = \min(F_0, F_1)(1 - t),\qquad F_{hi} = \max(F_0, F_1)(1 + t)

    tolerance : t, the pressure tolerance as a fraction (0.05 for +/- 5 %) [-]."""
    return mx.fmin(force_start, force_end) * (1.0 - tolerance), mx.fmax(force_start, force_end) * (
        1.0 + tolerance
    )


def cylinder_worst_force(weight, force_low, force_high):
    r"""The cylinder force within [F_lo, F_hi] that leaves the screw the largest net weight |W - F|
    [N]: the least force while the head outweighs the cylinder on average, the largest once the
    cylinder overbalances it

    .. math:: F_w = F_{lo} \text{ if } W - F_{lo} \ge F_{hi} - W \text{ else } F_{hi}

    weight : W, the head's weight [N].  The worst side of the tolerance, as the servo vendors size
        for the unbalanced torque (Yaskawa Sigma-7 11.2.4, vertical ball screw: "Falling when W1 !=
        W2")."""
    return mx.if_else(weight - force_low >= force_high - weight, force_low, force_high)


def unbalanced_torque(head_mass, counter_mass, lead, efficiency, g=G):
    r"""Mitsubishi's unbalanced torque of a counterweighted vertical axis at the motor [N m]
    (MR-J2S-A Instruction Manual sec. 11, eq. 11-20; MELDAS MDS-R-V1 Appendix 2-4):

    .. math:: T_U = (W_1 - W_2)\,g\,P_h / (2\pi\eta)

    head_mass : W_1 [kg];  counter_mass : W_2 [kg];  lead : P_h [m];  efficiency : η of the drive
        [-]."""
    return (head_mass - counter_mass) * g * lead / (2.0 * mx.pi * efficiency)


def vertical_load_torque(
    head_mass, counter_mass, lead, efficiency, friction_coefficient, direction, g=G
):
    r"""Mitsubishi's load torque of a counterweighted vertical axis at the motor, in the direction
    of the motion [N m] (MR-J2S-A eq. 11-18 to 11-21):

    .. math::
        T_F = \mu (W_1 + W_2)\,g\,P_h / (2\pi\eta)
        T_L = T_U + T_F \ \text{rising } (s = +1),\qquad T_L = -T_U\,\eta^2 + T_F \ \text{lowering } (s = -1)

    friction_coefficient : μ of the moving parts (guides, chain) on the head's and the
        counterweight's weight [-];  direction : s, +1 rising, -1 lowering.  Lowering, the
        unbalanced weight drives the screw back through η (hence η^2 on T_U, which holds η in its
        denominator)."""  # noqa: E501
    t_u = unbalanced_torque(head_mass, counter_mass, lead, efficiency, g)
    t_f = friction_coefficient * (head_mass + counter_mass) * g * lead / (2.0 * mx.pi * efficiency)
    rising = 0.5 * (1.0 + direction)  # 1 rising, 0 lowering (direction a plain +/-1)
    return rising * t_u + (1.0 - rising) * (-t_u * efficiency**2) + t_f


def counterweighted_inertia(head_mass, counter_mass, lead, ratio=1.0):
    r"""Inertia of the head and its counterweight at the motor [kg m^2] (Yaskawa Sigma-7 manual
    11.2.1, vertical axis, :math:`J_{L1} = (M + M_c)(P_B / 2\pi R)^2`; ``ratio`` = 1/R, screw turns
    per motor turn)."""
    return (head_mass + counter_mass) * (lead * ratio / (2.0 * mx.pi)) ** 2
