"""Synthetic measurements from a known axis with chosen effects (tests, benchmarks, test planning).

``simulate(plant, kind, columns, effects={...}, noise=0.01, seed=0)`` evaluates the same measurement
model the diagnosis fits, with the given parameter values (SI), and adds Gaussian noise of ``noise``
times the weight scale of each row (``max(|y|, 0.1 rms(y))``, i.e. relative noise with a floor).
"""

from __future__ import annotations

import numpy as np

from ..effects import library
from .data import Dataset
from .diagnose import Context, build_problem
from .measure import baseline_params, observations

MEASURED = {
    "stiffness": ("displacement",),
    "friction": ("friction_force",),
    "frequency": ("frequency",),
    "frf": ("real", "imag"),
}


def simulate(
    plant,
    kind: str,
    columns: dict,
    effects=None,
    baseline=None,
    noise: float = 0.01,
    seed: int = 0,
    source: str = "synthetic.csv",
) -> Dataset:
    """A :class:`Dataset` of ``kind`` at the conditions in ``columns`` (SI arrays, no measured
    column).

    effects  : {effect name: {parameter: SI value}} hidden in the data
    baseline : {baseline parameter: SI value}, e.g. {'screw_modulus': 200e9}
    """
    effects = effects or {}
    baseline = baseline or {}
    cols = {k: np.asarray(v, dtype=float) for k, v in columns.items()}
    n = len(next(iter(cols.values())))
    for m in MEASURED[kind]:
        cols[m] = np.zeros(n) if m == "imag" else np.ones(n)  # placeholders
    ds = Dataset(kind, source, cols, np.arange(2, n + 2))
    obs = [observations(ds, plant)]
    ctx = Context(plant, obs, resid=[np.zeros(obs[0].n)])
    lib = library()
    eff = [lib[name] for name in effects]
    ctx.params = {e.name: e.params(ctx) for e in eff}
    base = baseline_params(
        {kind} | ({"stiffness"} if "screw_modulus" in baseline else set()), plant
    )
    prob = build_problem(ctx, eff, base)
    given = dict(baseline)
    for vals in effects.values():
        given.update(vals)
    unknown = set(given) - {p.name for p in prob.params}
    if unknown:
        raise ValueError(f"unknown parameter(s) {sorted(unknown)} for {kind}")
    theta = np.array([given.get(p.name, p.init) for p in prob.params])
    y = prob.predict(theta)
    rng = np.random.default_rng(seed)
    rms = float(np.sqrt(np.mean(y**2)))
    if kind == "frf":
        h = n
        mag = np.hypot(y[:h], y[h:])
        sc = np.r_[mag, mag]
    else:
        sc = np.maximum(np.abs(y), 0.1 * rms)
    y = y + noise * sc * rng.standard_normal(len(y))
    if kind == "frf":
        cols["real"], cols["imag"] = y[:n], y[n:]
    else:
        cols[MEASURED[kind][0]] = y
    return Dataset(kind, source, cols, np.arange(2, n + 2))
