"""The closest designs of an infeasible problem as candidates: each combination the explanation
ranks closest, at its best preload, with its misses (:func:`closest_designs`)."""

from __future__ import annotations

import numpy as np

from ..candidates import candidate_values
from ..task.constraints import as_vector
from ..task.space import Space, respond


def closest_designs(space: Space, constraints, objective, combos) -> list:
    """The candidates of ``combos`` (ranked 1, 2, ...), each at the preload that minimises its total
    miss on a grid of its allowed range (one model evaluation per mounting for all of them), with
    their misses."""
    G = 33
    pre = np.zeros(len(combos))
    parts = [tuple(int(v) for v in space.unravel(int(c))) for c in combos]
    for mi in {p[0] for p in parts}:
        rows = [k for k, p in enumerate(parts) if p[0] == mi]
        n = np.array([parts[k][1] for k in rows])
        b = np.array([parts[k][2] for k in rows])
        g = np.array([parts[k][3] for k in rows])
        # as np.linspace(lo, hi, G) each
        grid = np.linspace(space.preload_lo[n], space.preload_hi[n], G, axis=1)
        mounting = space.mountings[mi]
        p = space.params_flat(mounting, np.repeat(n, G), np.repeat(b, G), np.repeat(g, G))
        out = respond(p, space.grid[mounting], mounting, grid.reshape(-1, 1), space.request)
        tot = np.zeros(len(rows) * G)
        for c in constraints:
            tot += c.violation(as_vector(c.value(out), len(rows) * G))
        # first of equal misses, as one design alone
        best = np.argmin(tot.reshape(len(rows), G), axis=1)
        pre[rows] = grid[np.arange(len(rows)), best]
    out = []
    for rank, (combo, (_mi, n, b, _g)) in enumerate(zip(combos, parts), start=1):
        cand, vals = candidate_values(space, int(combo), float(pre[rank - 1]), objective, rank=rank)
        misses = {}
        for c in constraints:
            v = float(np.min(vals[c.key]))
            miss = float(c.violation(np.asarray(v)))
            if miss > 0:
                misses[c.label] = miss
        if not space.fits[n, b]:
            misses["bearing bore fits screw"] = 1.0
        cand.misses = misses
        out.append(cand)
    return out
