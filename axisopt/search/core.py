"""Default (bound-ordered, proven) and exhaustive searches for scalar objectives.

Default method
    0. *Blocks* (:func:`bound_order_search`): each (mounting, nut, bearing) block of combinations -- all its
       guides and drives -- is tested and bounded at once with an optimistic guide (the most favourable
       value of every guide column); blocks are screened best-first and only while their bound can still
       reach the incumbent, so most of the product is never formed.
    1. *Screening* (the combinations of a block, vectorized, structured broadcasting): every preload-independent
       limit is checked exactly; each preload-dependent limit at its most favourable preload (drag and
       life at the lowest allowed preload, lift-off and minimum stiffness/frequency at the highest),
       which is exact as a necessary condition.  The bound is the objective at the highest allowed
       preload over a few grid positions (an upper bound of the minimum over the full grid).
    2. *Bound order*: the survivors are solved in decreasing bound, in growing vectorized batches
       (exact 1-D solve of the preload: threshold search on the monotone limits, objective on the full grid),
       until no remaining bound can reach the incumbent (the N-th best for ``top`` N).  The gap is 0
       then; the pruned count is the certificate.
    3. The winners' continuous problem is re-solved by IPOPT on the CasADi model (the reported preload)
       and cross-checked against the 1-D solve.

Exhaustive method
    Every combination, no bounds and no screening: each limit is checked exactly on every combination
    (the preload-dependent ones by their own bisection, the motor-torque ones by their interval), and the
    preload problem of each combination that some preload can make feasible is solved on a grid of that
    feasible interval (this does not assume that the objective grows with the preload), chunked and
    vectorized.  IPOPT polishes the winners as in the default method.
"""

from __future__ import annotations

import time

import numpy as np

from .. import model
from ..design import Design
from ..model.limits import LIMITS
from . import nlp
from .result import Candidate, Certificate
from .space import (
    BISECTION_STEPS,
    DRIVE_KEYS,
    N_PER_UM,
    SCREEN_CHUNK,
    Exact,
    ObjectiveSpec,
    Space,
    _ok_all,
    _vec,
    convex_interval,
    convex_margin_bound,
    exact_solve,
    objective_floor,
    rank_order,
    respond,
    subset,
)

SCREEN_RTOL = 1e-4  # float32 screening: relative slack on every test and on the bound


# ------------------------------------------------------------------------------------ screening
def screen(space: Space, constraints, objective: ObjectiveSpec):
    """Vectorized screening of every combination.  Returns (idx, bound, seconds) for the survivors.

    Two structured evaluations per block of nuts: at the lowest allowed preload on one position (the
    preload-independent limits and the ones that favour a low preload) and at the highest allowed
    preload on :meth:`Space.bound_positions` (the limits that favour a high preload and the bound).
    Screening runs in float32 for memory bandwidth; every test is relaxed by SCREEN_RTOL and the bound
    raised by it, so rounding can only keep a combination, never drop one (exact checks follow in
    float64).

    The mechanics are screened once per (screw, nut, bearing, guide) combination on every limit the drive
    does not change (the stiffness chain, the modes, the objective bound); each surviving combination is
    then expanded by its (motor, coupling) pairs -- one, the axis's motor and coupling values, without a
    drive search -- and screened on the drive's limits (:data:`DRIVE_KEYS`) with the drive sub-assembly
    alone.  (Without a drive search this two-stage order is 3x faster too: the motor-torque bounds then run
    on the few mechanical survivors.)
    """
    t0 = time.perf_counter()
    N = space.shape[1]
    step = space.nuts_per_screen()
    idx_parts, bound_parts = [], []
    for mi in range(len(space.mountings)):
        for n0 in range(0, N, step):
            i, bnd = screen_nuts(space, mi, slice(n0, min(N, n0 + step)), constraints, objective)
            idx_parts.append(i)
            bound_parts.append(bnd)
    idx = np.concatenate(idx_parts) if idx_parts else np.zeros(0, np.int64)
    bound = np.concatenate(bound_parts) if bound_parts else np.zeros(0)
    return idx, bound, time.perf_counter() - t0


def _mechanical(constraints):
    return [c for c in constraints if c.key not in DRIVE_KEYS]


CACHE_BLOCK = 200_000  # (nut, bearing, guide) combinations per evaluation inside screen_nuts (cache-sized arrays)


def screen_nuts(space: Space, mi: int, nuts, constraints, objective: ObjectiveSpec, premask=None):
    """:func:`screen` over the nuts ``nuts`` (a slice or an index array) of mounting ``mi``, every bearing
    and guide (and drive); ``premask`` (nuts x bearings, optional) leaves out (nut, bearing) blocks.
    Returns the survivors' combination numbers and bounds.  The model is evaluated over sub-blocks of about
    :data:`CACHE_BLOCK` combinations (whole nuts): numpy then works on arrays that stay in the CPU cache,
    about twice as fast as over millions of combinations at once; the survivors are the same."""
    mounting = space.mountings[mi]
    _, N, B, G = space.shape
    D = space.n_drives
    Gm = G // D  # guide axis of the mechanical stage
    phases = space.problem.axis_for(mounting).phases
    nut_idx = np.arange(N)[nuts] if isinstance(nuts, slice) else np.asarray(nuts, dtype=np.int64)
    step = max(1, CACHE_BLOCK // max(B * Gm, 1))
    parts = []
    for s0 in range(0, len(nut_idx), step):
        s1 = min(len(nut_idx), s0 + step)
        if isinstance(nuts, slice):
            sub = slice(int(nut_idx[s0]), int(nut_idx[s1 - 1]) + 1) if len(nut_idx) else nuts
        else:
            sub = nut_idx[s0:s1]
        pm = None if premask is None else premask[s0:s1]
        parts.append(_screen_mechanics(space, mounting, sub, nut_idx[s0:s1], constraints, objective, pm))
    if parts:
        nn, bb, gg, bnd = (np.concatenate([q[i] for q in parts]) for i in range(4))
    else:
        nn, bb, gg, bnd = (np.zeros(0, np.int64),) * 3 + (np.zeros(0),)
    nn, bb, gg, bnd = _screen_drives(space, mounting, constraints, phases, nn, bb, gg, bnd)
    return np.ravel_multi_index((np.full(len(nn), mi), nn, bb, gg), space.shape), bnd


def _screen_mechanics(space: Space, mounting: str, nuts, nut_idx, constraints, objective: ObjectiveSpec, premask):
    """The mechanical stage of :func:`screen_nuts` over the nuts ``nuts`` (numbers ``nut_idx``): every limit
    but the drive's (:data:`DRIVE_KEYS`, which hold the motor-torque limits, the only convex ones), and the
    bound.  Returns the survivors' (nut, bearing, guide, bound)."""
    _, _, B, G = space.shape
    Gm = G // space.n_drives
    mech = _mechanical(constraints)
    low_end = [c for c in mech if not c.lower_type]  # independent or favoured by a low preload
    high_end = [c for c in mech if c.lower_type]
    xs = space.bound_positions(mounting).astype(np.float32)
    x1 = xs[-1:]
    p = space.params_structured(mounting, nuts, dtype=np.float32, mechanics=True)
    lo = space.preload_lo[nut_idx].reshape(-1, 1, 1, 1).astype(np.float32)
    hi = space.preload_hi[nut_idx].reshape(-1, 1, 1, 1).astype(np.float32)
    nc = len(nut_idx)
    fits = space.fits[nut_idx] if premask is None else space.fits[nut_idx] & premask
    mask = np.broadcast_to(fits[:, :, None], (nc, B, Gm)).copy()
    with np.errstate(all="ignore"):
        chain_lo = any(c.key in model.CHAIN_OUTPUTS for c in low_end)
        out_lo = model.axis_response(p, x1, mounting, lo, extras=False, drive_block=False, chain=chain_lo)
        for c in low_end:
            mask &= _screen_ok(c, out_lo)
        out = model.axis_response(p, xs, mounting, hi, extras=False, drive_block=False)
        for c in high_end:
            mask &= _screen_ok(c, out)
        bound = objective.value(out)
    bound = np.broadcast_to(bound + SCREEN_RTOL * np.abs(bound), (nc, B, Gm))
    nn, bb, gg = np.nonzero(mask)
    return nut_idx[nn], bb, gg, bound[nn, bb, gg].astype(float)


def block_bounds(space: Space, constraints, objective: ObjectiveSpec):
    """Per (mounting, nut, bearing) block of combinations: whether some guide (and drive) could meet the
    mechanical limits, and an upper bound of the objective over the block, both from one evaluation with
    the optimistic guide of each guide type (:meth:`Space.params_optimistic_guide`).  Limits the drive
    changes, and the motor-torque limits, are left to the screening.  Returns a list over mountings of
    (ok, bound), each nuts x bearings."""
    _, N, B, _ = space.shape
    # every mechanical limit, and the cost (the optimistic guide carries the cheapest drive pair's price)
    mech = [c for c in constraints if not c.convex and (c.key not in DRIVE_KEYS or c.key == "cost")]
    low_end = [c for c in mech if not c.lower_type]
    high_end = [c for c in mech if c.lower_type]
    types = np.unique(space.g_arr["type"]) if len(space.guides) else np.array([], dtype=str)
    step = max(1, SCREEN_CHUNK // max(B, 1))
    out = []
    for mounting in space.mountings:
        xs = space.bound_positions(mounting).astype(np.float32)
        ok_all = np.zeros((N, B), dtype=bool)
        bound_all = np.full((N, B), -np.inf)
        # the model's outputs here do not depend on the limits: kept for the sensitivities' re-solves
        keep = N * B * len(xs) <= BOUNDS_KEPT
        for n0 in range(0, N, step):
            sl = slice(n0, min(N, n0 + step))
            for t in types:
                with np.errstate(all="ignore"):
                    out_lo, o = _block_outputs(space, mounting, sl, str(t), xs, keep)
                    ok = np.broadcast_to(space.fits[sl][:, :, None], (sl.stop - sl.start, B, 1)).copy()
                    for c in low_end:
                        ok &= _screen_ok(c, out_lo)
                    for c in high_end:
                        ok &= _screen_ok(c, o)
                    bnd = np.broadcast_to(objective.value(o), ok.shape).astype(float)
                bnd = bnd + 2.0 * SCREEN_RTOL * np.abs(bnd)
                ok_all[sl] |= ok[..., 0]
                bound_all[sl] = np.maximum(bound_all[sl], np.where(ok[..., 0], bnd[..., 0], -np.inf))
        out.append((ok_all, bound_all))
    return out


BOUNDS_KEPT = 200_000  # block-bound model values kept per space up to this many (nut, bearing, position)s


def _block_outputs(space: Space, mounting: str, sl: slice, guide_type: str, xs, keep: bool):
    """The optimistic guide's model outputs over the nuts ``sl`` and every bearing, at the lowest preload
    (last position) and at the highest (positions ``xs``): what :func:`block_bounds` tests and bounds."""
    key = ("block outputs", mounting, sl.start, sl.stop, guide_type)
    hit = space._cache.get(key) if keep else None
    if hit is not None:
        return hit
    lo = space.preload_lo[sl].reshape(-1, 1, 1, 1).astype(np.float32)
    hi = space.preload_hi[sl].reshape(-1, 1, 1, 1).astype(np.float32)
    p = space.params_optimistic_guide(mounting, sl, guide_type, dtype=np.float32)
    res = (model.axis_response(p, xs[-1:], mounting, lo, extras=False),
           model.axis_response(p, xs, mounting, hi, extras=False))
    if keep:
        space._cache[key] = res
    return res


DRIVE_CHUNK = 50_000  # (combination, drive) pairs per block of the drive stage (cache-sized float64 arrays)


def _screen_drives(space: Space, mounting: str, constraints, phases, nn, bb, gg, bound):
    """The drive stage of :func:`screen`: each mechanical survivor (nut nn, bearing bb, guide gg) times
    every (motor, coupling) pair, checked on the limits the drive changes at the lowest and highest allowed
    preload (float64, same slack), structured over (survivor, drive pair) (:meth:`Space.params_drives`:
    the mechanics once per survivor, the drive once per pair).  Returns the survivors' (nut, bearing,
    guide-and-drive, bound)."""
    D = space.n_drives
    cons = [c for c in constraints if c.key in DRIVE_KEYS]
    if not cons or len(nn) == 0:
        g_full = (gg[:, None] * D + np.arange(D)[None]).ravel()
        return np.repeat(nn, D), np.repeat(bb, D), g_full, np.repeat(bound, D)
    cvx = [c for c in cons if c.convex]
    out_parts = []
    rows = max(1, DRIVE_CHUNK // D)
    for s0 in range(0, len(nn), rows):
        n_, b_, g_, bd = nn[s0:s0 + rows], bb[s0:s0 + rows], gg[s0:s0 + rows], bound[s0:s0 + rows]
        K = len(n_)
        p = space.params_drives(mounting, n_, b_, g_)
        lo, hi = space.preload_lo[n_][:, None, None], space.preload_hi[n_][:, None, None]
        with np.errstate(all="ignore"):
            out_lo = model.drive_response(p, lo)
            out_hi = model.drive_response(p, hi) if cvx or any(c.lower_type for c in cons) else None
            ok = np.ones((K, D), dtype=bool)
            for c in cons:
                if c.convex:
                    ub = np.asarray(convex_margin_bound(c, out_lo, out_hi, phases))
                    ok_c = ub >= c.limit * (1.0 - SCREEN_RTOL)
                    ok &= ok_c[..., 0] if ok_c.ndim == 3 else ok_c
                else:  # at the preload end that favours it (the regenerated power falls with the preload)
                    ok &= _screen_ok(c, out_hi if c.lower_type else out_lo)
        k, d = np.nonzero(ok)
        out_parts.append((n_[k], b_[k], g_[k] * D + d, bd[k]))
    return tuple(np.concatenate([o[i] for o in out_parts]) for i in range(4))


def _screen_ok(c, out):
    v = c.value(out)
    if not c.profile:
        v = np.asarray(v)[..., 0] if np.ndim(v) else v
    lim = c.limit * (1.0 + SCREEN_RTOL) if c.sense == "<=" else c.limit * (1.0 - SCREEN_RTOL)
    return np.asarray(v <= lim if c.sense == "<=" else v >= lim, dtype=bool)


def _concat(parts):
    return Exact(*(np.concatenate([getattr(p, f) for p in parts]) for f in
                   ("idx", "feasible", "preload", "objective", "cost", "total_mass", "moving_mass",
                    "min_stiffness", "min_frequency")))


def bound_order_search(space: Space, constraints, objective: ObjectiveSpec, top: int = 1, *,
                       max_evaluations: int | None = None, incumbent: float = -np.inf):
    """Default method core: best-first over blocks of combinations, never forming the whole product.

    1. :func:`block_bounds`: every (mounting, nut, bearing) block -- all its guides and drives -- gets a
       feasibility test and an objective bound from one evaluation with the optimistic guide.
    2. The blocks are taken in decreasing bound.  A group of blocks is screened (:func:`screen_nuts`, exact
       per combination up to the float32 slack) and its survivors join a pool; the pool's best bounds are
       solved exactly (:func:`exact_solve`) before the next group whenever they beat the next block's
       bound.  The incumbent is the ``top``-th best exact objective.
    3. It stops when neither the next block nor the pool can reach the incumbent: the gap is then 0.  Blocks
       never screened are the certificate's ``pruned_by_block``; survivors never solved its
       ``pruned_by_bound``.
    ``incumbent``: an objective some design is known to reach (top 1): what cannot tie with it is pruned from
    the start, and the Exact returned may then be empty.
    Returns (Exact of evaluated combinations, certificate fields dict)."""
    t0 = time.perf_counter()
    GD = space.shape[3]
    blocks = block_bounds(space, constraints, objective)
    bm, bn, bb, bv = [], [], [], []
    n_block_ok = 0
    for mi, (ok, bound) in enumerate(blocks):
        n, b = np.nonzero(ok)
        n_block_ok += len(n)
        bm.append(np.full(len(n), mi))
        bn.append(n)
        bb.append(b)
        bv.append(bound[n, b])
    bm, bn, bb, bv = (np.concatenate(x) if x else np.zeros(0) for x in (bm, bn, bb, bv))
    order = np.argsort(-bv, kind="stable")
    bm, bn, bb, bv = bm[order].astype(int), bn[order].astype(int), bb[order].astype(int), bv[order]
    t_screen = time.perf_counter() - t0
    _, N, B, _ = space.shape
    per_group = space.nuts_per_screen()
    pos, batch, n_eval, screened_blocks, feasible = 0, 64, 0, 0, 0
    group = 1  # distinct nuts per screened group: grows as long as no incumbent prunes
    pool_idx, pool_bnd = np.zeros(0, np.int64), np.zeros(0)
    parts, thr = [], (incumbent if top == 1 else -np.inf)
    while True:
        floor = objective_floor(thr)
        nxt = bv[pos] if pos < len(bv) else -np.inf
        best_pool = pool_bnd.max() if len(pool_bnd) else -np.inf
        if max(nxt, best_pool) < floor or (pos >= len(bv) and not len(pool_bnd)):
            break
        if max_evaluations is not None and n_eval >= max_evaluations:
            break
        if len(pool_bnd) and best_pool >= nxt:  # exact solves of the pool's best bounds
            cand = np.nonzero(pool_bnd >= max(nxt, floor))[0]
            take = cand[np.argsort(-pool_bnd[cand], kind="stable")[:batch]]
            batch = min(batch * 2, 131072)
            ex = exact_solve(space, pool_idx[take], constraints, objective)
            n_eval += len(take)
            parts.append(ex)
            keep = np.ones(len(pool_bnd), dtype=bool)
            keep[take] = False
            pool_idx, pool_bnd = pool_idx[keep], pool_bnd[keep]
            allobj = np.concatenate([p.objective for p in parts])
            fin = allobj[np.isfinite(allobj)]
            if len(fin) >= top:
                thr = np.partition(fin, len(fin) - top)[len(fin) - top]
            continue
        # screen the next group of blocks: up to per_group distinct nuts, in bound order
        t1 = time.perf_counter()
        end, seen = pos, set()
        while end < len(bv) and bv[end] >= floor:
            key = (bm[end], bn[end])
            if key not in seen and len(seen) >= min(group, per_group):
                break
            seen.add(key)
            end += 1
        end = max(end, pos + 1)
        grp = slice(pos, end)
        group = min(group * 2, per_group)
        screened_blocks += end - pos
        pos = end
        new_idx, new_bnd = [], []
        for mi in np.unique(bm[grp]):
            sel = bm[grp] == mi
            gn, gb = bn[grp][sel], bb[grp][sel]
            nuts = np.unique(gn)
            premask = np.zeros((len(nuts), B), dtype=bool)
            premask[np.searchsorted(nuts, gn), gb] = True
            i, bnd = screen_nuts(space, int(mi), nuts, constraints, objective, premask=premask)
            new_idx.append(i)
            new_bnd.append(bnd)
        add_i = np.concatenate(new_idx) if new_idx else np.zeros(0, np.int64)
        add_b = np.concatenate(new_bnd) if new_bnd else np.zeros(0)
        feasible += len(add_i)
        pool_idx, pool_bnd = np.concatenate([pool_idx, add_i]), np.concatenate([pool_bnd, add_b])
        t_screen += time.perf_counter() - t1
    ex = _concat(parts) if parts else exact_solve(space, [], constraints, objective)
    rest = max(bv[pos] if pos < len(bv) else -np.inf, pool_bnd.max() if len(pool_bnd) else -np.inf)
    best = ex.objective.max() if len(ex.objective) else -np.inf
    if rest == -np.inf or rest < objective_floor(thr) or rest < objective_floor(best):
        gap = 0.0
    else:
        gap = float((rest - best) / max(abs(best), 1e-30)) if np.isfinite(best) else float("inf")
    screened = screened_blocks * GD
    info = {"combinations": space.size, "feasible": int(feasible), "pruned_by_bound": int(feasible - n_eval),
            "exact_evaluations": int(n_eval), "gap": gap, "proven": gap == 0.0,
            "screening_time": t_screen, "screening_rate": space.size / max(t_screen, 1e-9),
            "pruned_by_block": int(space.size - screened), "screened": int(screened)}
    return ex, info


# ------------------------------------------------------------------------------------ exhaustive
def grid_solve(space: Space, idx, constraints, objective: ObjectiveSpec, n_grid: int = 9) -> Exact:
    """Per-combination preload optimum that does not assume the objective grows with the preload.

    Each preload-dependent limit on its own is monotone in the preload (module docstring of
    ``space``), so its threshold is found by its own bisection; the feasible preloads are the interval
    between the largest lower threshold and the smallest upper one.  The objective is then evaluated
    on an even grid of that interval, both ends included, and the best feasible point kept.
    """
    idx = np.asarray(idx, dtype=np.int64)
    K = len(idx)
    res = Exact(idx, np.zeros(K, bool), np.full(K, np.nan), np.full(K, -np.inf), np.zeros(K), np.zeros(K),
                np.zeros(K))
    dep = [c for c in constraints if c.direction != 0]
    indep = [c for c in constraints if c.direction == 0]
    for mounting, sel, n, b, _g, p, x in space.by_mounting(idx):
        k = len(sel)
        lo, hi = space.preload_lo[n], space.preload_hi[n]
        out_lo = respond(p, x, mounting, lo[:, None])
        out_hi = respond(p, x, mounting, hi[:, None])
        ok = _ok_all(indep, out_lo, k) & space.fits[n, b]
        res.cost[sel] = _vec(out_lo["cost"], k)
        res.total_mass[sel] = _vec(out_lo["total_mass"], k)
        res.moving_mass[sel] = _vec(out_lo["moving_mass"], k)
        low, up = lo.copy(), hi.copy()
        for c in dep:
            w = np.nonzero(ok)[0]  # only the combinations every limit so far allows (exact, not a bound)
            if not len(w):
                break
            pw = subset(p, w, k)
            xc = x if c.profile else x[-1:]
            if c.convex:  # a motor-torque limit: met on an interval of preloads
                ex, a_lo, a_hi = convex_interval(c, pw, xc, mounting, lo[w], hi[w])
                ok[w] &= ex
                low[w] = np.where(ex, np.maximum(low[w], a_lo), low[w])
                up[w] = np.where(ex, np.minimum(up[w], a_hi), up[w])
                continue
            ok_lo = _ok_all([c], out_lo, k)
            ok_hi = _ok_all([c], out_hi, k)
            if c.upper_type:
                ok &= ok_lo
                a, z = np.where(ok_hi, hi, lo), hi.copy()  # a: feasible end, z: infeasible end
                todo = ok & ~ok_hi
            else:
                ok &= ok_hi
                a, z = np.where(ok_lo, lo, hi), lo.copy()
                todo = ok & ~ok_lo
            if todo.any():
                j = np.nonzero(todo)[0]
                pj = subset(p, j, k)
                aj, zj = a[j], z[j]
                for _ in range(BISECTION_STEPS):
                    mid = 0.5 * (aj + zj)
                    good = _ok_all([c], respond(pj, xc, mounting, mid[:, None]), len(j))
                    aj = np.where(good, mid, aj)
                    zj = np.where(good, zj, mid)
                a[j] = aj
            if c.upper_type:
                up = np.minimum(up, a)
            else:
                low = np.maximum(low, a)
        ok &= low <= up
        best_obj = np.full(k, -np.inf)
        best_pre = np.full(k, np.nan)
        w = np.nonzero(ok)[0]  # the grid runs on the combinations with a feasible preload interval
        if len(w):
            pw = subset(p, w, k)
            bo, bp = np.full(len(w), -np.inf), np.full(len(w), np.nan)
            for t in np.linspace(0.0, 1.0, n_grid):
                # clipped: low + 1.0 * (up - low) can round one ulp above up, past a threshold
                pre = np.clip(low[w] + t * (up[w] - low[w]), low[w], up[w])
                out = respond(pw, x, mounting, pre[:, None])
                good = _ok_all(constraints, out, len(w))
                J = np.broadcast_to(objective.value(out), (len(w),))
                better = good & (J > bo)
                bo = np.where(better, J, bo)
                bp = np.where(better, pre, bp)
            best_obj[w], best_pre[w] = bo, bp
        feas = np.isfinite(best_obj)
        res.feasible[sel] = feas
        res.objective[sel] = best_obj
        res.preload[sel] = best_pre
        ks, fs = np.full(k, np.nan), np.full(k, np.nan)
        f = np.nonzero(feas)[0]
        if len(f):
            out = respond(subset(p, f, k), x, mounting, best_pre[f][:, None])
            ks[f] = _vec(np.min(out["k_total"], axis=-1), len(f)) / N_PER_UM
            fs[f] = _vec(np.min(out["f1"], axis=-1), len(f))
        res.min_stiffness[sel] = ks
        res.min_frequency[sel] = fs
    return res


def exhaustive_search(space: Space, constraints, objective: ObjectiveSpec, chunk: int = 20000):
    t0 = time.perf_counter()
    parts = []
    for s in range(0, space.size, chunk):
        parts.append(grid_solve(space, np.arange(s, min(space.size, s + chunk)), constraints, objective))
    ex = _concat(parts) if parts else grid_solve(space, [], constraints, objective)
    info = {"combinations": space.size, "feasible": int(ex.feasible.sum()), "pruned_by_bound": 0,
            "exact_evaluations": space.size, "gap": 0.0, "proven": True, "screening_time": 0.0,
            "screening_rate": space.size / max(time.perf_counter() - t0, 1e-9)}
    return ex, info


# ------------------------------------------------------------------------------------ candidates
def make_candidate(space: Space, combo: int, preload: float, objective: ObjectiveSpec, rank: int = 0,
                   name: str = "") -> Candidate:
    return candidate_values(space, combo, preload, objective, rank, name)[0]


def candidate_values(space: Space, combo: int, preload: float, objective: ObjectiveSpec, rank: int = 0,
                     name: str = "") -> tuple:
    """(:func:`make_candidate`'s Candidate, the model's values of its design: ``Evaluation.values``)."""
    mi, n, b, g = (int(v) for v in space.unravel(combo))
    mounting = space.mountings[mi]
    screw, nut, bearing, guide, motor, coupling = space.part_rows(n, b, g)
    lo, hi = float(space.preload_lo[n]), float(space.preload_hi[n])
    preload = float(min(max(preload, lo), hi))
    design = Design(axis=space.problem.axis_for(mounting), screw=screw, nut=nut, bearing=bearing, guide=guide,
                    motor=motor, coupling=coupling, nut_preload=preload,
                    name=name or f"{space.problem.name}-{rank or 'design'}",
                    source=space.problem.source, assumed=space.problem.assumed)
    # the model on numpy: the same formula as the CasADi Function (tests/model/test_model.py holds them to 1e-10)
    # without building that Function for every new axis (a study's cases, the closest designs)
    ev = model.evaluate(design, use_casadi=False)
    v = ev.values
    J = float(objective.value({k: np.asarray(v[k]) for k, _ in objective.terms}))
    return Candidate(rank=rank, combination=int(combo), mounting=mounting, screw=str(screw["id"]),
                     nut=str(nut["id"]), bearing=str(bearing["id"]), guide=str(guide["id"]), nut_preload=preload,
                     motor="" if motor is None else str(motor["id"]),
                     coupling="" if coupling is None else str(coupling["id"]),
                     objective=J, min_stiffness=float(np.min(v["k_total"])) / N_PER_UM,
                     min_frequency=float(np.min(v["f1"])), cost=float(v["cost"]),
                     moving_mass=float(v["moving_mass"]), total_mass=float(v["total_mass"]),
                     drag_torque=float(v["drag_torque"]), life_h=float(v["life"]) / 3600.0, design=design,
                     outputs={lim.output: float(np.min(v[lim.output])) for lim in LIMITS.values() if lim.output in v}
                     ), v


def polish(space: Space, ex: Exact, constraints, objective: ObjectiveSpec, top: int):
    """IPOPT on the ``top`` best combinations of ``ex``.  Returns (candidates, NLPs solved, failed ranks, notes):
    the ranks whose NLP failed (their 1-D solution is kept).  A combination whose 1-D solution is the top of
    its preload range needs no NLP: the objective does not fall with the preload (the exact solve rests on
    it), so no preload in the range does better."""
    pick = rank_order(ex.objective, ex.cost, ex.total_mass, ex.idx, top)
    cands, fails, notes = [], [], []
    solved = 0
    for r, j in enumerate(pick, start=1):
        combo = int(ex.idx[j])
        mi, n, b, g = (int(v) for v in space.unravel(combo))
        mounting = space.mountings[mi]
        lo, hi = float(space.preload_lo[n]), float(space.preload_hi[n])
        pre = float(ex.preload[j])
        if pre >= hi:
            cands.append(make_candidate(space, combo, pre, objective, rank=r))
            continue
        p = space.params_flat(mounting, np.array([n]), np.array([b]), np.array([g]))
        p1 = model.one_design(p)
        res = nlp.solve_preload(mounting, space.positions(mounting), p1, lo, hi, constraints, objective,
                                guess=pre)
        solved += 1
        if not res.success:
            fails.append(r)
            notes.append(f"IPOPT {res.status} on combination {combo} (rank {r}); kept the 1-D solution")
        elif res.objective < ex.objective[j] - 1e-6 * max(abs(ex.objective[j]), 1e-9):
            notes.append(f"IPOPT objective {res.objective:.6g} below the 1-D solve {ex.objective[j]:.6g} on "
                         f"combination {combo} (rank {r}); kept the 1-D solution")
        elif _feasible_at(space, combo, res.preload, constraints):
            pre = res.preload
        # else: IPOPT's point violates a limit by its tolerance; keep the (feasible) 1-D solution
        cands.append(make_candidate(space, combo, pre, objective, rank=r))
    return cands, solved, fails, notes


def _feasible_at(space: Space, combo: int, preload: float, constraints) -> bool:
    mi, n, b, g = (int(v) for v in space.unravel(combo))
    mounting = space.mountings[mi]
    p = space.params_flat(mounting, np.array([n]), np.array([b]), np.array([g]))
    out = respond(p, space.positions(mounting), mounting, np.array([[preload]]))
    return bool(_ok_all(constraints, out, 1)[0])


def certificate(info: dict, nlps: int, fails: int, notes) -> Certificate:
    return Certificate(nlps_solved=nlps, nlp_failures=fails, notes=tuple(notes), **info)
