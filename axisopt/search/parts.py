"""The parts a problem may use: the catalog's tables filtered by the problem's restrictions, the
(motor, coupling, reduction) drives, and a process cache of the result (:func:`build_space` ->
:class:`.task.space.Space`).

The filters: vendors, series, provenance status, estimated values, nut types, bearing arrangements
and preload classes, guide types and preload levels, require/exclude; nuts keep their screw; each
nut's preload range is the problem's (preloaded nuts, capped by the vendors' 10 % Ca ceiling) or its
catalog range (single nuts).  Couplings another beats on every count, and drives whose coupling
cannot carry the motor's peak torque through the drive's reduction, are never formed.  A drive's
reduction is a reductions row or none (the axis's reduction values: direct drive by default), when
the problem allows reductions (``catalog.reductions``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .. import model
from ..catalog.columns import COLUMNS, USER_STATUS
from ..catalog.grades import grade_table
from ..catalog.parttable import PartTable
from ..errors import InputError
from ..model.chain import drive_torsional_stiffness
from ..model.paramnames import columns_read
from ..physics import nut as pnut
from ..problem import Problem
from .task.space import SCREEN_CHUNK, Space

_SCREW_COLS, _NUT_COLS, _BEARING_COLS, _GUIDE_COLS, _MOTOR_COLS, _COUPLING_COLS, _REDUCTION_COLS = (
    columns_read(t)
    for t in ("screws", "nuts", "bearings", "guides", "motors", "couplings", "reductions")
)


# text columns the model reads through a rule (a part's type, a bearing set's arrangement): kept as
# strings
_TEXT_COLUMNS = frozenset(c.name for cols in COLUMNS.values() for c in cols if c.kind == "str")


def _arrays(t, cols):
    return {c: (np.asarray(t[c]).astype(str) if c in _TEXT_COLUMNS else t.number(c)) for c in cols}


def vendor_filled(t: PartTable, table: str) -> PartTable:
    """The rows of a part table with a vendor value in every column the model would otherwise
    estimate (``catalog.COLUMNS``: an optional column with an ``estimate``)."""
    from ..catalog.columns import COLUMNS

    keep = np.ones(len(t), dtype=bool)
    for c in COLUMNS[table]:
        if c.estimate and c.name in t:
            # a column that applies only where a flag is set (a rotating-nut unit's) counts on those
            # rows only
            off = (t.number(c.applies) != 1.0) if c.applies and c.applies in t else False
            keep &= np.isfinite(t.number(c.name)) | off
    return t.take(keep)


# Spaces built in this process, by what they are made of (the catalog object and the problem's
# choices that filter it): a study's cases share the catalog and most of their restrictions, and
# filtering the part tables is a few ms a case.  Each problem gets its own Space (its axis, its
# parameter cache) on the shared, read-only part tables and arrays.
_SPACES: dict = {}
SPACES_KEPT = 4


def build_space(problem: Problem) -> Space:
    """The filtered part tables of ``problem`` as a :class:`Space` (reused from an earlier problem
    on the same catalog object with the same restrictions, preload range, reduction ratio and
    coupling margin)."""
    # everything the filters and the drive pruning read (_add_drives: the cycle's top speed, the
    # speed margins and the lost-motion limit prune drives): a study case differing in any of them
    # builds its own
    key = (
        id(problem.catalog),
        problem.restrictions,
        tuple(problem.mountings),
        problem.preload_min,
        problem.preload_max,
        float(problem.axis.reduction_ratio),
        float(problem.margin_map.get("coupling_torque", 1.0)),
        problem.axis.torque_limit,
        _top_speed(problem),
        tuple(float(problem.margin_map.get(k, 1.0)) for k in ("motor_speed", "reduction_speed")),
        float(problem.limit_map.get("max_backlash", np.inf)),
        _grades_chosen(problem),
        float(problem.axis.stroke) if _grades_chosen(problem) else 0.0,
        problem.axis.feedback == "linear_scale",  # leaves the rotating-nut units out
    )
    hit = _SPACES.get(key)
    if hit is None or hit[0] is not problem.catalog:
        sp = _build_space(problem)
        if len(_SPACES) >= SPACES_KEPT:
            _SPACES.pop(next(iter(_SPACES)))
        _SPACES[key] = hit = (problem.catalog, sp)
    sp = replace(hit[1], problem=problem, _cache={})
    sp.request = model.SCREEN.but(budget=reads_budget(problem))
    sp.grid = {m: model.positions(problem.axis_for(m)) for m in sp.mountings}
    # the drives' torsional stiffnesses (a drive without a coupling takes this problem's axis value)
    sp.coupling_k = (
        np.unique(drive_stiffnesses(sp))
        if sp.m_arr is not None
        else np.array([float(problem.axis.coupling_stiffness)])
    )
    return sp


# the limits that read the positioning budget
BUDGET_LIMITS = ("max_positioning_error", "max_repeatability")


def reads_budget(problem: Problem) -> bool:
    """Whether a limit or the Pareto front reads the positioning budget (model.accuracy)."""
    return any(k in problem.limit_map for k in BUDGET_LIMITS) or "positioning_error" in (
        problem.objective.pareto or ()
    )


def _grades_chosen(problem: Problem) -> bool:
    """Whether the screw's grade is a choice of the search (or fixed by the problem): a positioning
    limit or front reads the grade's lead error, or the problem names the grades.  Otherwise every
    screw takes the cheapest grade it is made in (C5 for every shipped series: the catalog price),
    which needs no expansion."""
    return (
        "max_positioning_error" in problem.limit_map
        or "positioning_error" in (problem.objective.pareto or ())
        or problem.restrictions.screw_grades is not None
    )


def screw_grade_rows(problem: Problem, screws, nut_lengths=0.0) -> tuple:
    """(row positions, grade names): each screw row repeated once per grade the search may give it
    -- those its series is made in (catalogs/screw_grades.csv), within the problem's
    ``catalog.screw_grades``, with a tolerance over the thread its nut travels, stroke +
    ``nut_lengths`` (one per row, or one for all; THK lists no C0 beyond 1600 mm), and not dominated
    (a grade that costs as much as a more accurate one is left out: C7 on a precision shaft, priced
    as C5)."""
    t = grade_table()
    allowed = problem.restrictions.screw_grades
    travels = problem.axis.stroke + np.broadcast_to(
        np.asarray(nut_lengths, dtype=float), (len(screws["vendor"]),)
    )
    rep, names = [], []
    cache: dict = {}
    for i, (vendor, series) in enumerate(zip(screws["vendor"], screws["series"])):
        key = (str(vendor), str(series), float(travels[i]))
        if key not in cache:
            opts = [g for g in t.orderable(*key[:2]) if allowed is None or g in allowed]
            opts = [(t.grade(g).price_factor, t.lead_error(g, key[2]), g) for g in opts]
            opts = sorted((o for o in opts if np.isfinite(o[1])), key=lambda o: (o[0], o[1]))
            kept, best = [], np.inf
            for _, err, g in opts:
                if err < best:
                    kept.append(g)
                    best = err
            cache[key] = kept
        for g in cache[key]:
            rep.append(i)
            names.append(g)
    return np.asarray(rep, dtype=np.int64), np.asarray(names, dtype=str)


def _top_speed(problem: Problem) -> float:
    """The duty cycle's largest table speed [m/s] (0 without a move): what the drives' speed pruning
    reads."""
    return max([ph.speed for ph in problem.axis.phases] + [0.0])


def _build_space(problem: Problem) -> Space:
    cat = problem.catalog
    r = problem.restrictions
    nuts, bearings, guides = cat.rows("nuts"), cat.rows("bearings"), cat.rows("guides")
    screws = cat.rows("screws")
    if r.vendors is not None:
        screws = screws.take(screws.isin("vendor", r.vendors))
        nuts = nuts.take(nuts.isin("vendor", r.vendors))
        bearings = bearings.take(bearings.isin("vendor", r.vendors))
        guides = guides.take(guides.isin("vendor", r.vendors))

    # provenance: a slot the problem names parts for ('require') takes them whatever their status
    def by_status(t, slot):
        if r.required(slot):
            return t
        if "status" not in t:
            return t if USER_STATUS in r.status else t.take(np.zeros(len(t), dtype=bool))
        return t.take(t.isin("status", tuple(r.status)))

    screws, nuts = by_status(screws, "screw"), by_status(nuts, "nut")
    bearings, guides = by_status(bearings, "bearing"), by_status(guides, "guide")
    # vendor values only: no row with an empty cell the model would estimate
    if r.estimated == "exclude":
        screws, nuts = vendor_filled(screws, "screws"), vendor_filled(nuts, "nuts")
        bearings, guides = vendor_filled(bearings, "bearings"), vendor_filled(guides, "guides")
    if r.nut_types is not None:
        nuts = nuts.take(nuts.isin("type", r.nut_types))
    if r.bearing_arrangements is not None:
        bearings = bearings.take(bearings.isin("arrangement", r.bearing_arrangements))
    if r.bearing_preload is not None:
        bearings = bearings.take(bearings.isin("preload_class", r.bearing_preload))
    if r.guide_types is not None:
        guides = guides.take(guides.isin("type", r.guide_types))
    if r.guide_preload is not None:
        guides = guides.take(
            guides.isin("preload_level", r.guide_preload)
            | guides.isin("preload_class", r.guide_preload)
        )
    screws, nuts = _filtered(screws, r, "screw"), _filtered(nuts, r, "nut")
    # a linear scale on the table is not supported with a driven rotating-nut unit (evaluate
    # refuses that design; a required unit is refused as the problem is read): offered units are
    # left out
    if problem.axis.feedback == "linear_scale" and "rotating" in nuts:
        nuts = nuts.take(~(np.nan_to_num(nuts.number("rotating")) == 1.0))
    bearings, guides = _filtered(bearings, r, "bearing"), _filtered(guides, r, "guide")
    nuts = nuts.take(nuts.isin("screw_id", set(screws.ids)))
    # the problem's preload bounds are for preloaded nuts; a single nut keeps its catalog range
    single = nuts["type"] == "single"
    lo = np.where(
        single,
        nuts.number("preload_min"),
        np.maximum(nuts.number("preload_min"), problem.preload_min),
    )
    hi = np.where(
        single,
        nuts.number("preload_max"),
        np.minimum(nuts.number("preload_max"), problem.preload_max),
    )
    # the vendors' preload ceiling (check nut_preload: 10 % Ca) bounds the range of a preloaded nut,
    # as the vendors' own preload ranges do: the search never goes above it, so it needs no
    # constraint of its own
    hi = np.where(
        single, hi, np.minimum(hi, pnut.preload_ceiling(nuts.number("dynamic_load_rating")))
    )
    keep = lo <= hi
    nuts, lo, hi = nuts.take(keep), lo[keep], hi[keep]
    # an empty part slot leaves no combination at all: a one-line error naming it (not an
    # "infeasible" result whose explanation has nothing to score)
    for t, what, filters in (
        (
            nuts,
            "screw and nut",
            "vendors, nut_types, status, require/exclude; "
            "continuous.nut_preload and the 10 % Ca preload ceiling for preloaded nuts",
        ),
        (
            bearings,
            "support bearing",
            "vendors, bearing_arrangements, bearing_preload, status, require/exclude",
        ),
        (guides, "linear guide", "vendors, guide_types, guide_preload, status, require/exclude"),
    ):
        if len(t) == 0:
            raise InputError(
                f"the search has nothing to choose from: no {what} is left after the filters "
                f"(catalog: {filters})",
                source=problem.source,
            )
    screws_al = cat.rows("screws").by_id(list(nuts["screw_id"]))
    grades = None
    # each nut row once per grade of its screw the search may choose (screw x grade)
    if _grades_chosen(problem):
        rep, grades = screw_grade_rows(problem, screws_al, model.nut_length(screws_al, nuts))
        nuts, lo, hi, screws_al = nuts.take(rep), lo[rep], hi[rep], screws_al.take(rep)
        if len(nuts) == 0:
            raise InputError(
                "the search has nothing to choose from: no screw left is made in the grades "
                f"catalog.screw_grades allows ({', '.join(r.screw_grades or ())}) over a "
                f"{problem.axis.stroke * 1e3:.0f} mm stroke (catalogs/screw_grades.csv, "
                "lead_tolerances.csv)",
                source=problem.source,
            )
    # the bearing journal rule is the model's margin_bearing_fit check; no extra pairing rule here
    fits = np.ones((len(nuts), len(bearings)), dtype=bool)
    sp = Space(
        problem=problem,
        mountings=tuple(problem.mountings),
        screws=screws_al,
        nuts=nuts,
        bearings=bearings,
        guides=guides,
        preload_lo=lo,
        preload_hi=hi,
        fits=fits,
    )
    sp.s_arr = _arrays(screws_al, _SCREW_COLS)
    if grades is not None:
        sp.grades = grades
        sp.s_arr["grade"] = grades
    sp.n_arr = _arrays(nuts, _NUT_COLS)
    sp.b_arr = _arrays(bearings, _BEARING_COLS)
    sp.g_arr = _arrays(guides, _GUIDE_COLS)
    _add_drives(sp, problem)
    D = len(sp.drives)
    sp.n_drives = D
    sp.shape = (len(sp.mountings), len(nuts), len(bearings), len(guides) * D)
    sp.size = int(np.prod(sp.shape))
    sp.pruned_by_dominance = int(sp.size // D * sp.pairs_left_out)
    # each block covers every bearing and (mechanical) guide
    Gm = sp.shape[3] // (D if sp.m_arr is not None else 1)
    sp.nuts_per_block = max(1, SCREEN_CHUNK // max(sp.shape[2] * Gm, 1))
    return sp


def drive_stiffnesses(sp: Space) -> np.ndarray:
    """The torsional stiffness between motor side and screw [N m/rad] of each searched drive (D,):
    its coupling's (the axis value without one) in series with its reduction's (none: rigid), as
    :func:`axisopt.model.chain. drive_torsional_stiffness` takes them."""
    D = sp.n_drives
    k = (
        sp.c_arr["torsional_stiffness"][:D]
        if sp.c_arr is not None
        else np.full(D, float(sp.problem.axis.coupling_stiffness))
    )
    if sp.r_arr is None:
        return k
    with np.errstate(divide="ignore", invalid="ignore"):
        c_red = np.nan_to_num(1.0 / sp.r_arr["torsional_stiffness"][:D], nan=0.0)
    return drive_torsional_stiffness({"coupling_stiffness": k, "reduction_compliance": c_red})


def _filtered(t, r, slot, series=None, vendors=None):
    """Rows of a part table the problem allows in ``slot``: vendor and series filters, require,
    exclude."""
    if vendors is not None:
        t = t.take(t.isin("vendor", vendors))
    if series is not None:
        t = t.take(t.isin("series", series))
    req, exc = r.required(slot), r.excluded(slot)
    if req:
        t = t.take(t.isin("id", req))
    if exc:
        t = t.take(~t.isin("id", exc))
    return t


def coupling_dominated(cp) -> np.ndarray:
    """Couplings another coupling beats on every count the model uses: at least its rated torque,
    torsional stiffness and maximum speed, at most its inertia and price, and better on one of them
    (mass and bore do not enter the model; a dominated coupling can never be the better choice)."""
    a = {
        c: np.asarray(cp[c], dtype=float)
        for c in ("rated_torque", "torsional_stiffness", "max_speed", "inertia", "price")
    }
    ge = (
        (a["rated_torque"][:, None] >= a["rated_torque"][None])
        & (a["torsional_stiffness"][:, None] >= a["torsional_stiffness"][None])
        & (a["max_speed"][:, None] >= a["max_speed"][None])
        & (a["inertia"][:, None] <= a["inertia"][None])
        & (a["price"][:, None] <= a["price"][None])
    )
    gt = (
        (a["rated_torque"][:, None] > a["rated_torque"][None])
        | (a["torsional_stiffness"][:, None] > a["torsional_stiffness"][None])
        | (a["max_speed"][:, None] > a["max_speed"][None])
        | (a["inertia"][:, None] < a["inertia"][None])
        | (a["price"][:, None] < a["price"][None])
    )
    return (ge & gt).any(axis=0)


def _add_drives(sp: Space, problem: Problem) -> None:
    """The (motor, coupling, reduction) drives the search chooses from, spread over the guide
    axis."""
    r = problem.restrictions
    cat = problem.catalog
    if not r.drive or len(cat.rows("motors")) == 0:
        return
    motors = _filtered(cat.rows("motors"), r, "motor", r.motor_series, r.motor_vendors)
    if r.max_motor_flange is not None:  # a motor without a listed flange cannot be shown to fit
        motors = motors.take(motors.number("flange") <= r.max_motor_flange * (1 + 1e-9))
    if r.estimated == "exclude":
        before = len(motors)
        motors = vendor_filled(motors, "motors")
        # the filter, not the catalog, left no motor: say which (docs/assumptions.md)
        if before and not len(motors):
            raise InputError(
                f"'exclude' removed all {before} motors the other filters left, so the drive "
                "search has nothing to choose from (the peak-torque zone above the corner speed is "
                "estimated for every motor without peak_corner_speed and peak_torque_at_max_speed "
                "read from its vendor's torque-speed curve); add those columns to a motors table, "
                "allow estimated values, or leave the drive out (catalog.drive: no)",
                source=problem.source,
                where="key 'catalog.estimated'",
            )
    couplings = _filtered(cat.rows("couplings"), r, "coupling", r.coupling_series)
    n_couplings = len(couplings)
    if len(couplings) and not r.required("coupling"):
        couplings = couplings.take(~coupling_dominated(couplings))
    reductions = cat.rows("reductions")
    if r.reductions:
        reductions = _filtered(reductions, r, "reduction")
        if not r.required("reduction") and "status" in reductions:
            reductions = reductions.take(reductions.isin("status", tuple(r.status)))
    else:
        reductions = reductions.take(np.zeros(len(reductions), dtype=bool))
    # a reduction's backlash is lost motion at the table (model.drive.lost_motion), least on the
    # shortest lead: a reduction that exceeds the problem's max_backlash even there is never formed
    backlash_max = problem.limit_map.get("max_backlash", np.inf)
    lead_min = float(np.min(sp.s_arr["lead"])) if len(sp.s_arr["lead"]) else 0.0
    if len(reductions):
        lost = reductions.number("backlash") * lead_min / (2.0 * np.pi)
        keep = lost <= backlash_max * (1.0 + 1e-9) + 1e-15
        if not r.required("reduction") or keep.any():
            sp.reductions_by_backlash = int(np.count_nonzero(~keep))
            sp.backlash_left_least = float(np.min(lost[~keep], initial=np.inf))
            reductions = reductions.take(keep)
    # the drive's reduction: none (the axis's values; left out when the problem requires reduction
    # parts) or a row
    choices = ([] if r.required("reduction") else [None]) + list(range(len(reductions)))
    ratios = [
        float(problem.axis.reduction_ratio) if ri is None else float(reductions.number("ratio")[ri])
        for ri in choices
    ]
    need = problem.margin_map.get("coupling_torque", 1.0)
    limit = np.inf if problem.axis.torque_limit is None else float(problem.axis.torque_limit)
    # the motor speed the cycle asks is smallest on the longest lead of the space (model.drive: 2 pi
    # v / P_h x ratio); a (motor, reduction) that fails the motor-speed or reduction-speed check
    # even there fails it on every screw, and is never formed (a check disabled by a margin of 0
    # prunes nothing)
    v_max = _top_speed(problem)
    lead_max = float(np.max(sp.s_arr["lead"])) if len(sp.s_arr["lead"]) else np.inf
    speed_need = {k: problem.margin_map.get(k, 1.0) for k in ("motor_speed", "reduction_speed")}
    red_speed = reductions.number("max_input_speed") if len(reductions) else np.zeros(0)

    def too_fast(mi, ri, ratio):
        n_min = 2.0 * np.pi * v_max / lead_max * ratio
        if n_min * speed_need["motor_speed"] > float(motors.number("max_speed")[mi]) * (
            1.0 + 1e-12
        ):
            return True
        return ri is not None and n_min * speed_need["reduction_speed"] > float(red_speed[ri]) * (
            1.0 + 1e-12
        )

    def drive_pairs(prune: bool):
        pairs = []
        for mi in range(len(motors)):
            for ri, ratio in zip(choices, ratios):
                if prune and too_fast(mi, ri, ratio):
                    continue
                if len(couplings) == 0:
                    pairs.append((mi, None, ri))
                    continue
                # a torque limit caps it
                peak = min(float(motors.number("peak_torque")[mi]), limit) * ratio
                # the coupling-torque check depends on the drive only: drives that fail it are never
                # formed
                ok = couplings.number("rated_torque") >= need * peak * (1.0 - 1e-12)
                if not prune:
                    ok = np.ones(len(couplings), dtype=bool)
                pairs.extend((mi, int(ci), ri) for ci in np.nonzero(ok)[0])
        return pairs

    pairs = drive_pairs(prune=True)
    if not pairs:
        # every drive fails its speed or coupling-torque check: a valid problem no design meets, not
        # an input error; every drive is formed, the model's checks then prove the infeasibility and
        # the explanation names the check (and the advice the filter to widen)
        pairs = drive_pairs(prune=False)
    if not pairs:
        why = (
            "no motor is left after the motor filters"
            if len(motors) == 0
            else "no reduction is left after the filters"
        )
        raise InputError(
            f"the drive search has nothing to choose from: {why} (catalog: motor_vendors, "
            "motor_series, max_motor_flange, reductions, require/exclude)",
            source=problem.source,
        )
    sp.motors, sp.couplings = motors, couplings
    sp.reductions = reductions if len(reductions) else None
    sp.drives = tuple(pairs)
    sp.pairs_left_out = len(motors) * max(n_couplings, 1) * len(choices) - len(pairs)
    D = len(pairs)
    sp.g_arr = {k: np.repeat(v, D) for k, v in sp.g_arr.items()}
    G = len(sp.guides)
    mpos = np.array([m for m, _, _ in pairs], dtype=np.int64)
    sp.m_arr = {k: np.tile(motors.number(k)[mpos], G) for k in _MOTOR_COLS}
    if len(couplings):
        cpos = np.array([c for _, c, _ in pairs], dtype=np.int64)
        sp.c_arr = {k: np.tile(couplings.number(k)[cpos], G) for k in _COUPLING_COLS}
    if sp.reductions is not None:
        # a drive without a reduction: NaN in every column (model.params.reduction_params: the
        # axis's values)
        rpos = np.array([-1 if ri is None else ri for _, _, ri in pairs], dtype=np.int64)
        sp.r_arr = {
            k: np.tile(np.where(rpos >= 0, reductions.number(k)[np.maximum(rpos, 0)], np.nan), G)
            for k in _REDUCTION_COLS
        }
