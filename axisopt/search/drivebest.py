"""The default method's search of a rack-and-pinion or linear-motor space: the drive block (every combination
of the parts but the guide, the last axis of a :class:`.drivespace.DriveSpace`) is bounded once with the
optimistic guide -- the least friction, seal drag and block mass for the drive checks and limits, the stiffest
block and the lightest or heaviest blocks (whichever is better for the objective: each output is monotone in
each guide value) for the objective -- the drives that fail even so are dropped, the rest are evaluated with
every guide in the order of their bound until no drive left can reach the ``top``-th best design.  The
guide checks (life, static safety) depend on the drive's mass and are checked with the pairs only.  Exact:
the tests compare it with every combination evaluated (:func:`.drivetype.search_space`, method exhaustive)."""

from __future__ import annotations

import numpy as np

from .drivespace import evaluate_one, respond

CHUNK = 64  # drives evaluated with all their guides at a time
GUIDE_KEYS = ("mu", "f_seal", "m_blocks", "k_n", "c_block", "c0_block", "roller", "rating_distance")


def _reduced(space, which: str) -> dict:
    """The parameters with the guide axis reduced to its optimistic value (``which``: 'light' or 'heavy'
    blocks)."""
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


def drive_bounds(problem, space, spec):
    """Per drive (flat over the drive axes): the optimistic objective, whether it may pass, its least miss."""
    from .drivetype import limit_arrays

    name, factor, _, sense = spec
    dshape = space.shape[:-1] + (1,)
    cost = space.drive_cost + np.min(space.guide_cost, axis=-1, keepdims=True)
    runs = []
    for which in ("light", "heavy"):
        res = respond(space, _reduced(space, which))
        out = {k: _flat(v, dshape) for k, v in res["outputs"].items()}
        marg = {
            k: _flat(v, dshape) for k, v in res["margins"].items() if not k.startswith("guide_")
        }
        runs.append((out, marg))
    c = _flat(cost, dshape)
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


def best_first(problem, space, spec, top: int):
    """(best ``top`` designs, evaluated pairs, closest combinations if none is feasible)."""
    from .drivetype import design_of, rank_designs, scores

    sense = spec[3]
    obj, ok, miss = drive_bounds(problem, space, spec)
    G = space.shape[-1]
    alive = np.flatnonzero(ok)
    key = -obj[alive] if sense == "max" else obj[alive]
    alive = alive[np.argsort(key, kind="stable")]
    sign = -1.0 if sense == "max" else 1.0
    best: list = []  # (ranking key, flat)
    evaluated = 0
    for start in range(0, alive.size, CHUNK):
        drives = alive[start : start + CHUNK]
        if len(best) >= top:
            kth = sign * best[top - 1][0][0]
            bound = obj[drives[0]]
            tol = 1e-9 * max(abs(kth), 1.0)
            if (sense == "max" and bound < kth - tol) or (sense == "min" and bound > kth + tol):
                break
        flats = (drives[:, None] * G + np.arange(G)[None, :]).reshape(-1)
        res = _evaluate_flats(space, flats)
        o, k, _ = scores(problem, space, res, spec)
        evaluated += flats.size
        mass = res["outputs"]["moving_mass"]
        for i in np.flatnonzero(k):
            best.append((rank_key(o[i], res["cost"][i], mass[i], sign), int(flats[i])))
        best = sorted(best)[:top]
    if best:
        designs = rank_designs(
            [design_of(space, f, evaluate_one(space, f), spec) for _, f in best], sense
        )
        return designs[:top], evaluated, []
    near_drives = np.argsort(miss, kind="stable")[:50]
    flats = (near_drives[:, None] * G + np.arange(G)[None, :]).reshape(-1)
    res = _evaluate_flats(space, flats)
    _, _, m = scores(problem, space, res, spec)
    return [], evaluated + flats.size, [int(flats[i]) for i in np.argsort(m, kind="stable")[:50]]


def rank_key(objective, cost, mass, sign) -> tuple:
    """The tie rule: the objective, then lower cost, then lower mass (rounded so float noise is no rank)."""
    return (round(float(sign * objective), 9), round(float(cost), 6), round(float(mass), 9))


def _take(v, idx):
    """The entries of a broadcastable array at the multi-index ``idx`` (a size-1 axis stays at 0)."""
    if not isinstance(v, np.ndarray) or v.ndim == 0:
        return v
    return v[tuple(ix if v.shape[d] != 1 else 0 for d, ix in enumerate(idx))]


def _evaluate_flats(space, flats) -> dict:
    """The model on the combinations ``flats`` (1-D arrays of parameters)."""
    shape = space.shape
    idx = np.unravel_index(flats, shape)
    p = {k: _take(v, idx) for k, v in space.p.items()}
    res = respond(space, p)
    n = flats.size
    return {
        "outputs": {
            k: np.broadcast_to(np.asarray(v, dtype=float), (n,)) for k, v in res["outputs"].items()
        },
        "margins": {
            k: np.broadcast_to(np.asarray(v, dtype=float), (n,)) for k, v in res["margins"].items()
        },
        "cost": np.broadcast_to(np.asarray(_take(space.cost, idx), dtype=float), (n,)),
    }
