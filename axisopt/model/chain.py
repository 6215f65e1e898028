r"""The axial stiffness chain at the nut, component by component (seed eq. 1-2 and the vendors'
sum).

.. math:: 1/k = 1/k_{SB}(x) + 1/k_{tors}(x) + 1/k_{cpl} + 1/k_N + r/k_{unit} + 1/k_{bracket}

* ``k_SB``: screw shaft and support-bearing sets (each in series with its housing).  One fixed end:
  set in series with the segment x.  Fixed-fixed: the two load paths in parallel (seed eq. 3-5, 10;
  THK A E L/(a b)).
* ``k_tors``: screw torsion from the coupling to the nut, through the lead, k_theta (2 pi / P_h)^2.
* ``k_cpl``: coupling torsion through the lead (motor held by its position loop at standstill), with
  a reduction's output-side torsional stiffness in series (:func:`drive_torsional_stiffness`).
* ``k_N``: nut.  Double nut: eq. 9 at the preload (HIWIN F 3.34), then the Hertz curve with lift-off
  at the largest axial load the axis sees (its softest point).  Single nut with play: HIWIN F 3.35
  at the mean operating load, 0.8 K (F_bm / 0.28 C)^(1/3).
* ``k_unit``: a driven rotating nut's built-in support bearing (its vendor's rigidity, else the
  estimate of :func:`axisopt.model.params.rotating_nut_params`), between the nut and its housing: in
  series (THK A-709 sums the nut's and the support bearing's compliances the same way); absent (0
  compliance) for a nut on a turning screw.  The screw's torsion stays in the chain: the stationary
  screw is held against the nut's torque at its end, and its twist between there and the nut turns
  the nut relative to the thread as a turning screw's would.
* ``k_bracket``: nut bracket; ``k_SB`` includes the bearing housings (axis values, else the
  estimates of :func:`axisopt.model.params.mount_compliances`).

``k_drive`` is the chain without the coupling: the spring between the screw and the table in the
drive-train model (:func:`axisopt.physics.dynamics.drive_train_eigenvalues`).
"""

from __future__ import annotations

from .. import mathx as mx
from ..physics import nut as pn
from ..physics import screw as ps
from ..physics import thermal as pt
from .loads import bearing_set_stiffness, unit


def drive_torsional_stiffness(p):
    r"""Torsional stiffness between the motor side and the screw [N m/rad]: the coupling and the
    reduction's output side in series (both on the screw side of the ratio),
    :math:`1/k_\theta = 1/k_{cpl} + 1/C_{t21}`.

    p["coupling_stiffness"] [N m/rad]; p["reduction_compliance"] = 1 / Ct21 [rad/(N m)], 0 without a
    reduction (Beckhoff AG2400/AG3400 "Maximum torsional rigidity Ct21 [Nm/arcmin]", output side).
    Series springs: the seed paper's eq. 1 for the axial chain, the same rule for torsion."""
    return 1.0 / (1.0 / p["coupling_stiffness"] + p["reduction_compliance"])


def nut_stiffness(p, preload, axial_force, mean_force):
    """(k at zero external load, k at ``axial_force``) [N/m] of the nut, double or single.

    A single nut with play is rated at the mean operating load (HIWIN F 3.35: 0.8 K (F_bm / 0.28
    C)^(1/3), the catalog's ``stiffness_preload`` holding the 0.28 C basis)."""
    single_load = mx.fmax(mean_force, 1e-6)
    load = mx.if_else(p["nut_double"] > 0.5, preload, single_load)
    k0 = pn.nut_stiffness_catalog(
        p["nut_stiffness"],
        load,
        p["nut_dynamic_load"],
        reference_preload=p["nut_stiffness_preload"],
    )
    k_loaded = pn.double_nut_stiffness_under_load(k0, mx.fmax(preload, 1e-9), axial_force)
    return k0, mx.if_else(p["nut_double"] > 0.5, k_loaded, k0)


def stiffness_chain(p, x, mounting, preload, axial_force, mean_force) -> dict:
    """Component stiffnesses [N/m] (profiles over x where they depend on it) and their series
    sum."""
    d_r, lead = p["root_diameter"], p["lead"]
    k_set = bearing_set_stiffness(p)
    k_sb = ps.screw_bearing_stiffness(d_r, x, p["span"], mounting, k_set)
    k_screw = ps.screw_stiffness(d_r, x, p["span"], mounting)
    k_tors = ps.torsion_axial_stiffness(ps.screw_torsional_stiffness(d_r, x), lead)
    k_cpl = ps.torsion_axial_stiffness(drive_torsional_stiffness(p), lead)
    k_n0, k_n = nut_stiffness(p, preload, axial_force, mean_force)
    # a driven rotating nut: the unit's built-in bearing between the nut and its housing on the
    # table, in series
    k_unit, c_unit = unit(p, "unit_bearing_stiffness"), unit(p, "nut_rotating")
    c_unit = c_unit / k_unit
    k_drive = 1.0 / (1.0 / k_sb + 1.0 / k_tors + 1.0 / k_n + c_unit + p["bracket_compliance"])
    k_tot = ps.series_stiffness(k_drive, k_cpl)
    u_th = pt.thermal_displacement(
        x, p["span"], d_r, p["temperature_rise"], k_set, p["bearing_sets"] - 1.0
    )
    # largest thermal growth at the nut over the stroke: u is linear in x, so at one of the stroke's
    # ends
    ends = [
        mx.fabs(
            pt.thermal_displacement(
                xe, p["span"], d_r, p["temperature_rise"], k_set, p["bearing_sets"] - 1.0
            )
        )
        for xe in (p["start_offset"], p["start_offset"] + p["stroke"])
    ]
    return {
        "k_screw": k_screw,
        "k_screw_bearings": k_sb,
        "k_torsion": k_tors,
        "k_coupling": k_cpl,
        "k_nut": k_n,
        "k_nut_unloaded": k_n0,
        "c_bracket": p["bracket_compliance"] + 0.0 * k_n,
        "c_housing": p["housing_compliance"] + 0.0 * k_n,
        "c_unit_bearing": c_unit + 0.0 * k_n,
        "k_bearing": p["bearing_sets"] * k_set,
        "k_drive": k_drive,
        "k_total": k_tot,
        "thermal_displacement": u_th,
        "thermal_growth": mx.fmax(ends[0], ends[1]),
    }
