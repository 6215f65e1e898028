"""Bounds over blocks of combinations, before any combination is formed.

:func:`block_bounds`: each (mounting, nut, bearing) block -- all its guides and drives -- is tested and bounded
at once with an optimistic guide (the most favourable value of every guide column,
:meth:`.space.Space.params_optimistic_guide`): every mechanical limit at its favourable preload end
(:attr:`.constraints.Constraint.favourable`) and an upper bound of the objective at the highest allowed
preload over a few grid positions.  :func:`convex_margin_bound` bounds a motor-torque margin over a preload
interval (the screening's drive stage).  :func:`screen_ok` is the float32 screening test both use: every limit
relaxed by :data:`SCREEN_RTOL`, so rounding can only keep a combination, never drop one.
"""

from __future__ import annotations

import numpy as np

from .. import model
from .constraints import Constraint, End
from .objective import ObjectiveSpec
from .space import DRIVE_KEYS, SCREEN_CHUNK, Space

SCREEN_RTOL = 1e-4  # float32 screening: relative slack on every test and on the bound


def block_bounds(space: Space, constraints, objective: ObjectiveSpec):
    """Per (mounting, nut, bearing) block of combinations: whether some guide (and drive) could meet the
    mechanical limits, and an upper bound of the objective over the block, both from one evaluation with
    the optimistic guide of each guide type (:meth:`Space.params_optimistic_guide`).  Limits the drive
    changes, and the motor-torque limits, are left to the screening.  Returns a list over mountings of
    (ok, bound), each nuts x bearings."""
    _, N, B, _ = space.shape
    # every mechanical limit, and the cost (the optimistic guide carries the cheapest drive pair's price)
    mech = [c for c in constraints if not c.convex and (c.key not in DRIVE_KEYS or c.key == "cost")]
    low_end = [c for c in mech if c.favourable is not End.HIGH]
    high_end = [c for c in mech if c.favourable is End.HIGH]
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
                        ok &= screen_ok(c, out_lo)
                    for c in high_end:
                        ok &= screen_ok(c, o)
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



def screen_ok(c, out):
    """Whether limit ``c`` is met by the model outputs ``out``, relaxed by :data:`SCREEN_RTOL` (screening)."""
    v = c.value(out)
    if not c.profile:
        v = np.asarray(v)[..., 0] if np.ndim(v) else v
    lim = c.limit * (1.0 + SCREEN_RTOL) if c.sense == "<=" else c.limit * (1.0 - SCREEN_RTOL)
    return np.asarray(v <= lim if c.sense == "<=" else v >= lim, dtype=bool)



def interval_min_abs(t_lo, t_hi):
    """min |T| over preloads between two ends where T is affine in the preload: 0 if it changes sign."""
    t_lo, t_hi = np.asarray(t_lo), np.asarray(t_hi)
    return np.where(t_lo * t_hi <= 0, 0.0, np.minimum(np.abs(t_lo), np.abs(t_hi)))


def convex_margin_bound(c: Constraint, out_lo: dict, out_hi: dict, phases) -> np.ndarray:
    """An upper bound of a motor-torque margin over every preload between the two ends of ``out_lo`` and
    ``out_hi`` (screening).  Each phase torque is affine in the preload (through the nut's drag), so its
    smallest magnitude over the interval is known; the thrusts grow with the preload.  RMS: a linear piece
    (T0^2 + T0 T1 + T1^2)/3 >= (T0^2 + T1^2)/6, and = T0^2 for a constant one."""
    v_lo = np.asarray(out_lo[c.key])
    if np.all(v_lo >= 1e8):  # not applicable anywhere (no motor): nothing to bound
        return v_lo
    thrust = "thrust_torque" if c.key == "margin_motor_peak_torque" else "mean_thrust_torque"
    # what the margin compares the torque with (the peak: the zone at each phase's speed, referred to the flat
    # peak; the RMS: rms_torque_ratio x rated), recovered exactly from the margin at the interval's low end
    need_lo = np.asarray(out_lo["needed_motor_peak_torque" if c.key == "margin_motor_peak_torque"
                                else "needed_motor_rated_torque"])
    available = v_lo * need_lo
    ends = [(interval_min_abs(a0, b0), interval_min_abs(a1, b1))
            for (a0, a1), (b0, b1) in zip(out_lo["duty_torques"], out_hi["duty_torques"])]
    if c.key == "margin_motor_peak_torque":  # each phase's smallest |T| referred to the flat peak (zone factor)
        lb = np.asarray(out_lo[thrust])
        for (m0, m1), k in zip(ends, out_lo["zone_factors"]):
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
