"""The CasADi Function of the axis model and the evaluation of one design."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import casadi as ca
import numpy as np

from ..design import Design, rotating_nut
from ..display import fmt, frame, html_fields, html_table, one_line
from .checks import CHECK_LABELS, CHECKS, DRIVE_CHECKS, passes
from .limits import CHECK_RECORDS, margin_output
from .outputs import PROFILE, SCALAR
from .paramnames import PARAM_NAMES
from .params import axis_params, positions
from .response import axis_response

# the CasADi Function's outputs, in order: the declared outputs (model.outputs.OUTPUT_TABLE), then
# each vendor check's margin, available and needed values (model.limits.CHECK_TABLE)
PROFILE_OUTPUTS = PROFILE
SCALAR_OUTPUTS = SCALAR + tuple(
    f"{w}_{c}" for w in ("margin", "available", "needed") for c in CHECKS
)


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
        f = ca.Function(
            f"axis_{mounting.replace('-', '_')}",
            [prm, pre, x],
            exprs,
            ["params", "preload", "x"],
            names,
        )
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
    return axis_params(
        design.axis,
        design.screw,
        design.nut,
        design.bearing,
        design.guide,
        design.motor,
        design.coupling,
        design.reduction,
        grade=design.grade,
    )


COMPONENTS = (
    ("bearings", "k_bearing"),
    ("screw", "k_screw"),
    ("screw torsion", "k_torsion"),
    ("coupling", "k_coupling"),
    ("nut", "k_nut"),
    ("unit bearing", "c_unit_bearing"),
    ("nut bracket", "c_bracket"),
)


@dataclass(frozen=True, repr=False)
class Evaluation:
    """A design evaluated over the stroke (SI)."""

    design: Design
    # nut positions of the model grid [m] (the stroke starts at design.axis.start_offset)
    x: np.ndarray
    # model output name -> value or profile over ``x``, in SI (k_total in N/m, f1 in Hz, ...)
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

        For fixed-fixed, 'bearings' and 'screw' are each with the other rigid (the two load paths
        combine them in parallel, see ``k_screw_bearings``).
        """
        i = self.i_min if i is None else i
        out = {}
        for name, key in COMPONENTS:
            v = self.at(key, i)
            if key == "c_unit_bearing" and v == 0:  # a nut on a turning screw: no unit bearing
                continue
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
        """(minimum value, nut position where it occurs, measured from stroke start) for a
        profile."""
        v = np.asarray(self.values[key])
        i = int(np.argmin(v))
        return float(v[i]), float(self.x[i] - self.design.axis.start_offset)

    def checks(self) -> dict:
        """Check name -> margin (available / needed, >= 1 passes), every check (see
        :meth:`check_table`)."""
        return {c: float(self.values[margin_output(c)]) for c in CHECKS}

    def check_rows(self) -> list:
        """The checks that apply to the design, one dict each (see :func:`check_rows`)."""
        return check_rows(self)

    def check_table(self):
        """pandas DataFrame, one row per check that applies: ``check``, ``label``, ``available``,
        ``needed`` (both in ``unit``, the unit vendors quote), ``unit``, ``margin`` (available /
        needed; empty when nothing loads it) and ``pass``."""
        rows = [{k: r[k] for k in CHECK_COLUMNS} for r in check_rows(self)]
        return frame(rows, CHECK_COLUMNS)

    def summary(self) -> dict:
        """Headline values in engineering units, the unit in each key (``min_stiffness [N/um]``)."""
        v, a = self.values, self.design.axis
        k, k_at = self.minimum("k_total")
        f, f_at = self.minimum("f1")
        rows = check_rows(self)
        return {
            "design": self.design.name,
            "mounting": a.mounting,
            **self.design.part_ids(),
            "nut_preload [N]": float(self.design.preload),
            "stroke [mm]": a.stroke * 1e3,
            "min_stiffness [N/um]": k / 1e6,
            "min_stiffness_at [mm]": k_at * 1e3,
            "weakest_link": self.weakest,
            "min_frequency [Hz]": f,
            "min_frequency_at [mm]": f_at * 1e3,
            "table_mode [Hz]": float(v["f_table"]),
            "drag_torque [N.m]": float(v["drag_torque"]),
            "moving_mass [kg]": float(v["moving_mass"]),
            "total_mass [kg]": float(v["total_mass"]),
            "cost [EUR]": float(v["cost"]),
            "checks_failed": ", ".join(r["check"] for r in rows if not r["pass"]) or "none",
        }

    def to_frame(self):
        """pandas DataFrame, one row per nut position over the stroke (model grid), units in the
        column
        names: ``position [mm]`` from stroke start, ``stiffness [N/um]``,
        ``screw_stiffness [N/um]``, ``frequency [Hz]`` (first natural), ``axial_frequency [Hz]``,
        ``axial_torsional_frequency [Hz]``, ``damping_ratio [%]``, ``thermal_displacement [mm]``.
        :meth:`summary` and :meth:`check_table` give the rest."""
        v = self.values
        n = len(self.x)

        def col(key, scale=1.0):
            return np.broadcast_to(np.asarray(v[key], dtype=float), (n,)) * scale

        import pandas as pd

        return pd.DataFrame(
            {
                "position [mm]": (self.x - self.design.axis.start_offset) * 1e3,
                "stiffness [N/um]": col("k_total", 1e-6),
                "screw_stiffness [N/um]": col("k_screw", 1e-6),
                "frequency [Hz]": col("f1"),
                "axial_frequency [Hz]": col("f_axial"),
                "axial_torsional_frequency [Hz]": col("f_axial_torsional"),
                "damping_ratio [%]": col("damping_ratio", 100.0),
                "thermal_displacement [mm]": col("thermal_displacement", 1e3),
            }
        )

    def __repr__(self) -> str:
        s = self.summary()
        fails = s["checks_failed"]
        return one_line(
            "Evaluation",
            f"{self.design.name!r}, {s['mounting']}",
            {
                "min stiffness": f"{fmt(s['min_stiffness [N/um]'], 'N/um')} at "
                f"{fmt(s['min_stiffness_at [mm]'], 'mm')}"
                f" (weakest: {s['weakest_link']})",
                "1st frequency": fmt(s["min_frequency [Hz]"], "Hz"),
                "drag": fmt(s["drag_torque [N.m]"], "N.m"),
                "cost": fmt(s["cost [EUR]"], "EUR"),
                "checks": "all pass" if fails == "none" else f"FAIL {fails}",
            },
        )

    def _repr_html_(self) -> str:
        s = self.summary()
        head = html_fields(
            {k: fmt(v) if isinstance(v, float) else v for k, v in s.items()},
            f"Evaluation of {self.design.name}",
        )
        rows = [
            {
                "check": r["label"],
                "available": fmt(r["available"], r["unit"]),
                "needed": fmt(r["needed"], r["unit"]),
                "margin": fmt(r["margin"]),
                "pass": "pass" if r["pass"] else "FAIL",
            }
            for r in check_rows(self)
        ]
        return head + html_table(rows, "checks (margin = available / needed, >= 1 passes)")


NOT_APPLICABLE = 1e8  # a margin at or above this: the check does not apply (or nothing loads it)
CHECK_COLUMNS = ("check", "label", "available", "needed", "unit", "margin", "pass")


def _finite(x):
    return float(x) if math.isfinite(x) and abs(x) < NOT_APPLICABLE else None


def check_rows(ev: Evaluation) -> list:
    """One dict per check that applies to the design: ``check``, ``label``, ``available`` and
    ``needed`` in ``unit`` (the vendor unit of :data:`model.limits.CHECK_TABLE`), ``margin``
    (available / needed; None when nothing loads it) and ``pass``.  bearing_fit's available value is
    the range of bores the screw end takes, as ``available_min`` .. ``available``."""
    d, v = ev.design, ev.values
    out = []
    for c in CHECKS:
        if c in DRIVE_CHECKS and (
            c.startswith("reduction_")
            and d.reduction is None
            or c.startswith("coupling_")
            and d.coupling is None
            or d.motor is None
            and not c.startswith(("coupling_", "reduction_"))
        ):
            continue
        m = float(v[margin_output(c)])
        if c == "brake_holding" and d.axis.orientation != "vertical":
            continue
        rec = CHECK_RECORDS[c]
        if rec.rotating_nut and not rotating_nut(d.nut):
            continue
        unit, f = rec.unit, rec.factor
        row = {
            "check": c,
            "label": CHECK_LABELS[c],
            "unit": unit,
            "available": _finite(float(v[f"available_{c}"]) * f),
            "needed": _finite(float(v[f"needed_{c}"]) * f),
            "margin": None if m >= NOT_APPLICABLE else _finite(m),
            "pass": passes(m),
        }
        if c == "bearing_fit":
            row["available_min"] = _finite(float(d.screw["support_bore_min"]) * f)
        if c in ("nut_lift_off", "nut_preload") and m >= NOT_APPLICABLE:
            row["available"] = None  # a single nut has no preload to lose
        out.append(row)
    return out


def drive_dict(ev: Evaluation) -> dict | None:
    """The drive values of an evaluation (None without a motor)."""
    d, v = ev.design, ev.values
    if d.motor is None:
        return None
    red = d.reduction
    return {
        "motor": str(d.motor["id"]),
        "coupling": None if d.coupling is None else str(d.coupling["id"]),
        "reduction": None if red is None else str(red["id"]),
        "reduction_ratio": d.axis.reduction_ratio if red is None else float(red["ratio"]),
        "output_peak_torque_Nm": v["output_peak_torque"],
        "output_rms_torque_Nm": v["output_rms_torque"],
        "peak_torque_Nm": v["peak_torque"],
        "rms_torque_Nm": v["rms_torque"],
        "thrust_torque_Nm": v["thrust_torque"],
        "mean_thrust_torque_Nm": v["mean_thrust_torque"],
        "holding_torque_Nm": v["holding_torque"],
        "unbalance_torque_Nm": v["unbalance_torque"],
        "motor_speed_rpm": v["motor_speed"] * 60 / (2 * math.pi),
        "load_inertia_kgm2": v["load_inertia"],
        "inertia_ratio": v["inertia_ratio"],
        "duty_time_s": v["duty_time"],
        "friction_torque_Nm": v["friction_torque"],
        "regen_energy_J": v["regen_energy"],
        "regen_power_W": v["regen_power"],
    }


def evaluate(
    design: Design,
    n_positions: int | None = None,
    *,
    use_casadi: bool = True,
    side: str = "governing",
) -> Evaluation:
    """Evaluate a design with the CasADi axis Function (or directly on numpy with use_casadi=False).

    ``side`` (a twin-drive gantry, :mod:`.gantry`): 'governing' (the side nearest the cross carriage
    at the end of its stroke: what the limits are checked on) or 'far' (the other side at
    that moment: share 1 - r of the process force and of the cross carriage's weight over the half).
    One drive: both are the drive."""
    if side not in ("governing", "far"):
        raise ValueError(f"side must be 'governing' or 'far', not {side!r}")
    tw = design.axis.twin_drive
    if tw is not None and tw.side != side:
        design = replace(design, axis=replace(design.axis, twin_drive=replace(tw, side=side)))
    x = positions(design.axis, n_positions)
    params = design_params(design)
    if use_casadi:
        values = model_for(design.axis.mounting, len(x), design.axis.phases)(
            params, design.preload, x
        )
    else:
        raw = axis_response(params, x, design.axis.mounting, design.preload)
        values = {
            k: (
                np.broadcast_to(np.asarray(v, float), x.shape).copy()
                if k in PROFILE_OUTPUTS
                else float(v)
            )
            for k, v in raw.items()
            if k not in ("duty_torques", "zone_factors", "output_torques")
        }
    return Evaluation(design, x, values)
