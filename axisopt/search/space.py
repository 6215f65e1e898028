"""The discrete search space of a problem and vectorized evaluation of the axis model over it.

A combination is (mounting, nut, bearing arrangement, guide); the nut fixes the screw.  Combinations
are numbered ``((m * N + n) * B + b) * G + g`` over the filtered part tables.

Two evaluation layouts use the same :func:`axisopt.model.axis_response`:

* *structured* (screening): nut/screw parameters shaped ``(N, 1, 1, 1)``, bearings ``(1, B, 1, 1)``,
  guides ``(1, 1, G, 1)``, positions on the last axis and the preload on a leading axis.  numpy
  broadcasting then computes each quantity only over the parts it depends on (the stiffness chain
  never touches the guides, the cost is a sum of per-part terms, ...).
* *flat* (exact evaluation of selected combinations): every parameter shaped ``(K, 1)``.

Preload structure (assumed from the model; default == exhaustive in tests/search checks it): the minimum stiffness and
frequency, the drag torque and the nut lift-off margin are nondecreasing in the nut preload, the nut
life is nonincreasing, and every other output is independent of it.  The feasible preloads of a
combination are therefore an interval and the best preload is its upper end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from .. import model
from ..catalog import USER_STATUS
from ..problem import LIMITS, Problem
from ..units import N_PER_UM

# Outputs that depend on the nut preload and how (+1 nondecreasing, -1 nonincreasing).
PRELOAD_DIRECTION = {"k_total": 1, "f1": 1, "k_nut": 1, "k_drive": 1, "f_axial": 1, "drag_torque": 1, "drag_nut": 1,
                     "margin_nut_lift_off": 1, "life": -1, "margin_nut_life": -1}
PROFILE = ("k_total", "f1")
TIE_RTOL = 1e-7  # objective values this close count as equal; ties go to lower cost, then mass
BISECTION_STEPS = 52

_SCREW_COLS = ("root_diameter", "nominal_diameter", "lead", "max_length", "mass_per_length", "dn_limit",
               "price_per_length", "price_fixed", "support_bore_min", "support_bore_max")
_NUT_COLS = ("stiffness", "stiffness_preload", "dynamic_load_rating", "static_load_rating", "mass", "price",
             "preload_min", "preload_max", "axial_play")
_BEARING_COLS = ("axial_rigidity", "lift_off_load", "preload", "f0", "f1", "bore", "outer_diameter",
                 "limiting_speed", "mass", "price", "dynamic_load_rating", "starting_torque")
_GUIDE_COLS = ("normal_rigidity", "tangential_rigidity", "friction_force", "friction_coefficient",
               "friction_viscous", "damping", "block_mass", "rail_mass_per_length", "block_price",
               "rail_price_per_length", "dynamic_load_rating", "preload")


@dataclass(frozen=True)
class Constraint:
    """``value(out) sense limit``; ``direction`` is how the value moves with the nut preload."""

    name: str  # limit key or 'margin_<check>'
    key: str  # model output
    sense: str  # '<=' or '>='
    limit: float  # SI
    direction: int  # 0 independent of preload, +1 nondecreasing, -1 nonincreasing
    label: str
    unit: str
    factor: float  # SI per display unit

    @property
    def profile(self) -> bool:
        return self.key in PROFILE

    @property
    def upper_type(self) -> bool:
        """Satisfied for preloads below a threshold (drag, life)."""
        return (self.sense == "<=" and self.direction > 0) or (self.sense == ">=" and self.direction < 0)

    @property
    def lower_type(self) -> bool:
        """Satisfied for preloads above a threshold (lift-off, minimum stiffness/frequency)."""
        return (self.sense == ">=" and self.direction > 0) or (self.sense == "<=" and self.direction < 0)

    def value(self, out, axis=-1):
        v = out[self.key]
        return min_last(v) if self.profile else v

    def ok(self, v):
        return v <= self.limit if self.sense == "<=" else v >= self.limit

    def violation(self, v):
        """Relative miss (0 when met)."""
        if self.sense == "<=":
            if self.limit <= 0:  # e.g. max_backlash 0: the miss in display units
                return np.maximum(v / self.factor, 0.0)
            return np.maximum(v / self.limit - 1.0, 0.0)
        return np.maximum(1.0 - v / self.limit, 0.0)


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


def build_constraints(problem: Problem) -> tuple[Constraint, ...]:
    out = []
    for key, value in problem.limits:
        kind, unit, factor, okey, sense = LIMITS[key]
        out.append(Constraint(key, okey, sense, value, PRELOAD_DIRECTION.get(okey, 0),
                              key.replace("_", " "), unit, factor))
    for check, m in problem.margins:
        if m > 0:
            k = f"margin_{check}"
            out.append(Constraint(k, k, ">=", m, PRELOAD_DIRECTION.get(k, 0), model.CHECK_LABELS[check], "", 1.0))
    return tuple(out)


@dataclass(frozen=True)
class ObjectiveSpec:
    """A scalar objective J(out) to maximise, in display units, built from performance minima."""

    terms: tuple  # ((output key, weight / scale in display units), ...)
    label: str
    unit: str

    def value(self, out, axis=-1):
        total = 0.0
        for key, w in self.terms:
            v = min_last(out[key])
            total = total + w * (v / N_PER_UM if key == "k_total" else v)
        return total


def objective_spec(kind: str, problem: Problem | None = None) -> ObjectiveSpec:
    if kind == "stiffness":
        return ObjectiveSpec((("k_total", 1.0),), "minimum axial stiffness", "N/um")
    if kind == "frequency":
        return ObjectiveSpec((("f1", 1.0),), "minimum first natural frequency", "Hz")
    if kind == "weighted":
        ob = problem.objective
        scale = dict(ob.scale)
        terms = []
        for k, w in ob.weights:
            s = scale[k] / N_PER_UM if k == "stiffness" else scale[k]
            terms.append(("k_total" if k == "stiffness" else "f1", w / s))
        return ObjectiveSpec(tuple(terms), "weighted objective " + ob.label, "-")
    raise ValueError(f"no scalar objective for '{kind}'")


def respond(p, x, mounting, preload) -> dict:
    """:func:`axisopt.model.axis_response` on numpy, without the outputs no limit or objective uses
    (axial-torsional frequency, damping ratio)."""
    with np.errstate(divide="ignore"):
        return model.axis_response(p, x, mounting, preload, extras=False)


def _arrays(df, cols):
    return {c: df[c].to_numpy(dtype=float) for c in cols}


@dataclass
class Space:
    """Filtered part tables of a problem, as numpy arrays, with per-nut preload ranges."""

    problem: Problem
    mountings: tuple
    screws: object  # DataFrame aligned with nuts (one screw row per nut)
    nuts: object
    bearings: object
    guides: object
    preload_lo: np.ndarray  # (N,) effective preload range
    preload_hi: np.ndarray
    fits: np.ndarray  # (N, B) bearing fits the screw
    s_arr: dict = field(repr=False, default_factory=dict)
    n_arr: dict = field(repr=False, default_factory=dict)
    b_arr: dict = field(repr=False, default_factory=dict)
    g_arr: dict = field(repr=False, default_factory=dict)
    _cache: dict = field(repr=False, default_factory=dict)

    @property
    def shape(self) -> tuple:
        return (len(self.mountings), len(self.nuts), len(self.bearings), len(self.guides))

    @property
    def size(self) -> int:
        return int(np.prod(self.shape))

    def unravel(self, idx):
        return np.unravel_index(np.asarray(idx, dtype=np.int64), self.shape)

    def by_mounting(self, idx):
        """Split combination numbers by mounting: yields (mounting, sel, n, b, g, params, positions) with
        ``sel`` the rows of ``idx`` of that mounting and n, b, g their nut, bearing and guide numbers."""
        m_i, n_i, b_i, g_i = self.unravel(idx)
        for mi, mounting in enumerate(self.mountings):
            sel = np.nonzero(m_i == mi)[0]
            if len(sel) == 0:
                continue
            n, b, g = n_i[sel], b_i[sel], g_i[sel]
            yield mounting, sel, n, b, g, self.params_flat(mounting, n, b, g), self.positions(mounting)

    def positions(self, mounting: str) -> np.ndarray:
        key = ("x", mounting)
        if key not in self._cache:
            self._cache[key] = model.positions(self.problem.axis_for(mounting))
        return self._cache[key]

    def bound_positions(self, mounting: str) -> np.ndarray:
        """A few grid positions; the minimum over them bounds the minimum over the grid from above."""
        x = self.positions(mounting)
        n = len(x)
        idx = {0, n // 2, n - 1}
        if mounting == "fixed-fixed":
            idx.add(int(np.argmin(np.abs(x - 0.5 * self.problem.axis.span))))
        return x[sorted(idx)]

    # ------------------------------------------------------------------ parameter dicts
    def params_structured(self, mounting: str, nut_slice=slice(None), dtype=float) -> dict:
        key = ("ps", mounting, nut_slice.start, nut_slice.stop, np.dtype(dtype).name)
        if key not in self._cache:
            def sh(d, shape):
                return {k: (v.reshape(shape).astype(dtype) if v.dtype.kind == "f" else v.reshape(shape))
                        for k, v in d.items()}
            s = sh({k: v[nut_slice] for k, v in self.s_arr.items()}, (-1, 1, 1, 1))
            nt = sh({k: v[nut_slice] for k, v in self.n_arr.items()}, (-1, 1, 1, 1))
            b = sh(self.b_arr, (1, -1, 1, 1))
            g = sh(self.g_arr, (1, 1, -1, 1))
            if len(self._cache) > 64:
                self._cache.clear()
            ps = model.axis_params(self.problem.axis_for(mounting), s, nt, b, g)
            if np.dtype(dtype) != np.float64:
                ps = {k: (v.astype(dtype) if isinstance(v, np.ndarray) else v) for k, v in ps.items()}
            self._cache[key] = ps
        return self._cache[key]

    def params_flat(self, mounting: str, n, b, g) -> dict:
        def pick(d, i):
            return {k: v[i][:, None] for k, v in d.items()}
        return model.axis_params(self.problem.axis_for(mounting), pick(self.s_arr, n), pick(self.n_arr, n),
                                 pick(self.b_arr, b), pick(self.g_arr, g))

    def part_rows(self, n, b, g):
        return (self.screws.iloc[int(n)], self.nuts.iloc[int(n)], self.bearings.iloc[int(b)],
                self.guides.iloc[int(g)])


def build_space(problem: Problem) -> Space:
    cat = problem.catalog
    r = problem.restrictions
    nuts, bearings, guides = cat.nuts, cat.bearings, cat.guides
    screws = cat.screws
    if r.vendors is not None:
        screws = screws[screws["vendor"].isin(r.vendors)]
        nuts = nuts[nuts["vendor"].isin(r.vendors)]
        bearings = bearings[bearings["vendor"].isin(r.vendors)]
        guides = guides[guides["vendor"].isin(r.vendors)]
    # provenance: a slot the problem names parts for ('require') takes them whatever their status
    def by_status(df, slot):
        if r.required(slot):
            return df
        st = df["status"] if "status" in df.columns else pd.Series(USER_STATUS, index=df.index)
        return df[st.isin(tuple(r.status)).to_numpy()]

    screws, nuts = by_status(screws, "screw"), by_status(nuts, "nut")
    bearings, guides = by_status(bearings, "bearing"), by_status(guides, "guide")
    if r.nut_types is not None:
        nuts = nuts[nuts["type"].isin(r.nut_types)]
    if r.bearing_arrangements is not None:
        bearings = bearings[bearings["arrangement"].isin(r.bearing_arrangements)]
    if r.bearing_preload is not None:
        bearings = bearings[bearings["preload_class"].isin(r.bearing_preload)]
    if r.guide_types is not None:
        guides = guides[guides["type"].isin(r.guide_types)]
    if r.guide_preload is not None:
        guides = guides[guides["preload_level"].isin(r.guide_preload) | guides["preload_class"].isin(r.guide_preload)]
    for slot, df_name in (("screw", "screws"), ("nut", "nuts"), ("bearing", "bearings"), ("guide", "guides")):
        req, exc = r.required(slot), r.excluded(slot)
        df = {"screws": screws, "nuts": nuts, "bearings": bearings, "guides": guides}[df_name]
        if req:
            df = df[df.index.isin(req)]
        if exc:
            df = df[~df.index.isin(exc)]
        if df_name == "screws":
            screws = df
        elif df_name == "nuts":
            nuts = df
        elif df_name == "bearings":
            bearings = df
        else:
            guides = df
    nuts = nuts[nuts["screw_id"].isin(screws.index)]
    # the problem's preload bounds are for preloaded nuts; a single nut keeps its catalog range
    single = (nuts["type"] == "single").to_numpy()
    lo = np.where(single, nuts["preload_min"].to_numpy(float),
                  np.maximum(nuts["preload_min"].to_numpy(float), problem.preload_min))
    hi = np.where(single, nuts["preload_max"].to_numpy(float),
                  np.minimum(nuts["preload_max"].to_numpy(float), problem.preload_max))
    keep = lo <= hi
    nuts, lo, hi = nuts[keep], lo[keep], hi[keep]
    screws_al = cat.screws.loc[nuts["screw_id"].to_numpy()]
    # the bearing journal rule is the model's margin_bearing_fit check; no extra pairing rule here
    fits = np.ones((len(nuts), len(bearings)), dtype=bool)
    sp = Space(problem=problem, mountings=tuple(problem.mountings), screws=screws_al, nuts=nuts,
               bearings=bearings, guides=guides, preload_lo=lo, preload_hi=hi, fits=fits)
    sp.s_arr = _arrays(screws_al, _SCREW_COLS)
    sp.n_arr = _arrays(nuts, _NUT_COLS)
    sp.n_arr["type"] = nuts["type"].to_numpy(dtype=object).astype(str)
    sp.b_arr = _arrays(bearings, _BEARING_COLS)
    sp.g_arr = _arrays(guides, _GUIDE_COLS)
    sp.g_arr["type"] = guides["type"].to_numpy(dtype=object).astype(str)
    return sp


# --------------------------------------------------------------------------- exact 1-D solve
@dataclass
class Exact:
    """Exact per-combination optimum of the continuous problem (vectorized over K combinations)."""

    idx: np.ndarray
    feasible: np.ndarray
    preload: np.ndarray
    objective: np.ndarray  # display units, -inf where infeasible
    cost: np.ndarray
    total_mass: np.ndarray
    moving_mass: np.ndarray
    min_stiffness: np.ndarray = None  # [N/um] at the chosen preload
    min_frequency: np.ndarray = None  # [Hz]

    def __post_init__(self):
        if self.min_stiffness is None:
            self.min_stiffness = np.full(len(self.idx), np.nan)
        if self.min_frequency is None:
            self.min_frequency = np.full(len(self.idx), np.nan)


def _vec(v, K):
    """A scalar, (K,) or (K, 1) array as a fresh (K,) array."""
    a = np.asarray(v, dtype=float)
    return np.full(K, a.item()) if a.size == 1 else a.reshape(K).copy()


def _ok_all(cons, out, K):
    ok = np.ones(K, dtype=bool)
    for c in cons:
        ok &= _vec(c.ok(c.value(out)), K).astype(bool)
    return ok


def exact_solve(space: Space, idx, constraints, objective: ObjectiveSpec, *, need=("k_total", "f1")) -> Exact:
    """Best preload (upper end of the feasible preload interval) and the exact objective on the full
    position grid for the combinations ``idx`` (any mix of mountings), vectorized per mounting.

    Assumes the preload structure in the module docstring: bisection finds the largest preload meeting
    the upper-type constraints (drag, life); the lower-type ones (lift-off, minimum stiffness or
    frequency) are then checked there.
    """
    idx = np.asarray(idx, dtype=np.int64)
    K = len(idx)
    res = Exact(idx, np.zeros(K, bool), np.full(K, np.nan), np.full(K, -np.inf), np.zeros(K), np.zeros(K),
                np.zeros(K))
    if K == 0:
        return res
    up = [c for c in constraints if c.direction != 0 and c.upper_type]
    low = [c for c in constraints if c.direction != 0 and c.lower_type]
    indep = [c for c in constraints if c.direction == 0]
    for mounting, sel, n, b, _g, p, x in space.by_mounting(idx):
        k = len(sel)
        x1 = x[-1:]
        lo = space.preload_lo[n][:, None]
        hi = space.preload_hi[n][:, None]
        out_lo = respond(p, x1, mounting, lo)
        ok = _ok_all(indep, out_lo, k) & space.fits[n, b]
        ok_up_lo = _ok_all([c for c in up if not c.profile], out_lo, k)
        out_hi = respond(p, x1, mounting, hi)
        ok_up_hi = _ok_all([c for c in up if not c.profile], out_hi, k)
        a = lo[:, 0].copy()  # feasible end
        bb = hi[:, 0].copy()  # infeasible end (unless ok_up_hi)
        need_bis = ok & ok_up_lo & ~ok_up_hi
        if need_bis.any():
            j = np.nonzero(need_bis)[0]
            pj = {kk: (v[j] if np.ndim(v) and np.shape(v)[0] == k else v) for kk, v in p.items()}
            aa, bj = a[j], bb[j]
            upc = [c for c in up if not c.profile]
            for _ in range(BISECTION_STEPS):
                mid = 0.5 * (aa + bj)
                o = respond(pj, x1, mounting, mid[:, None])
                good = _ok_all(upc, o, len(j))
                aa = np.where(good, mid, aa)
                bj = np.where(good, bj, mid)
            a[j] = aa
        pstar = np.where(ok_up_hi, hi[:, 0], a)
        ok &= ok_up_lo
        out = respond(p, x, mounting, pstar[:, None])
        ok &= _ok_all(low, out, k)
        ok &= _ok_all([c for c in up if c.profile], out, k)
        J = np.broadcast_to(objective.value(out), (k,))
        res.feasible[sel] = ok
        res.preload[sel] = pstar
        res.objective[sel] = np.where(ok, J, -np.inf)
        res.cost[sel] = _vec(out["cost"], k)
        res.total_mass[sel] = _vec(out["total_mass"], k)
        res.moving_mass[sel] = _vec(out["moving_mass"], k)
        res.min_stiffness[sel] = _vec(np.min(out["k_total"], axis=-1), k) / N_PER_UM
        res.min_frequency[sel] = _vec(np.min(out["f1"], axis=-1), k)
    return res


def rank_order(objective, cost, mass, idx, top: int) -> np.ndarray:
    """Positions of the ``top`` best entries: highest objective; values within TIE_RTOL count as equal
    and go to the lower cost, then the lower total mass, then the lower combination number."""
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
