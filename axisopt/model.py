"""The feed-axis model: physics assembled for an axis and its chosen parts.

``axis_response(p, x, mounting)`` is one pure function.  ``p`` maps the names in
:data:`PARAM_NAMES` to floats, numpy arrays (one entry per candidate design; they broadcast
against the positions ``x``) or CasADi symbols.  The same function therefore

* evaluates one design on floats,
* screens millions of catalog combinations at once on numpy arrays (``search``), and
* builds the symbolic CasADi Function of :class:`AxisModel` that IPOPT differentiates.

Component stiffness chain (seed eq. 1-2): ``1/k = 1/k_B + 1/k_S(x) + 1/k_N`` with ``k_B`` the
support bearings acting on the screw (both ends in parallel for fixed-fixed), ``k_S`` the screw
shaft between the bearing and the nut (eq. 3-5, 10), ``k_N`` the nut at its preload (eq. 9).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from . import mathx as mx
from .design import Design, G
from .physics import bearings as pb
from .physics import checks as pc
from .physics import damping as pdm
from .physics import dynamics as pdy
from .physics import guides as pg
from .physics import nut as pn
from .physics import screw as ps

# Efficiency of the ball screw used to refer guide friction to the motor (vendor typical 0.9).
SCREW_EFFICIENCY = 0.9
# Material damping ratio of steel structures, seed Table 5 (0.001-0.002).
STEEL_DAMPING = 0.002

PARAM_NAMES = (
    # axis
    "stroke", "start_offset", "span", "table_mass", "acceleration", "max_speed", "mean_speed",
    "axial_load", "mean_axial_load", "required_life", "load_factor", "guide_blocks", "rails",
    "rail_length", "normal_load", "viscosity", "motor_inertia", "bearing_sets", "gravity_axial",
    # screw
    "root_diameter", "nominal_diameter", "lead", "screw_max_length", "screw_mass_per_length",
    "dn_limit", "screw_price_per_length", "screw_price_fixed",
    # nut
    "nut_stiffness", "nut_stiffness_preload", "nut_double", "nut_dynamic_load", "nut_static_load",
    "nut_mass", "nut_price", "nut_preload_min", "nut_preload_max",
    # bearing arrangement (per screw end)
    "bearing_stiffness", "bearing_lift_off", "bearing_preload", "bearing_f0", "bearing_f1",
    "bearing_mean_diameter", "bearing_limiting_speed", "bearing_mass", "bearing_price",
    "bearing_dynamic_load", "bearing_bore",
    # guide block and rail
    "guide_normal_stiffness", "guide_tangential_stiffness", "guide_friction_force",
    "guide_friction_coefficient", "guide_friction_viscous", "guide_damping", "guide_block_mass",
    "guide_rail_mass_per_length", "guide_block_price", "guide_rail_price_per_length", "guide_dynamic_load",
    "guide_preload", "guide_roller",
)

CHECKS = ("critical_speed", "buckling", "nut_life", "guide_life", "dn", "nut_lift_off", "bearing_lift_off",
          "bearing_speed", "bearing_fit", "screw_length")

CHECK_LABELS = {
    "critical_speed": "critical speed / max screw speed",
    "buckling": "buckling load / max axial force",
    "nut_life": "nut L10 life / required life",
    "guide_life": "guide block L10 travel / required travel",
    "dn": "DN limit / DN at max speed",
    "nut_lift_off": "nut lift-off force / max axial force",
    "bearing_lift_off": "bearing lift-off load / max axial force",
    "bearing_speed": "bearing limiting speed / max screw speed",
    "bearing_fit": "screw root diameter / bearing bore",
    "screw_length": "screw max length / needed length",
}


def axis_params(axis, screw, nut, bearing, guide) -> dict:
    """Flat SI parameter dict for :func:`axis_response` from an Axis and four part rows.

    Part rows may be pandas Series (one design) or DataFrames / dicts of arrays (many designs).
    """
    col = _getter
    mounting = axis.mounting
    p = {
        "stroke": axis.stroke, "start_offset": axis.start_offset, "span": axis.span,
        "table_mass": axis.moving_mass, "acceleration": axis.acceleration, "max_speed": axis.max_speed,
        "mean_speed": axis.mean_speed_eff, "axial_load": axis.axial_load,
        "mean_axial_load": axis.mean_axial_load_eff, "required_life": axis.required_life,
        "load_factor": axis.load_factor, "guide_blocks": float(axis.guide_blocks), "rails": float(axis.rails),
        "rail_length": axis.stroke + axis.table_length, "normal_load": axis.normal_load,
        "viscosity": axis.lubricant_viscosity, "motor_inertia": axis.motor_inertia,
        "bearing_sets": 2.0 if mounting == "fixed-fixed" else 1.0,
        "gravity_axial": 1.0 if axis.orientation == "vertical" else 0.0,
        "root_diameter": col(screw, "root_diameter"), "nominal_diameter": col(screw, "nominal_diameter"),
        "lead": col(screw, "lead"), "screw_max_length": col(screw, "max_length"),
        "screw_mass_per_length": col(screw, "mass_per_length"), "dn_limit": col(screw, "dn_limit"),
        "screw_price_per_length": col(screw, "price_per_length"), "screw_price_fixed": col(screw, "price_fixed"),
        "nut_stiffness": col(nut, "stiffness"), "nut_stiffness_preload": col(nut, "stiffness_preload"),
        "nut_double": _is_type(nut, "double"), "nut_dynamic_load": col(nut, "dynamic_load_rating"),
        "nut_static_load": col(nut, "static_load_rating"), "nut_mass": col(nut, "mass"),
        "nut_price": col(nut, "price"), "nut_preload_min": col(nut, "preload_min"),
        "nut_preload_max": col(nut, "preload_max"),
        "bearing_stiffness": col(bearing, "axial_rigidity"), "bearing_lift_off": col(bearing, "lift_off_load"),
        "bearing_preload": col(bearing, "preload"), "bearing_f0": col(bearing, "f0"),
        "bearing_f1": col(bearing, "f1"),
        "bearing_mean_diameter": 0.5 * (col(bearing, "bore") + col(bearing, "outer_diameter")),
        "bearing_limiting_speed": col(bearing, "limiting_speed"), "bearing_mass": col(bearing, "mass"),
        "bearing_price": col(bearing, "price"), "bearing_dynamic_load": col(bearing, "dynamic_load_rating"),
        "bearing_bore": col(bearing, "bore"),
        "guide_normal_stiffness": col(guide, "normal_rigidity"),
        "guide_tangential_stiffness": col(guide, "tangential_rigidity"),
        "guide_friction_force": col(guide, "friction_force"),
        "guide_friction_coefficient": col(guide, "friction_coefficient"),
        "guide_friction_viscous": col(guide, "friction_viscous"), "guide_damping": col(guide, "damping"),
        "guide_block_mass": col(guide, "block_mass"),
        "guide_rail_mass_per_length": col(guide, "rail_mass_per_length"),
        "guide_block_price": col(guide, "block_price"),
        "guide_rail_price_per_length": col(guide, "rail_price_per_length"),
        "guide_dynamic_load": col(guide, "dynamic_load_rating"),
        "guide_preload": col(guide, "preload"),
        "guide_roller": _is_type(guide, "roller"),
    }
    return p


def _getter(row, name):
    v = row[name]
    return float(v) if np.ndim(v) == 0 else np.asarray(v, dtype=float)


def _is_type(row, value):
    """1.0 where the part's ``type`` column is ``value`` (one part or an array of parts)."""
    t = row["type"]
    if isinstance(t, str):
        return 1.0 if t == value else 0.0
    return (np.asarray(t) == value).astype(float)


def positions(axis, n: int | None = None) -> np.ndarray:
    """Nut positions x (fixed bearing to nut) [m] over the stroke: an even grid plus, for
    fixed-fixed, the mid-span point where the screw is softest (when it lies on the stroke)."""
    n = n or axis.positions
    x = axis.start_offset + np.linspace(0.0, axis.stroke, n)
    if axis.mounting == "fixed-fixed":
        mid = 0.5 * axis.span
        if axis.start_offset < mid < axis.start_offset + axis.stroke:
            x = np.unique(np.append(x, mid))
    return x


def nut_life_load(preload, axial_load, double):
    r"""Load the loaded half of a preloaded double nut carries (ISO 3408-5 / Steinmeyer form).

    .. math:: F_1 = F_{pr}\,(1 + F/(2^{3/2} F_{pr}))^{3/2}\ \text{for}\ F < 2^{3/2}F_{pr},\ F_1 = F\ \text{above}

    preload [N], axial_load [N] (mean), double: 1 for a preloaded double nut, 0 for a single nut.
    Source: Steinmeyer technical pages ("expressions and definitions"), mechanixcalc (ISO 3408-5).
    """
    lift = 2.0**1.5 * mx.fmax(preload, 1e-9)
    f1 = mx.fmax(preload, 1e-9) * (1.0 + mx.fmin(axial_load, lift) / lift) ** 1.5
    loaded = mx.if_else(axial_load < lift, f1, axial_load)
    return double * loaded + (1.0 - double) * mx.fmax(axial_load, 1e-9)


def axis_response(p: dict, x, mounting: str, preload, extras: bool = True) -> dict:
    """Evaluate the axis model.  See module docstring.

    p        : dict of :data:`PARAM_NAMES` -> float / ndarray / CasADi
    x        : nut positions, fixed bearing to nut [m]
    mounting : 'fixed-free' | 'fixed-supported' | 'fixed-fixed'
    preload  : nut preload [N] (float / ndarray / CasADi)
    extras   : also compute the axial-torsional frequency and the damping ratio (screening skips them)
    Returns a dict: per-position arrays (``k_screw``, ``k_total``, ``f_axial``, ``f1``),
    per-design scalars (``k_nut``, ``k_bearing``, ``f_table``, ``drag_torque``, masses, ``cost``)
    and ``margin_<check>`` for each of :data:`CHECKS` (>= 1 passes).
    """
    span = p["span"]
    # --- stiffness chain (N/m)
    k_s = ps.screw_stiffness(p["root_diameter"], x, span, mounting)
    # eq. 9 at the preload for a double nut; a single nut keeps its catalog value (quoted at 0.3 Ca axial
    # load, no preload to speak of), so its stiffness does not depend on the preload variable
    nut_load = mx.if_else(p["nut_double"] > 0.5, preload, p["nut_stiffness_preload"])
    k_n = pn.nut_stiffness_catalog(p["nut_stiffness"], nut_load, p["nut_dynamic_load"],
                                   reference_preload=p["nut_stiffness_preload"])
    k_b = p["bearing_sets"] * p["bearing_stiffness"]
    k_tot = 1.0 / (1.0 / k_b + 1.0 / k_s + 1.0 / k_n)

    # --- masses (kg)
    screw_mass = p["screw_mass_per_length"] * span
    blocks = p["guide_blocks"]
    moving = p["table_mass"] + p["nut_mass"] + blocks * p["guide_block_mass"]
    rails_mass = p["rails"] * p["rail_length"] * p["guide_rail_mass_per_length"]
    total_mass = moving + screw_mass + rails_mass + p["bearing_sets"] * p["bearing_mass"]

    # --- natural frequencies (Hz).  Rayleigh: the strained screw segment adds a third of its
    # mass; for fixed-free / fixed-supported the part beyond the nut moves with the nut.
    m_eff = pdy.effective_axial_mass(moving, screw_mass, x, span, mounting)
    f_axial = pdy.axial_natural_frequency(k_tot, m_eff)
    f_table = mx.sqrt(blocks * p["guide_normal_stiffness"] / moving) / (2.0 * math.pi)
    f1 = mx.fmin(f_axial, f_table)
    # axial-torsional 2-DOF (rotor + screw inertia on the screw's torsional stiffness up to the nut,
    # motor held by the servo), and the modal damping ratio of the axial mode from the guide blocks
    # (seed Table 7) and steel structure (Table 5, 0.002)
    out_extra = {}
    if extras:
        j_rot = p["motor_inertia"] + ps.screw_rotary_inertia(0.5 * (p["nominal_diameter"] + p["root_diameter"]), span)
        k_tor = ps.screw_torsional_stiffness(p["root_diameter"], x)
        f_coupled, _ = pdy.axial_torsional_frequencies(j_rot, k_tor, k_tot, m_eff, p["lead"])
        zeta = pdm.modal_damping_ratio(m_eff, k_tot, blocks * p["guide_damping"], structural_ratio=STEEL_DAMPING)
        out_extra = {"f_axial_torsional": f_coupled, "damping_ratio": zeta}

    # --- drag torque at the motor at max speed (N*m)
    omega = 2.0 * math.pi * p["max_speed"] / p["lead"]
    t_nut = p["nut_double"] * pn.nut_preload_drag_torque(preload, p["lead"], p["nominal_diameter"])
    t_brg = p["bearing_sets"] * pb.bearing_friction_torque(
        p["bearing_f0"], p["bearing_f1"], p["viscosity"], omega, p["bearing_mean_diameter"],
        p["bearing_preload"])
    n_block = (p["table_mass"] * G * (1.0 - p["gravity_axial"]) + p["normal_load"]) / blocks
    f_guides = blocks * pg.guide_friction_force(
        p["guide_friction_force"], p["guide_friction_coefficient"], p["guide_friction_viscous"],
        n_block, p["max_speed"])
    t_guides = f_guides * p["lead"] / (2.0 * math.pi * SCREW_EFFICIENCY)
    drag = t_nut + t_brg + t_guides

    # --- cost (EUR)
    n_bear = p["bearing_sets"]
    cost = (p["screw_price_per_length"] * span + p["screw_price_fixed"] + p["nut_price"]
            + n_bear * p["bearing_price"] + blocks * p["guide_block_price"]
            + p["rails"] * p["rail_length"] * p["guide_rail_price_per_length"])

    # --- checks (margins, >= 1 passes)
    gravity = p["gravity_axial"] * moving * G
    f_max = p["axial_load"] + moving * p["acceleration"] + f_guides + gravity
    x_far = p["start_offset"] + p["stroke"]
    crit = pc.critical_speed(p["root_diameter"], span, mounting)
    buck_len = x_far if mounting != "fixed-fixed" else mx.fmax(x_far, span - p["start_offset"])
    buck = pc.buckling_load(p["root_diameter"], buck_len, mounting)
    mean_omega = 2.0 * math.pi * p["mean_speed"] / p["lead"]
    f_mean = p["mean_axial_load"] + f_guides + gravity
    life = pc.life_time(p["nut_dynamic_load"], nut_life_load(preload, f_mean, p["nut_double"]),
                        mean_omega, p["load_factor"])
    # guide blocks: the load per block with the block preload acting like a preloaded pair of ball rows
    # (same law as the double nut), against the travel the required life asks for at the mean speed
    guide_load = nut_life_load(p["guide_preload"], n_block, 1.0)
    guide_life = pc.guide_life_distance(p["guide_dynamic_load"], guide_load, p["load_factor"], p["guide_roller"])
    dn = pc.dn_value(p["nominal_diameter"], omega)
    lift = pn.lift_off_force(mx.fmax(preload, 1e-9))
    margins = {
        "critical_speed": crit / omega,
        "buckling": buck / f_max,
        "nut_life": life / p["required_life"],
        "guide_life": guide_life / (p["required_life"] * p["mean_speed"]),
        "dn": p["dn_limit"] / dn,
        # a single nut has no preload to lose: the check does not apply (margin reported as inf)
        "nut_lift_off": mx.if_else(p["nut_double"] > 0.5, lift / f_max, 1e9),
        "bearing_lift_off": p["bearing_lift_off"] / f_max,
        "bearing_speed": p["bearing_limiting_speed"] / omega,
        # the bearing journal is turned from the screw: its bore must not exceed the root diameter
        "bearing_fit": p["root_diameter"] / p["bearing_bore"],
        "screw_length": p["screw_max_length"] / span,
    }
    out = {
        "k_screw": k_s, "k_nut": k_n, "k_bearing": k_b, "k_total": k_tot,
        "f_axial": f_axial, "f_table": f_table, "f1": f1, "m_eff": m_eff,
        "drag_torque": drag, "drag_nut": t_nut, "drag_bearings": t_brg, "drag_guides": t_guides,
        "moving_mass": moving, "total_mass": total_mass, "screw_mass": screw_mass, "cost": cost,
        "max_axial_force": f_max, "life": life, "screw_speed": omega,
    }
    out.update({f"margin_{k}": v for k, v in margins.items()})
    out.update(out_extra)
    return out


SCALAR_OUTPUTS = ("k_nut", "k_bearing", "f_table", "drag_torque", "drag_nut", "drag_bearings",
                  "drag_guides", "moving_mass", "total_mass", "screw_mass", "cost", "max_axial_force",
                  "life", "screw_speed") + tuple(f"margin_{c}" for c in CHECKS)
PROFILE_OUTPUTS = ("k_screw", "k_total", "f_axial", "f1", "m_eff", "f_axial_torsional", "damping_ratio")


@dataclass
class AxisModel:
    """One CasADi Function for a mounting: ``f(params, preload, x) -> outputs``, built once.

    ``params`` is the vector of :data:`PARAM_NAMES` values, ``preload`` the nut preload [N] and
    ``x`` a column of nut positions.  Profile outputs are columns the length of ``x``; scalar
    outputs are 1x1.  ``AxisModel.for_design(design)`` binds a design's parameters.
    """

    mounting: str
    n_positions: int
    function: ca.Function

    @classmethod
    def build(cls, mounting: str, n_positions: int) -> AxisModel:
        prm = ca.SX.sym("params", len(PARAM_NAMES))
        pre = ca.SX.sym("preload")
        x = ca.SX.sym("x", n_positions)
        p = {name: prm[i] for i, name in enumerate(PARAM_NAMES)}
        out = axis_response(p, x, mounting, pre)
        names = list(PROFILE_OUTPUTS) + list(SCALAR_OUTPUTS)
        exprs = [out[n] if out[n].shape[0] == n_positions or n not in PROFILE_OUTPUTS
                 else out[n] * ca.DM.ones(n_positions) for n in names]
        f = ca.Function(f"axis_{mounting.replace('-', '_')}", [prm, pre, x], exprs,
                        ["params", "preload", "x"], names)
        return cls(mounting, n_positions, f)

    def __call__(self, params: dict, preload: float, x) -> dict:
        vec = np.array([float(params[n]) for n in PARAM_NAMES])
        res = self.function(params=vec, preload=preload, x=np.asarray(x, dtype=float))
        out = {}
        for n in PROFILE_OUTPUTS:
            out[n] = np.asarray(res[n]).ravel()
        for n in SCALAR_OUTPUTS:
            out[n] = float(res[n])
        return out


_MODELS: dict[tuple, AxisModel] = {}


def model_for(mounting: str, n_positions: int) -> AxisModel:
    """Cached :meth:`AxisModel.build` (one Function per mounting and grid size)."""
    key = (mounting, n_positions)
    if key not in _MODELS:
        _MODELS[key] = AxisModel.build(mounting, n_positions)
    return _MODELS[key]


def design_params(design: Design) -> dict:
    return axis_params(design.axis, design.screw, design.nut, design.bearing, design.guide)


@dataclass(frozen=True)
class Evaluation:
    """A design evaluated over the stroke (SI)."""

    design: Design
    x: np.ndarray
    values: dict

    def __getitem__(self, key):
        return self.values[key]

    @property
    def weakest(self) -> str:
        """The component with the lowest stiffness at the position of minimum total stiffness."""
        i = int(np.argmin(self.values["k_total"]))
        comps = {"screw": self.values["k_screw"][i], "nut": self.values["k_nut"],
                 "bearings": self.values["k_bearing"]}
        return min(comps, key=comps.get)

    def minimum(self, key: str) -> tuple[float, float]:
        """(minimum value, nut position where it occurs, measured from stroke start) for a profile."""
        v = np.asarray(self.values[key])
        i = int(np.argmin(v))
        return float(v[i]), float(self.x[i] - self.design.axis.start_offset)

    def checks(self) -> dict:
        return {c: float(self.values[f"margin_{c}"]) for c in CHECKS}


def evaluate(design: Design, n_positions: int | None = None, *, use_casadi: bool = True) -> Evaluation:
    """Evaluate a design with the CasADi axis Function (or directly on numpy with use_casadi=False)."""
    x = positions(design.axis, n_positions)
    params = design_params(design)
    if use_casadi:
        values = model_for(design.axis.mounting, len(x))(params, design.preload, x)
    else:
        raw = axis_response(params, x, design.axis.mounting, design.preload)
        values = {k: (np.broadcast_to(np.asarray(v, float), x.shape).copy() if k in PROFILE_OUTPUTS
                      else float(v)) for k, v in raw.items()}
    return Evaluation(design, x, values)
