"""Bounds of the drive's limits, per drive, over the guides of a (nut, bearing) block, before any
(guide, drive) combination is formed.

The guide enters the drive block (:func:`axisopt.model.drive.drive`) only through the moving mass,
the drag torque and the guide friction at standstill (:func:`axisopt.model.drive_inputs`), so the
block is evaluated once per drive in interval arithmetic (:mod:`.interval`) over the range of those
three that the block's guides give (a box holding every guide's triple).  The bearings are taken in
:data:`DRIVE_BEARING_GROUPS` groups of neighbouring drag torque, each bearing parameter an interval
over its group.

Two uses: :func:`drive_box` at each preload end (the explanation's block bounds, which read each
limit at its favourable end), and :func:`drive_hull` over the whole allowed preload range at once
(the drag torque is affine in the nut preload, so every preload between the ends lies in the box): a
value no combination of the block beats at any allowed preload, for each drive -- the screening's
and the explanation's per-drive test.
"""

from __future__ import annotations

import numpy as np

from .. import model
from ..model.drive import drive as drive_block
from ..model.drive import lost_motion
from .interval import Interval, ends
from .task.constraints import reads_regen
from .task.space import Space, shaped

# bearings taken together in the drive limits' interval bounds (module docstring)
DRIVE_BEARING_GROUPS = 8
# fewer searched drives than this: the screening and the explanation evaluate every drive without
# the per-drive bounds first (on the 1000-case study, 10 drives per case, the bounds cost more than
# they saved)
PER_DRIVE_MIN = 64
# (nut, bearing group, drive) elements per interval evaluation of the drive block by a caller that
# splits its nuts (the screening's viable drives, the explanation's per-block drive bounds): its
# temporaries stay near 1 GB
HULL_BLOCK = 400_000


def drive_pair_params(space: Space, mounting: str, nut_sel, bearings=None) -> dict:
    """Parameters over (nuts ``nut_sel``, bearings, drives, 1) with the first guide's columns (or,
    with ``bearings`` aligned with the nuts, over ((nut, bearing) pairs, 1, drives, 1)): for the
    drive block, which takes the guide only through the moving mass, the drag torque and the
    standstill friction passed to it."""
    s, nt, b = space.nut_bearing_arrays(nut_sel, float, bearings)
    g = shaped({k: v[:1] for k, v in space.g_arr.items()}, (1, 1, 1, 1), float)
    return model.axis_params(
        space.problem.axis_for(mounting), s, nt, b, g, *space.drive_columns((1, 1, -1, 1))
    )


def drive_box(
    space: Space, mounting: str, nut_sel, regen: bool, bearings=None, across: bool = False
):
    """The drive block's outputs in interval arithmetic per (nut, bearing group, drive) of the nuts
    ``nut_sel`` (or per (nut, bearing) pair of ``bearings``, one group each): a list of (lower ends,
    upper ends) dicts, one per preload end (lowest, highest), or one over the whole preload range if
    ``across``; with ``group``, each bearing's group.  The lost motion (``backlash``: nut and
    reduction alone) is exact."""
    # (n, B, guides, 1)
    pm = space.params_structured(mounting, nut_sel, mechanics=True, bearings=bearings)
    pd = drive_pair_params(space, mounting, nut_sel, bearings)  # (n, B, drives, 1)
    nc = len(space.nut_numbers(nut_sel))
    B = 1 if bearings is not None else space.shape[2]
    if B > 1:
        torque = np.broadcast_to(np.asarray(pd["bearing_torque"], dtype=float), (1, B, 1, 1))[
            0, :, 0, 0
        ]
        order = np.argsort(torque, kind="stable")
        starts = np.unique(np.linspace(0, B, min(B, DRIVE_BEARING_GROUPS) + 1).astype(int)[:-1])
    else:
        order, starts = np.zeros(1, dtype=np.int64), np.zeros(1, dtype=np.int64)
    group = np.empty(B, dtype=np.int64)
    group[order] = np.searchsorted(starts, np.arange(B), side="right") - 1

    def over_groups(lo, hi):
        """(lo, hi) along the bearing axis reduced to each group's range."""
        lo, hi = np.take(lo, order, axis=1), np.take(hi, order, axis=1)
        return np.minimum.reduceat(lo, starts, axis=1), np.maximum.reduceat(hi, starts, axis=1)

    def by_group(v):
        a = np.asarray(v)
        if B > 1 and a.ndim >= 2 and a.shape[1] == B and a.dtype.kind == "f":
            return Interval(*over_groups(a, a))
        return v

    pg = {k: (v if k == "duty" else by_group(v)) for k, v in pd.items()}
    backlash = np.broadcast_to(lost_motion(pd), (nc, 1, space.n_drives, 1))
    red = (nc, B, 1, 1)  # the guide axis reduced

    def guide_range(v):
        """(least, largest) over the guides, as (nuts, bearings, 1, 1): reduced before any
        broadcast."""
        v = np.asarray(v, dtype=float)
        if v.ndim == 4 and v.shape[2] > 1:
            return (
                np.broadcast_to(v.min(axis=2, keepdims=True), red),
                np.broadcast_to(v.max(axis=2, keepdims=True), red),
            )
        v = np.broadcast_to(v, red) if v.ndim < 4 or v.shape[2] == 1 else v
        return v, v

    inputs = []
    for pre in (space.preload_lo[nut_sel], space.preload_hi[nut_sel]):
        with np.errstate(divide="ignore"):
            moving, drag, hold_friction = model.drive_inputs(pm, pre.reshape(-1, 1, 1, 1))
        inputs.append([guide_range(v) for v in (moving, drag["drag_torque"], hold_friction)])
    # every preload between the ends: the drag is affine in it, so the two ends' hull holds it
    if across:
        inputs = [[(np.minimum(a[0], b[0]), np.maximum(a[1], b[1])) for a, b in zip(*inputs)]]
    out = []
    for vals in inputs:
        ranges = [Interval(*over_groups(lo, hi)) for lo, hi in vals]
        with np.errstate(divide="ignore", invalid="ignore"):
            lo, hi = ends(drive_block(pg, *ranges, regen=regen))
        lo["backlash"] = hi["backlash"] = backlash
        out.append((lo, hi))
    return out, group


# a mounting's hull is computed once for every nut and kept up to this many (nut, bearing group,
# drive) elements (the interval drive block, about 2 us each: 3.4 s for the laser axis's 2 M) and
# this many (nut, bearing, guide) elements of the mechanics it takes; above, each caller's nuts are
# evaluated when asked
HULL_CACHE = 100_000
HULL_CACHE_MECHANICS = 4_000_000


def _whole_hull(space: Space) -> bool:
    """Whether a mounting's hull is computed once for every nut (:data:`HULL_CACHE`)."""
    N, B = space.shape[1], space.shape[2]
    Gm = space.shape[3] // max(space.n_drives, 1)
    return (
        N * min(B, DRIVE_BEARING_GROUPS) * space.n_drives <= HULL_CACHE
        and N * B * Gm <= HULL_CACHE_MECHANICS
    )


def hull_ends(space: Space, mounting: str, nut_sel, regen: bool, bearings=None):
    """:func:`drive_box` over the whole preload range (lower ends, upper ends) for the nuts
    ``nut_sel`` (or the (nut, bearing) pairs of ``bearings``), and each bearing's group.  Where the
    mounting's every nut fits in :data:`HULL_CACHE`, the box of every nut is evaluated once per
    space and these rows are taken from it (the screening, the explanation's block bounds and its
    scored blocks read the same values)."""
    N = space.shape[1]
    nut_idx = space.nut_numbers(nut_sel)
    if not _whole_hull(space):
        (box,), group = drive_box(space, mounting, nut_idx, regen, bearings, across=True)
        return box, group
    key = ("drive hull", mounting, regen, DRIVE_BEARING_GROUPS)
    hit = space._cache.get(key)
    if hit is None:
        hit = drive_box(space, mounting, slice(0, N), regen, across=True)
        space._cache[key] = hit
    (box,), group = hit

    def rows(v):
        v = np.asarray(v)
        if v.ndim == 0:
            return v
        if v.shape[0] > 1:
            v = v[nut_idx]
        if bearings is not None and v.shape[1] > 1:  # each pair's own bearing group
            first = np.arange(len(v)) if v.shape[0] > 1 else np.zeros(len(nut_idx), dtype=np.int64)
            v = v[first, group[np.asarray(bearings, dtype=np.int64)]][:, None]
        return v

    box = tuple(
        {k: rows(v) for k, v in end.items() if isinstance(v, (np.ndarray, float))} for end in box
    )
    return box, (np.zeros(1, dtype=np.int64) if bearings is not None else group)


# the per-nut rows of :func:`drive_hull` kept on the space for the searches that follow on it (the
# limit sensitivities' and the cheaper design's re-searches open the same nuts: 0.3-0.8 s of
# interval arithmetic per nut on the 2 t boring table), in float32 rounded outward, up to this many
# bytes
HULL_ROWS_BYTES = 192 * 2**20


def _outward32(v: np.ndarray, up: bool) -> np.ndarray:
    """``v`` in float32, each value rounded away from the side a limit tests (up for an upper end):
    a bound it was stays a bound."""
    w = v.astype(np.float32)
    with np.errstate(invalid="ignore"):
        off = w < v if up else w > v
    if off.any():
        w[off] = np.nextafter(w[off], np.float32(np.inf if up else -np.inf))
    return w


def drive_hull(space: Space, mounting: str, nut_sel, constraints, bearings=None):
    """Per (nut, bearing group, drive) of the nuts ``nut_sel`` (or per (nut, bearing) pair of
    ``bearings``), for each limit of ``constraints`` a value no (guide, preload) of the block beats
    with that drive: the drive block's limits from its interval bounds, the cost its least value
    (:func:`least_cost`): {limit name: (nuts, groups, drives)}, and each bearing's group.  Without
    ``bearings`` each nut's rows are kept on the space (:data:`HULL_ROWS_BYTES`, float32 rounded
    outward): a later search on the space (a limit relaxed, the cheaper design) takes them from
    there."""
    if not constraints:
        return {}, None
    if bearings is None and not _whole_hull(space):
        return _hull_rows(space, mounting, nut_sel, constraints)
    return _drive_hull(space, mounting, nut_sel, constraints, bearings)


def _row_key(c):
    """What a constraint's hull row depends on: its output and sense (the cost: its least value)."""
    return ("cost",) if c.key == "cost" else (c.key, c.sense, c.profile)


def _hull_rows(space: Space, mounting: str, nut_sel, constraints):
    """:func:`_drive_hull` per nut through the space's store of rows (:data:`HULL_ROWS_BYTES`)."""
    regen = reads_regen([c for c in constraints if c.key != "cost"])
    store = space._cache.setdefault(("hull rows", HULL_ROWS_BYTES), {"bytes": 0, "rows": {}})
    rows = store["rows"]
    nut_idx = np.asarray(space.nut_numbers(nut_sel), dtype=np.int64)
    if not len(nut_idx):
        return _drive_hull(space, mounting, nut_sel, constraints)
    need = {_row_key(c) for c in constraints}
    got = {int(n): rows.get((mounting, regen, int(n))) for n in nut_idx}
    miss = [n for n, hit in got.items() if hit is None or not need <= hit[0].keys()]
    if miss:
        hull, group = _drive_hull(space, mounting, np.asarray(miss, dtype=np.int64), constraints)
        by_key = {}
        for c in constraints:
            by_key.setdefault(_row_key(c), (hull[c.name], c.sense == ">="))
        for i, n in enumerate(miss):
            vals = {k: _outward32(np.asarray(v[i]), up) for k, (v, up) in by_key.items()}
            got[n] = (vals, group)
            had = rows.get((mounting, regen, n), ({}, group))[0]
            size = sum(v.nbytes for k, v in vals.items() if k not in had)
            if store["bytes"] + size <= HULL_ROWS_BYTES:
                store["bytes"] += size
                rows[(mounting, regen, n)] = ({**had, **vals}, group)
    hits = [got[int(n)] for n in nut_idx]
    out = {c.name: np.stack([h[0][_row_key(c)] for h in hits]).astype(float) for c in constraints}
    return out, hits[0][1]


def _drive_hull(space: Space, mounting: str, nut_sel, constraints, bearings=None):
    """:func:`drive_hull` evaluated."""
    cons = [c for c in constraints if c.key != "cost"]
    box, group = hull_ends(space, mounting, nut_sel, reads_regen(cons), bearings)
    shape = (len(space.nut_numbers(nut_sel)), int(group.max()) + 1, space.n_drives, 1)
    out = {}
    for c in cons:
        end = box[1] if c.sense == ">=" else box[0]
        if c.key in end:
            out[c.name] = np.broadcast_to(np.asarray(c.value(end), dtype=float), shape)[..., 0]
    if len(cons) < len(constraints):
        least = least_cost(space, mounting, nut_sel, group, bearings)
        out.update({c.name: least for c in constraints if c.key == "cost"})
    return out, group


def least_cost(space: Space, mounting: str, nut_sel, group, bearings=None) -> np.ndarray:
    """The least cost [EUR] of a block's combinations with each drive, over its guides and the
    bearings of each group (``group``: each bearing's), per (nut, group, drive) of the nuts
    ``nut_sel`` (or per (nut, bearing) pair of ``bearings``, one group).  The cost is a sum of part
    prices (:func:`axisopt.model.cost.cost`, the drive's counted once per drive of the axis) and
    reads no preload, so this is exact: the least over guides and bearings with the first drive,
    plus each drive's price difference from it (:func:`cost_parts`)."""
    by_group, per_drive = cost_parts(space, mounting, nut_sel, group, bearings)
    return by_group[..., None] + per_drive[None, None, :]


def cost_parts(space: Space, mounting: str, nut_sel, group, bearings=None) -> tuple:
    """(the least cost [EUR] with the first searched drive per (nut, group) as in
    :func:`least_cost`, each drive's price difference from the first (drives,))."""
    from ..model.cost import cost

    nut_idx = space.nut_numbers(nut_sel)
    first = np.zeros(1, dtype=np.int64)
    mech = np.asarray(
        cost(space.params_drives(mounting, nut_idx, bearings, drives=first)), dtype=float
    )
    nb = (len(nut_idx), len(group))
    # (nuts, bearings), the first drive
    mech = np.broadcast_to(mech, nb + mech.shape[2:]).min(axis=(2, 3))
    # one nut and bearing
    one = space.params_drives(mounting, nut_idx[:1], np.zeros(1, dtype=np.int64))
    per = np.asarray(cost(one), dtype=float)
    # one combination, every drive
    per = np.broadcast_to(per, per.shape[:3] + (space.n_drives,))[0, 0, 0]
    n_groups = int(group.max()) + 1
    # (nuts, groups)
    by_group = np.stack([mech[:, group == k].min(axis=1) for k in range(n_groups)], axis=1)
    return by_group, per - per[0]
