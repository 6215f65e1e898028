"""The carriage on its guide blocks: block loads of the vendors' load cases, the mean load over the
duty cycle, and the table's rocking stiffness (pitch, yaw) and modes.

Load cases (THK General Catalog A-103..A-110, HIWIN G99TE20 §1-5), each with the moving mass's
weight at its centre of gravity (pressing onto the rails for a horizontal axis, along the rail for a
vertical one, across it for a wall-mounted one):

* standstill: the weight alone;
* cutting: the full cutting force (axial_load along, cross_load across, normal_load onto the rails)
  at the cutting point, feed and cross components with either sign (the cut reverses with the feed
  direction);
* acceleration and deceleration: the inertia force m a at the centre of gravity, either direction;
* each phase of the duty cycle: its process force (``force:`` of a move; the cross and normal
  components scale with it) at the cutting point and its inertia force at the centre of gravity,
  with the phase's moving mass (an entry's own ``moving_mass``: a workpiece loaded or unloaded; its
  weight too).

The static safety takes the largest equivalent block load of every case; the life takes, block by
block, the cubic mean over the travel of the duty cycle's phases (THK A-96/A-107), the phases'
process force being the mean axial load when the cycle gives none (the default rapid cycle), and the
most loaded block.
"""

from __future__ import annotations

from .. import mathx as mx
from ..physics import carriage as pcr
from .gantry import single_drive, tp
from .loads import phase_groups, phase_moving_mass

G = 9.80665


def shares(p) -> dict:
    """Moment shares (1/m) of the block pattern, blocks per rail and the block count."""
    rails = p["rails"]
    per_rail = p["guide_blocks"] / rails
    c0 = p["guide_static_load"]
    return {
        "per_rail": per_rail,
        "n": p["guide_blocks"],
        "pitch": pcr.moment_share(
            per_rail, p["block_spacing"], c0 / p["guide_moment_pitch"], rails
        ),
        "roll": pcr.moment_share(rails, p["rail_spacing"], c0 / p["guide_moment_roll"], per_rail),
        "yaw": pcr.moment_share(per_rail, p["block_spacing"], c0 / p["guide_moment_yaw"], rails),
    }


def _sum(forces):
    """(f_n, f_y, M_P, M_R, M_Y) of forces [(f_x, f_y, f_n, y, h)] acting at x = 0 (the carriage
    centre)."""
    fn = fy = mp = mr = my = 0.0
    for fx_, fy_, fn_, y, h in forces:
        a, b, c = pcr.carriage_moments(fx_, fy_, fn_, 0.0, y, h)
        fn, fy, mp, mr, my = fn + fn_, fy + fy_, mp + a, mr + b, my + c
    return fn, fy, mp, mr, my


def carriage_loads(p, moving) -> dict:
    """Largest equivalent block load of the load cases [N], the guides' static safety factor [-],
    the mean block load over the duty cycle [N] (most loaded block) and the moment shares."""
    sh = shares(p)
    n = sh["n"]
    ga, gc = p["gravity_axial"], p["gravity_cross"]

    y_t, h_t, h_g = p["tool_offset"], p["tool_height"], p["cg_height"]
    # a twin gantry's cross carriage (m_c) at either end of its stroke across the rails (+-s/2): the
    # weight and the inertia force of the moving mass m act at the centre of gravity y_g + m_c y_c /
    # m (statics; the vendors' load distribution, THK A-82..A-89, HIWIN G99TE20 1-5, then takes the
    # moments); one drive: y_c 0
    ends = [0.0]
    if not single_drive(p):
        half = 0.5 * tp(p, "cross_stroke")
        ends = [half, -half]
    m_c = tp(p, "cross_mass")

    def cg(m, y_c):
        return p["cg_offset"] + m_c * y_c / m if len(ends) > 1 else p["cg_offset"]

    def weight_of(m, y_c):
        return (-ga * m * G, gc * m * G, (1.0 - ga - gc) * m * G, cg(m, y_c), h_g)

    # a twin drive's parameters carry the governing side's share of the process force
    # (model.gantry): the guides carry the whole gantry and the whole force (force_share 1 for one
    # drive)
    fs = tp(p, "force_share")
    f_feed, f_cross, f_norm = p["axial_load"] / fs, p["cross_load"], p["normal_load"]

    def pe_max(forces):
        fn, fy, mp, mr, my = _sum(forces)
        return pcr.max_block_load(fn, fy, mp, mr, my, n, sh["pitch"], sh["roll"], sh["yaw"])

    groups = phase_groups(tuple(p.get("duty", ())))
    ratio = mx.if_else(f_feed > 0.0, 1.0 / mx.fmax(f_feed, 1e-12), 0.0)
    cases = []
    for y_c in ends:
        weight, y_g = weight_of(moving, y_c), cg(moving, y_c)
        cases.append([weight])
        for s in (1.0, -1.0):
            cases.append([weight, (s * moving * p["acceleration"], 0.0, 0.0, y_g, h_g)])
            for t in (1.0, -1.0):
                cases.append([weight, (s * f_feed, t * f_cross, f_norm, y_t, h_t)])
        # the phases' own process forces (a duty cycle that gives them): the cut with the phase's
        # inertia force
        for (force, peak, _, direction, mass), _ in groups:
            if force:
                m = phase_moving_mass(p, moving, mass)
                scale = p["duty_process"] * (force / fs) * ratio
                sign = -direction if direction else 1.0
                cases.append(
                    [
                        weight_of(m, y_c),
                        (-m * peak, 0.0, 0.0, cg(m, y_c), h_g),
                        (
                            sign * p["duty_process"] * (force / fs),
                            scale * f_cross,
                            scale * f_norm,
                            y_t,
                            h_t,
                        ),
                    ]
                )
    p_max = pe_max(cases[0])
    for c in cases[1:]:
        p_max = mx.fmax(p_max, pe_max(c))

    # mean load per block over the travel: the phase's process force, or the mean axial load (rapid
    # cycle); a twin gantry's cross carriage at the end that loads the block most (conservative: it
    # may stand there)
    p_mean = None
    for y_c in ends:
        loads = {corner: [] for corner in pcr.CORNERS}
        travel = []
        for (force, _, mean_acc, direction, mass), dist in groups:
            if dist <= 0.0:
                continue
            m = phase_moving_mass(p, moving, mass)
            f = (p["duty_process"] * force + (1.0 - p["duty_process"]) * p["mean_axial_load"]) / fs
            scale = f * ratio
            fn, fy, mp, mr, my = _sum(
                [
                    weight_of(m, y_c),
                    (-m * mean_acc, 0.0, 0.0, cg(m, y_c), h_g),
                    (-direction * f, scale * f_cross, scale * f_norm, y_t, h_t),
                ]
            )
            for corner, pe in zip(
                pcr.CORNERS,
                pcr.corner_block_loads(fn, fy, mp, mr, my, n, sh["pitch"], sh["roll"], sh["yaw"]),
            ):
                loads[corner].append(pe)
            travel.append(dist)
        if travel:
            means = [pcr.mean_load(v, travel) for v in loads.values()]
        else:  # a cycle without travel: the standstill load
            means = [pe_max([weight_of(moving, y_c)])]
        for m in means:
            p_mean = m if p_mean is None else mx.fmax(p_mean, m)
    return {
        "guide_max_load": p_max,
        "guide_static_safety": pcr.static_safety(p["guide_static_load"], p_max),
        "guide_mean_load": p_mean,
    }


def rocking(p) -> dict:
    """Pitch and yaw stiffness of the block pattern [N*m/rad] and the table's rocking modes [Hz]."""
    rails = p["rails"]
    per_rail = p["guide_blocks"] / rails
    c0 = p["guide_static_load"]
    k_pitch = pcr.pattern_rocking_stiffness(
        p["guide_normal_stiffness"],
        per_rail,
        p["block_spacing"],
        rails,
        c0 / p["guide_moment_pitch"],
    )
    k_yaw = pcr.pattern_rocking_stiffness(
        p["guide_tangential_stiffness"],
        per_rail,
        p["block_spacing"],
        rails,
        c0 / p["guide_moment_yaw"],
    )
    return {
        "k_pitch": k_pitch,
        "k_yaw": k_yaw,
        "f_pitch": pcr.rocking_frequency(k_pitch, p["pitch_inertia"]),
        "f_yaw": pcr.rocking_frequency(k_yaw, p["yaw_inertia"]),
    }


def tool_stiffness(p, k_total, rock) -> dict:
    r"""Stiffness in the feed direction at the cutting point [N/m] (per position, like ``k_total``).

    .. math:: 1/k_{tool} = 1/k_{total} + h_t^2 / K_P + y_t^2 / K_Y

    The axial chain in series with the table pitching (lever h_t, the tool's height above the screw
    axis in the mounting plane) and yawing (lever y_t, its offset across the rail) on its blocks.
    """
    c_rock = p["tool_height"] ** 2 / rock["k_pitch"] + p["tool_offset"] ** 2 / rock["k_yaw"]
    return {"k_tool": 1.0 / (1.0 / k_total + c_rock), "c_rocking": c_rock}
