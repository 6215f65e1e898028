"""Masses and the axial loads the axis sees: inertia, guide friction, gravity, pretension, heat, and
the axial load of each duty-cycle phase with its travel, for the life checks."""

from __future__ import annotations

from functools import lru_cache

from .. import mathx as mx
from ..physics import counterbalance as pcb
from ..physics import guides as pg
from ..physics import motion
from ..physics import thermal as pt
from .gantry import side_moving_mass, tp

G = 9.80665

# The driven rotating-nut unit's parameters for a nut on a turning screw
# (model.params.rotating_nut_params gives the same): what a bare parameter dict without them (a
# test's, an older caller's) stands for
NUT_ON_TURNING_SCREW = {
    "nut_rotating": 0.0,
    "unit_inertia": 0.0,
    "unit_max_speed": 1.0,
    "unit_bearing_dynamic_load": 1.0,
    "unit_bearing_static_load": 1.0,
    "unit_bearing_preload": 0.05,
    "unit_bearing_stiffness": 1.0,
    "unit_bearing_torque": 0.0,
}


# No counterbalance: what a parameter dict without the counterbalance parameters (a test's, an older
# caller's) stands for (model.params.counterbalance_params gives the same for an axis without one)
NO_COUNTERBALANCE = {
    "balance_mass": 0.0,
    "balance_efficiency": 1.0,
    "balance_moving_mass": 0.0,
    "balance_force": 0.0,
}


def balance(p, name):
    """A counterbalance parameter of ``p``, or its value without a counterbalance when ``p`` has
    none."""
    return p[name] if name in p else NO_COUNTERBALANCE[name]


def balance_force(p, direction):
    r"""Force of the counterbalance on the head along the axis (up) [N], the head moving in
    ``direction`` (+1 up, -1 down, 0 at rest): the counterweight's pull through its chain's
    efficiency (:func:`axisopt.physics.counterbalance.counterweight_force`) plus a cylinder's force
    at the worst end of its range (chosen once for the axis, model.params.counterbalance_params); 0
    on a horizontal axis.

    .. math:: F_b = g_{ax} (m_c\,g\,\eta_p^{s} + F_{cyl})

    The counterweight's inertia is not in it: its mass (and the chain's, a cylinder's piston) moves
    with the head, so it joins the mass the drive accelerates (``balance_moving_mass``, Yaskawa
    Sigma-7 11.2.1: J_L1 = (M + M_c)(P_B / 2 pi)^2)."""
    return p["gravity_axial"] * (
        pcb.counterweight_force(
            balance(p, "balance_mass"), balance(p, "balance_efficiency"), direction
        )
        + balance(p, "balance_force")
    )


def balance_summary(p, moving) -> dict:
    """What a counterbalance takes off the head [N]: its force up at rest, rising and lowering
    (:func:`balance_force`), the head's weight (``moving`` [kg]: table + workpiece, nut and blocks)
    and the net weight the screw carries at rest."""
    weight = p["gravity_axial"] * moving * G
    rest = balance_force(p, 0.0)
    return {
        "rest": rest,
        "rising": balance_force(p, 1.0),
        "lowering": balance_force(p, -1.0),
        "weight": weight,
        "net": weight - rest,
    }


def unit(p, name):
    """A rotating-nut unit parameter of ``p``, or its value for a nut on a turning screw when ``p``
    has none."""
    return p[name] if name in p else NUT_ON_TURNING_SCREW[name]


@lru_cache(maxsize=64)
def phase_groups(phases: tuple) -> tuple:
    """Duty-cycle phases grouped by (process force, peak acceleration, mean acceleration, direction,
    the entry's moving mass or None), with the travel of each group [m]
    (:func:`axisopt.physics.motion.phase_travel`)."""
    groups: dict = {}
    for ph in phases:
        travel = motion.phase_travel(ph) if ph.direction else 0.0
        peak = ph.a0 if abs(ph.a0) >= abs(ph.a1) else ph.a1
        key = (ph.force, peak, 0.5 * (ph.a0 + ph.a1), ph.direction, ph.moving_mass)
        groups[key] = groups.get(key, 0.0) + travel
    return tuple((k, v) for k, v in groups.items())


def phase_moving_mass(p, moving, entry_mass):
    """Moving mass in a phase [kg]: ``moving`` (the axis's table + workpiece, nut and blocks) with
    the duty-cycle entry's own table + workpiece ``entry_mass`` [kg] in place of the axis's (a
    workpiece loaded or unloaded); ``moving`` when the entry names none (None)."""
    return moving if entry_mass is None else moving + (entry_mass - p["table_mass"])


def guide_friction(p, table_mass, speed):
    r"""Normal load per guide block [N] and the friction of all blocks [N] at a table speed [m/s],
    with ``table_mass`` [kg] (table + workpiece) on the blocks unless the axis is vertical:
    :math:`N = (m g (1 - g_{ax}) + F_n) / n`, :math:`f = n\,(F_0 + \mu N + c_v v)`
    (:func:`axisopt.physics.guides.guide_friction_force`).  THK's worked examples write the same
    term :math:`\mu m g + f` (A-725)."""
    blocks = p["guide_blocks"]
    n_block = (table_mass * G * (1.0 - p["gravity_axial"]) + p["normal_load"]) / blocks
    f = blocks * pg.guide_friction_force(
        p["guide_friction_force"],
        p["guide_friction_coefficient"],
        p["guide_friction_viscous"],
        n_block,
        speed,
    )
    return n_block, f


def life_rows(p, moving, f_guides, share=1.0) -> list[dict]:
    """The life checks' load cases, one per duty-cycle phase group that travels: ``load`` the signed
    axial load on the nut [N] (+ along the axis's positive direction, up on a vertical axis),
    ``travel`` the travel under it [m], and what makes the load: ``direction`` (+1/-1),
    ``acceleration`` (the phases' mean) [m/s^2], ``mass`` the moving mass [kg], ``friction`` the
    guide friction [N], ``process`` the process force [N] and ``weight`` [N] (the weight less a
    counterbalance's force in the phase's direction, :func:`balance_force`; the counterbalance's
    moving mass accelerates with the head).

    A duty cycle of the user's: per phase, with the phase's moving mass m (an entry's own
    ``moving_mass``, a workpiece loaded or unloaded, else the axis's), the inertia force at the
    phase's mean acceleration, the guide friction and the phase's process force against the motion,
    and the weight (THK A-725/A-739: e.g.  Fa1 = mu m g + f + m alpha).  Without one: the mean axial
    load (with friction) each way over half the travel, and the weight.
    """
    phases = p.get("duty", ())
    rows = []
    if getattr(phases, "given", False):
        for (force, _, mean_acc, direction, mass), dist in phase_groups(tuple(phases)):
            if dist <= 0.0 or not direction:
                continue
            m = phase_moving_mass(p, moving, mass)
            f_fric = (
                f_guides if mass is None else share * guide_friction(p, mass, p["max_speed"])[1]
            )
            f_proc = p["duty_process"] * force + (1.0 - p["duty_process"]) * p["mean_axial_load"]
            # net of a counterbalance
            weight = p["gravity_axial"] * m * G - balance_force(p, direction)
            accelerated = m + balance(p, "balance_moving_mass")
            rows.append(
                {
                    "load": accelerated * mean_acc + direction * (f_fric + f_proc) + weight,
                    "travel": dist,
                    "direction": direction,
                    "acceleration": mean_acc,
                    "mass": m,
                    "friction": f_fric,
                    "process": f_proc,
                    "weight": weight,
                }
            )
    if not rows:
        for direction in (1.0, -1.0):
            weight = p["gravity_axial"] * moving * G - balance_force(p, direction)
            rows.append(
                {
                    "load": direction * (p["mean_axial_load"] + f_guides) + weight,
                    "travel": 0.5,
                    "direction": direction,
                    "acceleration": 0.0,
                    "mass": moving,
                    "friction": f_guides,
                    "process": p["mean_axial_load"],
                    "weight": weight,
                }
            )
    return rows


def lift_off_load(p, moving, f_guides, f_max, net, share=1.0):
    """The largest axial load [N] the nut lift-off check holds the preload against, each load case
    with its own load (THK A-725, A-739: the cut at feed speed, the inertia in the rapid, each phase
    of a duty cycle with its own acceleration, process force, friction and weight):

    * the axis's largest process force at feed speed (no inertia), with the guide friction and the
      weight ``net`` (less a counterbalance), always;
    * a duty cycle of the user's: each phase group's peak inertia force, friction and process force
      against the motion and its weight (a dwell: its weight and process force); the default cycle:
      the rapid's inertia force at the axis's acceleration with friction and weight;
    * ``cut_while_accelerating`` 1 (the user says the cut happens while the axis accelerates):
      ``f_max``, both at once."""
    cut = p["axial_load"] + f_guides + net
    phases = p.get("duty", ())
    cases = []
    if getattr(phases, "given", False):
        for (force, peak, _, direction, mass), _dist in phase_groups(tuple(phases)):
            m = phase_moving_mass(p, moving, mass)
            f_fric = (
                f_guides if mass is None else share * guide_friction(p, mass, p["max_speed"])[1]
            )
            f_proc = p["duty_process"] * force + (1.0 - p["duty_process"]) * p["mean_axial_load"]
            if direction:
                weight = p["gravity_axial"] * m * G - balance_force(p, direction)
                accelerated = m + balance(p, "balance_moving_mass")
                cases.append(mx.fabs(accelerated * peak + direction * (f_fric + f_proc) + weight))
            else:
                cases.append(mx.fabs(p["gravity_axial"] * m * G - balance_force(p, 0.0)) + f_proc)
    else:
        cases.append(
            (moving + balance(p, "balance_moving_mass")) * p["acceleration"] + f_guides + net
        )
    need = cut
    for c in cases:
        need = mx.fmax(need, c)
    flag = p.get("cut_while_accelerating", 0.0)
    return flag * f_max + (1.0 - flag) * need


def life_loads(p, moving, f_guides, share=1.0) -> tuple[list, list]:
    """The signed axial loads [N] and travels [m] of :func:`life_rows`, for the life checks
    (physics.life)."""
    rows = life_rows(p, moving, f_guides, share)
    return [r["load"] for r in rows], [r["travel"] for r in rows]


def masses(p) -> dict:
    """Moving mass (table + nut + blocks), screw mass and total mass [kg].  A twin drive
    (:mod:`.gantry`): the second nut moves too and the second screw and bearing sets count in the
    total; ``moving_mass`` is then the governing side's share (what each drive moves,
    :func:`axisopt.model.gantry.side_moving_mass`) and ``gantry_moving_mass`` the whole (what the
    guides carry; the same as ``moving_mass`` for one drive)."""
    twin = tp(p, "twin")
    screw_mass = p["screw_mass_per_length"] * p["span"]
    moving = (
        p["table_mass"] + (1.0 + twin) * p["nut_mass"] + p["guide_blocks"] * p["guide_block_mass"]
    )
    rails_mass = p["rails"] * p["rail_length"] * p["guide_rail_mass_per_length"]
    total = (
        moving
        + (1.0 + twin) * screw_mass
        + rails_mass
        + (1.0 + twin) * (p["bearing_sets"] * p["bearing_mass"])
    )
    return {
        "moving_mass": side_moving_mass(p, moving),
        "gantry_moving_mass": moving,
        "screw_mass": screw_mass,
        "total_mass": total,
    }


def bearing_set_stiffness(p):
    """One support-bearing set in series with its housing [N/m]."""
    return 1.0 / (1.0 / p["bearing_stiffness"] + p["housing_compliance"])


def axial_loads(p, moving, whole=None) -> dict:
    """Axial forces on the screw [N]: the largest (cutting + inertia + friction + weight) and the
    mean one for life; guide friction at max speed and the normal load per block; the screw
    pretension and the thermal force of a fixed-fixed screw; the static load this leaves on a
    support-bearing set; the guide friction at standstill (THK's f, credited to the holding torque,
    A-745).  With a counterbalance the weight is net of its force (:func:`balance_force`): the
    largest load the larger of the head rising (the least balance) and lowering (the most, an
    overbalanced head pushing up), the mean one at rest; its moving mass accelerates with the head.
    ``moving`` is the mass the drive moves [kg], ``whole`` the whole moving mass on the guides
    (default ``moving``): a twin drive's side takes the guide friction in the share moving / whole
    (:mod:`.gantry`; ``axial_load`` is already the side's share)."""
    share = 1.0 if whole is None else moving / whole
    n_block, f_guides = guide_friction(p, p["table_mass"], p["max_speed"])
    f_guides = share * f_guides
    gravity = p["gravity_axial"] * moving * G
    # = gravity without one
    net = mx.fmax(gravity - balance_force(p, 1.0), balance_force(p, -1.0) - gravity)
    f_max = (
        p["axial_load"]
        + (moving + balance(p, "balance_moving_mass")) * p["acceleration"]
        + f_guides
        + net
    )
    f_mean = (
        p["mean_axial_load"]
        + f_guides
        + mx.fmax(gravity - balance_force(p, 0.0), balance_force(p, 0.0) - gravity)
    )
    ff = p["bearing_sets"] - 1.0  # 1 for fixed-fixed
    k_set = bearing_set_stiffness(p)
    # pretension, fixed-fixed only: 'auto' is the force that absorbs the vendor's design rise, E A
    # alpha dT_design (THK A-715: a negative target travel for 2-5 degC, the shaft stretched to it;
    # design.PRETENSION_RISE), not the heat balance's whole rise; a given pretension wins
    pre = ff * (
        p["pretension_auto"] * pt.restrained_thermal_force(p["root_diameter"], p["pretension_rise"])
        + (1.0 - p["pretension_auto"]) * p["pretension"]
    )
    # the thermal force of the whole rise on the elastic ends (bearing sets with their housings): it
    # eats the pretension, and what exceeds it pushes the screw into compression (rises with the nut
    # preload)
    d_thermal = ff * pt.thermal_force_elastic_ends(
        p["root_diameter"], p["span"], p["temperature_rise"], k_set
    )
    # a set carries the pretension when cold and, warm, the pretension left or the thermal push
    # beyond it: max(pre, |d - pre|) = max(pre, d - pre) for d >= 0, nondecreasing in the rise
    static = mx.fmax(pre, d_thermal - pre)
    # compression in the screw when pushing: the load, plus the thermal push not absorbed by
    # pretension (a pretension above the thermal push is not credited against the load:
    # conservative, and monotone in the temperature rise, which rises with the nut preload through
    # the heat balance)
    compression = f_max + mx.fmax(d_thermal - pre, 0.0)
    life, travel = life_loads(p, moving, f_guides, share)
    return {
        "life_loads": life,
        "life_travels": travel,
        "block_load": n_block,
        "guide_friction": f_guides,
        "guide_friction_static": share * guide_friction(p, p["table_mass"], 0.0)[1],
        "max_axial_force": f_max,
        "lift_off_load": lift_off_load(p, moving, f_guides, f_max, net, share),
        "mean_axial_force": f_mean,
        "pretension": pre,
        "thermal_force": d_thermal,
        "bearing_static_load": static,
        "screw_compression": compression,
        "screw_tension": f_max + pre,
    }
