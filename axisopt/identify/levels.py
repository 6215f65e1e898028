"""Levels of a factor logged with jitter: readings meant at one speed, position or load are logged a
little apart (a speed held to +-0.5 %, a position to +-1 mm); they are one level for replicates and
held-out groups.

A sorted factor is cut where the gap to the next value exceeds ``REL`` of the value or, for every
factor but the velocity, ``SPAN`` of the factor's range (a velocity spans decades: its levels are
relative).
"""

from __future__ import annotations

import numpy as np

# a gap up to 1.2 % of the value joins two readings (jitter of +-0.5 % spreads a level by 1 %)
REL = 0.012
SPAN = 0.004  # ... or up to 0.4 % of the factor's range (+-1 mm on an 800 mm stroke)
RELATIVE_ONLY = ("velocity",)


def cluster_levels(values, name: str = "") -> np.ndarray:
    """``values`` with each level replaced by its mean (the level as meant); exact repeats stay as
    they are."""
    v = np.asarray(values, dtype=float)
    if v.size < 2:
        return v.copy()
    order = np.argsort(v, kind="stable")
    s = v[order]
    tol = REL * np.abs(s[1:])
    if name not in RELATIVE_ONLY:
        tol = np.maximum(tol, SPAN * float(np.ptp(s)))
    cut = np.diff(s) > tol
    label = np.r_[0, np.cumsum(cut)]
    means = np.bincount(label, weights=s) / np.bincount(label)
    out = np.empty_like(v)
    out[order] = means[label]
    return out
