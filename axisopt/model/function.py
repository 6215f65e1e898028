"""The CasADi Function of the axis model and the evaluation of one design."""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..design import Design
from .checks import CHECKS
from .params import PARAM_NAMES, axis_params, positions
from .response import axis_response

PROFILE_OUTPUTS = ("k_screw", "k_screw_bearings", "k_torsion", "k_drive", "k_total", "f_axial", "f1", "m_eff",
                   "thermal_displacement", "f_axial_torsional", "f_axial_torsional_2", "damping_ratio",
                   "zeta_guides", "zeta_nut", "zeta_bearings", "zeta_structure")
SCALAR_OUTPUTS = ("k_nut", "k_nut_unloaded", "k_bearing", "k_coupling", "c_bracket", "c_housing", "f_table",
                  "drag_torque", "drag_nut", "drag_bearings", "drag_guides", "moving_mass", "total_mass",
                  "screw_mass", "cost",
                  "max_axial_force", "mean_axial_force", "guide_friction", "pretension", "thermal_force",
                  "bearing_static_load", "screw_compression", "backlash", "life", "bearing_life", "guide_life",
                  "screw_speed", "critical_speed", "buckling_load", "yield_load", "dn", "nut_lift_off_force",
                  "bearing_max_load", "load_inertia", "total_inertia", "inertia_ratio", "motor_speed", "peak_torque",
                  "rms_torque", "thrust_torque", "mean_thrust_torque", "holding_torque", "friction_torque",
                  "gravity_torque",
                  "duty_time", "friction_power", "heat_transfer", "heat_balance_rise", "temperature_rise",
                  "thermal_growth") + tuple(f"{w}_{c}" for w in ("margin", "available", "needed") for c in CHECKS)


@dataclass
class AxisModel:
    """One CasADi Function for a mounting: ``f(params, preload, x) -> outputs``, built once.

    ``params`` is the vector of :data:`PARAM_NAMES` values, ``preload`` the nut preload [N] and
    ``x`` a column of nut positions.  Profile outputs are columns the length of ``x``; scalar
    outputs are 1x1.
    """

    mounting: str
    n_positions: int
    function: ca.Function
    duty: tuple = ()

    @classmethod
    def build(cls, mounting: str, n_positions: int, duty: tuple = ()) -> AxisModel:
        """``duty``: the axis's duty-cycle phases (the cycle is built into the Function)."""
        prm = ca.SX.sym("params", len(PARAM_NAMES))
        pre = ca.SX.sym("preload")
        x = ca.SX.sym("x", n_positions)
        p = {name: prm[i] for i, name in enumerate(PARAM_NAMES)}
        p["duty"] = duty
        out = axis_response(p, x, mounting, pre)
        names = list(PROFILE_OUTPUTS) + list(SCALAR_OUTPUTS)
        exprs = []
        for n in names:
            e = ca.SX(out[n])
            if n in PROFILE_OUTPUTS and e.shape[0] != n_positions:
                e = e * ca.DM.ones(n_positions)
            exprs.append(e)
        f = ca.Function(f"axis_{mounting.replace('-', '_')}", [prm, pre, x], exprs,
                        ["params", "preload", "x"], names)
        return cls(mounting, n_positions, f, duty)

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


def model_for(mounting: str, n_positions: int, duty: tuple = ()) -> AxisModel:
    """Cached :meth:`AxisModel.build` (one Function per mounting, grid size and duty cycle)."""
    key = (mounting, n_positions, duty)
    if key not in _MODELS:
        if len(_MODELS) > 64:
            _MODELS.clear()
        _MODELS[key] = AxisModel.build(mounting, n_positions, duty)
    return _MODELS[key]


def design_params(design: Design) -> dict:
    return axis_params(design.axis, design.screw, design.nut, design.bearing, design.guide, design.motor,
                       design.coupling)


COMPONENTS = (("bearings", "k_bearing"), ("screw", "k_screw"), ("screw torsion", "k_torsion"),
              ("coupling", "k_coupling"), ("nut", "k_nut"), ("nut bracket", "c_bracket"))


@dataclass(frozen=True)
class Evaluation:
    """A design evaluated over the stroke (SI)."""

    design: Design
    x: np.ndarray
    values: dict

    def __getitem__(self, key):
        return self.values[key]

    def at(self, key: str, i: int) -> float:
        v = np.asarray(self.values[key])
        return float(v) if v.ndim == 0 else float(v[i])

    @property
    def i_min(self) -> int:
        """Index of the position of minimum total stiffness."""
        return int(np.argmin(self.values["k_total"]))

    def components(self, i: int | None = None) -> dict:
        """Component stiffness [N/m] at position index ``i`` (default: where the total is lowest).

        For fixed-fixed, 'bearings' and 'screw' are each with the other rigid (the two load paths combine
        them in parallel, see ``k_screw_bearings``).
        """
        i = self.i_min if i is None else i
        out = {}
        for name, key in COMPONENTS:
            v = self.at(key, i)
            if key.startswith("c_"):  # given as compliance: 0 is rigid
                v = 1.0 / v if v > 0 else float("inf")
            out[name] = v
        return out

    @property
    def weakest(self) -> str:
        """The component with the lowest stiffness at the position of minimum total stiffness."""
        comps = self.components()
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
        values = model_for(design.axis.mounting, len(x), design.axis.phases)(params, design.preload, x)
    else:
        raw = axis_response(params, x, design.axis.mounting, design.preload)
        values = {k: (np.broadcast_to(np.asarray(v, float), x.shape).copy() if k in PROFILE_OUTPUTS
                      else float(v)) for k, v in raw.items() if k not in ("duty_torques", "zone_factors")}
    return Evaluation(design, x, values)
