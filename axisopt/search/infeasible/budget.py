"""The least budget at which the catalogs hold a design meeting every other limit
(:func:`least_cost`): the advice of an impossible ``max_cost`` (:mod:`.advice`), found apart from
the explanation's closest designs.

A best-first search over blocks of combinations like the default method's (:mod:`.bestfirst`), with
the cost as the objective (minimised) and the problem's ``max_cost`` left out:

1. every (mounting, nut, bearing) block gets a lower bound of its combinations' cost (the cheapest
   guide with the cheapest drive, :func:`.bounds.block_bounds` on the objective -cost) and a test of
   the mechanical limits;
2. blocks are screened in increasing bound (:func:`.screen.screen_nuts`, with the cost capped at the
   cheapest design found so far, which prunes the drives per block:
   :func:`.drivebounds.least_cost`), the survivors' costs computed exactly (the cost reads
   no preload: a sum of part prices, :func:`axisopt.model.cost.cost`);
3. the cheapest survivors are solved exactly (:func:`.preload.exact_solve`, every other limit)
   whenever they cost no more than the next block's bound, or no design is known yet; the search
   stops when no block or survivor left could cost less than the cheapest feasible design found.
   The answer is proven least (the bounds are exact or below).

The work is counted, not timed: at most :data:`MAX_BLOCKS` blocks are screened (the same answer on
any machine); a search cut there returns the cheapest design found by then, not proven least, or
None.
"""

from __future__ import annotations

import numpy as np

from ...model.cost import cost
from ..bounds import block_bounds
from ..preload import exact_solve
from ..screen import group_end, screen_blocks
from ..task.constraints import build_constraints
from ..task.objective import ObjectiveSpec

LEAST_COST = ObjectiveSpec((("cost", -1.0),), "least cost", "EUR")
# (mounting, nut, bearing) blocks screened at most (a count of work; the lathe Z at 500 EUR
MAX_BLOCKS = 400
# screens 49 of its 35 904, in 0.6 s)
FIRST_SOLVES = 64  # survivors solved exactly in the first batch (doubling)


def _costs(space, idx) -> np.ndarray:
    """The exact cost [EUR] of the combinations ``idx`` (any mix of mountings)."""
    out = np.empty(len(idx))
    for _mounting, sel, _n, _b, _g, p, _x in space.by_mounting(idx):
        out[sel] = np.broadcast_to(np.asarray(cost(p), dtype=float), (len(sel), 1))[:, 0]
    return out


def least_cost(problem, space, max_blocks: int = MAX_BLOCKS) -> tuple[float, int, bool] | None:
    """(the least cost [EUR] of a design meeting every limit of ``problem`` but ``max_cost``, its
    combination number, whether it is proven least), or None when the catalogs hold no such design
    (or the search was cut before it found one; module docstring).  ``space``: the problem's search
    space (a limit leaves the parts as they are)."""
    free = problem.with_limit("max_cost", None)
    cons = build_constraints(free)
    blocks = block_bounds(space, cons, LEAST_COST)
    bm, bn, bb, lb = [], [], [], []
    for mi, (ok, bound) in enumerate(blocks):
        n, b = np.nonzero(ok)
        bm.append(np.full(len(n), mi))
        bn.append(n)
        bb.append(b)
        lb.append(-bound[n, b])
    bm, bn, bb, lb = (np.concatenate(x) for x in (bm, bn, bb, lb))
    order = np.argsort(lb, kind="stable")
    bm, bn, bb, lb = bm[order].astype(int), bn[order].astype(int), bb[order].astype(int), lb[order]
    best, best_idx = np.inf, -1
    pool_idx, pool_cost = np.zeros(0, np.int64), np.zeros(0)
    pos, screened, group, batch = 0, 0, 1, FIRST_SOLVES
    capped = cons
    while True:
        nxt = lb[pos] if pos < len(lb) else np.inf
        cheapest = pool_cost.min() if len(pool_cost) else np.inf
        if min(nxt, cheapest) >= best:  # nothing left could cost less (inf: nothing left at all)
            return (float(best), int(best_idx), True) if best_idx >= 0 else None
        # the cheapest survivors, solved exactly: as soon as there are some while no design is known
        # (its cost then caps the screening), else when they cost no more than the next block's
        # bound
        if len(pool_cost) and (cheapest <= nxt or best == np.inf):
            take = np.argsort(pool_cost, kind="stable")[:batch]
            batch *= 2
            ex = exact_solve(space, pool_idx[take], cons, LEAST_COST)
            ok = np.isfinite(ex.objective)
            if ok.any():
                k = int(np.argmin(np.where(ok, pool_cost[take], np.inf)))
                if pool_cost[take][k] < best:
                    best, best_idx = float(pool_cost[take][k]), int(pool_idx[take][k])
                    capped = build_constraints(problem.with_limit("max_cost", best))
            keep = np.ones(len(pool_cost), dtype=bool)
            keep[take] = False
            pool_idx, pool_cost = pool_idx[keep], pool_cost[keep]
            continue
        # cut: the cheapest design found so far, if any, not proven least
        if screened >= max_blocks:
            return (float(best), int(best_idx), False) if best_idx >= 0 else None
        # the next blocks: ``group`` nuts
        end = group_end(bm, bn, pos, lambda i, c=best: lb[i] < c, group)
        grp = slice(pos, end)
        screened += end - pos
        pos, group = end, group * 2
        for idx, _ in screen_blocks(space, bm[grp], bn[grp], bb[grp], capped, LEAST_COST):
            c = _costs(space, idx)
            fine = c < best
            pool_idx, pool_cost = (
                np.concatenate([pool_idx, idx[fine]]),
                np.concatenate([pool_cost, c[fine]]),
            )
