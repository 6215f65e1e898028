"""Optimistic values of every limit over a block of combinations (interval bounds of the mechanics
and of the drives), the cheapest combination: what the best-first explanation (:mod:`.explain`)
prunes blocks with."""

from __future__ import annotations

import time

import numpy as np

from ... import model
from ...model.limits import CHECK_RECORDS, check_name
from ..bounds import (
    SCREEN_RTOL,
    block_chunk,
    block_outputs,
    bound_positions,
    optimistic_guide_params,
)
from ..drivebounds import DRIVE_BEARING_GROUPS, HULL_BLOCK, cost_parts, drive_hull
from ..task.constraints import End
from ..task.space import DRIVE_KEYS, MECHANICS_BOUNDED, Space, respond


def _last(c, v):
    """A limit's value over the block without the trailing position axis (profiles are reduced
    already)."""
    v = np.asarray(v, dtype=float)
    return v[..., 0] if (not c.profile and v.ndim == 4) else v


CHUNK = 2_000_000  # response elements per block


# A compatibility rule (the bearing bore does not fit the screw end, the screw is too short:
# Check.relaxable False) weighs this much more than a limit in the miss score, so the closest
# designs are ones the user can free by relaxing their own limits whenever such designs miss by less
# than ten limits' worth (a bearing that does not fit is not a design).  1000 gave the same
# proposals on the shipped variants but let fewer blocks be pruned: the explanation of the slowest
# vmc_random_1000 cases took 1.5x as long.
RULE_WEIGHT = 10.0


def weight(c) -> float:
    """The weight of constraint ``c``'s relative miss in the miss score."""
    if check_name(c.name) is not None:
        rec = CHECK_RECORDS.get(check_name(c.name))
        if rec is not None and not rec.relaxable:
            return RULE_WEIGHT
    return 1.0


# nuts per evaluation of the drive limits' interval bounds (memory: nuts x bearings x guides)
DRIVE_NUTS = 64


# slack on block bounds read from the search's float32 outputs (as its bound)
FLOAT32_RTOL = 2.0 * SCREEN_RTOL


def favourable_bound(c, out_lo, out_hi, shape, positions: bool = True):
    """The limit's value at the preload end that favours it (for a limit met on an interval of
    preloads, the better of the two ends), broadcast to ``shape``; only the end(s) it needs are read
    (``out_lo`` may be None, or without the chain outputs, when no limit read there needs them).
    ``positions``: the outputs have a trailing position axis (not the drive layout's, whose last
    axis is the drives)."""

    def val(o):
        v = c.value(o)
        return np.broadcast_to(_last(c, v) if positions else np.asarray(v, dtype=float), shape)

    end = c.favourable
    if end is End.INTERVAL:
        v_lo, v_hi = val(out_lo), val(out_hi)
        return np.maximum(v_lo, v_hi) if c.sense == ">=" else np.minimum(v_lo, v_hi)
    return val(out_hi) if end is End.HIGH else val(out_lo)


def cheapest_cost(space: Space) -> float:
    """The least cost [EUR] of any (fitting, if any fits) combination of a space with a drive
    search, exact (:func:`.drivebounds.cost_parts`): the budget's single-limit check when the
    explanation was cut."""
    B = space.shape[2]
    usable = space.fits if space.fits.any() else np.ones_like(space.fits)
    best = np.inf
    for mounting in space.mountings:
        by_bearing, per_drive = cost_parts(space, mounting, slice(0, space.shape[1]), np.arange(B))
        best = min(best, float(np.min(np.where(usable, by_bearing, np.inf)) + per_drive.min()))
    return best


def is_bounded(c) -> bool:
    """Whether the optimistic guide bounds the limit ``c`` over every guide and drive of a block
    (the limits of :func:`axisopt.search.bounds.block_bounds`: not the drive's, except the cost)."""
    return not c.convex and (c.key not in DRIVE_KEYS or c.key in MECHANICS_BOUNDED)


def block_optimism(space: Space, constraints, drive: bool = True):
    """Per mounting and (nut, bearing) block: for each limit a value no combination of the block
    beats at the limit's favourable preload end -- the limits the optimistic guide bounds from it
    (profiles on :func:`.bounds.bound_positions`), the drive's from :func:`drive_optimism` (unless
    not ``drive``) -- and a lower bound of the block's miss scores.  Returns a list over mountings
    of (values dict, lower bound)."""
    _, N, B, _ = space.shape
    bounded = [c for c in constraints if is_bounded(c)]
    drive = [c for c in constraints if not is_bounded(c)] if drive else []
    constraints = bounded + drive
    types = np.unique(space.g_arr["type"]) if len(space.guides) else np.array([], dtype=str)
    # at the lowest preload only the limits it favours are read: the stiffness chain and modes are
    # skipped there unless one of those reads them (as in _score_nuts)
    chain_lo = any(c.key in model.CHAIN_OUTPUTS for c in bounded if c.convex or not c.lower_type)
    # a minimum over a few positions bounds the minimum over the grid from above: optimistic for a
    # ">=" limit, so the few suffice unless a "<=" limit reads a profile
    few = all(c.sense == ">=" for c in bounded if c.profile)
    out = []
    for mounting in space.mountings:
        x = bound_positions(space, mounting) if few else space.grid[mounting]
        step = block_chunk(space) if few else max(1, CHUNK // max(B * len(x), 1))
        best = {
            c.name: np.full((N, B), -np.inf if c.sense == ">=" else np.inf) for c in constraints
        }
        for n0 in range(0, N, step):
            sl = slice(n0, min(N, n0 + step))
            lo = space.preload_lo[sl].reshape(-1, 1, 1, 1)
            hi = space.preload_hi[sl].reshape(-1, 1, 1, 1)
            shape = (sl.stop - sl.start, B)
            for t in types if bounded else ():
                # the search's block bounds' float32 outputs (the lowest preload at one position: a
                if few:
                    # ">=" profile's minimum over fewer positions is no lower), relaxed below for
                    # the rounding
                    with np.errstate(all="ignore"):
                        out_lo, out_hi = block_outputs(space, mounting, sl, str(t))
                else:
                    p = optimistic_guide_params(space, mounting, sl, str(t))
                    out_lo = respond(p, x, mounting, lo, model.MECHANICS.but(chain=chain_lo))
                    out_hi = respond(p, x, mounting, hi, model.MECHANICS)
                for c in bounded:
                    v = np.asarray(
                        favourable_bound(c, out_lo, out_hi, shape + (1,))[..., 0], dtype=float
                    )
                    pick = np.maximum if c.sense == ">=" else np.minimum
                    if few:
                        v = v + (1.0 if c.sense == ">=" else -1.0) * FLOAT32_RTOL * np.abs(v)
                    best[c.name][sl] = pick(best[c.name][sl], v)
        if drive:
            best.update(drive_bounds_of(space, mounting, drive))
        lb = np.where(space.fits, 0.0, RULE_WEIGHT)
        for c in constraints:
            lb = lb + weight(c) * c.violation(best[c.name])
        out.append((best, lb))
    return out


def drive_bounds_of(
    space: Space, mounting: str, drive, deadline: float | None = None
) -> dict | None:
    """:func:`drive_optimism` over every nut of ``mounting``, at most :data:`DRIVE_NUTS` nuts at
    a time: {limit name: (nuts, bearings)}; None when ``deadline`` (a time.perf_counter() value)
    passed first."""
    N, B = space.shape[1], space.shape[2]
    out = {c.name: np.empty((N, B)) for c in drive}
    # as many nuts as keep one interval evaluation within HULL_BLOCK (nut, bearing group,
    # drive) elements: thousands of drives times 64 nuts held arrays of GB in the drive block's
    # temporaries
    per_nut = max(space.n_drives, 1) * min(B, DRIVE_BEARING_GROUPS)
    rows = max(1, min(DRIVE_NUTS, HULL_BLOCK // per_nut))
    for n0 in range(0, N, rows):
        if deadline is not None and time.perf_counter() > deadline:
            return None
        sl = slice(n0, min(N, n0 + rows))
        for name, v in drive_optimism(space, mounting, sl, drive).items():
            out[name][sl] = v
    return out


def drive_optimism(space: Space, mounting: str, nut_slice: slice, drive) -> dict:
    """For the drive limits ``drive`` (motor and coupling checks, inertia ratio: the outputs of the
    drive block), per (nut, bearing) block of ``nut_slice`` a value no combination of the block
    beats at any allowed preload: the drive block in interval arithmetic over the block's guides and
    preloads (:func:`.drivebounds.drive_hull`); the best over the drives bounds the block.  Returns
    {limit name: (nuts, bearings)}."""
    hull, group = drive_hull(space, mounting, nut_slice, drive)
    out = {}
    for c in drive:
        if c.name not in hull:
            raise KeyError(
                f"limit {c.name} reads {c.key}, which neither the optimistic guide nor the drive "
                "block bounds"
            )
        v = hull[c.name]
        out[c.name] = (v.max(axis=-1) if c.sense == ">=" else v.min(axis=-1))[:, group]
    return out
