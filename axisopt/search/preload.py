"""The exact preload solve of selected combinations (:func:`exact_solve`): for each, the best
preload and the exact objective on the full position grid, vectorized per mounting.

It rests on the preload structure the model declares (``axisopt.model.limits.OUTPUT_PRELOAD``, see
:mod:`.task.constraints`): the feasible preloads of a combination are an interval and the best
preload is its upper end.  A threshold search (:func:`kary_threshold`) finds the largest preload
meeting the limits that favour a low preload; a motor-torque limit (convex in the preload) lowers it
into its interval (:func:`convex_feasible_top`); the limits that favour a high preload are then
checked there.

Its one-dimensional numerics are vectorized over combinations and free of the model: the k-ary
threshold search (:func:`kary_threshold`, bisection generalised to ``points`` trials per round) and
the golden-section maximum of a unimodal function (:func:`golden_best`; Kiefer, "Sequential minimax
search for a maximum", Proc. AMS 4 (1953) 502-506).
"""

from __future__ import annotations

import math
from dataclasses import fields

import numpy as np

from .. import model
from ..model.goals import RESULT_GOALS
from .result import Exact
from .task.constraints import Constraint, as_vector, ok_all, reads_regen
from .task.objective import ObjectiveSpec
from .task.space import DRIVE_KEYS, Space, respond, respond_drive

SEARCH_ROWS = 4096  # threshold search: combinations times preloads per model evaluation, about
GOLDEN_STEPS = 60  # golden-section steps for the most favourable preload of a convex limit
BISECTION_STEPS = 52
# k-ary threshold search (default method): most preloads tried per round in one evaluation
SEARCH_POINTS = 64
# exact_solve: bits of the threshold bracket after which the combinations that miss a limit a higher
# preload helps even at its upper end are dropped (the rest refined to BISECTION_STEPS)
COARSE_BITS = 8


def golden_best(value, a, b, steps=GOLDEN_STEPS):
    """Preload in [a, b] maximising a unimodal ``value(preload) -> (K,)`` (vectorized golden
    section)."""
    r = (math.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = b - r * (b - a), a + r * (b - a)
    f1, f2 = value(x1), value(x2)
    for _ in range(steps):
        left = f1 >= f2
        b = np.where(left, x2, b)
        a = np.where(left, a, x1)
        x2n = np.where(left, x1, a + r * (b - a))
        x1n = np.where(left, b - r * (b - a), x2)
        x1, x2 = x1n, x2n
        f1, f2 = value(x1), value(x2)
    return np.where(f1 >= f2, x1, x2)


def kary_threshold(good, a, z, points: int = SEARCH_POINTS):
    """The end of the set ``good`` holds on, between a end ``a`` where it holds and ``z`` where it
    does not, for a set that is one interval containing ``a`` (a monotone limit, or a convex one
    seen from a feasible point).  Each round tries ``points - 1`` evenly spaced preloads in one
    vectorized call of ``good(pre (K, points - 1)) -> bool (K, points - 1)`` and keeps the segment
    where it stops holding, so the bracket shrinks ``points``-fold per round: to the bisection's
    2^-52 in 9 calls instead of 52."""
    return kary_bracket(good, a, z, points)[0]


def kary_rounds(points: int, bits: int = BISECTION_STEPS) -> int:
    """Rounds of :func:`kary_bracket` with ``points`` that shrink a bracket 2^``bits``-fold."""
    return math.ceil(bits / math.log2(points))


def kary_bracket(good, a, z, points: int = SEARCH_POINTS, rounds: int | None = None):
    """:func:`kary_threshold`'s bracket (a where ``good`` holds, z above the threshold) after
    ``rounds`` rounds (default: :func:`kary_rounds`, to the bisection's 2^-52)."""
    a, z = np.array(a, dtype=float), np.array(z, dtype=float)
    if not a.size:
        return a, z
    t = np.arange(1, points) / points
    rows = np.arange(len(a))
    for _ in range(kary_rounds(points) if rounds is None else rounds):
        pts = a[:, None] + (z - a)[:, None] * t[None, :]
        ok = np.asarray(good(pts), dtype=bool).reshape(pts.shape)
        lead = np.cumprod(ok, axis=1).sum(axis=1)  # points that hold before the first that does not
        a_new = np.where(lead > 0, pts[rows, np.maximum(lead - 1, 0)], a)
        z = np.where(lead < points - 1, pts[rows, np.minimum(lead, points - 2)], z)
        a = a_new
    return a, z


def search_points(k: int) -> int:
    """Preloads per round of :func:`kary_threshold` for ``k`` combinations: many while a model
    evaluation costs mostly its fixed Python overhead (few combinations), 2 (bisection) once the
    rows cost more."""
    return int(max(2, min(SEARCH_POINTS, 2 ** round(math.log2(SEARCH_ROWS / max(k, 1) + 1)))))


def subset(p: dict, j, k: int) -> dict:
    """The parameters of rows ``j`` of a flat layout of ``k`` combinations (the duty cycle is
    shared)."""
    return {
        kk: (v[j] if kk != "duty" and np.ndim(v) and np.shape(v)[0] == k else v)
        for kk, v in p.items()
    }


def repeat_rows(p: dict, k: int, r: int) -> dict:
    """A flat layout of ``k`` combinations with every row repeated ``r`` times (row i*r + j is row
    i)."""
    return {
        kk: (np.repeat(v, r, axis=0) if kk != "duty" and np.ndim(v) and np.shape(v)[0] == k else v)
        for kk, v in p.items()
    }


def new_exact(idx) -> Exact:
    """An Exact of the combinations ``idx`` with nothing solved yet (infeasible, objective -inf,
    goals NaN)."""
    K = len(idx)
    return Exact(
        idx,
        np.zeros(K, bool),
        np.full(K, np.nan),
        np.full(K, -np.inf),
        {g.key: np.full(K, np.nan) for g in RESULT_GOALS},
    )


def concat_exact(parts) -> Exact:
    """One Exact of the combinations of ``parts`` (in order)."""
    return Exact(
        *(
            np.concatenate([getattr(p, f.name) for p in parts])
            for f in fields(Exact)
            if f.name != "goals"
        ),
        {g.key: np.concatenate([p.goals[g.key] for p in parts]) for g in RESULT_GOALS},
    )


def goal_arrays(out: dict, K: int, goals=RESULT_GOALS) -> dict:
    """Goal key -> (K,) value in the goal's display unit of the model outputs ``out`` of K
    combinations, for each of ``goals`` whose output ``out`` holds: the minimum over the stroke of a
    profile, divided by the display factor (the values :class:`.result.Exact` carries)."""
    return {
        g.key: as_vector(np.min(out[g.output], axis=-1) if g.profile else out[g.output], K)
        / g.factor
        for g in goals
        if g.output in out
    }


def exact_solve(
    space: Space, idx, constraints, objective: ObjectiveSpec, *, need=("k_total", "f1")
) -> Exact:
    """Best preload (upper end of the feasible preload interval) and the exact objective on the full
    position grid for the combinations ``idx`` (any mix of mountings), vectorized per mounting.

    Assumes the preload structure in the module docstring: a threshold search
    (:func:`kary_threshold`: up to 63 preloads per vectorized round for few combinations, bisection
    for many) finds the largest preload meeting the upper-type constraints (drag, life); the
    lower-type ones (lift-off, minimum stiffness or frequency) are then checked there.
    """
    idx = np.asarray(idx, dtype=np.int64)
    K = len(idx)
    res = new_exact(idx)
    if K == 0:
        return res
    up = [c for c in constraints if c.direction != 0 and c.upper_type]
    low = [c for c in constraints if c.direction != 0 and c.lower_type]
    cvx = [c for c in constraints if c.convex]
    indep = [c for c in constraints if c.direction == 0]
    for mounting, sel, n, b, g, p, x in space.by_mounting(idx):
        k = len(sel)
        x1 = x[-1:]
        lo = space.preload_lo[n][:, None]
        hi = space.preload_hi[n][:, None]
        out_lo = respond(p, x1, mounting, lo, space.request)
        ok = ok_all(indep, out_lo, k) & space.fits[n, b]
        ok_up_lo = ok_all([c for c in up if not c.profile], out_lo, k)
        out_hi = respond(p, x1, mounting, hi, space.request)
        ok_up_hi = ok_all([c for c in up if not c.profile], out_hi, k)
        a = lo[:, 0].copy()  # feasible end
        bb = hi[:, 0].copy()  # infeasible end (unless ok_up_hi)
        need_bis = ok & ok_up_lo & ~ok_up_hi
        if need_bis.any():
            j = np.nonzero(need_bis)[0]
            upc = [c for c in up if not c.profile]
            # the threshold of limits the drive does not change is the mechanical combination's:
            # searched once per (nut, bearing, guide) and shared by its drives (guide-and-drive
            # index g = guide * D + drive)
            inv = np.arange(len(j))
            if space.n_drives > 1 and not any(c.key in DRIVE_KEYS for c in upc):
                mech = (n[j] * space.shape[2] + b[j]) * (space.shape[3] // space.n_drives) + g[
                    j
                ] // space.n_drives
                _, first, inv = np.unique(mech, return_index=True, return_inverse=True)
                j_all, j = j, j[first]
            else:
                j_all = j
            P = search_points(len(j))
            pr = repeat_rows(subset(p, j, k), len(j), P - 1)

            # only the sub-assemblies these limits read (the chain, the drive block, the regenerated
            # energy)
            parts = space.request.but(
                drive=any(c.key in DRIVE_KEYS for c in upc),
                chain=any(c.key in model.CHAIN_OUTPUTS for c in upc),
                regen=reads_regen(upc),
            )

            def good(pre, pr=pr, upc=upc, x1=x1, mounting=mounting, parts=parts):
                return ok_all(upc, respond(pr, x1, mounting, pre.reshape(-1, 1), parts), pre.size)

            first_rounds = min(kary_rounds(P, COARSE_BITS), kary_rounds(P))
            a0, z0 = kary_bracket(good, a[j], bb[j], P, first_rounds)
            a[j_all] = a0[inv]
            # a limit a higher preload helps (lift-off, minimum stiffness or frequency) missed at
            # the bracket's upper end misses at every preload below it, the threshold among them:
            # those combinations are infeasible, their threshold not refined (the answer is the
            # same)
            if low:
                zr = z0[inv]
                sub = subset(p, j_all, k)
                out_z = respond(sub, x, mounting, zr[:, None], space.request)
                ok[j_all] &= ok_all(low, out_z, len(j_all))
            rest = ok[j_all]
            if rest.any():
                # refine the threshold of the mechanical rows some combination still needs
                need = np.zeros(len(j), dtype=bool)
                need[inv[rest]] = True
                r = np.nonzero(need)[0]
                if len(r) < len(j):
                    pr_r = repeat_rows(subset(p, j[r], k), len(r), P - 1)

                    def good_r(pre, pr=pr_r, upc=upc, x1=x1, mounting=mounting, parts=parts):
                        return ok_all(
                            upc, respond(pr, x1, mounting, pre.reshape(-1, 1), parts), pre.size
                        )

                else:
                    good_r = good
                a_r, _ = kary_bracket(good_r, a0[r], z0[r], P, kary_rounds(P) - first_rounds)
                a0[r] = a_r
                a[j_all] = a0[inv]
        pstar = np.where(ok_up_hi, hi[:, 0], a)
        ok &= ok_up_lo
        for c in cvx:  # lower the preload into each motor-torque interval (drag and life stay met)
            j = np.nonzero(ok)[0]
            if len(j):
                ex, top = convex_feasible_top(c, subset(p, j, k), x1, mounting, lo[j, 0], pstar[j])
                ok[j] &= ex
                pstar[j] = np.where(ex, top, pstar[j])
        out = respond(p, x, mounting, pstar[:, None], space.request)
        ok &= ok_all(cvx, out, k)
        ok &= ok_all(low, out, k)
        ok &= ok_all([c for c in up if c.profile], out, k)
        J = np.broadcast_to(objective.value(out), (k,))
        res.feasible[sel] = ok
        res.preload[sel] = pstar
        res.objective[sel] = np.where(ok, J, -np.inf)
        for key, v in goal_arrays(out, k).items():
            res.goals[key][sel] = v
    return res


def convex_feasible_top(c: Constraint, p: dict, x1, mounting: str, lo, top):
    """For a convex (interval) limit: the largest preload in [lo, top] meeting it, per combination.
    Returns (exists, preload).  Met at ``top``: top.  Else met at ``lo``: threshold search from lo
    (:func:`kary_threshold`; the limit's interval contains lo and ends below top).  Else: its most
    favourable preload by golden section, then the threshold search from there."""
    K = len(lo)
    lo, top = np.asarray(lo, float), np.asarray(top, float)

    def value(pj, pre):
        return as_vector(c.value(respond_drive(pj, pre[:, None], reads_regen([c]))), len(pre))

    exists = c.ok(value(p, top)).astype(bool)
    pb = top.copy()
    j = np.nonzero(~exists)[0]
    if len(j):
        pj = subset(p, j, K)
        start = np.where(c.ok(value(pj, lo[j])), lo[j], np.nan)
        g = np.nonzero(np.isnan(start))[0]
        if len(g):
            pg = subset(pj, g, len(j))
            best = golden_best(lambda pre: value(pg, pre), lo[j][g], top[j][g])
            start[g] = np.where(c.ok(value(pg, best)), best, np.nan)
        has = np.isfinite(start)
        h = np.nonzero(has)[0]
        if len(h):
            P = search_points(len(h))
            pr = repeat_rows(subset(pj, h, len(j)), len(h), P - 1)
            pb[j[h]] = kary_threshold(
                lambda pre: c.ok(value(pr, pre.reshape(-1))), start[h], top[j][h], P
            )
        exists[j] = has
    return exists, pb


def convex_interval(c: Constraint, p: dict, x1, mounting: str, lo, hi):
    """For a convex limit: (exists, low end, high end) of the preloads in [lo, hi] meeting it, found
    without assuming anything but convexity (golden section for a feasible point, then a bisection
    to each side)."""
    K = len(lo)
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)

    def value(pj, pre):
        return as_vector(c.value(respond_drive(pj, pre[:, None], reads_regen([c]))), len(pre))

    ok_lo, ok_hi = (c.ok(value(p, v)).astype(bool) for v in (lo, hi))
    start = np.where(ok_lo, lo, hi)
    exists = ok_lo | ok_hi
    # met at neither end: look for the most favourable preload in between
    g = np.nonzero(~exists)[0]
    if len(g):
        pg = subset(p, g, K)
        best = golden_best(lambda pre: value(pg, pre), lo[g], hi[g])
        exists[g] = c.ok(value(pg, best)).astype(bool)
        start[g] = best
    ends = []
    for edge, ok_edge in ((lo, ok_lo), (hi, ok_hi)):
        end = edge.copy()
        # the interval stops short of this edge: bisect for its end
        j = np.nonzero(exists & ~ok_edge)[0]
        if len(j):
            pj = subset(p, j, K)
            a, z = start[j], edge[j]
            for _ in range(BISECTION_STEPS):
                mid = 0.5 * (a + z)
                good = c.ok(value(pj, mid)).astype(bool)
                a = np.where(good, mid, a)
                z = np.where(good, z, mid)
            end[j] = a
        ends.append(end)
    return exists, ends[0], ends[1]


def solve_known(space: Space, idx, constraints, objective: ObjectiveSpec, known=None):
    """:func:`exact_solve` of the combinations ``idx``, the feasible rows of ``known`` (an Exact, or
    None) copied from it rather than solved again (see :func:`.bestfirst.bound_order_search`)."""
    idx = np.asarray(idx, dtype=np.int64)
    if known is None or not len(idx) or not len(known.idx):
        return exact_solve(space, idx, constraints, objective)
    order = np.argsort(known.idx, kind="stable")
    keys = known.idx[order]
    at = np.minimum(np.searchsorted(keys, idx), len(keys) - 1)
    src = order[at]
    hit = (keys[at] == idx) & known.feasible[src]
    if not hit.any():
        return exact_solve(space, idx, constraints, objective)
    res = new_exact(idx)
    h, s = np.nonzero(hit)[0], src[hit]
    res.feasible[h], res.preload[h], res.objective[h] = True, known.preload[s], known.objective[s]
    for key, v in known.goals.items():
        res.goals[key][h] = v[s]
    miss = np.nonzero(~hit)[0]
    if len(miss):
        ex = exact_solve(space, idx[miss], constraints, objective)
        res.feasible[miss], res.preload[miss], res.objective[miss] = (
            ex.feasible,
            ex.preload,
            ex.objective,
        )
        for key, v in ex.goals.items():
            res.goals[key][miss] = v
    return res
