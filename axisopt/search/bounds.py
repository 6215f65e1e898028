"""Bounds over blocks of combinations, before any combination is formed.

:func:`block_bounds`: each (mounting, nut, bearing) block -- all its guides and drives -- is tested
and bounded at once with an optimistic guide (the most favourable value of every guide column,
:func:`optimistic_guide_params`): every mechanical limit at its favourable preload end
(:attr:`.constraints.Constraint.favourable`) and an upper bound of the objective at the highest
allowed preload over a few grid positions (:func:`bound_positions`).  :func:`screen_ok` is the
float32 test the bounds and the screening use: every limit relaxed by :data:`SCREEN_RTOL`, so
rounding can only keep a combination, never drop one.
"""

from __future__ import annotations

import numpy as np

from .. import model
from ..model.params import GUIDE_RATING_DISTANCE
from .task.constraints import End
from .task.objective import ObjectiveSpec
from .task.space import DRIVE_KEYS, MECHANICS_BOUNDED, SCREEN_CHUNK, Space, as_dtype, shaped

SCREEN_RTOL = 1e-4  # float32 screening: relative slack on every test and on the bound

# The guide values that favour every mechanical limit and the objective (the optimistic guide of the
# block bounds): the table carries the blocks, so less block mass, rail mass, friction, price and
# preload, and more rigidity, damping and load rating never make a design worse.  The drive's limits
# (motor torques, where less friction can raise a deceleration torque) are not bounded this way
# (DRIVE_KEYS: checked per pair).
GUIDE_BEST = {
    "normal_rigidity": np.nanmax,
    "tangential_rigidity": np.nanmax,
    "friction_force": np.nanmin,
    "friction_coefficient": np.nanmin,
    "friction_viscous": np.nanmin,
    "damping": np.nanmax,
    "block_mass": np.nanmin,
    "rail_mass_per_length": np.nanmin,
    "block_price": np.nanmin,
    "rail_price_per_length": np.nanmin,
    "dynamic_load_rating": np.nanmax,
    "preload": np.nanmin,
    # carriage (model.carriage): a higher static or moment rating never loads a block more
    "static_load_rating": np.nanmax,
    "moment_roll": np.nanmax,
    "moment_pitch": np.nanmax,
    "moment_yaw": np.nanmax,
    # the longest rating basis, an empty cell read as the model reads it (model.params)
    "rating_distance": lambda v: np.max(np.nan_to_num(v, nan=GUIDE_RATING_DISTANCE)),
}


def bound_positions(space: Space, mounting: str) -> np.ndarray:
    """A few grid positions; the minimum over them bounds the minimum over the grid from above."""
    x = space.grid[mounting]
    n = len(x)
    idx = {0, n // 2, n - 1}
    if mounting == "fixed-fixed":
        idx.add(int(np.argmin(np.abs(x - 0.5 * space.problem.axis.span))))
    return x[sorted(idx)]


def optimistic_guide_params(
    space: Space, mounting: str, nut_sel, guide_type: str, dtype=float
) -> dict:
    """Parameters over (nuts ``nut_sel``, bearings, one guide, positions) where the one guide takes,
    column by column, the most favourable value of the searched guides of ``guide_type``
    (:data:`GUIDE_BEST`).  No mechanical limit and no objective value of any (nut, bearing, guide)
    combination is better than with this guide, so the (nut, bearing) results bound every guide (and
    every drive: the axis values stand in for motor and coupling, with the stiffest searched
    coupling in the stiffness chain)."""
    D = space.n_drives
    sel = space.g_arr["type"][::D] == guide_type
    s, nt, b = space.nut_bearing_arrays(nut_sel, dtype)
    g = {
        k: np.array([GUIDE_BEST[k](v[::D][sel])]) for k, v in space.g_arr.items() if k in GUIDE_BEST
    }
    g["type"] = np.array([guide_type])
    g = shaped(g, (1, 1, 1, 1), dtype)
    ps = model.axis_params(space.problem.axis_for(mounting), s, nt, b, g, None, None)
    if space.m_arr is not None:
        ps["coupling_stiffness"] = float(space.coupling_k[-1])
        # the cheapest searched drive (motor, coupling, reduction): the cost is a lower bound over
        # every drive
        price = np.nan_to_num(space.m_arr["price"][:D])
        for arr in (space.c_arr, space.r_arr):
            if arr is not None:
                price = price + np.nan_to_num(arr["price"][:D])
        ps["motor_price"], ps["coupling_price"], ps["reduction_price"] = (
            float(price.min()),
            0.0,
            0.0,
        )
    return as_dtype(ps, dtype)


def block_bounds(space: Space, constraints, objective: ObjectiveSpec):
    """Per (mounting, nut, bearing) block of combinations: whether some guide (and drive) could meet
    the mechanical limits, and an upper bound of the objective over the block, both from one
    evaluation with the optimistic guide of each guide type (:func:`optimistic_guide_params`).
    Limits the drive changes, and the motor-torque limits, are left to the screening.  Returns a
    list over mountings of (ok, bound), each nuts x bearings."""
    _, N, B, _ = space.shape
    # every mechanical limit, and the cost (the optimistic guide carries the cheapest drive pair's
    # price)
    mech = [
        c
        for c in constraints
        if not c.convex and (c.key not in DRIVE_KEYS or c.key in MECHANICS_BOUNDED)
    ]
    low_end = [c for c in mech if c.favourable is not End.HIGH]
    high_end = [c for c in mech if c.favourable is End.HIGH]
    types = np.unique(space.g_arr["type"]) if len(space.guides) else np.array([], dtype=str)
    step = block_chunk(space)
    out = []
    for mounting in space.mountings:
        ok_all = np.zeros((N, B), dtype=bool)
        bound_all = np.full((N, B), -np.inf)
        for n0 in range(0, N, step):
            sl = slice(n0, min(N, n0 + step))
            for t in types:
                with np.errstate(all="ignore"):
                    out_lo, o = block_outputs(space, mounting, sl, str(t))
                    ok = np.broadcast_to(
                        space.fits[sl][:, :, None], (sl.stop - sl.start, B, 1)
                    ).copy()
                    for c in low_end:
                        ok &= screen_ok(c, out_lo)
                    for c in high_end:
                        ok &= screen_ok(c, o)
                    bnd = np.broadcast_to(objective.value(o), ok.shape).astype(float)
                bnd = bnd + 2.0 * SCREEN_RTOL * np.abs(bnd)
                ok_all[sl] |= ok[..., 0]
                bound_all[sl] = np.maximum(
                    bound_all[sl], np.where(ok[..., 0], bnd[..., 0], -np.inf)
                )
        out.append((ok_all, bound_all))
    return out


# block-bound model values kept per space up to this many (nut, bearing, position)s
BOUNDS_KEPT = 200_000


def block_chunk(space: Space) -> int:
    """Nuts per evaluation of :func:`block_outputs` (the slices :func:`block_bounds` takes)."""
    return max(1, SCREEN_CHUNK // max(space.shape[2], 1))


def block_outputs(space: Space, mounting: str, sl: slice, guide_type: str):
    """The optimistic guide's model outputs over the nuts ``sl`` and every bearing in float32, at
    the lowest preload (last of :func:`bound_positions`) and at the highest (those positions): what
    :func:`block_bounds` tests and bounds (and the explanation's block bounds, relaxed for the
    rounding).  The outputs do not depend on the limits: kept per space (the sensitivities'
    re-solves) where they are small."""
    xs = bound_positions(space, mounting).astype(np.float32)
    keep = space.shape[1] * space.shape[2] * len(xs) <= BOUNDS_KEPT
    key = ("block outputs", mounting, sl.start, sl.stop, guide_type)
    hit = space._cache.get(key) if keep else None
    if hit is not None:
        return hit
    lo = space.preload_lo[sl].reshape(-1, 1, 1, 1).astype(np.float32)
    hi = space.preload_hi[sl].reshape(-1, 1, 1, 1).astype(np.float32)
    p = optimistic_guide_params(space, mounting, sl, guide_type, dtype=np.float32)
    # the drive block is left out: block_bounds reads no limit the drive changes but the cost
    # (outside it)
    res = (
        model.axis_response(p, xs[-1:], mounting, lo, model.MECHANICS),
        model.axis_response(p, xs, mounting, hi, model.MECHANICS),
    )
    if keep:
        space._cache[key] = res
    return res


def screen_ok(c, out):
    """Whether limit ``c`` is met by the model outputs ``out``, relaxed by :data:`SCREEN_RTOL`
    (screening)."""
    v = c.value(out)
    if not c.profile:
        v = np.asarray(v)[..., 0] if np.ndim(v) else v
    return relaxed_ok(c, v)


def relaxed_ok(c, v):
    """Whether the value ``v`` of limit ``c`` meets it, relaxed by :data:`SCREEN_RTOL`."""
    lim = c.limit * (1.0 + SCREEN_RTOL) if c.sense == "<=" else c.limit * (1.0 - SCREEN_RTOL)
    return np.asarray(v <= lim if c.sense == "<=" else v >= lim, dtype=bool)
