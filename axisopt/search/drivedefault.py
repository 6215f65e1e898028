"""The drive types the shipped catalogs offer by default: a problem without ``search.drive_types``
is solved as a screw drive (the usual search and its answer), then rack and pinion and linear motors
are offered beside it, each pruned by its bound before any of its combinations is formed into a
design.

A type is left out, with the reason, when it does not apply: the objective or method is one the
drive-type search does not run (a Pareto front, Bonmin, SCIP), the problem sizes no drive
(``catalog.drive: no``), pins a screw-drive part (``catalog.require`` of a screw, nut or bearing),
chooses among arrangements (``search.counterbalance`` / ``search.twin_drive``), a rack on a stroke
under :data:`RACK_MIN_STROKE` or without a reduction (``catalog.reductions: no``), states a limit on
an output only a screw drive has (``max_drag_torque``, ``max_total_mass``, ...: it could not bind
the other types), or a linear motor on a vertical axis without a counterbalance (the vendors forbid
it without a brake).  The rows follow the problem's vendor, status and ``estimated`` filters.

Each remaining type is bounded as the drive-type search bounds it (:mod:`.drivebest`: per (rack,
reduction, twin pinion) block for a large rack space, per drive otherwise, the optimistic guide):
when no drive may pass its checks, or the best bound cannot reach the screw drive's optimum, the
type cannot win and the screw answer stands as printed.  Otherwise that type's space is searched
(best-first, or every combination with the exhaustive method) and the best design of any type wins
by the drive-type search's tie rule; the tests compare this with the exhaustive search over every
type listed explicitly (:func:`.drivetype.solve_drive_types`).  When no type has a design and the
screw answer's advice finds no change, another drive type is proposed as the change
(:func:`type_change`)."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np

from ..design.drivechoice import DriveChoice
from ..drivecatalog import DriveTables, default_drive_tables
from .drivebest import LEVEL1_MIN, beaten, block_bounds, drive_bounds
from .drivedesigns import (
    HANDLED,
    OBJECTIVES,
    DriveTypeResult,
    TypeSummary,
    rank_key,
    screw_designs,
    spaces,
)

OTHER_TYPES = ("rack_pinion", "linear_motor")
# rack and pinion is offered by default from this stroke [m]: builders use it beyond about 4 m,
# below it a screw (issue 54's router; Thomson: screw drives "commonly" reach 5.5-6 m with support
# bearing pairs).  A shorter axis compares it when search.drive_types lists it: its stiffness rests
# on the mesh estimate (physics.rack, ISO 6336 guidance) and counts no pinion-shaft, gearbox-bearing
# or mounting compliance, so on a short axis it would win on an optimistic estimate (the rule of
# model.estimates)
RACK_MIN_STROKE = 4.0
SCREW_SLOTS = ("screw", "nut", "bearing")
CUT = "not searched: the time limit was reached"


@dataclass
class Offer:
    """What the default offer did: per type, 'bounded' / 'infeasible' / 'searched' / why it does not
    apply, and the answer over every type when a type other than the screw wins (else None: the
    screw stands)."""

    reasons: dict
    result: DriveTypeResult | None = None
    time: float = 0.0


def left_out(problem, method: str) -> str:
    """Why no other drive type is offered to ``problem`` ('' when they are)."""
    mode = problem.objective.mode
    if problem.drives is not None:
        return "the problem lists its drive types"
    if method not in ("default", "exhaustive"):
        return f"the {method} method searches screw drives only"
    if mode not in OBJECTIVES:
        return f"objective {mode}: the drive-type search does not run it"
    rs = problem.restrictions
    if not rs.drive:
        return "the problem sizes no drive (catalog.drive)"
    pinned = [s for s in SCREW_SLOTS if rs.required(s)]
    if pinned:
        return f"catalog.require names screw-drive parts ({', '.join(pinned)})"
    if problem.arrangements:
        return "the search chooses among arrangements (search.counterbalance / search.twin_drive)"
    screw_only = sorted(k for k, _ in problem.limits if k not in HANDLED)
    if screw_only:  # the other types have no such output: the limit could not bind them
        return f"limits only a screw drive has: {', '.join(screw_only)}"
    return ""


def _rows(rows, rs) -> tuple:
    """The drive-type rows the problem's catalog filters keep (vendors, status, estimated:
    exclude)."""
    out = []
    for r in rows:
        if rs.vendors and r.get("vendor") not in rs.vendors:
            continue
        if r.get("status") and r["status"] not in rs.status:
            continue
        if rs.estimated == "exclude" and r.get("estimated"):
            continue
        out.append(r)
    return tuple(out)


def offered(problem, tables: DriveTables) -> tuple[tuple, dict, DriveTables]:
    """(types offered beside the screw, {type: why not} for the others, the filtered tables)."""
    rs = problem.restrictions
    t = DriveTables(_rows(tables.racks, rs), _rows(tables.linear_motors, rs))
    why = {}
    if problem.axis.stroke < RACK_MIN_STROKE:
        why["rack_pinion"] = (
            f"a stroke under {RACK_MIN_STROKE:g} m (list it in search.drive_types to compare)"
        )
    elif not t.racks:
        why["rack_pinion"] = "no racks.csv row passes the catalog filters"
    elif not rs.reductions:
        why["rack_pinion"] = "catalog.reductions: no (a pinion drives through a gearbox)"
    if not t.linear_motors:
        why["linear_motor"] = "no linear_motors.csv row passes the catalog filters"
    elif problem.axis.orientation == "vertical" and problem.axis.counterbalance is None:
        why["linear_motor"] = "a vertical axis without a counterbalance (the vendors ask a brake)"
    return tuple(k for k in OTHER_TYPES if k not in why), why, t


def space_bound(problem, space, spec) -> tuple[float, bool]:
    """(the best objective any design of ``space`` may reach, whether any drive may pass its
    checks): the drive-type search's own bounds (:mod:`.drivebest`), so a type pruned here is one it
    would not open."""
    sense = spec[3]
    n_drives = int(np.prod(space.shape[:-1]))
    if space.kind == "rack_pinion" and n_drives >= LEVEL1_MIN:
        # blocks first: only the blocks whose bound may still win are bounded per drive
        b = block_bounds(space, spec)
        return (float(np.max(b)) if sense == "max" else float(np.min(b))), True
    obj, ok, _ = drive_bounds(problem, space, spec)
    if not ok.any():
        return float("nan"), False
    v = obj[ok]
    return (float(np.max(v)) if sense == "max" else float(np.min(v))), True


def offer(
    problem, screw_res, method: str = "default", *, top: int = 5, tables=None, deadline=None
) -> Offer:
    """Offer rack and pinion and linear motors beside the screw answer ``screw_res`` of ``problem``
    (see the module); ``tables``: the drive-type catalogs (default: the shipped ones).  When no
    type has a design and the screw answer proposes no design change, another drive type is
    proposed as one (:func:`type_change`, put into ``screw_res``'s infeasibility).  ``deadline`` (a
    time.perf_counter() value): no type is searched, and no change verified, past it (said in the
    reasons)."""
    t0 = time.perf_counter()
    why = left_out(problem, method)
    if why:
        return Offer({k: why for k in OTHER_TYPES}, None, time.perf_counter() - t0)
    tables = default_drive_tables() if tables is None else tables
    types, reasons, tables = offered(problem, tables)
    if not types:
        return Offer(reasons, None, time.perf_counter() - t0)
    from .drivetype import search_space

    spec = OBJECTIVES[problem.objective.mode]
    sense = spec[3]
    sign = -1.0 if sense == "max" else 1.0
    p2 = replace(problem, drives=DriveChoice(types=("screw", *types), tables=tables))
    screw = screw_designs(screw_res)
    best = screw[0].objective if screw else None
    designs, summaries = list(screw), []
    for space in spaces(p2):
        if deadline is not None and time.perf_counter() >= deadline:
            reasons[space.kind] = CUT
            continue
        bound, may = space_bound(p2, space, spec)
        if not may:
            reasons[space.kind] = "no drive passes its checks even with the optimistic guide"
            continue
        if best is not None and beaten(bound, best, sense):
            reasons[space.kind] = (
                f"bounded out: at most {bound:.6g} {spec[2]}, the screw drive reaches {best:.6g}"
            )
            continue
        ds, nfeas, _ = search_space(p2, space, spec, method, top)
        reasons[space.kind] = "searched"
        designs += ds
        summaries.append(
            TypeSummary(
                space.kind,
                "optimal" if ds else "infeasible",
                space.size,
                nfeas,
                ds[0].objective if ds else None,
            )
        )
    order = ("screw", *types)
    ranked = sorted(
        designs,
        key=lambda d: (
            rank_key(d.objective, d.cost, d.moving_mass, sign),
            order.index(d.drive_type),
        ),
    )
    if not ranked and method == "default":
        inf = getattr(screw_res, "infeasibility", None)
        if inf is not None and not inf.design_changes:
            inf.design_changes = type_change(problem, tables, deadline)
            if not inf.design_changes and deadline is not None and time.perf_counter() >= deadline:
                from .sensitivity import cut_note

                note = cut_note("advice", [])
                screw_res.message = "; ".join(x for x in (screw_res.message, note) if x)
    if not ranked or ranked[0].drive_type == "screw":
        return Offer(reasons, None, time.perf_counter() - t0)
    cert = screw_res.certificate
    screw_summary = TypeSummary("screw", screw_res.status, cert.combinations, cert.feasible, best)
    notes = [f"drive types offered by default: {', '.join(order)}"]
    notes += [f"{k}: {v}" for k, v in reasons.items() if v != "searched"]
    mode = problem.objective.mode
    res = DriveTypeResult(
        "optimal" if screw_res.status in ("optimal", "infeasible") else screw_res.status,
        method,
        f"{'maximise' if sense == 'max' else 'minimise'} {mode.replace('_', ' ')}",
        spec[2],
        ranked[0],
        ranked[1:top],
        [screw_summary, *summaries],
        0.0,
        tuple(notes),
    )
    out = Offer(reasons, res, time.perf_counter() - t0)
    res.time = float(getattr(screw_res, "time", 0.0) or 0.0) + out.time
    return out


def round_down(x: float) -> float:
    """``x`` > 0 rounded down to three significant figures."""
    e = math.floor(math.log10(x)) - 2
    return round(math.floor(x / 10**e + 1e-9) * 10**e, -e)


def type_change(problem, tables: DriveTables, deadline: float | None = None) -> list:
    """Another drive type as the design change of an infeasible screw answer: each type the
    catalogs hold that applies to the axis (:func:`left_out`; rack and pinion on a stroke under
    :data:`RACK_MIN_STROKE` too: the screw has no design), listed in ``search.drive_types`` beside
    the screw, as asked or with the least lowered acceleration or rapid speed (bisection,
    :func:`.drivechange.lowest_change`) at which its spaces hold a design.  The value is rounded
    down to three significant figures and verified again there.  [] when no type gives one."""
    from ..errors import InputError
    from .drivechange import KEYS, TYPE_LABELS, first_design, lowest_change, scaled
    from .infeasible.answer import DesignChange

    if left_out(problem, "default"):
        return []
    _, why, t = offered(problem, tables)
    kinds = [k for k in OTHER_TYPES if k not in why or why[k].startswith("a stroke under")]
    if not problem.restrictions.reductions or not t.racks:
        kinds = [k for k in kinds if k != "rack_pinion"]
    axis = problem.axis
    best = None  # (factor, kind, key, value, parts)
    for kind in kinds:
        if deadline is not None and time.perf_counter() >= deadline:
            break
        p = replace(problem, drives=DriveChoice(types=(kind,), tables=t))
        try:
            hit = first_design(p, axis)
        except InputError:  # the type's space has nothing to choose from (its catalog filters)
            continue
        if hit is not None:
            best = (1.0, kind, None, None, hit[1])
            break
        for key, _, _, scale in KEYS:
            found = lowest_change(p, key, deadline)
            if found is None or (best is not None and found[0] <= best[0]):
                continue
            value = round_down(getattr(axis, key) * found[0] * scale) / scale
            hit = first_design(p, scaled(axis, key, value / getattr(axis, key)))
            if hit is not None:
                best = (value / getattr(axis, key), kind, key, value, hit[1])
    if best is None:
        return []
    _, kind, key, value, parts = best
    rows = [
        DesignChange(
            "search.drive_types",
            "",
            float("nan"),
            float("nan"),
            f"a {TYPE_LABELS[kind]}: "
            + ", ".join(f"{k.replace('_', ' ')} {v}" for k, v in parts.items())
            + ", the best design there",
            "add",
            ("screw", kind),
        )
    ]
    if key is not None:
        _, _, unit, scale = next(k for k in KEYS if k[0] == key)
        rows.append(DesignChange(f"axis.{key}", unit, getattr(axis, key) * scale, value * scale))
    return rows
