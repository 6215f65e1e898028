"""The drive type as a search choice (``search.drive_types``): the screw drive (the usual search, its proof),
rack and pinion and linear motors (every combination of their parts, :mod:`.drivespace`), the best design of
any type wins.  The default method evaluates each new type's whole space at once on numpy arrays; the
exhaustive method evaluates every combination alone in floats (the ground truth the tests compare with); both
take the screw drive from the screw search with the same method.  Ties: lower cost, then lower moving mass,
then the type listed first.

The objective is one of stiffness, frequency (maximised), cost, moving mass, positioning error (minimised);
the limits on those outputs and min_life hold for every type; a limit on an output only the screw drive has
(drag torque, screw sag, ...) binds the screw drive alone (noted in the answer).  When no type has a design,
the answer names the checks the closest designs miss and a design change verified by evaluating the closest
designs again (the acceleration, then the rapid speed lowered by bisection)."""

from __future__ import annotations

import time
from dataclasses import dataclass, field, replace

import numpy as np

from ..errors import InputError
from .drivespace import evaluate_one, evaluate_space, lm_space, rack_space, side_of

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
    """The rack-and-pinion and linear-motor spaces ``problem`` lists (its catalog filters: vendors of guides,
    guide types, require/exclude of the guide, motor and reduction slots)."""
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
    from .drivebest import rank_key

    sign = -1.0 if sense == "max" else 1.0
    return sorted(designs, key=lambda d: rank_key(d.objective, d.cost, d.moving_mass, sign))


def search_space(problem, space, spec, method: str, top: int):
    """The best ``top`` designs of one space, the number of combinations evaluated (exhaustive: the feasible
    count) and, when none is feasible, the closest combinations."""
    if method != "exhaustive":
        from .drivebest import best_first

        designs, _, near = best_first(problem, space, spec, top)
        return designs, None, near
    from .drivebest import rank_key

    res = evaluate_space(space)
    objs, oks, misses = scores(problem, space, res, spec)
    sense = spec[3]
    sign = -1.0 if sense == "max" else 1.0
    idx = np.flatnonzero(oks)
    if idx.size:
        cost = np.asarray(res["cost"]).ravel()
        mass = np.asarray(res["outputs"]["moving_mass"]).ravel()
        keys = sorted((rank_key(objs[i], cost[i], mass[i], sign), int(i)) for i in idx)[:top]
        designs = rank_designs(
            [design_of(space, i, evaluate_one(space, i), spec) for _, i in keys], sense
        )
        return designs[:top], int(idx.size), []
    order = np.argsort(misses, kind="stable")[:CLOSEST]
    return [], 0, [int(i) for i in order]


def scalar_search(problem, space, spec, top: int):
    """Every combination alone in floats (the tests' ground truth for small spaces): (designs, feasible)."""
    from .drivebest import rank_key

    sign = -1.0 if spec[3] == "max" else 1.0
    found = []
    for i in range(space.size):
        one = evaluate_one(space, i)
        res = {
            "outputs": {k: np.array([v]) for k, v in one["outputs"].items()},
            "margins": {k: np.array([v]) for k, v in one["margins"].items()},
            "cost": np.array([one["cost"]]),
        }
        o, k, _ = scores(problem, space, res, spec)
        if k[0]:
            found.append((rank_key(o[0], one["cost"], one["outputs"]["moving_mass"], sign), i))
    found.sort()
    return rank_designs(
        [design_of(space, i, evaluate_one(space, i), spec) for _, i in found[:top]], spec[3]
    ), len(found)


def _screw(problem, method: str, top: int, time_limit: float, spec):
    from .front import solve

    res = solve(
        replace(problem, drives=None), method, top=top, time_limit=time_limit, sensitivities=False
    )
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
    return res, designs


def solve_drive_types(problem, method: str = "default", *, top: int = 5, time_limit: float = 100.0):
    """Solve ``problem`` over its drive types (see the module); a :class:`DriveTypeResult`."""
    t0 = time.perf_counter()
    if method not in ("default", "exhaustive"):
        raise InputError(
            f"method '{method}': a search over drive types runs the default or exhaustive method",
            source=problem.source,
            where="method",
        )
    mode, spec = objective_of(problem)
    unit, sense = spec[2], spec[3]
    designs, types, notes, closest = [], [], [], {}
    status = "optimal"
    for kind in problem.drives.types:
        if kind == "screw":
            res, ds = _screw(
                problem, method, top, max(time_limit - (time.perf_counter() - t0), 1.0), spec
            )
            designs += ds
            types.append(
                TypeSummary(
                    "screw",
                    res.status,
                    res.certificate.combinations,
                    res.certificate.feasible,
                    ds[0].objective if ds else None,
                )
            )
            if res.status not in ("optimal", "infeasible"):
                status = res.status
            continue
        for space in spaces(problem):
            if space.kind != kind:
                continue
            ds, nfeas, near = search_space(problem, space, spec, method, top)
            designs += ds
            closest[kind] = (space, near)
            types.append(
                TypeSummary(
                    kind,
                    "optimal" if ds else "infeasible",
                    space.size,
                    nfeas,
                    ds[0].objective if ds else None,
                )
            )
    left = sorted(k for k, _ in problem.limits if k not in HANDLED)
    if left and any(t != "screw" for t in problem.drives.types):
        notes.append(f"limits on screw-drive outputs bind the screw drive only: {', '.join(left)}")
    from .drivebest import rank_key

    sign = -1.0 if sense == "max" else 1.0
    ranked = sorted(
        designs,
        key=lambda d: (
            rank_key(d.objective, d.cost, d.moving_mass, sign),
            problem.drives.types.index(d.drive_type),
        ),
    )
    out = DriveTypeResult(
        status if ranked else "infeasible",
        method,
        f"{'maximise' if sense == 'max' else 'minimise'} {mode.replace('_', ' ')}",
        unit,
        ranked[0] if ranked else None,
        ranked[1:top],
        types,
        0.0,
        tuple(notes),
    )
    if not ranked:
        from .drivechange import design_change

        out.closest, out.change = design_change(problem, closest, spec)
    out.time = time.perf_counter() - t0
    return out
