r"""Twin-drive (H-type) gantry: a bridge on two synchronised axial drives with a cross carriage on
it.

Lumped planar model with the yaw degree of freedom, the model structure of the dual-drive / H-type
gantry
papers: a rigid bridge of mass :math:`m_b` and yaw inertia :math:`J_b` (about its centre)
translating along the axis (:math:`x`) and yawing (:math:`\theta`, racking), a cross carriage of
mass :math:`m_c` on it at the cross position :math:`y` (from the bridge centre), two axial drives at
:math:`y_1 = -L/2` and :math:`y_2 = +L/2` modelled as springs :math:`k_1, k_2` (each side's
axial chain: screw, nut, bearings), and optionally the guides' yaw stiffness :math:`k_g`.
References (model structure):

[1] M. Garcia-Herreros, X. Kestelyn, J. Gomand, R. Coleman, P.-J. Barre, "Model-based decoupling
control
    method for dual-drive gantry stages: a case study with experimental validations", Control Engineering
    Practice 21(3), 2013 (lumped-parameter model in (X, Theta, Y) by Lagrange: the beam's yaw inertia
    :math:`M_{22} = J_t + m_h Y^2` with the head at Y from the beam's centre, the drives at +/-L_b/2; as
    summarised at https://a-lab.ee/edu/node/942).
[2] H. Lu, W. Fan, X. Zhang, Y. Zhang, S. Wang, M. Duan, "Dynamic characteristics analysis and test
of
    dual-driving feed system driven by center of gravity", Mathematical Problems in Engineering 2018,
    9490826 (twin ball-screw drives, Lagrange model with the rotation from the moving centre of gravity).
[3] C. S. Teo, K. K. Tan, S. Y. Lim, S. Huang, E. B. Tay, "Dynamic modeling and adaptive control of
a H-type
    gantry stage", Mechatronics 17(7), 2007 (the rigid-body H-type gantry with the yaw DOF).

The papers' full equations were not available to us verbatim: the equations below are DERIVED here
(rigid-body statics of a beam on two supports and a 2-DOF vibration by Lagrange) in the structure of
[1] and [2] (their mass matrix with the cross carriage's m_c y and m_c y^2 terms; here the drives'
axial springs in place of [1]'s beam joints); the tests check them against closed-form limits (load
at the centre = two independent halves; one drive alone = a free rigid body on one spring).

Kinetic energy :math:`T = \tfrac12 m_b \dot x^2 + \tfrac12 J_b \dot\theta^2 + \tfrac12 m_c(\dot x +
y\dot\theta)^2`, potential energy :math:`V = \tfrac12 k_1 (x - \theta L/2)^2 + \tfrac12 k_2 (x +
\theta L/2)^2 + \tfrac12 k_g \theta^2` give the mass and stiffness matrices of
:func:`gantry_matrices`.
"""  # noqa: E501

from __future__ import annotations

import math

from axisopt import mathx as mx

__all__ = [
    "side_shares",
    "side_force_share",
    "side_mass_share",
    "yaw_stiffness",
    "bridge_yaw_inertia_estimate",
    "gantry_matrices",
    "gantry_eigenvalues",
    "gantry_frequencies",
]


def side_force_share(force, y, span):
    r"""Axial force on each drive from a force :math:`F` along the axis acting at the cross position
    :math:`y` (statics of a beam on two supports, the bridge held at both drives).

    .. math:: F_1 = F\,\frac{L/2 - y}{L}, \qquad F_2 = F\,\frac{L/2 + y}{L}

    force : F [N];  y : cross position from the bridge centre [m] (side 1 at -L/2, side 2 at +L/2);
    span : L, distance between the two drives [m].  Returns (F_1, F_2) [N]; F_1 + F_2 = F at every
        y.
    The guides' yaw stiffness is not credited with any share (it would take a part of the moment
    only through the drives' deflection): conservative for the more loaded side.
    """
    return force * (0.5 * span - y) / span, force * (0.5 * span + y) / span


def side_mass_share(bridge_mass, cross_mass, y, span):
    r"""Each drive's share of the moving mass [kg]: the inertia force of the bridge and the cross
    carriage translating together (no yaw) at acceleration :math:`a` splits as a force at the centre
    and one at :math:`y` (:func:`side_force_share`), so each side carries :math:`m_i a` with

    .. math:: m_1 = \frac{m_b}{2} + m_c\,\frac{L/2 - y}{L}, \qquad m_2 = \frac{m_b}{2} + m_c\,\frac{L/2 + y}{L}

    bridge_mass : m_b [kg] (centre of mass at the bridge centre);  cross_mass : m_c [kg];  y, span
        [m].
    Returns (m_1, m_2) [kg]; m_1 + m_2 = m_b + m_c at every y.
    """  # noqa: E501
    c1, c2 = side_force_share(cross_mass, y, span)
    return 0.5 * bridge_mass + c1, 0.5 * bridge_mass + c2


def side_shares(cross_stroke, span):
    r"""The governing side's largest share of a force acting on the cross carriage [-]: at the end
    of the cross stroke nearest that side, :math:`y = \mp s/2` (stroke centred on the bridge),

    .. math:: r = \frac{L/2 + s/2}{L} = \frac{1}{2} + \frac{s}{2L}

    cross_stroke : s [m] (s <= L);  span : L [m].  Returns r [-] (1/2 for s = 0, 1 for s = L).
    """
    return 0.5 + 0.5 * cross_stroke / span


def yaw_stiffness(k1, k2, span, k_guides=0.0):
    r"""Yaw (racking) stiffness of the bridge about its centre [N m/rad].

    .. math:: k_\theta = (k_1 + k_2)\,(L/2)^2 + k_g

    k1, k2 : the two drives' axial stiffnesses [N/m];  span : L [m];  k_guides : k_g, the guides'
        yaw stiffness [N m/rad] (0 by default).  Exact for k_1 = k_2 (the yaw stiffness about the
        bridge centre; for k_1 != k_2 the centre of stiffness moves off the centre and
        :func:`gantry_matrices` couples x and theta).
    """
    return (k1 + k2) * (0.25 * span * span) + k_guides


def bridge_yaw_inertia(bridge_mass, span, upright_mass):
    r"""The bridge's yaw inertia about its centre from its parts [kg m^2]: the beam (the bridge's
    mass less its uprights) as a uniform slender beam over the span, the uprights (both together) as
    masses at the drives, :math:`J_b = (m_b - m_u) L^2 / 12 + m_u (L/2)^2` (rigid-body inertia of a
    beam and two end masses).
    bridge_mass : m_b, the whole bridge [kg];  span : L [m];  upright_mass : m_u, both uprights
        [kg], at most m_b."""
    beam = bridge_mass - upright_mass
    return beam * span * span / 12.0 + upright_mass * 0.25 * span * span


# Where the problem gives neither the bridge's inertia nor its uprights: half the bridge's mass in
# its uprights at the drives (an ESTIMATE, conservative for the racking mode against the
# uniform beam: J = m L^2 / 6, twice m L^2 / 12; a bridge with its uprights as light as a beam
# section would sit between)
UPRIGHT_SHARE = 0.5


def bridge_yaw_inertia_estimate(bridge_mass, span):
    r"""ESTIMATE of the bridge's yaw inertia about its centre [kg m^2]: a uniform slender beam of
    the bridge's mass over the span between the drives, :math:`J_b = m_b L^2 / 12` (no published
    figure for a machine's bridge; the side columns' mass sits at the ends, so the real inertia is
    larger and the racking mode lower: give ``bridge_yaw_inertia`` when known).  bridge_mass [kg],
    span [m]."""
    return bridge_mass * span * span / 12.0


def gantry_matrices(bridge_mass, bridge_inertia, cross_mass, y, k1, k2, span, k_guides=0.0):
    r"""Mass and stiffness matrices of the gantry in the coordinates :math:`(x, \theta)`.

    .. math::
        M = \begin{bmatrix} m_b + m_c & m_c y \\ m_c y & J_b + m_c y^2 \end{bmatrix}, \qquad
        K = \begin{bmatrix} k_1 + k_2 & (k_2 - k_1) L/2 \\ (k_2 - k_1) L/2 & (k_1 + k_2) L^2/4 + k_g \end{bmatrix}

    bridge_mass : m_b [kg];  bridge_inertia : J_b [kg m^2] about the bridge centre;  cross_mass :
        m_c [kg] (a point mass at y);  y : cross position [m];  k1, k2 : drive stiffnesses at -L/2
        and +L/2 [N/m];  span : L [m];
    k_guides : k_g [N m/rad].  Returns (m11, m12, m22, k11, k12, k22) [kg, kg m, kg m^2; N/m, N, N
        m].
    """  # noqa: E501
    m11 = bridge_mass + cross_mass
    m12 = cross_mass * y
    m22 = bridge_inertia + cross_mass * y * y
    k11 = k1 + k2
    k12 = (k2 - k1) * 0.5 * span
    k22 = yaw_stiffness(k1, k2, span, k_guides)
    return m11, m12, m22, k11, k12, k22


def gantry_eigenvalues(bridge_mass, bridge_inertia, cross_mass, y, k1, k2, span, k_guides=0.0):
    r"""The two squared angular frequencies :math:`\omega^2` [rad^2/s^2] of
    :math:`\det(K - \omega^2 M) = 0` (:func:`gantry_matrices`), lower first:

    .. math:: a\,\omega^4 - b\,\omega^2 + c = 0, \quad a = \det M, \quad
              b = k_{11} m_{22} + k_{22} m_{11} - 2 k_{12} m_{12}, \quad c = \det K

    .. math:: \omega_2^2 = \frac{b + \sqrt{b^2 - 4ac}}{2a}, \qquad \omega_1^2 = \frac{2c}{b + \sqrt{b^2 - 4ac}}

    (the lower root in the cancellation-free form; the discriminant, >= 0 for symmetric positive M
    and K, is clipped at 0 against rounding).  Arguments as :func:`gantry_matrices`; float, numpy or
    CasADi.
    """  # noqa: E501
    m11, m12, m22, k11, k12, k22 = gantry_matrices(
        bridge_mass, bridge_inertia, cross_mass, y, k1, k2, span, k_guides
    )
    a = m11 * m22 - m12 * m12
    b = k11 * m22 + k22 * m11 - 2.0 * k12 * m12
    c = k11 * k22 - k12 * k12
    root = mx.sqrt(mx.fmax(b * b - 4.0 * a * c, 0.0))
    return 2.0 * c / (b + root), (b + root) / (2.0 * a)


def gantry_frequencies(bridge_mass, bridge_inertia, cross_mass, y, k1, k2, span, k_guides=0.0):
    r"""The gantry's two natural frequencies [Hz], lower first:
    :math:`f_i = \sqrt{\omega_i^2} / 2\pi` (:func:`gantry_eigenvalues`).  With the load at the
    centre (y = 0, k_1 = k_2 = k) they decouple into the translation
    :math:`\sqrt{2k/(m_b + m_c)}/2\pi` (one side with half the mass) and the racking
    :math:`\sqrt{k_\theta/J_b}/2\pi`, whichever is lower first."""
    w1, w2 = gantry_eigenvalues(bridge_mass, bridge_inertia, cross_mass, y, k1, k2, span, k_guides)
    return mx.sqrt(w1) / (2.0 * math.pi), mx.sqrt(w2) / (2.0 * math.pi)
