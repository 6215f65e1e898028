"""The drive: servo motor, coupling and reduction over the axis's duty cycle, and the drive checks.

Inertia at the motor (THK eq. 45): table, nut and blocks through the lead, screw and coupling
through the reduction, the reduction's own inertia and the rotor (with its holding brake when the
brake is used).  The screw counts as the vendors size it: a solid steel cylinder of the nominal
(outer) diameter (THK A-744, FANUC B-65142E sec. 4, HIWIN F 3.20, Mitsubishi MDS-B-SVJ2 sec. 11-5),
over the model's screw length, the bearing span (the length the screw_length check asks of the
catalog).  The torsional mode keeps the mean of nominal and root diameter (model.modes): the shaft's
physical inertia, not the sizing convention.  Per duty-cycle phase the motor torque is inertia x
angular acceleration, plus the friction of the axis (the model's drag torque: nut preload, support
bearings, guide blocks) against the motion, the external force through the screw and reduction
efficiency, and gravity for a vertical axis (:func:`axisopt.physics.drive.phase_torques`), each with
the phase's moving mass (a duty-cycle entry's own ``moving_mass``, the workpiece loaded or unloaded:
inertia and weight); the guide friction in the drag is the axis's (the heaviest mass's: a lighter
phase's is below it, and on a vertical axis the mass does not press on the guides).  At a dwell the
motor holds (THK A-745): the weight at the dwell plus its force, less the guide friction at
standstill, through the screw.  Steady thrust: the torque that pushes an axial load at feed with
friction and weight.  Yaskawa's selection asks the load torque to stay within the rated torque: the
thrust at the mean axial load counts with the cycle's RMS torque against the rated torque, the
thrust at the largest axial load with the cycle's peak against the motor's peak torque.

A reduction part (a planetary gearbox on the motor flange) is checked as its vendor rates it
(Beckhoff AG2400 / AG3400 "Mechanical data": T2B "maximum acceleration torque, maximum 1000 cycles
per hour", T2N "nominal output torque", n1Max "maximum input speed"): the largest output torque of
the cycle (acceleration, thrust) against T2B, the cycle's RMS output torque (or the mean thrust, if
larger) against T2N, the largest motor speed against n1Max.  The output torque is the torque the
screw side takes (:func:`output_torques`): the same phase torques at the screw, without the rotor's
and the reduction's own inertia and loss.

The phases are the axis's (``p["duty"]``, floats); the design enters through the parameters, so this
evaluates on floats, numpy arrays and CasADi symbols like every other sub-assembly.
"""

from __future__ import annotations

import math

import numpy as np

from .. import mathx as mx
from ..physics import drive as pd
from ..physics import screw as ps
from .checks import check_pairs
from .drag import SCREW_EFFICIENCY
from .limits import margin_output
from .loads import G, balance, balance_force, phase_moving_mass, unit
from .motorrule import DEFAULT_RULE

# margin of a check that does not apply (no motor, horizontal axis for the brake)
NOT_APPLICABLE = 1e9


def turning_inertia(p):
    """Inertia of what the drive turns on the screw side [kg m^2]: the screw, or for a driven
    rotating nut (``nut_rotating`` 1) the unit's rotating parts instead (THK prints them, T-GC
    B-721/B-723 "nut inertia")."""
    r = unit(p, "nut_rotating")
    return (1.0 - r) * ps.screw_rotary_inertia(p["nominal_diameter"], p["span"]) + r * unit(
        p, "unit_inertia"
    )


def drive_inertias(p, moving_mass):
    """(load inertia at the motor without the rotor, rotor inertia) [kg m^2]
    (:func:`turning_inertia` through the reduction; a counterbalance's moving mass, a counterweight
    and its chain, with the head's: Yaskawa Sigma-7 11.2.1, J_L1 = (M + M_c)(P_B / 2 pi R)^2)."""
    a = 1.0 / p["reduction_ratio"]
    j_load = pd.reflected_inertia(
        moving_mass + balance(p, "balance_moving_mass"),
        p["lead"],
        turning_inertia(p),
        p["coupling_inertia"],
        a,
        p["reduction_inertia"],
    )
    return j_load, p["rotor_inertia"]


def lost_motion(p):
    r"""Lost motion of the drive at the table [m]: the axial play of a single nut with play (a
    preloaded nut has none) plus a reduction's torsional backlash through the lead,

    .. math:: \delta = (1 - d)\,\delta_{nut} + j_t \frac{P_h}{2\pi}

    p["nut_axial_play"] [m], p["nut_double"] (1: preloaded), p["reduction_backlash"] j_t [rad] at
    the output (Beckhoff AG2400/AG3400 "Maximum torsional backlash jt [arcmin]"; 0 without a
    reduction), p["lead"] P_h [m].  A semi-closed loop (encoder on the motor) does not see it; the
    problem's max_backlash limits it."""
    return (1.0 - p["nut_double"]) * p["nut_axial_play"] + p["reduction_backlash"] * p["lead"] / (
        2.0 * math.pi
    )


def output_torques(p, moving_mass, drag, phases, hold_friction=0.0):
    r"""Torque at the reduction's output (the screw side of the ratio) per duty-cycle phase [N m],
    signed (THK eq. 40-45 at the screw, A = 1):

    .. math:: T_2 = (m (P_h/2\pi)^2 + J_S + J_{cpl}) \frac{2\pi}{P_h} a + s\,(T_f + \frac{F P_h}{2\pi\eta_s}) + T_g

    (J_S: :func:`turning_inertia`, the screw or a rotating-nut unit's turning parts)

    p : parameters (lead, nominal_diameter, span, coupling_inertia, gravity_axial, table_mass);
        moving_mass [kg];
    drag : friction torque at the screw T_f [N m];  phases : the duty cycle;  hold_friction : guide
        friction at standstill [N].  Returns (phase torques [(T_start, T_end)], steady thrust at the
        largest axial load, at the mean axial load) [N m].  What the motor torque is less the
        rotor's and the reduction's inertia and loss, referred to the output: what the gearbox's T2B
        and T2N rate (Beckhoff AG2400 Mechanical data)."""  # noqa: E501
    j_turn = turning_inertia(p)
    by_mass = {}
    for ph in phases:
        if ph.moving_mass not in by_mass:
            m = phase_moving_mass(p, moving_mass, ph.moving_mass)
            by_mass[ph.moving_mass] = (
                pd.reflected_inertia(
                    m + balance(p, "balance_moving_mass"),
                    p["lead"],
                    j_turn,
                    p["coupling_inertia"],
                    1.0,
                ),
                m,
            )
    weights = _net_weights(
        p,
        phases,
        {k: v[1] for k, v in by_mass.items()},
        lambda w: pd.force_torque(w, p["lead"], SCREW_EFFICIENCY, 1.0),
    )
    torques = pd.phase_torques(
        phases,
        [by_mass[ph.moving_mass][0] for ph in phases],
        p["lead"],
        drag,
        [weights[ph.moving_mass, ph.direction] for ph in phases],
        SCREW_EFFICIENCY,
        1.0,
        hold_friction,
    )
    gravity = pd.force_torque(
        p["gravity_axial"] * moving_mass * G - balance_force(p, 1.0),
        p["lead"],
        SCREW_EFFICIENCY,
        1.0,
    )
    thrust = drag + pd.force_torque(p["axial_load"], p["lead"], SCREW_EFFICIENCY, 1.0) + gravity
    thrust_mean = (
        drag + pd.force_torque(p["mean_axial_load"], p["lead"], SCREW_EFFICIENCY, 1.0) + gravity
    )
    return torques, thrust, thrust_mean


def drive(p, moving_mass, drag, hold_friction=0.0, regen: bool = True) -> dict:
    """Motor torques over the duty cycle, motor speed, inertia ratio, holding torque and the drive
    margins.

    moving_mass : the axis's moving mass [kg] (table + workpiece, nut, blocks); a phase whose
        duty-cycle entry names its own table + workpiece takes that instead;  drag : friction torque
        at the screw [N m];
    hold_friction : guide friction at standstill [N] (THK's f, credited to the holding torque);
    regen : also the regenerated energy and power (``regen_energy``, ``regen_power``: a Simpson sum
        over every jerk-limited piece, the costliest output of the block; a search whose limits do
        not read them skips it)."""
    a = 1.0 / p["reduction_ratio"]
    eta = SCREW_EFFICIENCY * p["reduction_efficiency"]
    j_load, j_rotor = drive_inertias(p, moving_mass)
    j_tot = j_load + j_rotor
    friction = drag * a / p["reduction_efficiency"]
    weight = p["gravity_axial"] * moving_mass * G
    # a counterbalance's force: the least (head rising) for the steady thrust, at rest for the
    # holding torque
    gravity = pd.force_torque(weight - balance_force(p, 1.0), p["lead"], eta, a)
    phases = p.get("duty", ())  # no cycle (a bare parameter dict): the steady thrusts alone
    # per phase: the inertia and the weight of the mass the phase carries (one evaluation per
    # distinct mass), the weight net of a counterbalance's force in the phase's direction (one per
    # distinct mass and direction)
    by_mass = {None: (j_tot, moving_mass)}
    for ph in phases:
        if ph.moving_mass not in by_mass:
            m = phase_moving_mass(p, moving_mass, ph.moving_mass)
            by_mass[ph.moving_mass] = (drive_inertias(p, m)[0] + j_rotor, m)
    weights = _net_weights(
        p,
        phases,
        {k: v[1] for k, v in by_mass.items()},
        lambda w: pd.force_torque(w, p["lead"], eta, a),
    )
    torques = pd.phase_torques(
        phases,
        [by_mass[ph.moving_mass][0] for ph in phases],
        p["lead"],
        friction,
        [weights[ph.moving_mass, ph.direction] for ph in phases],
        eta,
        a,
        hold_friction,
    )
    durations = [ph.duration for ph in phases]
    t_rms = pd.linear_rms_torque(torques, durations) if phases else 0.0 * friction
    # each distinct torque pair's largest |torque|, and the largest over the pairs that run at each
    # phase speed
    pair_peak = _pair_peaks(torques)
    at_speed: dict = {}
    for pair, ph in zip(torques, phases):
        at_speed.setdefault(ph.speed, {})[id(pair)] = pair_peak[id(pair)]
    t_peak_cycle = _largest(pair_peak.values()) if phases else 0.0 * friction
    # each phase's largest |torque| against the peak torque the motor gives at the phase's largest
    # speed (the intermittent zone, physics.drive.peak_torque_available); the steady thrust (feed)
    # against the flat peak
    by_speed: dict = {}  # one zone value per distinct phase speed
    for ph in phases:
        if ph.speed not in by_speed:
            by_speed[ph.speed] = pd.peak_torque_available(
                pd.motor_speed(ph.speed, p["lead"], a),
                p["motor_peak_torque"],
                p["motor_peak_corner_speed"],
                p["motor_peak_at_max_speed"],
                p["motor_max_speed"],
            )
    # steady thrust at feed (no acceleration): the largest and the mean axial load with friction and
    # weight
    thrust = friction + pd.force_torque(p["axial_load"], p["lead"], eta, a) + gravity
    thrust_mean = friction + pd.force_torque(p["mean_axial_load"], p["lead"], eta, a) + gravity
    t_peak = mx.fmax(t_peak_cycle, thrust)
    # an unbalanced (vertical) axis's steady load torque, friction and the weight less a
    # counterbalance (either way: an overbalanced head pushes up), against the vendor's share of the
    # rated torque (Mitsubishi MDS-D-SVJ3 eq. 7-12: TL <= 0.6 Tst; model.motorrule), referred to the
    # RMS ratio so one check holds both
    unbalance = p["gravity_axial"] * (friction + mx.fabs(gravity))
    unbalance_need = (
        unbalance * p["rms_torque_ratio"] / p.get("unbalance_torque_ratio", DEFAULT_RULE.unbalance)
    )
    t_cont = mx.fmax(mx.fmax(t_rms, thrust_mean), unbalance_need)
    # peak torque needed, referred to the flat (low-speed) peak: max over phases of |T| T_pk /
    # T_pk(n); convex in the nut preload like |T| (the zone does not depend on it), so the margin
    # holds on an interval of preloads >= 1
    factor_of = {s: p["motor_peak_torque"] / mx.fmax(avail, 1e-9) for s, avail in by_speed.items()}
    factors = [factor_of[ph.speed] for ph in phases]  # preload-independent
    use = thrust
    for speed, peaks in at_speed.items():  # max(a k, b k) = max(a, b) k for the factor k >= 1
        use = mx.fmax(use, _largest(peaks.values()) * factor_of[speed])
    thrust_ratio = p["rms_torque_ratio"] * p["motor_rated_torque"]
    v_max = max([ph.speed for ph in phases] + [0.0])
    n_motor = pd.motor_speed(v_max, p["lead"], a)
    ratio = pd.inertia_ratio(j_load, j_rotor)
    # holding a vertical axis at standstill (THK A-745: T_S = (m g - f) P_h / 2 pi eta, guide
    # friction credited): the brake holds wherever the power fails, so with the heaviest mass the
    # table carries (the axis's moving_mass), or a dwell's weight and force if larger; times the
    # brake safety factor
    hold = p["gravity_axial"] * pd.holding_torque(
        weight - balance_force(p, 0.0), hold_friction, p["lead"], eta, a
    )
    for ph, (t0, _) in zip(phases, torques):
        if ph.direction == 0.0:
            hold = mx.fmax(hold, t0)
    has = p["has_motor"] > 0.5
    brake_needed = p["gravity_axial"] > 0.5
    # the reduction's output torques (screw side): the cycle's largest against T2B, its RMS against
    # T2N
    red = p["has_reduction"] > 0.5
    # numbers without a reduction: no output torques to compute
    if isinstance(red, (bool, np.bool_)) and not red:
        out_torques, out_thrust, out_thrust_mean = (
            [(0.0 * friction, 0.0 * friction)] * len(phases),
            0.0 * friction,
            0.0 * friction,
        )
    else:
        out_torques, out_thrust, out_thrust_mean = output_torques(
            p, moving_mass, drag, phases, hold_friction
        )
    # reported where a reduction is (0 without one, on every backend)
    out_peak = mx.if_else(
        red,
        mx.fmax(_largest(_pair_peaks(out_torques).values()), out_thrust) if phases else out_thrust,
        0.0,
    )
    out_rms = mx.if_else(
        red,
        mx.fmax(pd.linear_rms_torque(out_torques, durations), out_thrust_mean)
        if phases
        else out_thrust_mean,
        0.0,
    )
    screw_speed = 2.0 * math.pi * v_max / p["lead"]
    # T2Stop (params: T2B if none)
    emergency = p.get("reduction_emergency_torque", p["reduction_accel_torque"])
    margins = {
        "motor_peak_torque": mx.if_else(has, p["motor_peak_torque"] / use, NOT_APPLICABLE),
        "motor_rated_torque": mx.if_else(has, thrust_ratio / t_cont, NOT_APPLICABLE),
        "motor_speed": mx.if_else(
            has, p["motor_max_speed"] / mx.fmax(n_motor, 1e-9), NOT_APPLICABLE
        ),
        "inertia_ratio": mx.if_else(has, p["max_inertia_ratio"] / ratio, NOT_APPLICABLE),
        "brake_holding": mx.if_else(
            has * brake_needed > 0.5,
            p["motor_brake_torque"] / (p["brake_safety"] * hold + 1e-12),
            NOT_APPLICABLE,
        ),
        # the coupling carries what the motor can deliver (its peak torque through the reduction)
        "coupling_torque": mx.if_else(
            p["has_coupling"] * has > 0.5,
            p["coupling_rated_torque"] / (p["motor_peak_torque"] * p["reduction_ratio"]),
            NOT_APPLICABLE,
        ),
        "coupling_speed": mx.if_else(
            p["has_coupling"] > 0.5,
            p["coupling_max_speed"] / mx.fmax(screw_speed, 1e-9),
            NOT_APPLICABLE,
        ),
        "reduction_accel_torque": mx.if_else(
            red, p["reduction_accel_torque"] / mx.fmax(out_peak, 1e-9), NOT_APPLICABLE
        ),
        "reduction_rated_torque": mx.if_else(
            red, p["reduction_rated_torque"] / mx.fmax(out_rms, 1e-9), NOT_APPLICABLE
        ),
        "reduction_speed": mx.if_else(
            red, p["reduction_max_speed"] / mx.fmax(n_motor, 1e-9), NOT_APPLICABLE
        ),
        # an emergency stop or a collision: the motor's peak (or the drive's torque limit) through
        # the ratio against the reduction's emergency-stop torque (Beckhoff AG2400 T2Em.stop;
        # Siemens 1FT7 5.4.1)
        "reduction_emergency_torque": mx.if_else(
            red * has > 0.5,
            emergency / (p["motor_peak_torque"] * p["reduction_ratio"]),
            NOT_APPLICABLE,
        ),
    }
    out = {margin_output(k): v for k, v in margins.items()}
    out.update(
        check_pairs(
            {
                "motor_peak_torque": (p["motor_peak_torque"], use),
                "motor_rated_torque": (thrust_ratio, t_cont),
                "motor_speed": (p["motor_max_speed"], n_motor),
                "inertia_ratio": (p["max_inertia_ratio"], ratio),
                "brake_holding": (p["motor_brake_torque"], p["brake_safety"] * hold),
                "coupling_torque": (
                    p["coupling_rated_torque"],
                    p["motor_peak_torque"] * p["reduction_ratio"],
                ),
                "coupling_speed": (p["coupling_max_speed"], screw_speed),
                "reduction_accel_torque": (p["reduction_accel_torque"], out_peak),
                "reduction_rated_torque": (p["reduction_rated_torque"], out_rms),
                "reduction_speed": (p["reduction_max_speed"], n_motor),
                "reduction_emergency_torque": (
                    emergency,
                    p["motor_peak_torque"] * p["reduction_ratio"],
                ),
            }
        )
    )
    # energy the motor returns to the drive over one cycle (braking, lowering a vertical axis) and
    # its mean power: what the drive's regenerative resistor must take (Yaskawa 12.8.6), before
    # winding and drive losses
    if regen:
        energy = sum(pd.regenerative_energy(phases, torques, p["lead"], a), 0.0 * friction)
        cycle = sum(durations)
        out.update(
            {"regen_energy": energy, "regen_power": energy / cycle if cycle > 0 else 0.0 * energy}
        )
    out.update(
        {
            "load_inertia": j_load,
            "total_inertia": j_tot,
            "inertia_ratio": ratio,
            "motor_speed": n_motor,
            "peak_torque": t_peak,
            "rms_torque": t_rms,
            "thrust_torque": thrust,
            "mean_thrust_torque": thrust_mean,
            "holding_torque": hold,
            "unbalance_torque": unbalance,
            "friction_torque": friction,
            "gravity_torque": gravity,
            "duty_time": sum(durations),
            "duty_torques": torques,
            "zone_factors": factors,
            "output_peak_torque": out_peak,
            "output_rms_torque": out_rms,
            "output_thrust_torque": out_thrust,
            "output_mean_thrust_torque": out_thrust_mean,
            "output_torques": out_torques,
        }
    )
    return out


def _net_weights(p, phases, masses: dict, torque) -> dict:
    """{(entry mass, direction): the torque ``torque(F)`` of the weight of the phase's mass less a
    counterbalance's force in the phase's direction (:func:`axisopt.model.loads.balance_force`)},
    one object per distinct pair (the phases that share one share their torque pair,
    physics.drive.phase_torques)."""
    out: dict = {}
    for ph in phases:
        key = (ph.moving_mass, ph.direction)
        if key not in out:
            out[key] = torque(
                p["gravity_axial"] * masses[ph.moving_mass] * G - balance_force(p, ph.direction)
            )
    return out


def _pair_peaks(torques) -> dict:
    """{id of a torque pair: its largest |torque|}, once per distinct pair (phases share pairs,
    :func:`axisopt.physics.drive.phase_torques`)."""
    peaks: dict = {}
    for pair in torques:
        if id(pair) not in peaks:
            peaks[id(pair)] = mx.fmax(mx.fabs(pair[0]), mx.fabs(pair[1]))
    return peaks


def _largest(values):
    """The elementwise largest of a non-empty collection of values (floats, arrays or CasADi)."""
    it = iter(values)
    out = next(it)
    for v in it:
        out = mx.fmax(out, v)
    return out
