"""The drive-type search's vocabulary below its strategies: objectives and limits by output, the
spaces of each type, the designs and their ranking (:mod:`.drivetype` solves, :mod:`.drivebest`
searches best-first, :mod:`.drivechange` verifies a design change; each reads these)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from .drivespace import lm_space, rack_space, side_of

OBJECTIVES = {  # mode: (output, factor to display, unit, sense)
    "stiffness": ("stiffness", 1e6, "N/um", "max"),
    "frequency": ("frequency", 1.0, "Hz", "max"),
    "cost": ("cost", 1.0, "EUR", "min"),
    "moving_mass": ("moving_mass", 1.0, "kg", "min"),
    "positioning_error": ("positioning_error", 1e-6, "um", "min"),
}
LIMITS = {  # limit key: (output, sense)
    "min_stiffness": ("stiffness", ">="),
    "min_frequency": ("frequency", ">="),
    "max_cost": ("cost", "<="),
    "max_moving_mass": ("moving_mass", "<="),
    "max_positioning_error": ("positioning_error", "<="),
    "max_backlash": (
        "lost_motion",
        "<=",
    ),  # the gearbox's backlash at the rack (0: a preloaded twin pinion)
}
LIMIT_FLOOR = {"max_backlash": 1e-6}  # a limit of 0: misses relative to 1 um
HANDLED = set(LIMITS) | {"min_life"}  # min_life: the guides' life (Side.life_needed)
CLOSEST = 50  # designs per type the design change is verified on


@dataclass
class DriveDesign:
    """One design of any drive type (display units in the named fields, SI in ``outputs``)."""

    drive_type: str
    parts: dict
    objective: float
    cost: float  # [EUR]
    moving_mass: float  # [kg] one side's
    stiffness: float  # [N/um]
    frequency: float  # [Hz]
    positioning_error: float  # [um]
    margins: dict = field(default_factory=dict)
    outputs: dict = field(default_factory=dict, repr=False)
    candidate: object = field(default=None, repr=False)  # the screw search's Candidate

    def to_dict(self) -> dict:
        return {
            "drive_type": self.drive_type,
            "parts": dict(self.parts),
            "objective": self.objective,
            "cost": self.cost,
            "moving_mass": self.moving_mass,
            "stiffness": self.stiffness,
            "frequency": self.frequency,
            "positioning_error": self.positioning_error,
            "margins": {k: float(v) for k, v in self.margins.items()},
        }


@dataclass
class TypeSummary:
    drive_type: str
    status: str
    combinations: int
    feasible: int | None
    best: float | None


@dataclass
class DriveTypeResult:
    status: str  # 'optimal' | 'infeasible' | another status of the screw search
    method: str
    objective_label: str
    objective_unit: str
    best: DriveDesign | None
    runners_up: list
    types: list  # TypeSummary per type, in the problem's order
    time: float
    notes: tuple = ()
    closest: list = field(default_factory=list)  # infeasible: the closest designs (their misses)
    change: str = ""  # infeasible: a verified design change

    def to_dict(self) -> dict:
        return {
            "status": self.status,
            "method": self.method,
            "objective": self.objective_label,
            "objective_unit": self.objective_unit,
            "time": self.time,
            "best": self.best.to_dict() if self.best else None,
            "runners_up": [d.to_dict() for d in self.runners_up],
            "types": [vars(t) for t in self.types],
            "notes": list(self.notes),
            "closest": [d.to_dict() for d in self.closest],
            "design_change": self.change,
        }


def screw_designs(res) -> list:
    """The screw search's best and runners-up (a :class:`~axisopt.search.result.SolveResult`) as
    designs."""
    designs = []
    for c in ([res.best] + list(res.runners_up)) if res.best is not None else []:
        out = c.outputs or {}
        perr = out.get("positioning_error")
        designs.append(
            DriveDesign(
                "screw",
                {"mounting": c.mounting, **c.parts()},
                c.objective,
                c.cost,
                c.moving_mass,
                c.min_stiffness,
                c.min_frequency,
                float(perr) * 1e6 if perr is not None else float("nan"),
                candidate=c,
            )
        )
    return designs


def objective_of(problem):
    mode = problem.objective.mode
    if mode not in OBJECTIVES:
        raise InputError(
            f"objective '{mode}': a search over drive types maximises stiffness or frequency or "
            f"minimises {', '.join(k for k, v in OBJECTIVES.items() if v[3] == 'min')}",
            source=problem.source,
            where="objective",
        )
    return mode, OBJECTIVES[mode]


def part_tables(problem):
    cat = problem.catalog
    return cat.rows("reductions"), cat.rows("motors"), cat.rows("guides")


def subset(table, keep):
    """A PartTable's columns restricted to the rows ``keep`` (a bool mask), as a dict of arrays."""
    return {c: np.asarray(table[c])[keep] for c in table.columns}


def spaces(problem, axis=None) -> list:
    """The rack-and-pinion and linear-motor spaces ``problem`` lists (its catalog filters: vendors
    of guides, guide types, require/exclude of the guide, motor and reduction slots)."""
    axis = problem.axis if axis is None else axis
    ch = problem.drives
    red, mot, gd = part_tables(problem)
    rs = problem.restrictions

    def keep(table, slot, extra=None):
        ids = np.asarray(table["id"])
        k = np.ones(len(ids), dtype=bool) if extra is None else extra
        req = rs.required(slot)
        if req:
            k &= np.isin(ids, list(req))
        if rs.excluded(slot):
            k &= ~np.isin(ids, list(rs.excluded(slot)))
        return k

    gk = keep(gd, "guide", np.isin(np.asarray(gd["status"]), list(rs.status)))
    if rs.guide_types:
        gk &= np.isin(np.asarray(gd["type"]), list(rs.guide_types))
    if rs.vendors:
        gk &= np.isin(np.asarray(gd["vendor"]), list(rs.vendors))
    mk = keep(mot, "motor", np.isfinite(np.asarray(mot["price"], dtype=float)))
    if rs.motor_vendors:
        mk &= np.isin(np.asarray(mot["vendor"]), list(rs.motor_vendors))
    if rs.motor_series:
        mk &= np.isin(np.asarray(mot["series"]), list(rs.motor_series))
    rk = keep(red, "reduction", np.isfinite(np.asarray(red["mass"], dtype=float)))
    side = side_of(axis)
    out = []
    guides = subset(gd, gk)
    if "rack_pinion" in ch.types and rk.any() and mk.any() and gk.any():
        out.append(rack_space(ch.tables.racks, subset(red, rk), subset(mot, mk), guides, side, ch))
    if "linear_motor" in ch.types and gk.any():
        out.append(lm_space(ch.tables.linear_motors, guides, side, ch))
    return out


def limit_arrays(problem, outputs: dict, cost):
    """Relative misses of the handled limits, arrays (>= 0 feasible)."""
    vals = {**outputs, "cost": cost}
    out = {}
    for key, value in problem.limits:
        if key not in LIMITS:
            continue
        name, sense = LIMITS[key]
        v = np.asarray(vals[name], dtype=float)
        if value <= 0.0:  # nothing allowed: the miss relative to LIMIT_FLOOR
            out[key] = -v / LIMIT_FLOOR.get(key, 1.0)
            continue
        out[key] = v / value - 1.0 if sense == ">=" else 1.0 - v / value
    return out


def scores(problem, space, res, spec):
    """Objective (display units) and feasibility of every combination of ``space`` (flat arrays)."""
    name, factor, _, sense = spec
    vals = res["cost"] if name == "cost" else res["outputs"][name]
    obj = np.asarray(vals, dtype=float).ravel() / factor
    ok = np.ones(obj.shape, dtype=bool)
    miss = np.zeros(obj.shape)
    for m in res["margins"].values():
        m = np.asarray(m, dtype=float).ravel()
        ok &= m >= 1.0
        miss += np.maximum(0.0, 1.0 - m)
    for v in limit_arrays(problem, res["outputs"], res["cost"]).values():
        v = np.asarray(v).ravel()
        ok &= v >= 0.0
        miss += np.maximum(0.0, -v)
    ok &= np.isfinite(obj)
    return obj, ok, miss


def design_of(space, flat, one, spec, problem=None) -> DriveDesign:
    name, factor, _, _ = spec
    o = one["outputs"]
    value = one["cost"] if name == "cost" else o[name]
    parts = space.parts(flat)
    d = DriveDesign(
        space.kind,
        parts,
        value / factor,
        one["cost"],
        o["moving_mass"],
        o["stiffness"] / 1e6,
        o["frequency"],
        o["positioning_error"] * 1e6,
        margins=one["margins"],
        outputs={**o, "cost": one["cost"]},
    )
    if (
        problem is not None
    ):  # an infeasible problem's closest design: the limits it misses, as margins
        lim = limit_arrays(
            problem, {k: np.array([v]) for k, v in o.items()}, np.array([one["cost"]])
        )
        d.margins = {**d.margins, **{k: float(1.0 + v[0]) for k, v in lim.items()}}
    return d


def rank_designs(designs: list, sense: str) -> list:
    sign = -1.0 if sense == "max" else 1.0
    return sorted(designs, key=lambda d: rank_key(d.objective, d.cost, d.moving_mass, sign))


def rank_key(objective, cost, mass, sign) -> tuple:
    """The tie rule: the objective, then lower cost, then lower mass (rounded so float noise is no
    rank)."""
    return (round(float(sign * objective), 9), round(float(cost), 6), round(float(mass), 9))
