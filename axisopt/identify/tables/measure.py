r"""Measurement models: what each test measures, as one CasADi expression per data row.

Terms (all SI; ``x`` = fixed bearing to nut, ``L`` = span, ``EA`` = screw section rigidity):

* screw + support bearings, two load paths in parallel (near bearing + screw segment x; far bearing
  ``k_far`` + segment L - x).  ``k_far = 0`` is the design's fixed-free / fixed-supported chain
  ``1/k_B + x/EA`` (seed eq. 1-3); ``k_far = k_B`` is the fixed-fixed arrangement (equal to
  :func:`axisopt.model.axis_response` at mid-span):

  .. math:: c_{SB}(x) = \left[\frac{1}{1/k_B + x/EA} + \frac{k_{far}}{1 + k_{far}(L-x)/EA}\right]^{-1}

* nut: ``1/k_N`` at the design preload (seed eq. 9), or the double-nut Hertz curve when asked;
* static stiffness test: ``delta = F (c_SB + c_extra) + delta_N(F) + offsets``;
* natural frequency: ``f = 1 / (2 pi sqrt(c_total m_eff(x)))`` (m_eff as the axis model);
* frequency response: ``G = 1/(k - m w^2 + 2 i zeta sqrt(k m) w)`` plus any extra modes;
* friction at the table: ``F = sgn(v) (F_c s(cycle) + mu N + k_a |F_a| + Stribeck) + c_v v + c_q
  v|v| + a/2``.

Effects (``effects.py``) change the fields of the :class:`Terms` record before the output is formed.
"""  # noqa: E501

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ... import mathx as mx
from ...physics import nut as pn
from ...physics import screw as ps
from ..fit import Param
from ..levels import cluster_levels
from .data import Dataset

FEATURES = {
    "stiffness": ("x", "force", "direction", "time", "dtemp", "cycle"),
    "friction": ("velocity", "normal", "axial", "x", "cycle", "temperature"),
    "frequency": ("x",),
    "frf": ("x", "omega", "part"),
}
FACTORS = {  # residual tables: column -> display (unit, factor)
    "stiffness": ("position", "force", "direction", "cycle", "time", "temperature"),
    "friction": (
        "velocity",
        "normal_load",
        "axial_load",
        "position",
        "cycle",
        "time",
        "temperature",
    ),
    "frequency": ("position", "mode", "cycle"),
    "frf": ("frequency", "position", "cycle"),
}
# The measured column(s) of each test (what the model predicts).
MEASURED_COLUMNS = {
    "stiffness": ("displacement",),
    "friction": ("friction_force", "drag_torque"),
    "frequency": ("frequency",),
    "frf": ("real", "imag", "magnitude", "phase"),
}
Y_UNIT = {
    "stiffness": ("um", 1e6),
    "friction": ("N", 1.0),
    "frequency": ("Hz", 1.0),
    "frf": ("um/N", 1e6),
}


@dataclass
class Obs:
    """A dataset turned into model rows: features Z (nz x n), measurements y, scale for weights."""

    dataset: Dataset
    kind: str
    Z: np.ndarray
    y: np.ndarray
    scale: np.ndarray
    groups: np.ndarray
    group_name: str
    factors: dict
    sigma_rel: float = 0.01  # noise relative to scale, estimated after the baseline fit
    noise_method: str = ""  # how sigma_rel was estimated (reported)

    @property
    def n(self) -> int:
        return len(self.y)

    @property
    def w(self) -> np.ndarray:
        return 1.0 / (self.sigma_rel * self.scale)

    def feature(self, name: str) -> np.ndarray:
        return self.Z[FEATURES[self.kind].index(name)]


def observations(ds: Dataset, plant) -> Obs:
    c = ds.columns
    n = ds.n
    zeros = np.zeros(n)
    if ds.kind == "stiffness":
        x = plant.nut_x(c["position"])
        f = c["force"]
        direction = c.get("direction", np.sign(f))
        t = c.get("time", zeros)
        dtemp = c["temperature"] - c["temperature"][0] if "temperature" in c else zeros
        Z = np.vstack([x, f, direction, t, dtemp, c.get("cycle", zeros)])
        y = c["displacement"]
        groups, gname = cluster_levels(c["position"], "position"), "position"
    elif ds.kind == "friction":
        if "friction_force" in c:
            y = c["friction_force"]
        else:
            y = c["drag_torque"] * 2.0 * math.pi * plant.efficiency / plant.lead
        normal = plant.weight_on_guides + c.get("normal_load", zeros)
        x = plant.nut_x(c["position"]) if "position" in c else zeros + plant.start_offset
        temp = c.get("temperature", zeros + 293.15)  # [K]; 20 degC when not recorded
        Z = np.vstack(
            [c["velocity"], normal, c.get("axial_load", zeros), x, c.get("cycle", zeros), temp]
        )
        groups, gname = _friction_groups(c)
    elif ds.kind == "frequency":
        Z = plant.nut_x(c["position"])[None, :]
        y = c["frequency"]
        groups, gname = c["position"], "position"
    else:
        x = plant.nut_x(c["position"])
        om = 2.0 * math.pi * c["frequency"]
        Z = np.vstack([np.r_[x, x], np.r_[om, om], np.r_[zeros, zeros + 1.0]])
        y = np.r_[c["real"], c["imag"]]
        mag = np.hypot(c["real"], c["imag"])
        groups, gname = np.r_[c["position"], c["position"]], "position"
        factors = {k: np.r_[c[k], c[k]] for k in FACTORS["frf"] if k in c}
        return Obs(ds, ds.kind, Z, y, np.r_[mag, mag], groups, gname, factors)
    rms = float(np.sqrt(np.mean(y**2))) or 1.0
    scale = np.maximum(np.abs(y), 0.1 * rms)
    factors = {k: c[k] for k in FACTORS[ds.kind] if k in c}
    return Obs(ds, ds.kind, Z, y, scale, groups, gname, factors)


def _friction_groups(c):
    for name in ("normal_load", "axial_load", "temperature", "cycle", "position"):
        if name in c and len(np.unique(lv := cluster_levels(c[name], name))) >= 3:
            return lv, name
    v = np.abs(c["velocity"])
    edges = np.quantile(v, [0.2, 0.4, 0.6, 0.8])
    return np.searchsorted(edges, v, side="right").astype(float), "speed band"


# ---------------------------------------------------------------------------------------------
@dataclass
class Terms:
    """Mutable record of the model pieces that effects may change (symbolic or numeric)."""

    EA: object = None
    c_bearing: object = None
    k_far: object = 0.0
    c_extra: object = 0.0
    preload: object = None
    preload_factor: object = 1.0
    hertz: bool = False
    offset: object = 0.0
    hysteresis: object = 0.0  # friction force causing elastic lost motion [N]
    added_mass: object = 0.0
    damping_ratio: object = 0.05
    modes: list = field(default_factory=list)  # (k, omega_n, zeta)
    coulomb: object = 0.0
    coulomb_factor: object = 1.0
    mu: object = 0.0
    viscous: object = 0.0
    stribeck: object = 0.0
    asymmetry: object = 0.0
    drag: object = 0.0  # quadratic drag coefficient c of c v|v| [N s^2/m^2]
    # nut friction per axial force, 1/eta - 1 [-] (of |axial_load|, sgn v)
    axial_ratio: object = 0.0
    # Coulomb friction change with temperature [N] (already times T - T_ref)
    coulomb_t: object = 0.0


def baseline_params(kinds, plant) -> list:
    """The calibration parameters a test engineer fits, for the test types present."""
    out = []
    if "stiffness" in kinds:
        out.append(
            Param(
                "screw_modulus",
                "screw Young's modulus (screw stiffness scale)",
                "GPa",
                "pressure",
                plant.youngs_modulus,
                5e9,
                2000e9,
                plausible=(0.9 * 206e9, 1.1 * 206e9),
                plausible_note="steel 206 GPa; low values point to unmodelled torsion/coupling",
            )
        )
    if "friction" in kinds:
        out.append(
            Param(
                "coulomb_friction",
                "Coulomb friction of the axis at the table",
                "N",
                "force",
                max(plant.coulomb, 1.0),
                0.0,
                math.inf,
                typical=max(plant.coulomb, 10.0),
                plausible=(0.25 * plant.coulomb, 4.0 * plant.coulomb),
                plausible_note="the catalog drag of nut, bearings and guides within a factor of 4",
            )
        )
    if "frf" in kinds:
        out.append(
            Param(
                "damping_ratio",
                "modal damping ratio of the axial mode",
                "-",
                "dimensionless",
                0.05,
                1e-4,
                1.0,
                typical=0.05,
                plausible=(0.005, 0.2),
            )
        )
    return out


def baseline_terms(plant, P) -> Terms:
    return Terms(
        EA=P.get("screw_modulus", plant.youngs_modulus) * plant.area,
        c_bearing=1.0 / plant.k_bearing,
        k_far=plant.k_far,
        preload=plant.preload,
        damping_ratio=P.get("damping_ratio", 0.05),
        coulomb=P.get("coulomb_friction", plant.coulomb),
        mu=plant.mu,
        viscous=plant.viscous,
    )


def screw_bearing_compliance(q: Terms, x, span):
    """Screw and bearing sets, the axis model's two-path form
    (:func:`axisopt.physics.screw.two_path_stiffness`)."""
    return 1.0 / ps.two_path_stiffness(1.0 / q.c_bearing, q.k_far, q.EA, x, span)


def drive_compliance(plant, x):
    """Compliance in the chain besides screw tension, bearings and nut, as the axis model has it:
    screw torsion through the lead up to the nut, nut bracket, coupling [m/N]."""
    tors = 0.0
    if plant.torsion:
        tors = 1.0 / ps.torsion_axial_stiffness(
            ps.screw_torsional_stiffness(plant.root_diameter, x), plant.lead
        )
    return plant.c_series + tors


def nut_k0(q: Terms, plant):
    ratio = q.preload * q.preload_factor / plant.preload
    return plant.k_nut * mx.cbrt(ratio)


def double_nut_deflection(force, preload, k0):
    r"""Axial deflection of a preloaded double nut under external load, with lift-off.

    Each half deflects as delta_i = C F_i^(2/3); F_1 - F_2 = F, common shift u = s delta_0:

    .. math:: (1+s)^{3/2} - (1-s)_+^{3/2} = |F|/F_{a0},\qquad \delta = \mathrm{sgn}(F)\, s\, 3F_{a0}/k_0

    (k_0 = 3 F_a0 / delta_0 is the stiffness at zero load).  Lift-off at |F| = 2^{3/2} F_a0.  The
    shift s is :func:`axisopt.physics.nut.double_nut_shift`, as in the axis model's double-nut
    stiffness. force [N], preload F_a0 [N], k0 [N/m]; returns [m].
    """  # noqa: E501
    s = pn.double_nut_shift(mx.fabs(force) / preload)
    return mx.sign(force) * s * 3.0 * preload / k0


def output(kind: str, q: Terms, Z: dict, plant):
    """The predicted measurement of one row from the (possibly modified) terms."""
    if kind == "friction":
        v = Z["velocity"]
        return (
            mx.sign(v)
            * (
                q.coulomb * q.coulomb_factor
                + q.mu * Z["normal"]
                + q.stribeck
                + q.coulomb_t
                + q.axial_ratio * mx.fabs(Z["axial"])
            )
            + q.viscous * v
            + q.drag * v * mx.fabs(v)
            + 0.5 * q.asymmetry
        )
    x = Z["x"]
    c_sb = screw_bearing_compliance(q, x, plant.span) + drive_compliance(plant, x)
    k0 = nut_k0(q, plant)
    if kind == "stiffness":
        f = Z["force"]
        d_nut = double_nut_deflection(f, q.preload * q.preload_factor, k0) if q.hertz else f / k0
        c_tot = c_sb + q.c_extra + 1.0 / k0
        return f * (c_sb + q.c_extra) + d_nut + q.offset - Z["direction"] * q.hysteresis * c_tot
    c_tot = c_sb + q.c_extra + 1.0 / k0
    m = plant.m_eff(x) + q.added_mass
    if kind == "frequency":
        return 1.0 / (2.0 * math.pi * mx.sqrt(c_tot * m))
    om = Z["omega"]
    k = 1.0 / c_tot
    re, im = _mode(k - m * om**2, 2.0 * q.damping_ratio * mx.sqrt(k * m) * om)
    for km, wn, zeta in q.modes:
        r2, i2 = _mode(km * (1.0 - (om / wn) ** 2), 2.0 * km * zeta * om / wn)
        re, im = re + r2, im + i2
    return mx.if_else(Z["part"] < 0.5, re, im)


def _mode(a, b):
    d = a * a + b * b
    return a / d, -b / d
