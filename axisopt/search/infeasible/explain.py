"""Why a problem is infeasible: limits no combination meets, and the closest designs.

Each limit is taken on its own at its most favourable allowed preload end; a limit no (fitting)
combination meets is reported with the best value any combination reaches, and the closest designs
minimise the sum of relative misses (:func:`miss_scores`).

Two ways to the same answer:

* *best-first over blocks* (default method): every (mounting, nut, bearing) block -- all its guides
  and drives -- gets the best value any of its combinations could reach on each limit, and so a
  lower bound of its combinations' miss scores: for the mechanical limits from one evaluation with
  the optimistic guide of each guide type (:func:`.bounds.optimistic_guide_params`); for the drive's
  (motor and coupling checks, inertia ratio), which the optimistic guide does not bound (less
  friction can raise a deceleration torque), from the drive block evaluated in interval arithmetic
  (:mod:`.interval`) per drive pair over the range of moving mass and drag torque the block's guides
  give (:func:`drive_optimism`).  Blocks are scored one by one only while they could still improve a
  limit's best value, meet a limit not met yet, or hold one of the closest designs.
* *every combination* (exhaustive method, and the reference of the tests): :func:`miss_scores` over
  the whole product.
"""

from __future__ import annotations

import time

import numpy as np

from ... import model
from .. import task as vocabulary
from ..drivebounds import PER_DRIVE_MIN, drive_hull
from ..parts import drive_stiffnesses
from ..task.constraints import reads_regen
from ..task.space import COUPLING_KEYS, DRIVE_KEYS, Space, respond, respond_chain, respond_drive
from .answer import Infeasibility
from .closest import closest_designs
from .optimism import (
    CHUNK,
    RULE_WEIGHT,
    block_optimism,
    cheapest_cost,
    drive_bounds_of,
    favourable_bound,
    is_bounded,
    weight,
)

CLOSEST = 5
# A limit that no combination meets on its own (the block bounds show it: a budget below the
# cheapest parts) adds its miss to every design's score, so the scores lie close together and the
# bounds leave many blocks open: the best-first explanation then stops once the blocks it scored
# hold this many combinations (a count of work, not a time: the same answer on any machine;
# Infeasibility.cut).  The shipped infeasible examples score 20 000 and 6 300; a lathe Z with a
# budget of a quarter of its cheapest combination would score 580 M in 1 400 blocks (35 s): it stops
# after 10 of its blocks of 420 000 (guides x drives)
MAX_OPENED = 4_000_000
# The best-first explanation's work in any case: it stops once it has made this many model
# evaluations (combinations x nut positions, at each preload end and, for the stiffness chain, each
# coupling stiffness; a count, not a time: the same answer on any machine; Infeasibility.cut).
# Where the bounds are weak (every limit met by some combination, the closest designs missing
# several by a few per cent) the explanation otherwise scores block after block until the
# time limit: a generated 6 m twin-drive gantry of 2 x 10^10 combinations scored 18 blocks of 330
# 000 in 100 s (its closest designs settled after the fourth, 7.2 M evaluations; issue 52).  The
# shipped infeasible examples make 0.2 M (infeasible_drive_problem) and 2.5 M (infeasible_problem).
MAX_WORK = 8_000_000


# blocks scored in the first round of the best-first explanation; doubles each round (4: 16 %
FIRST_BATCH = 4
# faster than 32 over 16 vmc_random_1000 variants, fewer blocks scored before the bounds prune)
BOUND_RTOL = 1e-9  # slack on the block bounds (rounding of the same sums in another order)


class _Tally:
    """Per limit: whether any fitting combination meets it, and the best value any combination
    reaches."""

    def __init__(self, constraints):
        self.best = {c.name: None for c in constraints}
        self.met = {c.name: False for c in constraints}
        # the block bounds show a limit no combination meets (best-first explanation)
        self.hopeless = False
        # model evaluations made (combinations x positions, each preload end and coupling value)
        self.work = 0
        # the deadline passed inside a step that yields no block (the drive limits' bounds)
        self.timed_out = False

    def add(self, c, v, miss, fits):
        self.met[c.name] = self.met[c.name] or bool(((miss <= 0) & fits).any())
        cand = v[fits] if fits.any() else v.ravel()
        bv = float(cand.max() if c.sense == ">=" else cand.min())
        old = self.best[c.name]
        if old is None or (bv > old if c.sense == ">=" else bv < old):
            self.best[c.name] = bv


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


def explain_infeasible(
    space: Space,
    constraints,
    objective,
    n_closest: int = CLOSEST,
    *,
    every_combination: bool = False,
    deadline: float | None = None,
    max_opened: int | None = MAX_OPENED,
    max_work: int | None = MAX_WORK,
) -> Infeasibility:
    """Limits no combination meets (with the best value any reaches) and the ``n_closest`` designs
    of lowest miss score (ties: lowest combination number).  Best-first over blocks unless
    ``every_combination`` (module docstring); both give the same answer.  ``deadline`` (a
    time.perf_counter() value): the explanation stops there with the closest designs found so far
    (``Infeasibility.cut``); so does the best-first one, when the block bounds show a limit that no
    combination meets on its own, once the blocks it scored hold ``max_opened`` combinations (None:
    no such limit; see :data:`MAX_OPENED`), and in any case once it has made ``max_work`` model
    evaluations (:data:`MAX_WORK`; None: no bound).  ``Infeasibility.cut_by`` says which stopped it:
    'time', 'opened' or 'work'."""
    tally = _Tally(constraints)
    top_idx, top_score = np.zeros(0, np.int64), np.zeros(0)
    scores = (
        miss_scores(space, constraints, tally)
        if every_combination
        else _best_first_scores(space, constraints, tally, n_closest, deadline)
    )
    cut, opened = False, 0
    t0 = shown = time.perf_counter()
    for idx, score in scores:
        top_idx, top_score = _closest(top_idx, top_score, idx, score, n_closest)
        opened += len(idx)
        if (now := time.perf_counter()) - shown > vocabulary.PROGRESS:
            shown = now
            vocabulary.LOG.info(
                f"  explaining: {opened:,} combinations scored for the closest designs, "
                f"{now - t0:.0f} s"
            )
        if deadline is not None and time.perf_counter() > deadline:
            cut = "time"
        elif tally.hopeless and max_opened is not None and opened >= max_opened:
            cut = "opened"
        elif max_work is not None and not every_combination and tally.work >= max_work:
            cut = "work"
        if cut:
            break
    if not cut and tally.timed_out:
        cut = "time"
    unmeetable = []
    for c in constraints:
        if not tally.met[c.name] and tally.best[c.name] is not None:
            best = tally.best[c.name]
            # the blocks left out may hold cheaper ones
            if cut and c.key == "cost" and space.m_arr is not None:
                best = min(best, cheapest_cost(space))
            unmeetable.append((c.label, best / c.factor, c.limit / c.factor, c.unit))
    return Infeasibility(
        unmeetable,
        closest_designs(space, constraints, objective, [int(c) for c in top_idx]),
        cut=bool(cut),
        cut_by=cut or "",
    )


def cut_note(why: Infeasibility) -> str:
    """What stopped the explanation ``why``, one clause for the answer's message ('' : it was not
    cut)."""
    if why.cut_by == "time":
        return (
            "the explanation stopped at the time limit: the closest designs are those found by "
            "then (a longer --time-limit explains further)"
        )
    if why.cut_by == "opened":
        return (
            "a limit no combination meets on its own makes every design miss: the explanation "
            f"stopped after scoring {MAX_OPENED:,} combinations, and the closest designs (and what "
            "to relax for them) are those found by then, perhaps not the closest of all"
        )
    if why.cut_by == "work":
        return (
            f"the explanation stopped after {MAX_WORK:,} model evaluations (its bound of work, the "
            "same on any machine): the closest designs (and what to relax for them) are those "
            "found by then, perhaps not the closest of all"
        )
    return ""


def _best_first_scores(
    space: Space, constraints, tally: _Tally, n_closest: int, deadline: float | None = None
):
    """Blocks of (combination numbers, miss scores) in best-first order, until no block left out
    could change the explanation: improve the best value of a limit no block meets yet (or meet it),
    or hold a design among the ``n_closest`` (its score lower bound not above the current
    ``n_closest``-th score)."""
    # the drive limits' bounds (interval arithmetic over every block) wait until a drive limit is
    # left unmet by the first round: most explanations never need them
    opt = block_optimism(space, constraints, drive=False)
    drive = [c for c in constraints if not is_bounded(c)]
    M, (_, N, B, _) = len(space.mountings), space.shape
    lb = np.stack([o[1] for o in opt])  # (M, N, B)
    vals = {name: np.stack([o[0][name] for o in opt]) for name in opt[0][0]}
    tally.hopeless = any(c.name in vals and not c.ok(vals[c.name]).any() for c in constraints)
    G, X = space.shape[3], max(len(space.grid[m]) for m in space.mountings)
    rows = max(1, CHUNK // max(G * X, 1))  # (nut, bearing) pairs scored per evaluation
    fits = np.broadcast_to(space.fits, (M, N, B))
    # the tally counts fitting combinations if any fit
    usable = fits if fits.any() else np.ones_like(fits)
    done = np.zeros((M, N, B), dtype=bool)
    scores = np.zeros(0)
    batch = FIRST_BATCH
    while not done.all():
        if done.any() and any(c.name not in vals and not tally.met[c.name] for c in drive):
            for mi, mounting in enumerate(space.mountings):
                got = drive_bounds_of(space, mounting, drive, deadline)
                if got is None:  # the deadline passed while bounding: stop with what was scored
                    tally.timed_out = True
                    return
                for name, v in got.items():
                    vals.setdefault(name, np.empty((M, N, B)))[mi] = v
            for c in drive:
                lb = lb + weight(c) * c.violation(vals[c.name])
        want = np.zeros((M, N, B), dtype=bool)
        open_ = ~done
        # first round: the lowest score bounds only (below)
        for c in constraints if done.any() else ():
            if tally.met[c.name]:
                continue
            cand = open_ & usable
            if c.name not in vals:  # a drive limit before its bounds: could be met anywhere
                want |= _first(cand, lb, batch)
                continue
            v = vals[c.name]
            b = tally.best[c.name]
            if b is not None:
                tol = BOUND_RTOL * max(abs(b), 1e-30)
                # a block that could meet the limit stays a candidate whatever the tolerance
                cand &= (v > b + tol if c.sense == ">=" else v < b - tol) | c.ok(v)
            want |= _first(cand, -v if c.sense == ">=" else v, batch)
        kth = (
            np.partition(scores, n_closest - 1)[n_closest - 1]
            if len(scores) >= n_closest
            else np.inf
        )
        cand = open_ & (lb <= kth + BOUND_RTOL * max(abs(kth), 1.0) if np.isfinite(kth) else open_)
        want |= _first(cand, lb, batch)
        if not want.any():
            break
        for mi in range(M):
            n_sel, b_sel = np.nonzero(want[mi])
            for s0 in range(0, len(n_sel), rows):
                kth = (
                    np.partition(scores, n_closest - 1)[n_closest - 1]
                    if len(scores) >= n_closest
                    else np.inf
                )
                for idx, score in _score_nuts(
                    space,
                    constraints,
                    tally,
                    mi,
                    n_sel[s0 : s0 + rows],
                    b_sel[s0 : s0 + rows],
                    kth=kth,
                    n_closest=n_closest,
                ):
                    scores = np.concatenate([scores, np.sort(score)[:n_closest]])
                    yield idx, score
        done |= want
        batch *= 2


def _first(cand, key, n):
    """``n`` blocks of ``cand`` of lowest ``key`` (blocks tied with the n-th wait for a later
    round)."""
    k = np.nonzero(cand.ravel())[0]
    if len(k) > n:
        k = k[np.argpartition(key.ravel()[k], n - 1)[:n]]
    out = np.zeros(cand.size, dtype=bool)
    out[k] = True
    return out.reshape(cand.shape)


def miss_scores(space: Space, constraints, tally: _Tally | None = None):
    """Blocks of (combination numbers, sum of relative misses) over every combination: each limit at
    its favourable preload end, plus RULE_WEIGHT when the bearing does not fit the screw, a
    compatibility rule weighted by RULE_WEIGHT (:func:`_score_nuts`)."""
    tally = tally or _Tally(constraints)
    _, N, B, G = space.shape
    D = space.n_drives if space.m_arr is not None else 1
    for mi, mounting in enumerate(space.mountings):
        x = space.grid[mounting]
        step = max(1, CHUNK // max(B * (G // D) * len(x), B * G, 1))
        for n0 in range(0, N, step):
            yield from _score_nuts(space, constraints, tally, mi, np.arange(n0, min(N, n0 + step)))


def _score_nuts(
    space: Space,
    constraints,
    tally: _Tally,
    mi: int,
    nut_idx,
    bearing_idx=None,
    kth=np.inf,
    n_closest: int = CLOSEST,
):
    """(combination numbers, miss scores) of mounting ``mi`` over every guide and drive of either
    the nuts ``nut_idx`` times every bearing, or, with ``bearing_idx`` (aligned with ``nut_idx``),
    the (nut, bearing) blocks of those pairs only.  ``kth``: the score a design must not exceed to
    be among the ``n_closest`` (the best-first order's current n-th): a drive whose bounds
    (:func:`.drivebounds.drive_hull`) show that it can neither score that low nor improve or meet a
    drive limit not met yet is not evaluated, and its combinations score inf
    (:func:`_score_drives`).

    Structured like the screening: the limits the drive does not change are evaluated once per
    (screw, nut, bearing, guide) combination, the ones the coupling's stiffness changes
    (:data:`COUPLING_KEYS`) once per distinct coupling stiffness, the drive's limits
    (:data:`DRIVE_KEYS`) on the drive sub-assembly alone for each (motor, coupling) pair."""
    mounting = space.mountings[mi]
    _, N, B, G = space.shape
    two_stage = space.m_arr is not None
    D = space.n_drives if two_stage else 1
    Gm = G // D
    drive = [c for c in constraints if two_stage and c.key in DRIVE_KEYS]
    # limits the coupling's stiffness changes: evaluated once per distinct stiffness, mapped to the
    # pairs
    k_cpl = space.coupling_k if two_stage else np.zeros(0)
    cpl = [c for c in constraints if two_stage and c.key in COUPLING_KEYS]
    mech = [c for c in constraints if c not in drive and c not in cpl]
    if two_stage:
        group = np.searchsorted(k_cpl, drive_stiffnesses(space))
    x = space.grid[mounting]
    nut_idx = np.asarray(nut_idx, dtype=np.int64)
    nc = len(nut_idx)
    pairs = bearing_idx is not None
    Bx = 1 if pairs else B  # the bearing axis: merged into the pair axis, or every bearing

    def params(**kw):
        return space.params_structured(mounting, nut_idx, bearings=bearing_idx, **kw)

    shape = (nc, Bx, Gm)
    lo = space.preload_lo[nut_idx].reshape(-1, 1, 1, 1)
    hi = space.preload_hi[nut_idx].reshape(-1, 1, 1, 1)
    fit_nb = space.fits[nut_idx, bearing_idx][:, None] if pairs else space.fits[nut_idx]
    fits = np.broadcast_to(fit_nb[:, :, None], shape)
    score = np.where(fits, 0.0, RULE_WEIGHT)
    p = params(mechanics=two_stage)
    # at the lowest preload only the limits it favours are read: the stiffness chain and modes are
    # skipped there unless one of those reads them
    chain_lo = any(c.key in model.CHAIN_OUTPUTS for c in mech if not c.lower_type)
    regen = reads_regen(constraints)
    tally.work += 2 * nc * Bx * Gm * len(x)
    out_lo = respond(
        p, x, mounting, lo, space.request.but(drive=not two_stage, chain=chain_lo, regen=regen)
    )
    out_hi = respond(p, x, mounting, hi, space.request.but(drive=not two_stage, regen=regen))
    for c in mech:
        v = favourable_bound(c, out_lo, out_hi, shape)
        miss = c.violation(v)
        score = score + weight(c) * miss
        tally.add(c, v, miss, fits)
    if two_stage:
        shape_d = (nc, Bx, Gm, D)
        fits_d = np.broadcast_to(fits[..., None], shape_d)
        score = np.broadcast_to(score[..., None], shape_d).copy()
        by_k = []
        # minimum stiffness and frequency: the highest preload only
        cpl_lo = any(not c.lower_type for c in cpl)
        # p: params(mechanics=True); the chain alone, once per coupling stiffness (one heat balance)
        if cpl:
            ks = [float(k) for k in k_cpl]
            tally.work += (1 + cpl_lo) * len(ks) * nc * Bx * Gm * len(x)
            by_lo = respond_chain(p, x, mounting, lo, ks) if cpl_lo else [None] * len(ks)
            by_k = list(zip(by_lo, respond_chain(p, x, mounting, hi, ks)))
        for c in cpl:
            v = np.stack([favourable_bound(c, *outs, shape) for outs in by_k], axis=-1)[..., group]
            miss = c.violation(v)
            score += weight(c) * miss
            tally.add(c, v, miss, fits_d)
        if drive:
            score = _score_drives(
                space,
                mounting,
                drive,
                tally,
                nut_idx,
                bearing_idx,
                score,
                fits_d,
                lo,
                hi,
                regen,
                kth,
                n_closest,
            )
    score = np.broadcast_to(score, shape_d if two_stage else shape).reshape(nc, Bx, G)
    if pairs:
        nn = np.repeat(nut_idx, G)
        bb = np.repeat(np.asarray(bearing_idx, dtype=np.int64), G)
        gg = np.tile(np.arange(G), nc)
    else:
        n3, bb, gg = np.meshgrid(nut_idx, np.arange(B), np.arange(G), indexing="ij")
        nn, bb, gg = n3.ravel(), bb.ravel(), gg.ravel()
    yield np.ravel_multi_index((np.full(len(nn), mi), nn, bb, gg), space.shape), score.reshape(-1)


# drives of lowest bound scored first when no n-th score is known yet (:func:`_score_drives`)
FIRST_DRIVES = 32


def _score_drives(
    space: Space,
    mounting: str,
    drive,
    tally: _Tally,
    nut_idx,
    bearing_idx,
    score,
    fits,
    lo,
    hi,
    regen: bool,
    kth: float,
    n_closest: int,
):
    """The miss scores of :func:`_score_nuts` with the drive limits added, (nuts, bearings, guides,
    drives): ``score`` holds the mechanical part.  A drive is evaluated (at both preload ends, every
    guide) only if its bounds over the block (:func:`.drivebounds.drive_hull`: every guide and
    preload) leave a score not above ``kth``, or could meet, or improve the best value of, a drive
    limit no combination meets yet; the others score inf.  A first pass scores the
    :data:`FIRST_DRIVES` drives of lowest score bound (without a ``kth``, fewer than ``n_closest``
    scores known: they give it) and of most favourable bound on each limit not met yet (they set its
    best value), so that the second leaves out what they rule out."""
    D = space.n_drives
    out = np.full(score.shape, np.inf)
    hull, group = (
        drive_hull(space, mounting, nut_idx, drive, bearings=bearing_idx)
        if D >= PER_DRIVE_MIN
        else ({}, None)
    )
    # drive numbers per pass; None: those the bounds leave worth scoring once the first is done
    passes = [None]
    # a few drives, or a limit the bounds do not cover: every drive
    if any(c.name not in hull for c in drive):
        passes = [np.arange(D)]
    else:
        lb = 0.0
        for c in drive:
            lb = lb + weight(c) * c.violation(hull[c.name])
        lb = np.broadcast_to(lb, hull[drive[0].name].shape)[:, group]  # (nuts, bearings, drives)
        low = score.min(axis=2) + lb
        # a first pass that sets the n-th score and the best values the second prunes by
        if D > FIRST_DRIVES:
            first = (
                [np.argsort(low.reshape(-1, D).min(axis=0), kind="stable")[:FIRST_DRIVES]]
                if not np.isfinite(kth)
                else []
            )
            for c in drive:
                # the drives of most favourable bound on a limit not met yet
                if not tally.met[c.name]:
                    v = hull[c.name].reshape(-1, D)
                    v = v.max(axis=0) if c.sense == ">=" else -v.min(axis=0)
                    first.append(np.argsort(-v, kind="stable")[:FIRST_DRIVES])
            if first:
                passes.insert(0, np.unique(np.concatenate(first)))
    done = np.zeros(D, dtype=bool)
    for cols in passes:
        if cols is None:
            cols = np.nonzero(_worth(drive, tally, hull, low, kth))[0]
        cols = cols[~done[cols]]
        done[cols] = True
        if not len(cols):
            continue
        sub = score.shape[:3] + (len(cols),)
        # the mechanics once per guide
        pd = space.params_drives(mounting, nut_idx, bearing_idx, drives=cols)
        tally.work += 2 * int(np.prod(sub))
        d_lo, d_hi = respond_drive(pd, lo, regen), respond_drive(pd, hi, regen)
        part = score[..., cols]
        for c in drive:
            v = favourable_bound(c, d_lo, d_hi, sub, positions=False)
            miss = c.violation(v)
            part = part + weight(c) * miss
            tally.add(c, v, miss, fits[..., cols])
        out[..., cols] = part
        if not np.isfinite(kth):  # the n-th score of this block bounds what the closest need
            flat = out.ravel()
            if np.isfinite(flat).sum() >= n_closest:
                kth = float(np.partition(flat, n_closest - 1)[n_closest - 1])
    return out


def _worth(drive, tally: _Tally, hull: dict, low, kth: float):
    """Per drive: whether its bounds (``hull``; ``low``: the least score it could reach per (nut,
    bearing)) leave a score not above ``kth``, or could meet, or improve the best value of, a limit
    not met yet."""
    D = low.shape[-1]
    need = (
        (low <= kth + BOUND_RTOL * max(abs(kth), 1.0)).reshape(-1, D).any(axis=0)
        if np.isfinite(kth)
        else np.ones(D, dtype=bool)
    )
    for c in drive:
        if not tally.met[c.name]:
            v, b = hull[c.name], tally.best[c.name]
            better = (
                np.ones_like(v, dtype=bool)
                if b is None
                else (
                    v > b - BOUND_RTOL * abs(b) if c.sense == ">=" else v < b + BOUND_RTOL * abs(b)
                )
            )
            need |= (better | c.ok(v)).reshape(-1, D).any(axis=0)
    return need
