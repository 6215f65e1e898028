"""Why a problem is infeasible: limits no combination meets, and the closest designs."""

from __future__ import annotations

import numpy as np

from .. import model
from .core import make_candidate
from .result import Infeasibility
from .space import COUPLING_KEYS, DRIVE_KEYS, Space, _vec, respond, respond_drive

CLOSEST = 5
CHUNK = 2_000_000  # response elements per block


class _Tally:
    """Per limit: whether any fitting combination meets it, and the best value any combination reaches."""

    def __init__(self, constraints):
        self.best = {c.name: None for c in constraints}
        self.met = {c.name: False for c in constraints}

    def add(self, c, v, miss, fits):
        self.met[c.name] = self.met[c.name] or bool(((miss <= 0) & fits).any())
        cand = v[fits] if fits.any() else v.ravel()
        bv = float(cand.max() if c.sense == ">=" else cand.min())
        old = self.best[c.name]
        if old is None or (bv > old if c.sense == ">=" else bv < old):
            self.best[c.name] = bv


def _favourable(c, v_lo, v_hi):
    """The value at the preload end that favours the limit (for a limit met on an interval of preloads,
    the better of the two ends)."""
    if c.convex:
        return np.maximum(v_lo, v_hi) if c.sense == ">=" else np.minimum(v_lo, v_hi)
    return v_hi if c.lower_type else v_lo


def _closest(top_idx, top_score, idx, score, n):
    """Merge a block's scores into the running n closest (lowest score, then lowest combination)."""
    if len(score) > n:
        part = np.argpartition(score, n - 1)[:n]
        # ties at the n-th score: keep every tied row so the lowest combination numbers win
        cut = score[part].max()
        part = np.nonzero(score <= cut)[0]
        idx, score = idx[part], score[part]
    allidx = np.concatenate([top_idx, idx])
    allsc = np.concatenate([top_score, score])
    keep = np.lexsort((allidx, allsc))[:n]
    return allidx[keep], allsc[keep]


def explain_infeasible(space: Space, constraints, objective, n_closest: int = CLOSEST) -> Infeasibility:
    """Each limit is checked on its own, at its most favourable allowed preload end, over every combination
    (full position grid).  A limit met by no combination is reported with the best value any combination
    reaches.  The closest designs minimise the sum of relative misses (:func:`miss_scores`)."""
    tally = _Tally(constraints)
    top_idx, top_score = np.zeros(0, np.int64), np.zeros(0)
    for idx, score in miss_scores(space, constraints, tally):
        top_idx, top_score = _closest(top_idx, top_score, idx, score, n_closest)
    unmeetable = []
    for c in constraints:
        if not tally.met[c.name] and tally.best[c.name] is not None:
            unmeetable.append((c.label, tally.best[c.name] / c.factor, c.limit / c.factor, c.unit))
    return Infeasibility(unmeetable, [_closest_design(space, constraints, objective, int(combo), r)
                                      for r, combo in enumerate(top_idx, start=1)])


def miss_scores(space: Space, constraints, tally: _Tally | None = None):
    """Blocks of (combination numbers, sum of relative misses): each limit at its favourable preload end,
    plus 1 when the bearing does not fit the screw.

    Structured like the screening: the limits the drive does not change are evaluated once per (screw, nut,
    bearing, guide) combination, the ones the coupling's stiffness changes (:data:`COUPLING_KEYS`) once per
    distinct coupling stiffness, the drive's limits (:data:`DRIVE_KEYS`) on the drive sub-assembly alone for
    each (motor, coupling) pair."""
    tally = tally or _Tally(constraints)
    _, N, B, G = space.shape
    two_stage = space.m_arr is not None
    D = space.n_drives if two_stage else 1
    Gm = G // D
    drive = [c for c in constraints if two_stage and c.key in DRIVE_KEYS]
    # limits the coupling's stiffness changes: evaluated once per distinct stiffness, mapped to the pairs
    k_cpl = space.coupling_stiffnesses() if two_stage else np.zeros(0)
    cpl = [c for c in constraints if two_stage and c.key in COUPLING_KEYS]
    mech = [c for c in constraints if c not in drive and c not in cpl]
    if two_stage:
        pair_k = space.c_arr["torsional_stiffness"][:D] if space.c_arr is not None else np.full(D, k_cpl[0])
        group = np.searchsorted(k_cpl, pair_k)
    for mi, mounting in enumerate(space.mountings):
        x = space.positions(mounting)
        step = max(1, CHUNK // max(B * Gm * len(x), B * G, 1))
        for n0 in range(0, N, step):
            sl = slice(n0, min(N, n0 + step))
            nc = sl.stop - sl.start
            shape = (nc, B, Gm)
            lo = space.preload_lo[sl].reshape(-1, 1, 1, 1)
            hi = space.preload_hi[sl].reshape(-1, 1, 1, 1)
            fits = np.broadcast_to(space.fits[sl][:, :, None], shape)
            score = np.where(fits, 0.0, 1.0)
            p = space.params_structured(mounting, sl, mechanics=two_stage)
            out_lo, out_hi = respond(p, x, mounting, lo), respond(p, x, mounting, hi)
            for c in mech:
                v = _favourable(c, *(np.broadcast_to(_last(c, c.value(o)), shape) for o in (out_lo, out_hi)))
                miss = c.violation(v)
                score = score + miss
                tally.add(c, v, miss, fits)
            if two_stage:
                shape_d = (nc, B, Gm, D)
                fits_d = np.broadcast_to(fits[..., None], shape_d)
                score = np.broadcast_to(score[..., None], shape_d).copy()
                by_k = []
                for k in k_cpl if cpl else ():
                    pk = space.params_structured(mounting, sl, mechanics=True, coupling_stiffness=float(k))
                    by_k.append((respond(pk, x, mounting, lo), respond(pk, x, mounting, hi)))
                for c in cpl:
                    v = np.stack([_favourable(c, *(np.broadcast_to(_last(c, c.value(o)), shape) for o in outs))
                                  for outs in by_k], axis=-1)[..., group]
                    miss = c.violation(v)
                    score += miss
                    tally.add(c, v, miss, fits_d)
                if drive:
                    pd = space.params_structured(mounting, sl)
                    d_lo, d_hi = respond_drive(pd, lo), respond_drive(pd, hi)
                    for c in drive:
                        v = _favourable(c, *(np.broadcast_to(_last(c, c.value(o)), (nc, B, G)).reshape(shape_d)
                                             for o in (d_lo, d_hi)))
                        miss = c.violation(v)
                        score += miss
                        tally.add(c, v, miss, fits_d)
            nn, bb, gg = np.meshgrid(np.arange(sl.start, sl.stop), np.arange(B), np.arange(G), indexing="ij")
            idx = np.ravel_multi_index((np.full(nn.size, mi), nn.ravel(), bb.ravel(), gg.ravel()), space.shape)
            yield idx, score.reshape(-1)


def _last(c, v):
    """A limit's value over the block without the trailing position axis (profiles are reduced already)."""
    v = np.asarray(v, dtype=float)
    return v[..., 0] if (not c.profile and v.ndim == 4) else v


def _closest_design(space: Space, constraints, objective, combo: int, rank: int):
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
    cand = make_candidate(space, combo, pre, objective, rank=rank)
    vals = dict(model.evaluate(cand.design).values)
    misses = {}
    for c in constraints:
        v = float(np.min(vals[c.key])) if c.profile else float(vals[c.key])
        miss = float(c.violation(np.asarray(v)))
        if miss > 0:
            misses[c.label] = miss
    if not space.fits[n, b]:
        misses["bearing bore fits screw"] = 1.0
    cand.misses = misses
    return cand
