"""Lumped axis dynamics: axial mode, table mode on guides, axial-torsional 2-DOF, dynamic
compliance."""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from axisopt import mathx as mx
from axisopt.physics.screw import E_STEEL, choose

__all__ = [
    "axial_natural_frequency",
    "effective_axial_mass",
    "axial_angular_frequency_eq11",
    "table_mode_frequency",
    "axial_torsional_eigenvalues",
    "axial_torsional_frequencies",
    "dynamic_compliance",
    "drive_train_eigenvalues",
    "drive_train_frequencies",
    "drive_train_compliance",
]


def effective_axial_mass(moving_mass, screw_mass, x, span, mounting):
    r"""Mass the axial mode moves: the table plus the Rayleigh share of the screw.

    .. math:: m_{eff} = m + m_s \left(\tfrac{x}{3L} + \tfrac{L - x}{L}\right) = m + m_s (1 - \tfrac{2x}{3L})
              \quad\text{(fixed-free, fixed-supported)}
    .. math:: m_{eff} = m + m_s / 3 \quad\text{(fixed-fixed)}

    The strained screw between the fixed bearing and the nut has a linear displacement profile, so a
    third of its mass acts at the nut; with an axially free far end, the screw beyond the nut
    carries no force and moves with the nut as a rigid body.  Fixed-fixed: both segments are
    strained, a third of each.  moving_mass : m [kg];  screw_mass : m_s [kg];  x : nut distance from
    the fixed bearing [m]
    span : L [m];  mounting : 'fixed-free' | 'fixed-supported' | 'fixed-fixed'.  Returns m_eff [kg].
    Source: Rayleigh's method on the lumped axial model (seed eq. 11 with the screw's own mass).
    """  # noqa: E501
    choose(_MASS_MOUNTINGS, mounting, "mounting")
    if mounting == "fixed-fixed":
        return moving_mass + screw_mass / 3.0 + 0.0 * x / span
    return moving_mass + screw_mass * (1.0 - 2.0 * x / (3.0 * span))


_MASS_MOUNTINGS = MappingProxyType({m: m for m in ("fixed-free", "fixed-supported", "fixed-fixed")})


def axial_natural_frequency(
    stiffness, moving_mass, screw_mass=0.0, x=None, span=None, mounting="fixed-supported"
):
    r"""First axial natural frequency of the table on the drive spring (seed eq. 11, lumped form).

    .. math:: f_1 = \frac{1}{2\pi}\sqrt{k / m_{eff}}

    stiffness   : k, axial stiffness at the nut position [N/m]
    moving_mass : m, table + workpiece + nut [kg]
    screw_mass  : m_s, whole screw [kg];  x : nut distance from fixed bearing [m];  span : L [m]
    With x and span, m_eff is :func:`effective_axial_mass` for the mounting; without them m + m_s
    / 3.  Returns f_1 [Hz].
    """
    if x is None or span is None:
        m_eff = moving_mass + screw_mass / 3.0
    else:
        m_eff = effective_axial_mass(moving_mass, screw_mass, x, span, mounting)
    return mx.sqrt(stiffness / m_eff) / (2.0 * mx.pi)


def axial_angular_frequency_eq11(root_diameter, length, mass, youngs_modulus=E_STEEL):
    r"""Position-dependent axial angular frequency of a mass on a screw segment of length l_x.

    .. math:: \omega_x = \sqrt{E A / (m\, l_x)},\ A = \pi d^2 / 4               (seed eq. 11)

    root_diameter : d [m];  length : l_x in [l_0, l_0 + h] [m];  mass : m [kg];  youngs_modulus : E
        [Pa]
    Returns omega_x [rad/s].  Screw-only stiffness (nut, bearings rigid).
    """
    return mx.sqrt(youngs_modulus * mx.pi * root_diameter**2 / 4.0 / (mass * length))


def table_mode_frequency(normal_stiffness_per_block, n_blocks, mass):
    r"""Vertical (normal) table mode on its guide blocks, all blocks in parallel.

    .. math:: f = \frac{1}{2\pi}\sqrt{n\, k_n / m}

    normal_stiffness_per_block : k_n [N/m];  n_blocks : n [-];  mass : m [kg].  Returns f [Hz].
    Rigid table, rigid rails; rocking modes not included.
    """
    return mx.sqrt(n_blocks * normal_stiffness_per_block / mass) / (2.0 * mx.pi)


def axial_torsional_eigenvalues(rotary_inertia, torsional_stiffness, axial_stiffness, mass, lead):
    r"""Squared angular frequencies of the coupled axial-torsional 2-DOF drive model.

    DOFs theta (screw + rotor inertia J, held by torsional stiffness k_t at the motor) and x (table
    m), coupled through the lead, r = P_h / (2 pi), by the axial stiffness k_a (screw + nut +
    bearing):

    .. math:: M = \mathrm{diag}(J, m),
    .. math:: K = \begin{bmatrix} k_t + k_a r^2 & -k_a r \\ -k_a r & k_a\end{bmatrix}
    .. math:: \omega^2_{1,2} = \frac{b \mp \sqrt{b^2 - 4 J m k_t k_a}}{2 J m},\ b = J k_a + m (k_t + k_a r^2)

    rotary_inertia : J [kg*m^2];  torsional_stiffness : k_t [N*m/rad];  axial_stiffness : k_a [N/m]
    mass : m [kg];  lead : P_h [m].  Returns (omega_1^2, omega_2^2) [rad^2/s^2], omega_1 <= omega_2.
    Source: standard feed-drive lumped model (seed Fig. 1-2).
    """  # noqa: E501
    r = lead / (2.0 * mx.pi)
    b = rotary_inertia * axial_stiffness + mass * (torsional_stiffness + axial_stiffness * r**2)
    disc = mx.sqrt(b**2 - 4.0 * rotary_inertia * mass * torsional_stiffness * axial_stiffness)
    den = 2.0 * rotary_inertia * mass
    return (b - disc) / den, (b + disc) / den


def axial_torsional_frequencies(rotary_inertia, torsional_stiffness, axial_stiffness, mass, lead):
    """Natural frequencies (f_1, f_2) [Hz] of axial_torsional_eigenvalues (same arguments, SI)."""
    w1, w2 = axial_torsional_eigenvalues(
        rotary_inertia, torsional_stiffness, axial_stiffness, mass, lead
    )
    return mx.sqrt(w1) / (2.0 * mx.pi), mx.sqrt(w2) / (2.0 * mx.pi)


def dynamic_compliance(
    frequency,
    mass,
    axial_stiffness,
    axial_damping,
    rotary_inertia=None,
    torsional_stiffness=None,
    torsional_damping=0.0,
    lead=None,
):
    r"""Table dynamic compliance X/F(j omega) of the lumped model (inverse dynamic stiffness, seed
    eq. 41).

    Without rotary data (SDOF):  X/F = 1 / (k_a - m omega^2 + j omega c_a).
    With rotary data (2-DOF of axial_torsional_eigenvalues, viscous c_a, c_t):

    .. math:: X/F = \frac{k_t + k_a r^2 - J\omega^2 + j\omega (c_t + c_a r^2)}
                         {(k_t + k_a r^2 - J\omega^2 + j\omega(c_t + c_a r^2))(k_a - m\omega^2 + j\omega c_a)
                          - r^2 (k_a + j\omega c_a)^2}

    frequency : f [Hz] (array);  mass : m [kg];  axial_stiffness : k_a [N/m];  axial_damping : c_a
        [N*s/m]
    rotary_inertia : J [kg*m^2];  torsional_stiffness : k_t [N*m/rad];  torsional_damping : c_t
        [N*m*s/rad]
    lead : P_h [m].  Returns complex ndarray [m/N] (numpy only, not symbolic).
    """  # noqa: E501
    w = 2.0 * np.pi * np.asarray(frequency, dtype=float)
    jw = 1j * w
    z_x = axial_stiffness - mass * w**2 + jw * axial_damping
    if rotary_inertia is None:
        return 1.0 / z_x
    if torsional_stiffness is None or lead is None:
        raise ValueError("dynamic_compliance: rotary_inertia needs torsional_stiffness and lead")
    r = lead / (2.0 * np.pi)
    z_t = (
        torsional_stiffness
        + axial_stiffness * r**2
        - rotary_inertia * w**2
        + jw * (torsional_damping + axial_damping * r**2)
    )
    coupling = r * (axial_stiffness + jw * axial_damping)
    return z_t / (z_t * z_x - coupling**2)


def drive_train_eigenvalues(
    motor_inertia, screw_inertia, coupling_stiffness, axial_stiffness, mass, lead
):
    r"""Squared angular frequencies of the two elastic modes of the motor-coupling-screw-table
    chain.

    Three DOFs (seed Fig. 1): motor rotor theta_m (J_m, with its half of the coupling), screw
    theta_s (J_s, with the other half), table x (m).  The coupling k_c joins theta_m and theta_s;
    the axial chain k (bearings, screw tension and torsion, nut, bracket) acts on x - r theta_s, r =
    P_h / (2 pi).  The motor is free at these frequencies (its position loop is far slower), so one
    mode is the rigid-body motion at 0 Hz.  The other two solve

    .. math:: J_m J_s m\,\lambda^2 - Q\lambda + k_c k (J_m + J_s + m r^2) = 0,
    .. math:: Q = k_c J_s m + J_m m (k_c + k r^2) + J_m J_s k

    (det(K - lambda M) = 0 divided by the rigid-body root).  As J_m -> inf it becomes the held-motor
    2-DOF of :func:`axial_torsional_eigenvalues` with k_t = k_c.

    motor_inertia : J_m [kg*m^2];  screw_inertia : J_s [kg*m^2];  coupling_stiffness : k_c [N*m/rad]
    axial_stiffness : k [N/m];  mass : m [kg];  lead : P_h [m].
    Returns (omega_1^2, omega_2^2) [rad^2/s^2], omega_1 <= omega_2.
    """
    r = lead / (2.0 * mx.pi)
    a, b, kc, k = motor_inertia, screw_inertia, coupling_stiffness, axial_stiffness
    q = kc * b * mass + a * mass * (kc + k * r**2) + a * b * k
    c0 = kc * k * (a + b + mass * r**2)
    den = 2.0 * a * b * mass
    disc = mx.sqrt(mx.hinge(q**2 - 4.0 * a * b * mass * c0))
    return (q - disc) / den, (q + disc) / den


def drive_train_frequencies(
    motor_inertia, screw_inertia, coupling_stiffness, axial_stiffness, mass, lead
):
    """Natural frequencies (f_1, f_2) [Hz] of drive_train_eigenvalues (same arguments, SI)."""
    w1, w2 = drive_train_eigenvalues(
        motor_inertia, screw_inertia, coupling_stiffness, axial_stiffness, mass, lead
    )
    return mx.sqrt(w1) / (2.0 * mx.pi), mx.sqrt(w2) / (2.0 * mx.pi)


def drive_train_compliance(
    frequency,
    motor_inertia,
    screw_inertia,
    coupling_stiffness,
    axial_stiffness,
    mass,
    lead,
    table_damping=0.0,
    chain_damping=0.0,
    coupling_damping=0.0,
    motor_held=False,
):
    r"""Table compliance X/F(j omega) of the motor-coupling-screw-table chain (inverse of seed eq.
    41).

    DOFs and springs as :func:`drive_train_eigenvalues`; viscous dampers: ``table_damping`` c_g from
    the table to the frame (guide blocks), ``chain_damping`` c_a across the axial chain (nut,
    bearings, as referred to x - r theta_s), ``coupling_damping`` c_c across the coupling.  With the
    motor free, the dynamic stiffness F/X is a ratio of polynomials in s, the form of seed eq. 41
    (here degree 6, zero at s = 0, over degree 4); ``motor_held`` fixes theta_m (the static
    compliance is then 1/k + r^2/k_c).

    frequency : f [Hz] (array).  Returns complex ndarray [m/N] (numpy only, not symbolic).
    """
    w = 2.0 * np.pi * np.asarray(frequency, dtype=float)
    r = lead / (2.0 * np.pi)
    s = 1j * w
    zc = coupling_stiffness + s * coupling_damping
    za = axial_stiffness + s * chain_damping
    # rows/cols: theta_m, theta_s, x
    a11 = motor_inertia * s**2 + zc
    a12 = -zc
    a22 = screw_inertia * s**2 + zc + za * r**2
    a23 = -za * r
    a33 = mass * s**2 + table_damping * s + za
    if motor_held:
        det2 = a22 * a33 - a23**2
        return a22 / det2
    det = a11 * (a22 * a33 - a23**2) - a12**2 * a33
    cof = a11 * a22 - a12**2
    return cof / det
