"""Screening: every combination of a set of (mounting, nut, bearing) blocks, vectorized in the
structured layout (:mod:`.task.space`), in float32 with the slack of :func:`.bounds.screen_ok`.

Every preload-independent limit is checked exactly; each preload-dependent limit at its most
favourable preload (drag and life at the lowest allowed preload, lift-off and minimum
stiffness/frequency at the highest), which is exact as a necessary condition.  The bound is the
objective at the highest allowed preload over a few grid positions (an upper bound of the minimum
over the full grid).  Entry points :func:`screen` (every combination) and :func:`screen_nuts` (the
blocks of some nuts: the best-first driver, the Pareto front).
"""

from __future__ import annotations

import time

import numpy as np

from .. import model
from ..model.limits import margin_output
from .bounds import SCREEN_RTOL, bound_positions, relaxed_ok, screen_ok
from .drivebounds import DRIVE_BEARING_GROUPS, HULL_BLOCK, PER_DRIVE_MIN, drive_hull
from .task.constraints import Constraint, End, reads_regen
from .task.objective import ObjectiveSpec
from .task.space import DRIVE_KEYS, Space, as_dtype


def screen(space: Space, constraints, objective: ObjectiveSpec):
    """Vectorized screening of every combination.  Returns (idx, bound, seconds) for the survivors.

    Two structured evaluations per block of nuts: at the lowest allowed preload on one position (the
    preload-independent limits and the ones that favour a low preload) and at the highest allowed
    preload on :func:`.bounds.bound_positions` (the limits that favour a high preload and the
    bound).  Screening runs in float32 for memory bandwidth; every test is relaxed by SCREEN_RTOL
    and the bound raised by it, so rounding can only keep a combination, never drop one (exact
    checks follow in float64).

    The mechanics are screened once per (screw, nut, bearing, guide) combination on every limit the
    drive does not change (the stiffness chain, the modes, the objective bound); each surviving
    combination is then expanded by its (motor, coupling) pairs -- one, the axis's motor and
    coupling values, without a drive search -- and screened on the drive's limits
    (:data:`DRIVE_KEYS`) with the drive sub-assembly alone.  (Without a drive search this two-stage
    order is 3x faster too: the motor-torque bounds then run on the few mechanical survivors.)
    """
    t0 = time.perf_counter()
    N = space.shape[1]
    step = space.nuts_per_block
    idx_parts, bound_parts = [], []
    for mi in range(len(space.mountings)):
        for n0 in range(0, N, step):
            i, bnd = screen_nuts(space, mi, slice(n0, min(N, n0 + step)), constraints, objective)
            idx_parts.append(i)
            bound_parts.append(bnd)
    idx = np.concatenate(idx_parts) if idx_parts else np.zeros(0, np.int64)
    bound = np.concatenate(bound_parts) if bound_parts else np.zeros(0)
    return idx, bound, time.perf_counter() - t0


def viable_drives(space: Space, mounting: str, nut_idx, constraints):
    """Per (nut, bearing group, drive) of the nuts ``nut_idx`` (sorted), whether the drive could
    meet every drive limit with some guide and preload of the block
    (:func:`.drivebounds.drive_hull`, relaxed as the screening), and each bearing's group; None
    without a drive search or drive limits.  A necessary
    condition: the drive stage then evaluates only the drives that pass it."""
    cons = [c for c in constraints if c.key in DRIVE_KEYS]
    if space.m_arr is None or not cons or not len(nut_idx) or space.n_drives < PER_DRIVE_MIN:
        return None
    D = space.n_drives
    rows = max(1, HULL_BLOCK // max(D * min(space.shape[2], DRIVE_BEARING_GROUPS), 1))
    parts, group = [], None
    for s0 in range(0, len(nut_idx), rows):
        hull, group = drive_hull(space, mounting, nut_idx[s0 : s0 + rows], cons)
        ok = True
        for c in cons:
            if c.name in hull:
                ok = ok & relaxed_ok(c, hull[c.name])
        if ok is True:
            return None
        parts.append(ok)
    return np.concatenate(parts), group


def _mechanical(constraints):
    """The limits of the mechanical stage: every limit the drive does not change, and the lost
    motion (its value without a reduction, the nut's play, is the least over every drive: the drive
    stage tests it again)."""
    return [c for c in constraints if c.key not in DRIVE_KEYS or c.key == "backlash"]


# (nut, bearing, guide) combinations per evaluation inside screen_nuts (cache-sized arrays)
CACHE_BLOCK = 200_000


def group_end(bm, bn, pos: int, reach, nuts: int) -> int:
    """The end of the next group of blocks to screen, from ``pos`` of the blocks in search order
    (mounting ``bm``, nut ``bn``): the blocks ``i`` with ``reach(i)``, up to ``nuts`` distinct
    (mounting, nut) pairs, and at least one block."""
    end, seen = pos, set()
    while end < len(bm) and reach(end):
        key = (bm[end], bn[end])
        if key not in seen and len(seen) >= nuts:
            break
        seen.add(key)
        end += 1
    return max(end, pos + 1)


def screen_blocks(space: Space, bm, bn, bb, constraints, objective: ObjectiveSpec):
    """:func:`screen_nuts` over a group of (mounting ``bm``, nut ``bn``, bearing ``bb``) blocks, one
    mounting at a time, each mounting's nuts with the bearings of its blocks only.  Yields
    (survivors' combination numbers, bounds) per mounting."""
    B = space.shape[2]
    for mi in np.unique(bm):
        sel = bm == mi
        gn, gb = bn[sel], bb[sel]
        nuts = np.unique(gn)
        premask = np.zeros((len(nuts), B), dtype=bool)
        premask[np.searchsorted(nuts, gn), gb] = True
        yield screen_nuts(space, int(mi), nuts, constraints, objective, premask=premask)


def screen_nuts(space: Space, mi: int, nuts, constraints, objective: ObjectiveSpec, premask=None):
    """:func:`screen` over the nuts ``nuts`` (a slice or an index array) of mounting ``mi``, every
    bearing and guide (and drive); ``premask`` (nuts x bearings, optional) leaves out (nut, bearing)
    blocks.  Returns the survivors' combination numbers and bounds.  The model is evaluated over
    sub-blocks of about :data:`CACHE_BLOCK` combinations (whole nuts): numpy then works on arrays
    that stay in the CPU cache, about twice as fast as over millions of combinations at once; the
    survivors are the same."""
    mounting = space.mountings[mi]
    _, N, B, G = space.shape
    D = space.n_drives
    Gm = G // D  # guide axis of the mechanical stage
    phases = space.problem.axis_for(mounting).phases
    nut_idx = space.nut_numbers(nuts)
    viable = viable_drives(space, mounting, nut_idx, constraints)
    # a (nut, bearing) block no drive could meet the drive's limits with: left out
    if viable is not None:
        block = viable[0].any(axis=-1)[:, viable[1]]
        premask = block if premask is None else premask & block
    step = max(1, CACHE_BLOCK // max(B * Gm, 1))
    parts = []
    for s0 in range(0, len(nut_idx), step):
        s1 = min(len(nut_idx), s0 + step)
        if isinstance(nuts, slice):
            sub = slice(int(nut_idx[s0]), int(nut_idx[s1 - 1]) + 1) if len(nut_idx) else nuts
        else:
            sub = nut_idx[s0:s1]
        pm = None if premask is None else premask[s0:s1]
        parts.append(
            _screen_mechanics(space, mounting, sub, nut_idx[s0:s1], constraints, objective, pm)
        )
    if parts:
        nn, bb, gg, bnd = (np.concatenate([q[i] for q in parts]) for i in range(4))
    else:
        nn, bb, gg, bnd = (np.zeros(0, np.int64),) * 3 + (np.zeros(0),)
    if viable is not None:  # each survivor's drives that pass the drive limits' bounds of its block
        first = (
            viable[0][np.searchsorted(nut_idx, nn), viable[1][bb]]
            if len(nn)
            else np.zeros((0, D), bool)
        )
    else:
        first = None
    nn, bb, gg, bnd = _screen_drives(space, mounting, constraints, phases, nn, bb, gg, bnd, first)
    return np.ravel_multi_index((np.full(len(nn), mi), nn, bb, gg), space.shape), bnd


def _screen_mechanics(
    space: Space, mounting: str, nuts, nut_idx, constraints, objective: ObjectiveSpec, premask
):
    """The mechanical stage of :func:`screen_nuts` over the nuts ``nuts`` (numbers ``nut_idx``):
    every limit but the drive's (:data:`DRIVE_KEYS`, which hold the motor-torque limits, the only
    convex ones), and the bound.  Returns the survivors' (nut, bearing, guide, bound)."""
    _, _, B, G = space.shape
    Gm = G // space.n_drives
    mech = _mechanical(constraints)
    # independent or favoured by a low preload
    low_end = [c for c in mech if c.favourable is not End.HIGH]
    high_end = [c for c in mech if c.favourable is End.HIGH]
    xs = bound_positions(space, mounting).astype(np.float32)
    x1 = xs[-1:]
    p = space.params_structured(mounting, nuts, dtype=np.float32, mechanics=True)
    lo = space.preload_lo[nut_idx].reshape(-1, 1, 1, 1).astype(np.float32)
    hi = space.preload_hi[nut_idx].reshape(-1, 1, 1, 1).astype(np.float32)
    nc = len(nut_idx)
    fits = space.fits[nut_idx] if premask is None else space.fits[nut_idx] & premask
    mask = np.broadcast_to(fits[:, :, None], (nc, B, Gm)).copy()
    with np.errstate(all="ignore"):
        chain_lo = any(c.key in model.CHAIN_OUTPUTS for c in low_end)
        out_lo = model.axis_response(
            p, x1, mounting, lo, space.request.but(drive=False, chain=chain_lo)
        )
        for c in low_end:
            mask &= screen_ok(c, out_lo)
        out = model.axis_response(p, xs, mounting, hi, space.request.but(drive=False))
        for c in high_end:
            mask &= screen_ok(c, out)
        bound = objective.value(out)
    bound = np.broadcast_to(bound + SCREEN_RTOL * np.abs(bound), (nc, B, Gm))
    nn, bb, gg = np.nonzero(mask)
    return nut_idx[nn], bb, gg, bound[nn, bb, gg].astype(float)


# (combination, drive) pairs per block of the drive stage (cache-sized float64 arrays)
DRIVE_CHUNK = 50_000


def _screen_drives(space: Space, mounting: str, constraints, phases, nn, bb, gg, bound, first=None):
    """The drive stage of :func:`screen`: each mechanical survivor (nut nn, bearing bb, guide gg)
    times every (motor, coupling) pair, checked on the limits the drive changes at the lowest and
    highest allowed preload (float64, same slack), structured over (survivor, drive pair)
    (:func:`drive_params`: the mechanics once per survivor, the drive once per pair).  ``first``
    (survivors x drives, optional): the pairs worth checking (:func:`viable_drives`); each block of
    survivors evaluates the drives any of them keeps.  Returns the survivors' (nut, bearing,
    guide-and-drive, bound)."""
    D = space.n_drives
    cons = [c for c in constraints if c.key in DRIVE_KEYS]
    if not cons or len(nn) == 0:
        g_full = (gg[:, None] * D + np.arange(D)[None]).ravel()
        return np.repeat(nn, D), np.repeat(bb, D), g_full, np.repeat(bound, D)
    cvx = [c for c in cons if c.convex]
    out_parts = [(np.zeros(0, np.int64),) * 3 + (np.zeros(0),)]
    if first is not None:  # survivors left no drive: none formed
        keep = first.any(axis=1)
        nn, bb, gg, bound, first = nn[keep], bb[keep], gg[keep], bound[keep], first[keep]
    rows = max(1, DRIVE_CHUNK // D)
    for s0 in range(0, len(nn), rows):
        n_, b_, g_, bd = (
            nn[s0 : s0 + rows],
            bb[s0 : s0 + rows],
            gg[s0 : s0 + rows],
            bound[s0 : s0 + rows],
        )
        K = len(n_)
        cols = np.arange(D) if first is None else np.nonzero(first[s0 : s0 + rows].any(axis=0))[0]
        p = drive_params(space, mounting, n_, b_, g_, drives=None if first is None else cols)
        lo, hi = space.preload_lo[n_][:, None, None], space.preload_hi[n_][:, None, None]
        with np.errstate(all="ignore"):
            regen = model.SCREEN.but(regen=reads_regen(cons))  # the drive block's request
            out_lo = model.drive_response(p, lo, regen)
            out_hi = (
                model.drive_response(p, hi, regen)
                if cvx or any(c.lower_type for c in cons)
                else None
            )
            ok = (
                np.ones((K, len(cols)), dtype=bool)
                if first is None
                else first[s0 : s0 + rows][:, cols].copy()
            )
            for c in cons:
                if c.convex:
                    ub = np.asarray(convex_margin_bound(c, out_lo, out_hi, phases))
                    ok_c = ub >= c.limit * (1.0 - SCREEN_RTOL)
                    ok &= ok_c[..., 0] if ok_c.ndim == 3 else ok_c
                # at the preload end that favours it (the regenerated power falls with the preload)
                else:
                    ok &= screen_ok(c, out_hi if c.favourable is End.HIGH else out_lo)
        k, d = np.nonzero(ok)
        out_parts.append((n_[k], b_[k], g_[k] * D + cols[d], bd[k]))
    return tuple(np.concatenate([o[i] for o in out_parts]) for i in range(4))


def drive_params(space: Space, mounting: str, n, b, g, dtype=float, drives=None) -> dict:
    """Parameters over (K mechanical combinations, D drive pairs, 1 position): screw, nut, bearing
    and guide columns of the combinations (nut ``n``, bearing ``b``, mechanical guide ``g``) shaped
    (K, 1, 1), the searched (motor, coupling) pairs (1, D, 1); element (k, d) is guide-and-drive
    ``g[k] * D + d``.
    ``drives``: those drive numbers only, in that order, on the second axis."""
    D = space.n_drives

    def pick(d, i):
        return {k: v[i][:, None, None] for k, v in d.items()}

    ps = model.axis_params(
        space.problem.axis_for(mounting),
        pick(space.s_arr, n),
        pick(space.n_arr, n),
        pick(space.b_arr, b),
        pick(space.g_arr, np.asarray(g) * D),
        *space.drive_columns((1, -1, 1), drives=drives),
    )
    return as_dtype(ps, dtype)


def interval_min_abs(t_lo, t_hi):
    """min |T| over preloads between two ends where T is affine in the preload: 0 if it changes
    sign."""
    t_lo, t_hi = np.asarray(t_lo), np.asarray(t_hi)
    return np.where(t_lo * t_hi <= 0, 0.0, np.minimum(np.abs(t_lo), np.abs(t_hi)))


# The torque checks convex in the nut preload (model.limits CONVEX), each with the model outputs its
# margin reads: (phase torques, the steady thrust that bounds it from below, the needed value, zone
# factors or None, peak or RMS)
CONVEX_TORQUES = {
    margin_output("motor_peak_torque"): (
        "duty_torques",
        "thrust_torque",
        "needed_motor_peak_torque",
        "zone_factors",
        True,
    ),
    margin_output("motor_rated_torque"): (
        "duty_torques",
        "mean_thrust_torque",
        "needed_motor_rated_torque",
        None,
        False,
    ),
    margin_output("reduction_accel_torque"): (
        "output_torques",
        "output_thrust_torque",
        "needed_reduction_accel_torque",
        None,
        True,
    ),
    margin_output("reduction_rated_torque"): (
        "output_torques",
        "output_mean_thrust_torque",
        "needed_reduction_rated_torque",
        None,
        False,
    ),
}


def convex_margin_bound(c: Constraint, out_lo: dict, out_hi: dict, phases) -> np.ndarray:
    """An upper bound of a motor- or reduction-torque margin (:data:`CONVEX_TORQUES`) over every
    preload between the two ends of ``out_lo`` and ``out_hi`` (screening).  Each phase torque is
    affine in the preload (through the nut's drag), so its smallest magnitude over the interval is
    known; the thrusts grow with the preload.
    RMS: a linear piece (T0^2 + T0 T1 + T1^2)/3 >= (T0^2 + T1^2)/6, and = T0^2 for a constant
    one."""
    v_lo = np.asarray(out_lo[c.key])
    if np.all(v_lo >= 1e8):  # not applicable anywhere (no motor, no reduction): nothing to bound
        return v_lo
    torques, thrust, needed, zone, peak = CONVEX_TORQUES[c.key]
    # what the margin compares the torque with (the motor peak: the zone at each phase's speed,
    # referred to the flat peak; the motor RMS: rms_torque_ratio x rated; the reduction: T2B, T2N),
    # recovered exactly from the margin at the interval's low end
    need_lo = np.asarray(out_lo[needed])
    available = v_lo * need_lo
    # phases sharing a torque pair at both ends (physics.drive.phase_torques): one evaluation
    shared: dict = {}
    ends = []
    for lo_pair, hi_pair in zip(out_lo[torques], out_hi[torques]):
        key = (id(lo_pair), id(hi_pair))
        if key not in shared:
            (a0, a1), (b0, b1) = lo_pair, hi_pair
            shared[key] = (interval_min_abs(a0, b0), interval_min_abs(a1, b1))
        ends.append(shared[key])
    if peak:  # each phase's smallest |T| (the motor's referred to the flat peak by its zone factor)
        lb = np.asarray(out_lo[thrust])
        factors = out_lo[zone] if zone else [1.0] * len(ends)
        for (m0, m1), k in zip(ends, factors):
            lb = np.maximum(lb, np.maximum(m0, m1) * k)
    else:
        total = sum(ph.duration for ph in phases)
        acc = 0.0
        for ph, (m0, m1) in zip(phases, ends):
            acc = acc + ph.duration * (m0 * m0 if ph.a0 == ph.a1 else (m0 * m0 + m1 * m1) / 6.0)
        lb = np.maximum(np.sqrt(acc / total) if total > 0 else 0.0, np.asarray(out_lo[thrust]))
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = np.where(lb > 0, available / lb, np.inf)
    return np.where(v_lo >= 1e8, v_lo, bound)  # not applicable (no motor): as is
