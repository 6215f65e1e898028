"""The default method's search of a rack-and-pinion or linear-motor space: the drive block (every
combination of the parts but the guide, the last axis of a :class:`.drivespace.DriveSpace`) is
bounded once with the optimistic guide -- the least friction, seal drag and block mass for the drive
checks and limits, the stiffest block and the lightest or heaviest blocks (whichever is better for
the objective: each output is monotone in each guide value) for the objective -- the drives that
fail even so are dropped, the rest are evaluated with every guide in the order of their bound until
no drive left can reach the ``top``-th best design.  The guide checks (life, static safety) depend
on the drive's mass and are checked with the pairs only.  Exact: the tests compare it with every
combination evaluated (:func:`.drivetype.search_space`, method exhaustive)."""

from __future__ import annotations

import numpy as np

from .drivedesigns import design_of, limit_arrays, rank_designs, rank_key, scores
from .drivespace import evaluate_one, respond, take

CHUNK = 64  # drives evaluated with all their guides at a time
GUIDE_KEYS = ("mu", "f_seal", "m_blocks", "k_n", "c_block", "c0_block", "roller", "rating_distance")


def _reduced(space, which: str) -> dict:
    """The parameters with the guide axis reduced to its optimistic value (``which``: 'light' or
    'heavy' blocks)."""
    p = dict(space.p)
    for k in ("mu", "f_seal"):
        p[k] = np.min(p[k], axis=-1, keepdims=True)
    for k in (
        "k_n",
        "c_block",
        "c0_block",
        "roller",
        "rating_distance",
    ):  # the guide checks are not bounded here
        p[k] = np.max(p[k], axis=-1, keepdims=True)
    p["m_blocks"] = (np.min if which == "light" else np.max)(p["m_blocks"], axis=-1, keepdims=True)
    return p


def _flat(v, shape) -> np.ndarray:
    return np.broadcast_to(np.asarray(v, dtype=float), shape).reshape(-1)


def _subset(p: dict, idx) -> dict:
    """The parameters at the multi-index ``idx`` (a size-1 axis stays at 0)."""
    return {k: take(v, idx) for k, v in p.items()}


def drive_bounds(problem, space, spec, drives=None):
    """Per drive (flat over the drive axes, or the flat indices ``drives`` of them): the optimistic
    objective, whether it may pass, its least miss."""
    name, factor, _, sense = spec
    dshape = space.shape[:-1] + (1,)
    cost = space.drive_cost + np.min(space.guide_cost, axis=-1, keepdims=True)
    idx = None
    if drives is not None:
        idx = np.unravel_index(drives, space.shape[:-1]) + (np.zeros(len(drives), dtype=int),)
        dshape = (len(drives),)
    runs = []
    for which in ("light", "heavy"):
        p = _reduced(space, which)
        res = respond(space, p if idx is None else _subset(p, idx))
        out = {k: _flat(v, dshape) for k, v in res["outputs"].items()}
        marg = {
            k: _flat(v, dshape) for k, v in res["margins"].items() if not k.startswith("guide_")
        }
        runs.append((out, marg))
    c = _flat(cost if idx is None else take(np.asarray(cost), idx), dshape)
    pick = np.maximum if sense == "max" else np.minimum
    vals = [c if name == "cost" else out[name] for out, _ in runs]
    obj = pick(vals[0], vals[1]) / factor
    ok = np.ones(obj.shape, dtype=bool)
    miss = np.zeros(obj.shape)
    for m in runs[0][1].values():  # light blocks: every drive check at its easiest
        ok &= m >= 1.0
        miss += np.maximum(0.0, 1.0 - m)
    lims = [limit_arrays(problem, out, c) for out, _ in runs]
    for key in lims[0]:
        v = np.maximum(lims[0][key], lims[1][key])
        ok &= v >= 0.0
        miss += np.maximum(0.0, -v)
    return obj, ok, miss


MOTOR_AXIS = 2  # of a rack space: rack, reduction, motor, twin pinion, guide
# drives from which the rack space is first bounded per (rack, reduction, twin) block
LEVEL1_MIN = 200_000
LEVEL1_BATCH = 8  # (rack, reduction, twin) blocks opened at a time


def block_bounds(space, spec):
    """The optimistic objective of each (rack, reduction, twin pinion) block of a rack space, over
    its motors and guides: every output the objective reads is monotone in the motors' and blocks'
    mass (lightest and heaviest tried), the stiffest block, the cheapest motor and guide; the other
    motor values do not enter it.  Flat over (rack, reduction, twin)."""
    name, factor, _, sense = spec
    shape = space.shape[:MOTOR_AXIS] + (1,) + space.shape[MOTOR_AXIS + 1 : -1] + (1,)
    out = []
    for which in ("light", "heavy"):
        p = _reduced(space, which)
        red = (np.min if which == "light" else np.max)(p["m_parts"], axis=MOTOR_AXIS, keepdims=True)
        p = {
            k: (
                v[:, :, :1]
                if isinstance(v, np.ndarray) and v.ndim == 5 and v.shape[MOTOR_AXIS] > 1
                else v
            )
            for k, v in p.items()
        }
        p["m_parts"] = red
        if name == "cost":
            v = np.min(space.drive_cost, axis=MOTOR_AXIS, keepdims=True) + np.min(
                space.guide_cost, axis=-1, keepdims=True
            )
        else:
            v = respond(space, p)["outputs"][name]
        out.append(np.broadcast_to(np.asarray(v, dtype=float), shape).reshape(-1))
    return (np.maximum if sense == "max" else np.minimum)(out[0], out[1]) / factor


def beaten(bound, kth, sense) -> bool:
    """Whether an optimistic ``bound`` cannot reach the value ``kth`` (1e-9 relative: a tie is not
    beaten)."""
    tol = 1e-9 * max(abs(kth), 1.0)
    return bool((sense == "max" and bound < kth - tol) or (sense == "min" and bound > kth + tol))


def best_first(problem, space, spec, top: int):
    """(best ``top`` designs, evaluated pairs, closest combinations if none is feasible).  A large
    rack space is opened block by block: the (rack, reduction, twin pinion) blocks in the order of
    their bound (:func:`block_bounds`), each block's drives bounded and evaluated as a space's,
    until no block left can reach the ``top``-th best design."""
    sense = spec[3]
    sign = -1.0 if sense == "max" else 1.0
    state = {"best": [], "evaluated": 0}
    n_drives = int(np.prod(space.shape[:-1]))
    if space.kind == "rack_pinion" and n_drives >= LEVEL1_MIN:
        bshape = space.shape[:MOTOR_AXIS] + space.shape[MOTOR_AXIS + 1 : -1]
        bound = block_bounds(space, spec)
        order = np.argsort(-bound if sense == "max" else bound, kind="stable")
        n_mot = space.shape[MOTOR_AXIS]
        for start in range(0, order.size, LEVEL1_BATCH):
            blocks = order[start : start + LEVEL1_BATCH]
            best = state["best"]
            if len(best) >= top and beaten(bound[blocks[0]], sign * best[top - 1][0][0], sense):
                break
            r, rd, t = np.unravel_index(blocks, bshape)
            drives = np.ravel_multi_index(
                (
                    np.repeat(r, n_mot),
                    np.repeat(rd, n_mot),
                    np.tile(np.arange(n_mot), blocks.size),
                    np.repeat(t, n_mot),
                ),
                space.shape[:-1],
            )
            _visit(problem, space, spec, top, drives, state)
        near = _closest(problem, space, spec, None) if not state["best"] else []
    else:
        near = _visit(problem, space, spec, top, None, state)
    if state["best"]:
        designs = rank_designs(
            [design_of(space, f, evaluate_one(space, f), spec) for _, f in state["best"]], sense
        )
        return designs[:top], state["evaluated"], []
    return [], state["evaluated"], near


def _visit(problem, space, spec, top, drives, state):
    """Bound ``drives`` (all when None) with the optimistic guide, then evaluate those that may
    still win with every guide in bound order, updating ``state``; returns the closest combinations
    when none is feasible and ``drives`` is None."""
    sense = spec[3]
    sign = -1.0 if sense == "max" else 1.0
    obj, ok, miss = drive_bounds(problem, space, spec, drives)
    ids = np.arange(obj.size) if drives is None else np.asarray(drives)
    G = space.shape[-1]
    alive = np.flatnonzero(ok)
    alive = alive[np.argsort(-obj[alive] if sense == "max" else obj[alive], kind="stable")]
    best = state["best"]
    for start in range(0, alive.size, CHUNK):
        sel = alive[start : start + CHUNK]
        if len(best) >= top and beaten(obj[sel[0]], sign * best[top - 1][0][0], sense):
            break
        flats = (ids[sel][:, None] * G + np.arange(G)[None, :]).reshape(-1)
        res = _evaluate_flats(space, flats)
        o, k, _ = scores(problem, space, res, spec)
        state["evaluated"] += flats.size
        mass = res["outputs"]["moving_mass"]
        for i in np.flatnonzero(k):
            best.append((rank_key(o[i], res["cost"][i], mass[i], sign), int(flats[i])))
        best.sort()
        del best[top:]
    if drives is None and not best:
        return _closest(problem, space, spec, miss)
    return []


def _closest(problem, space, spec, miss):
    """The 50 combinations of least summed miss among the 50 drives of least optimistic miss."""
    if miss is None:
        _, _, miss = drive_bounds(problem, space, spec)
    G = space.shape[-1]
    near_drives = np.argsort(miss, kind="stable")[:50]
    flats = (near_drives[:, None] * G + np.arange(G)[None, :]).reshape(-1)
    _, _, m = scores(problem, space, _evaluate_flats(space, flats), spec)
    return [int(flats[i]) for i in np.argsort(m, kind="stable")[:50]]


def _evaluate_flats(space, flats) -> dict:
    """The model on the combinations ``flats`` (1-D arrays of parameters)."""
    shape = space.shape
    idx = np.unravel_index(flats, shape)
    p = {k: take(v, idx) for k, v in space.p.items()}
    res = respond(space, p)
    n = flats.size
    return {
        "outputs": {
            k: np.broadcast_to(np.asarray(v, dtype=float), (n,)) for k, v in res["outputs"].items()
        },
        "margins": {
            k: np.broadcast_to(np.asarray(v, dtype=float), (n,)) for k, v in res["margins"].items()
        },
        "cost": np.broadcast_to(np.asarray(space.cost_of(idx), dtype=float), (n,)),
    }
