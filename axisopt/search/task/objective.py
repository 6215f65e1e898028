"""The scalar objective of a search and its tie rule.

:class:`ObjectiveSpec` (a weighted sum of performance minima, maximised, in display units) is
derived from :data:`axisopt.model.goals.OBJECTIVE_TABLE` by :func:`objective_spec`;
:func:`rank_order` and :func:`objective_floor` are the tie rule every method shares: objective
values within :data:`TIE_RTOL` count as equal and go to the lower cost, then the lower total mass,
then the lower combination number.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from ...model.goals import GOALS, OBJECTIVE_TABLE
from ...problem import Problem
from ...units import N_PER_UM

TIE_RTOL = 1e-7  # objective values this close count as equal; ties go to lower cost, then mass

# SI per display unit of each objective output (N/um for the stiffnesses); the objective is in
# display units
DISPLAY_FACTOR = MappingProxyType({g.output: g.factor for g in OBJECTIVE_TABLE})
# shown in N/um
STIFFNESS_OUTPUTS = frozenset(o for o, f in DISPLAY_FACTOR.items() if f == N_PER_UM)


def min_last(v):
    """Minimum over the last (position) axis; elementwise chains for short axes (much faster)."""
    v = np.asarray(v)
    if v.ndim == 0:
        return v
    n = v.shape[-1]
    if n > 8:
        return np.min(v, axis=-1)
    m = v[..., 0]
    for i in range(1, n):
        m = np.minimum(m, v[..., i])
    return m


def in_display_units(key: str, v):
    """An objective output ``key``'s value ``v`` (numpy or CasADi) in its display unit."""
    f = DISPLAY_FACTOR.get(key, 1.0)
    return v / f if f != 1.0 else v


@dataclass(frozen=True)
class ObjectiveSpec:
    """A scalar objective J(out) to maximise, in display units, built from performance minima."""

    terms: tuple  # ((output key, weight / scale in display units), ...)
    label: str
    unit: str

    @property
    def sign(self) -> float:
        """-1 for a least cost or mass (the search maximises its negative), else 1: the sign that
        turns the search's objective into the value shown."""
        return -1.0 if self.terms and all(w < 0 for _, w in self.terms) else 1.0

    def value(self, out, axis=-1):
        total = 0.0
        for key, w in self.terms:
            total = total + w * in_display_units(key, min_last(out[key]))
        return total


def objective_spec(kind: str, problem: Problem | None = None) -> ObjectiveSpec:
    """The objective of the mode ``kind`` (a scalar goal of ``OBJECTIVE_TABLE``, or ``'weighted'``
    with the weights and scales of ``problem``)."""
    g = GOALS.get(kind)
    # a least cost or mass is maximised as its negative (ObjectiveSpec.sign)
    if g is not None and g.mode:
        return ObjectiveSpec(((g.output, 1.0 if g.sense == "max" else -1.0),), g.label, g.unit)
    if kind == "weighted":
        ob = problem.objective
        scale = dict(ob.scale)
        terms = []
        for k, w in ob.weights:
            g = GOALS[k]
            terms.append((g.output, w / (scale[k] / g.factor if g.factor != 1.0 else scale[k])))
        return ObjectiveSpec(tuple(terms), "weighted objective " + ob.label, "-")
    raise ValueError(f"no scalar objective for '{kind}'")


def rank_order(objective, cost, mass, idx, top: int) -> np.ndarray:
    """Positions of the ``top`` best entries: highest objective; values within TIE_RTOL count as
    equal and go to the lower cost, then the lower total mass, then the lower combination number."""
    objective = np.asarray(objective, float)
    finite = np.isfinite(objective)
    pos = np.nonzero(finite)[0]
    chosen = []
    remaining = pos
    while len(chosen) < top and len(remaining):
        jv = objective[remaining]
        best = jv.max()
        tie = remaining[jv >= best - TIE_RTOL * max(abs(best), 1e-30)]
        order = np.lexsort((idx[tie], mass[tie], cost[tie]))
        take = tie[order[: top - len(chosen)]]
        chosen.extend(take.tolist())
        remaining = np.setdiff1d(remaining, take, assume_unique=True)
    return np.asarray(chosen, dtype=np.int64)


def objective_floor(value: float) -> float:
    """Smallest objective that could still tie with ``value`` (for pruning)."""
    if not math.isfinite(value):
        return value
    return value - 2.0 * TIE_RTOL * max(abs(value), 1e-30)
