"""Masses and the axial loads the axis sees: inertia, guide friction, gravity, pretension, heat, and the
axial load of each duty-cycle phase with its travel, for the life checks."""

from __future__ import annotations

from functools import lru_cache

from .. import mathx as mx
from ..physics import guides as pg
from ..physics import motion
from ..physics import thermal as pt

G = 9.80665


@lru_cache(maxsize=64)
def phase_groups(phases: tuple) -> tuple:
    """Duty-cycle phases grouped by (process force, peak acceleration, mean acceleration, direction), with the
    travel of each group [m] (:func:`axisopt.physics.motion.phase_travel`)."""
    groups: dict = {}
    for ph in phases:
        travel = motion.phase_travel(ph) if ph.direction else 0.0
        peak = ph.a0 if abs(ph.a0) >= abs(ph.a1) else ph.a1
        key = (ph.force, peak, 0.5 * (ph.a0 + ph.a1), ph.direction)
        groups[key] = groups.get(key, 0.0) + travel
    return tuple((k, v) for k, v in groups.items())


def life_loads(p, moving, f_guides) -> tuple[list, list]:
    """Signed axial load on the nut in each phase that travels [N] (+ along the axis's positive direction, up
    on a vertical axis) and the travel under it [m], for the life checks (physics.life).

    A duty cycle of the user's: per phase, the inertia force at the phase's mean acceleration, the guide
    friction and the phase's process force against the motion, and the weight (THK A-725/A-739: e.g.
    Fa1 = mu m g + f + m alpha).  Without one: the mean axial load (with friction) each way over half the
    travel, and the weight.
    """
    phases = p.get("duty", ())
    weight = p["gravity_axial"] * moving * G
    loads, travels = [], []
    if getattr(phases, "given", False):
        for (force, _, mean_acc, direction), dist in phase_groups(tuple(phases)):
            if dist <= 0.0 or not direction:
                continue
            f_proc = p["duty_process"] * force + (1.0 - p["duty_process"]) * p["mean_axial_load"]
            loads.append(moving * mean_acc + direction * (f_guides + f_proc) + weight)
            travels.append(dist)
    if not travels:
        f = p["mean_axial_load"] + f_guides
        loads, travels = [f + weight, -f + weight], [0.5, 0.5]
    return loads, travels


def masses(p) -> dict:
    """Moving mass (table + nut + blocks), screw mass and total mass [kg]."""
    screw_mass = p["screw_mass_per_length"] * p["span"]
    moving = p["table_mass"] + p["nut_mass"] + p["guide_blocks"] * p["guide_block_mass"]
    rails_mass = p["rails"] * p["rail_length"] * p["guide_rail_mass_per_length"]
    total = moving + screw_mass + rails_mass + p["bearing_sets"] * p["bearing_mass"]
    return {"moving_mass": moving, "screw_mass": screw_mass, "total_mass": total}


def bearing_set_stiffness(p):
    """One support-bearing set in series with its housing [N/m]."""
    return 1.0 / (1.0 / p["bearing_stiffness"] + p["housing_compliance"])


def axial_loads(p, moving) -> dict:
    """Axial forces on the screw [N]: the largest (cutting + inertia + friction + weight) and the mean one
    for life; guide friction at max speed and the normal load per block; the screw pretension and the
    thermal force of a fixed-fixed screw; the static load this leaves on a support-bearing set."""
    blocks = p["guide_blocks"]
    n_block = (p["table_mass"] * G * (1.0 - p["gravity_axial"]) + p["normal_load"]) / blocks
    f_guides = blocks * pg.guide_friction_force(
        p["guide_friction_force"], p["guide_friction_coefficient"], p["guide_friction_viscous"],
        n_block, p["max_speed"])
    gravity = p["gravity_axial"] * moving * G
    f_max = p["axial_load"] + moving * p["acceleration"] + f_guides + gravity
    f_mean = p["mean_axial_load"] + f_guides + gravity
    ff = p["bearing_sets"] - 1.0  # 1 for fixed-fixed
    k_set = bearing_set_stiffness(p)
    # pretension, fixed-fixed only: 'auto' is the force that absorbs the vendor's design rise, E A alpha dT_design
    # (THK A-715: a negative target travel for 2-5 degC, the shaft stretched to it; design.PRETENSION_RISE), not the
    # heat balance's whole rise; a given pretension wins
    pre = ff * (p["pretension_auto"] * pt.restrained_thermal_force(p["root_diameter"], p["pretension_rise"])
                + (1.0 - p["pretension_auto"]) * p["pretension"])
    # the thermal force of the whole rise on the elastic ends (bearing sets with their housings): it eats the
    # pretension, and what exceeds it pushes the screw into compression (rises with the nut preload)
    d_thermal = ff * pt.thermal_force_elastic_ends(p["root_diameter"], p["span"], p["temperature_rise"], k_set)
    # a set carries the pretension when cold and, warm, the pretension left or the thermal push beyond it:
    # max(pre, |d - pre|) = max(pre, d - pre) for d >= 0, nondecreasing in the rise
    static = mx.fmax(pre, d_thermal - pre)
    # compression in the screw when pushing: the load, plus the thermal push not absorbed by pretension (a
    # pretension above the thermal push is not credited against the load: conservative, and monotone in the
    # temperature rise, which rises with the nut preload through the heat balance)
    compression = f_max + mx.fmax(d_thermal - pre, 0.0)
    life, travel = life_loads(p, moving, f_guides)
    return {"life_loads": life, "life_travels": travel,
            "block_load": n_block, "guide_friction": f_guides, "max_axial_force": f_max,
            "mean_axial_force": f_mean, "pretension": pre, "thermal_force": d_thermal,
            "bearing_static_load": static, "screw_compression": compression,
            "screw_tension": f_max + pre}
