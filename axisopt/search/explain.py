"""Why a problem is infeasible: limits no combination meets, and the closest designs."""

from __future__ import annotations

import numpy as np

from .. import model
from .core import make_candidate
from .result import Infeasibility
from .space import Space, _vec, respond

CLOSEST = 5


def explain_infeasible(space: Space, constraints, objective, n_closest: int = CLOSEST) -> Infeasibility:
    """Each limit is checked on its own, at its most favourable allowed preload, over every combination
    (vectorized, full position grid).  A limit met by no combination is reported with the best value
    any combination reaches.  The closest designs minimise the sum of relative misses."""
    best = {c.name: None for c in constraints}
    met = {c.name: False for c in constraints}
    top_idx, top_score = np.zeros(0, np.int64), np.zeros(0)
    chunk = 20000
    for s in range(0, space.size, chunk):
        idx = np.arange(s, min(space.size, s + chunk))
        score = np.zeros(len(idx))
        for mounting, sel, n, b, _g, p, x in space.by_mounting(idx):
            k = len(sel)
            outs = {-1: respond(p, x, mounting, space.preload_lo[n][:, None]),
                    1: respond(p, x, mounting, space.preload_hi[n][:, None])}
            fit_pen = np.where(space.fits[n, b], 0.0, 1.0)
            score[sel] += fit_pen
            for c in constraints:
                end = 1 if c.lower_type else -1
                v = _vec(c.value(outs[end]), k)
                miss = c.violation(v)
                score[sel] += miss
                ok = (miss <= 0) & (fit_pen == 0)
                met[c.name] = met[c.name] or bool(ok.any())
                cand = v[space.fits[n, b]] if space.fits[n, b].any() else v
                bv = cand.max() if c.sense == ">=" else cand.min()
                if best[c.name] is None or (bv > best[c.name] if c.sense == ">=" else bv < best[c.name]):
                    best[c.name] = float(bv)
        allidx = np.concatenate([top_idx, idx])
        allsc = np.concatenate([top_score, score])
        keep = np.argsort(allsc, kind="stable")[:n_closest]
        top_idx, top_score = allidx[keep], allsc[keep]
    unmeetable = []
    for c in constraints:
        if not met[c.name] and best[c.name] is not None:
            unmeetable.append((c.label, best[c.name] / c.factor, c.limit / c.factor, c.unit))
    closest = []
    for r, combo in enumerate(top_idx, start=1):
        mi, n, b, g = (int(v) for v in space.unravel(combo))
        # the preload that minimises the total miss, on a grid of the allowed range
        lo, hi = float(space.preload_lo[n]), float(space.preload_hi[n])
        grid = np.linspace(lo, hi, 33)
        mounting = space.mountings[mi]
        p = space.params_flat(mounting, np.full(33, n), np.full(33, b), np.full(33, g))
        out = respond(p, space.positions(mounting), mounting, grid[:, None])
        tot = np.zeros(33)
        for c in constraints:
            tot += c.violation(_vec(c.value(out), 33))
        pre = float(grid[int(np.argmin(tot))])
        cand = make_candidate(space, int(combo), pre, objective, rank=r)
        ev = model.evaluate(cand.design)
        vals = dict(ev.values)
        misses = {}
        for c in constraints:
            v = float(np.min(vals[c.key])) if c.profile else float(vals[c.key])
            miss = float(c.violation(np.asarray(v)))
            if miss > 0:
                misses[c.label] = miss
        if not space.fits[n, b]:
            misses["bearing bore fits screw"] = 1.0
        cand.misses = misses
        closest.append(cand)
    return Infeasibility(unmeetable, closest)
