"""One-dimensional numerics of the preload solve, vectorized over combinations and free of the model: the
k-ary threshold search (:func:`kary_threshold`, bisection generalised to ``points`` trials per round) and the
golden-section maximum of a unimodal function (:func:`golden_best`).  Kiefer, "Sequential minimax search for a
maximum", Proc. AMS 4 (1953) 502-506 (golden section).
"""

from __future__ import annotations

import math

import numpy as np

GOLDEN_STEPS = 60  # golden-section steps for the most favourable preload of a convex limit
BISECTION_STEPS = 52
SEARCH_POINTS = 64  # k-ary threshold search (default method): most preloads tried per round in one evaluation


def golden_best(value, a, b, steps=GOLDEN_STEPS):
    """Preload in [a, b] maximising a unimodal ``value(preload) -> (K,)`` (vectorized golden section)."""
    r = (math.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = b - r * (b - a), a + r * (b - a)
    f1, f2 = value(x1), value(x2)
    for _ in range(steps):
        left = f1 >= f2
        b = np.where(left, x2, b)
        a = np.where(left, a, x1)
        x2n = np.where(left, x1, a + r * (b - a))
        x1n = np.where(left, b - r * (b - a), x2)
        x1, x2 = x1n, x2n
        f1, f2 = value(x1), value(x2)
    return np.where(f1 >= f2, x1, x2)



def kary_threshold(good, a, z, points: int = SEARCH_POINTS):
    """The end of the set ``good`` holds on, between a end ``a`` where it holds and ``z`` where it does not,
    for a set that is one interval containing ``a`` (a monotone limit, or a convex one seen from a feasible
    point).  Each round tries ``points - 1`` evenly spaced preloads in one vectorized call of
    ``good(pre (K, points - 1)) -> bool (K, points - 1)`` and keeps the segment where it stops holding, so
    the bracket shrinks ``points``-fold per round: to the bisection's 2^-52 in 9 calls instead of 52."""
    a, z = np.array(a, dtype=float), np.array(z, dtype=float)
    if not a.size:
        return a
    t = np.arange(1, points) / points
    rows = np.arange(len(a))
    for _ in range(math.ceil(BISECTION_STEPS / math.log2(points))):
        pts = a[:, None] + (z - a)[:, None] * t[None, :]
        ok = np.asarray(good(pts), dtype=bool).reshape(pts.shape)
        lead = np.cumprod(ok, axis=1).sum(axis=1)  # points that hold before the first that does not
        a_new = np.where(lead > 0, pts[rows, np.maximum(lead - 1, 0)], a)
        z = np.where(lead < points - 1, pts[rows, np.minimum(lead, points - 2)], z)
        a = a_new
    return a

