"""Rack-and-pinion drive as a sub-assembly: parameters in, outputs and margins out, on floats, numpy
arrays and CasADi symbols alike (the duty cycle enters as :func:`axisopt.physics.rack.cycle_gram` of
its phases, floats).  One drive side (a twin-drive gantry: the governing side, as the screw model
checks it).

The vendors' sizing (THK A-241, Apex Dynamics, Yaskawa 11.2.4): the feed force over the duty cycle
(inertia of the moving mass with motor, gearbox and blocks riding on it, guide friction, process
force, weight on a vertical axis); the pinion's largest thrust against its permissible capacity over
the overload factor; the motor's peak and RMS torque through the gearbox (the motor's and gearbox's
inertia at the motor, the gearbox's efficiency), the motor speed, the gearbox's T2B / T2N / n1Max as
``model.drive`` rates them; the inertia ratio.  A preloaded twin pinion (two motors per rack,
electrically biased): each pinion carries half the feed force plus the bias ``bias x peak force``
(RMS bounded by rms(F)/2 + bias: Minkowski), no backlash, both meshes and gearboxes in parallel.
The axial chain: mesh (ISO 6336-1 guidance, an estimate) in series with the gearbox's torsional
stiffness at the pinion radius; no position dependence (the rack is fixed).  The positioning error:
the rack's cumulative pitch error over the stroke plus the lost motion of the gearbox's backlash
(none with a twin pinion).

Keys of ``p`` (SI): m_axis (moving mass of this side without drive parts and blocks), m_parts
(motors, gearboxes, pinions riding on the carriage), m_blocks, mu (guide friction coefficient),
f_seal (blocks' seal friction), normal (normal force on this side's blocks), vertical (0/1), d
(pinion pitch diameter), perm (permissible feed force), k_o (overload factor), face (face width),
err (pitch error per metre), stroke, ratio, eta, j_motor, j_red, t_rated, t_peak, n_max (motor,
rad/s), t2b, t2n, n1max (rad/s), backlash (rad), kt_red (N m/rad), twin (0/1), bias, rms_ratio,
max_inertia_ratio, k_n (guide normal stiffness per block), blocks (per side), v_max (the cycle's top
speed), thrust and mean_thrust (this side's share of the axis's largest and mean axial load: the
steady feed force).
"""

from __future__ import annotations

from .. import mathx as mx
from ..physics import linearmotor as plm
from ..physics import rack as pr
from ..physics.dynamics import table_mode_frequency

BIG = 1.0e3  # the margin of a check that does not apply


def _halves(p):
    """Per-pinion share of the feed force: 1 (one pinion) or 1/2 (twin pinion)."""
    return 1.0 - 0.5 * p["twin"]


def rack_response(p, cycle) -> dict:
    """Outputs and margins of a rack-and-pinion drive side (see the module)."""
    g = plm.G
    m = p["m_axis"] + p["m_parts"] + p["m_blocks"]
    horiz = 1.0 - p["vertical"]
    resist = p["mu"] * (m * g * horiz + p["normal"]) + p["f_seal"]
    weight = m * g * p["vertical"]
    r = p["d"] / 2.0
    # the cycle (rapids with the duty cycle's forces), and the steady thrust at feed: the largest
    # axial load against the peak, the mean axial load against the RMS (as model.drive rates a screw
    # drive's motor)
    thrust = resist + p["thrust"] + weight
    mean_thrust = resist + p["mean_thrust"] + weight
    f_peak = mx.fmax(pr.peak_linear(cycle, m, resist, 1.0, weight), thrust)
    f_rms = mx.fmax(pr.rms_linear(cycle, m, resist, 1.0, weight), mean_thrust)
    h = _halves(p)
    f_bias = p["twin"] * p["bias"] * f_peak
    tooth = h * f_peak + f_bias
    out_peak = tooth * r  # gearbox output (pinion) torque
    out_rms = (h * f_rms + f_bias) * r
    through = r / (p["ratio"] * p["eta"])
    j_rot = (
        (p["j_motor"] + p["j_red"]) * p["ratio"] / r
    )  # motor-side inertia per unit table acceleration
    t_peak = (
        mx.fmax(
            pr.peak_linear(
                cycle,
                j_rot + h * m * through,
                h * resist * through,
                h * through,
                h * weight * through,
            ),
            h * thrust * through,
        )
        + f_bias * through
    )
    t_rms = (
        mx.fmax(
            pr.rms_linear(
                cycle,
                j_rot + h * m * through,
                h * resist * through,
                h * through,
                h * weight * through,
            ),
            h * mean_thrust * through,
        )
        + f_bias * through
    )
    v_max = p["v_max"]
    n_motor = pr.pinion_speed(v_max, p["d"]) * p["ratio"]
    j_load = h * m * r * r / (p["ratio"] * p["ratio"])
    pinions = 1.0 + p["twin"]
    k_mesh = pr.mesh_stiffness(p["face"], pinions)
    k_gear = pinions * pr.torsion_at_rack(p["kt_red"], p["d"])
    k = pr.series(k_mesh, k_gear)
    f_axial = mx.sqrt(k / m) / (2.0 * mx.pi)
    f_table = table_mode_frequency(p["k_n"], p["blocks"], m)
    out = {
        "moving_mass": m,
        "feed_force": f_peak,
        "feed_force_rms": f_rms,
        "tooth_force": tooth,
        "pinion_torque": out_peak,
        "motor_peak_torque": t_peak,
        "motor_rms_torque": t_rms,
        "motor_speed": n_motor,
        "inertia_ratio": j_load / p["j_motor"],
        "stiffness": k,
        "mesh_stiffness": k_mesh,
        "gearbox_stiffness": k_gear,
        "frequency": mx.fmin(f_axial, f_table),
        "axial_frequency": f_axial,
        "lost_motion": pr.lost_motion(p["backlash"], p["d"], p["twin"]),
        "positioning_error": pr.pitch_error(p["err"], p["stroke"])
        + pr.lost_motion(p["backlash"], p["d"], p["twin"]),
    }
    margins = {
        "pinion_tooth": pr.tooth_margin(p["perm"], p["k_o"], tooth),
        "motor_peak": p["t_peak"] / t_peak,
        "motor_rms": p["rms_ratio"] * p["t_rated"] / t_rms,
        "motor_speed": p["n_max"] / n_motor,
        "gearbox_peak": p["t2b"] / out_peak,
        "gearbox_rated": p["t2n"] / out_rms,
        "gearbox_speed": p["n1max"] / n_motor,
        "inertia_ratio": p["max_inertia_ratio"] * p["j_motor"] / j_load,
    }
    return {"outputs": out, "margins": margins}


def guide_response(p, m, attraction=0.0) -> dict:
    """The guide blocks of a drive side, evenly loaded (the vendors' centred-load case, THK A-82
    case 1): each block carries (weight on the guides + normal force + magnetic attraction) /
    blocks; L10 travel life against the life the axis needs over its mean speed, static safety C0 /
    P against the axis's least.  Keys of ``p``: vertical, normal, blocks, c_block, c0_block, roller,
    rating_distance, fw, life_needed (travel [m]), static_safety."""
    from ..physics.checks import guide_life_distance

    load = (m * plm.G * (1.0 - p["vertical"]) + p["normal"] + attraction) / p["blocks"]
    load = mx.fmax(load, 1.0)
    life = guide_life_distance(p["c_block"], load, p["fw"], p["roller"], p["rating_distance"])
    return {
        "outputs": {"block_load": load, "guide_life": life},
        "margins": {
            "guide_life": life / p["life_needed"],
            "guide_static": p["c0_block"] / load / p["static_safety"],
        },
    }
