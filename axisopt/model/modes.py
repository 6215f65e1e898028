"""Natural frequencies over the stroke (axial, table on guides, drive train) and modal damping."""

from __future__ import annotations

import math

from .. import mathx as mx
from ..physics import damping as pdm
from ..physics import dynamics as pdy
from ..physics import screw as ps
from .chain import drive_torsional_stiffness
from .gantry import NO_MODE, gantry_modes, single_drive, tp
from .loads import unit

# Material damping ratio of steel structures, seed Table 5 (0.001-0.002).
STEEL_DAMPING = 0.002


def axial_modes(p, x, mounting, chain, moving, screw_mass, rock=None, whole=None) -> dict:
    """Axial mode (motor held, Rayleigh screw mass), the table's bounce mode on the guide blocks
    and, given the rocking modes (``model.carriage.rocking``: pitch and yaw), the first of them all
    [Hz].  ``moving`` is the mass the drive moves, ``whole`` the whole moving mass (default
    ``moving``; a twin drive: its side's share and the gantry, whose 2-DOF translation and racking
    modes take the place of the guides-only yaw mode in the minimum,
    :func:`axisopt.model.gantry.gantry_modes`)."""
    whole = moving if whole is None else whole
    m_eff = pdy.effective_axial_mass(moving, screw_mass, x, p["span"], mounting)
    f_axial = pdy.axial_natural_frequency(chain["k_total"], m_eff)
    f_table = mx.sqrt(p["guide_blocks"] * p["guide_normal_stiffness"] / whole) / (2.0 * math.pi)
    f1 = mx.fmin(f_axial, f_table)
    out = {"m_eff": m_eff, "f_axial": f_axial, "f_table": f_table}
    if rock is not None and single_drive(p):
        f1 = mx.fmin(f1, mx.fmin(rock["f_pitch"], rock["f_yaw"]))
        out.update(
            {k: NO_MODE + 0.0 * chain["k_total"] for k in ("f_gantry", "f_racking", "k_racking")}
        )
    elif rock is not None:
        t = tp(p, "twin")  # a twin drive: its racking takes the place of the guides-only yaw mode
        yaw = rock["f_yaw"] + t * NO_MODE if mx.is_symbolic(t) else NO_MODE
        f1 = mx.fmin(f1, mx.fmin(rock["f_pitch"], yaw))
        gm = gantry_modes(p, chain["k_total"], whole, moving, m_eff, rock["k_yaw"])
        f1 = mx.fmin(f1, gm["f_gantry"])
        out.update(gm)
    out["f1"] = f1
    return out


def drive_inertias(p):
    """(motor side, screw side) rotary inertia [kg*m^2]: rotor plus half the coupling; screw plus
    the other half (a driven rotating nut: the unit's rotating parts instead of the screw)."""
    r = unit(p, "nut_rotating")
    j_screw = (1.0 - r) * ps.screw_rotary_inertia(
        0.5 * (p["nominal_diameter"] + p["root_diameter"]), p["span"]
    ) + r * unit(p, "unit_inertia")
    return p["motor_inertia"] + 0.5 * p["coupling_inertia"], j_screw + 0.5 * p["coupling_inertia"]


def drive_train_modes(p, chain, m_eff) -> dict:
    """First two elastic modes of motor - coupling - screw - table (motor free at these frequencies)
    [Hz]."""
    j_m, j_s = drive_inertias(p)
    f1, f2 = pdy.drive_train_frequencies(
        j_m, j_s, drive_torsional_stiffness(p), chain["k_drive"], m_eff, p["lead"]
    )
    return {"f_axial_torsional": f1, "f_axial_torsional_2": f2}


def dampers(p, chain) -> dict:
    """Viscous dampers of the axial mode referred to the table [N*s/m], each source apart.

    Guide blocks: seed Table 7 (catalog column); nut and support-bearing sets: seed Table 6 by bore,
    each weighted by its share of the chain's deformation
    (:func:`axisopt.physics.damping.chain_damper_share`).
    """
    k = chain["k_total"]
    c_nut = pdm.chain_damper_share(
        pdm.rolling_joint_damping(p["nominal_diameter"]), k, chain["k_nut"]
    )
    # the bearing sets deform by (k / k_bearing) of the table motion (both sets together for
    # fixed-fixed)
    c_brg = pdm.chain_damper_share(
        p["bearing_sets"] * pdm.rolling_joint_damping(p["bearing_bore"]), k, chain["k_bearing"]
    )
    return {"c_guides": p["guide_blocks"] * p["guide_damping"], "c_nut": c_nut, "c_bearings": c_brg}


def damping(p, chain, m_eff) -> dict:
    """Modal damping ratio of the axial mode and each source's part of it [-]."""
    c = dampers(p, chain)
    crit = pdm.critical_damping(m_eff, chain["k_total"])
    out = {f"zeta_{k[2:]}": v / crit for k, v in c.items()}
    out["zeta_structure"] = STEEL_DAMPING + 0.0 * crit
    out["damping_ratio"] = STEEL_DAMPING + (c["c_guides"] + c["c_nut"] + c["c_bearings"]) / crit
    return out
