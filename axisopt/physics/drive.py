r"""Drive sizing: inertia reflected to the motor, motor torque over a move, RMS torque, motor speed.

The vendors' procedure (THK General Catalog A-717 to A-720, "Studying the Rotational Torque" and
"Studying the Driving Motor"; HIWIN F 3.15-3.24; Yaskawa Σ-7 manual ch. 2) in SI units:

.. math::
    J = m (P_h/2\pi)^2 A^2 + J_S A^2 + J_A A^2 + J_B          (THK eq. 45)
    T_1 = F_a P_h A / (2\pi \eta)                             (THK eq. 43, friction and external force)
    T_3 = (J + J_M) \omega',\quad \omega' = 2\pi N_M / (60 t)  (THK eq. 45, acceleration)
    T_{rms} = \sqrt{\sum T_i^2 t_i / \sum t_i}                (THK eq. 48)

``A`` is THK's reduction ratio: screw turns per motor turn (1 for a direct drive, < 1 for a
reduction).  Every function works on floats, numpy arrays and CasADi symbols (plain arithmetic;
``rms_torque`` takes sequences).
"""  # noqa: E501

from __future__ import annotations

from math import pi

from .. import mathx as mx


def load_inertia(mass, lead, ratio=1.0):
    r"""Inertia of a translating mass seen at the motor, :math:`m (P_h / 2\pi)^2 A^2` [kg m^2].

    mass : m [kg];  lead : P_h [m];  ratio : A, screw turns per motor turn [-]."""
    return mass * (lead / (2.0 * pi)) ** 2 * ratio**2


def reflected_inertia(
    mass, lead, screw_inertia_, coupling_inertia=0.0, ratio=1.0, motor_side_inertia=0.0
):
    r"""Total load inertia at the motor shaft (THK eq. 45 without the rotor):
    :math:`m (P_h/2\pi)^2 A^2 + (J_S + J_{cpl}) A^2 + J_B`, with ``coupling_inertia`` on the screw
    side of the reduction and ``motor_side_inertia`` (e.g. a pulley on the motor) unreduced [kg
    m^2]."""
    return (
        load_inertia(mass, lead, ratio)
        + (screw_inertia_ + coupling_inertia) * ratio**2
        + motor_side_inertia
    )


def force_torque(axial_force, lead, efficiency=0.9, ratio=1.0):
    r"""Motor torque to drive an axial force through the screw, :math:`F_a P_h A / (2\pi\eta)` [N m]
    (THK eq. 43; η is the screw efficiency times the reduction's, 0.9-0.95 for a ball screw)."""
    return axial_force * lead * ratio / (2.0 * pi * efficiency)


def motor_speed(linear_speed, lead, ratio=1.0):
    """Motor speed [rad/s] for a table speed [m/s] (THK eq. 46: N_M = V / P_h / A)."""
    return 2.0 * pi * linear_speed / (lead * ratio)


def acceleration_torque(total_inertia, motor_speed_, time):
    r"""Torque to bring ``total_inertia`` (load plus rotor) [kg m^2] to ``motor_speed_`` [rad/s] in
    ``time`` [s] at constant acceleration: :math:`J \omega'` (THK eq. 45) [N m]."""
    return total_inertia * motor_speed_ / time


def rms_torque(torques, durations):
    r"""Effective (RMS) torque over a duty cycle, :math:`\sqrt{\sum T_i^2 t_i / \sum t_i}` (THK
    eq. 48) [N m].

    torques, durations : sequences of equal length (floats, arrays or CasADi symbols); dwell
        segments carry their holding torque (0 when the motor is free)."""
    torques, durations = list(torques), list(durations)
    if len(torques) != len(durations) or not torques:
        raise ValueError("rms_torque needs one duration per torque")
    num = sum(t * t * d for t, d in zip(torques, durations))
    return mx.sqrt(num / sum(durations))


def inertia_ratio(load_inertia_, rotor_inertia):
    """Load-to-rotor inertia ratio J_L / J_M [-] (THK eq. 49 asks J_M >= J/C with C 3-10)."""
    return load_inertia_ / rotor_inertia


def holding_torque(held_force, friction, lead, efficiency=0.9, ratio=1.0):
    r"""Motor torque holding an axis at standstill against a force on gravity's side [N m] (THK
    General Catalog, vertical conveyance example, A-745: "When stationary (m2 = 0): TS = 658 N.mm",
    the work removed):

    .. math:: T_S = \max(0,\ m g - f)\,\frac{P_h A}{2\pi\eta}

    held_force : m g, the weight of what the table carries at the stop, plus any force held on its
        side [N]
    friction   : f, the guide resistance at standstill [N], which helps hold (THK subtracts it)
    lead       : P_h [m];  efficiency : η, THK's forward efficiency (it divides, as for the
                 moving torques: above the back-driving torque m g P_h η' / 2π, so the motor or
                 brake is not sized short)
    ratio      : A, screw turns per motor turn [-]
    THK's numbers: m1 = 40 kg, f = 20 N, P_h = 10 mm, η = 0.9 give 658 N.mm.  Floats, arrays,
    CasADi."""
    return mx.fmax(held_force - friction, 0.0) * lead * ratio / (2.0 * pi * efficiency)


def _each(value, n: int) -> list:
    """A per-phase value: a list or tuple of one per phase as it is, anything else the same for
    all."""
    if isinstance(value, (list, tuple)):
        if len(value) != n:
            raise ValueError("one value per phase")
        return list(value)
    return [value] * n


def phase_torques(
    phases,
    total_inertia,
    lead,
    friction_torque,
    gravity_torque,
    efficiency=0.9,
    ratio=1.0,
    hold_friction=0.0,
):
    r"""Motor torque at the start and end of each duty-cycle phase [N m] (THK eq. 40-45, signed):

    .. math:: T = J\,\frac{2\pi}{P_h A} a + s\,\Big(T_f + \frac{F P_h A}{2\pi\eta}\Big) + T_g

    and at standstill (s = 0, a dwell) the holding torque of :func:`holding_torque`,
    :math:`\max(0, T_g + (F - f) P_h A / (2\pi\eta))`, the dwell's force F held on gravity's side
    and the guide friction f credited (THK A-745).

    phases          : :class:`axisopt.physics.motion.Phase` sequence (acceleration a, direction s,
                      force F)
    total_inertia   : load plus rotor at the motor [kg m^2], one for all phases or a list of one per
                      phase (a duty-cycle entry that loads or unloads the workpiece changes it)
    friction_torque : friction/drag at the motor, opposing the motion [N m]
    gravity_torque  : torque holding the weight of a vertical axis, positive lifting [N m]; one or
                      one per phase
    efficiency      : η of screw and reduction for the external force;  ratio : A (screw turns per
                      motor turn)
    hold_friction   : f, the guide friction at standstill [N] (credited at a dwell; 0: no credit)
    Returns a list of (T_start, T_end).  Friction is absent at standstill (s = 0).  Works on floats,
    numpy arrays and CasADi symbols (the phases are floats)."""
    k_acc = 2.0 * pi / (lead * ratio)
    per_newton = lead * ratio / (2.0 * pi * efficiency)
    n = len(phases)
    out = []
    # phases of the same accelerations, direction, force and mass (the S-curve pieces of every move
    # that reaches full acceleration) share one computed pair: the same object, which the RMS and
    # peak below count once
    seen: dict = {}
    for ph, j_tot, t_g in zip(phases, _each(total_inertia, n), _each(gravity_torque, n)):
        key = (ph.direction, ph.force, id(t_g)) + (
            (id(j_tot), ph.a0, ph.a1) if ph.direction != 0.0 else ()
        )
        pair = seen.get(key)
        if pair is None:
            if ph.direction == 0.0:
                hold = mx.fmax(t_g + (ph.force - hold_friction) * per_newton, 0.0)
                pair = (hold, hold)
            else:
                base = ph.direction * (friction_torque + ph.force * per_newton) + t_g
                j = j_tot * k_acc
                pair = (j * ph.a0 + base, j * ph.a1 + base)
            seen[key] = pair
        out.append(pair)
    return out


# Mitsubishi MDS-D-SVJ3/SPJ3 Specifications Manual sec. 7-1 (2), p. 7-4: the maximum torque governs
# the acceleration "in a low-speed rotation range (approximately less than half of the servomotor
# maximum speed)"; beyond it the torque characteristics of the high-speed range apply.  The
# estimated corner of the peak zone where a vendor prints no curve values is the lower of the rated
# speed and this fraction of the max speed.
PEAK_CORNER_FRACTION = 0.5


def peak_torque_available(speed, peak_torque, corner_speed, peak_at_max_speed, max_speed):
    r"""Peak (intermittent-zone) torque a servo motor can give at a speed, from two corner points of
    the vendor's torque-speed curve: flat to the corner speed, then falling linearly to its value at
    max speed.

    .. math:: T_{pk}(n) = T_{pk} - (T_{pk} - T_{pk,max}) \min(1, \max(0, n - n_c) / (n_{max} - n_c))

    speed : n [rad/s];  peak_torque : T_pk [N m];  corner_speed : n_c [rad/s];  peak_at_max_speed :
        T_pk,max [N m]
    max_speed : n_max [rad/s].  Returns [N m].  Yaskawa Sigma-7 "Torque-Motor Speed Characteristics"
        (A: continuous, B: intermittent duty zone), Siemens 1FT7 "Mmax" characteristic; a speed
        above max is held at the max-speed value (the motor speed check refuses it)."""
    over = mx.fmax(speed - corner_speed, 0.0)
    frac = mx.fmin(over / mx.fmax(max_speed - corner_speed, 1e-9), 1.0)
    return peak_torque - (peak_torque - peak_at_max_speed) * frac


# Simpson sub-intervals per phase for the regenerative energy (exact while the power keeps its sign)
REGEN_STEPS = 8


def regenerative_energy(phases, torques, lead, ratio=1.0):
    r"""Energy the motor returns to the drive in each duty-cycle phase [J]: the negative part of the
    shaft power,

    .. math:: E = \int_0^{t} \max(0, -T(\tau)\,\omega(\tau))\,d\tau,\qquad \omega = \frac{2\pi v}{P_h A}

    with T linear over the phase (:func:`phase_torques`) and the table speed v from the phase's
    start speed and acceleration.  A phase of constant acceleration (trapezoidal profiles, cruises)
    has a constant torque and a speed of one sign, so E = max(0, -T \int omega dt) exactly; a
    jerk-limited piece (torque varying) takes Simpson's rule on :data:`REGEN_STEPS` sub-intervals (T
    omega is a cubic: exact unless the power changes sign inside the piece).  The vendors'
    regeneration sizing integrates the same torque x speed (Yaskawa Sigma-7 manual 12.8.6: E_S - E_L
    = J n^2 / 182 - (pi / 60) n T_L t_D for a stop; Mitsubishi MR-JE
    11.2.2: the sum of the negative energies; Omron 1S 4-4-1) and then subtracts the motor's winding
    loss (Omron: the actual energy is about 90 % of it) and what the drive's capacitors absorb: this
    is the mechanical energy before those losses, an upper estimate.  phases:
    :class:`axisopt.physics.motion.Phase`;
    torques: their (T_start, T_end) [N m]; lead [m]; ratio: screw turns per motor turn.  Returns a
    list [J]."""  # noqa: E501
    k = 2.0 * pi / (lead * ratio)  # motor rad/s per table m/s
    out = []
    for ph, (t0, t1) in zip(phases, torques):
        if ph.duration <= 0.0 or ph.direction == 0.0:
            out.append(0.0 * t0)
            continue
        if ph.a0 == ph.a1:  # constant torque: the motor angle turned in the phase times it
            angle = k * (ph.v0 * ph.duration + 0.5 * ph.a0 * ph.duration**2)
            out.append(mx.fmax(-t0 * angle, 0.0))
            continue
        h = ph.duration / REGEN_STEPS
        acc = 0.0 * t0
        for i in range(REGEN_STEPS + 1):
            tau = i * h
            w = 1.0 if i in (0, REGEN_STEPS) else (4.0 if i % 2 else 2.0)
            torque = t0 + (t1 - t0) * (tau / ph.duration)
            acc = acc + w * mx.fmax(-torque * k * ph.speed_at(tau), 0.0)
        out.append(acc * h / 3.0)
    return out


def linear_rms_torque(torques, durations):
    r"""RMS torque over phases whose torque varies linearly from T0 to T1 (exact for jerk-limited
    ramps): :math:`\sqrt{\sum t_i (T_0^2 + T_0 T_1 + T_1^2)/3 \,/\, \sum t_i}` [N m] (THK eq. 48 for
    constant torques)."""
    total: dict = {}  # phases sharing one torque pair (phase_torques): their durations summed first
    for pair, d in zip(torques, durations):
        entry = total.setdefault(id(pair), [pair, 0.0])
        entry[1] += d
    num = sum(d * (t0 * t0 + t0 * t1 + t1 * t1) / 3.0 for (t0, t1), d in total.values())
    return mx.sqrt(num / sum(durations))
