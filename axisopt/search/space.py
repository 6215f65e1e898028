"""The discrete search space of a problem and vectorized evaluation of the axis model over it.

A combination is (mounting, nut, bearing arrangement, guide, drive); the nut fixes the screw and a drive
is a (motor, coupling) pair.  The drive shares the last part axis with the guide: its index is
``g * D + d`` over G guides and D drives, so combinations are numbered ``((m * N + n) * B + b) * (G D) + g D + d``
and every layout below holds with "guide" read as "guide and drive".  Without drive search D = 1 (the
axis's motor inertia and coupling values, drive checks off).

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
from dataclasses import dataclass, field, replace

import numpy as np

from .. import model
from ..catalog import COLUMNS, USER_STATUS
from ..errors import InputError
from ..model.limits import CHECK_RECORDS, CONVEX, LIMITS
from ..model.params import GUIDE_RATING_DISTANCE, columns_read
from ..parttable import PartTable
from ..physics import nut as pnut
from ..problem import Problem
from ..units import N_PER_UM

GOLDEN_STEPS = 60  # golden-section steps for the most favourable preload of a convex limit
PROFILE = ("k_total", "f1", "k_tool", "kv")
STIFFNESS_OUTPUTS = ("k_total", "k_tool")  # shown and scaled in N/um
TIE_RTOL = 1e-7  # objective values this close count as equal; ties go to lower cost, then mass
BISECTION_STEPS = 52
SEARCH_POINTS = 64  # k-ary threshold search (default method): most preloads tried per round in one evaluation
SEARCH_ROWS = 4096  # ... as long as the combinations times the points stay about this many rows per evaluation


def search_points(k: int) -> int:
    """Preloads per round of :func:`kary_threshold` for ``k`` combinations: many while a model evaluation
    costs mostly its fixed Python overhead (few combinations), 2 (bisection) once the rows cost more."""
    return int(max(2, min(SEARCH_POINTS, 2 ** round(math.log2(SEARCH_ROWS / max(k, 1) + 1)))))

_SCREW_COLS, _NUT_COLS, _BEARING_COLS, _GUIDE_COLS, _MOTOR_COLS, _COUPLING_COLS = (
    columns_read(t) for t in ("screws", "nuts", "bearings", "guides", "motors", "couplings"))


# The guide values that favour every mechanical limit and the objective (the optimistic guide of the block
# bounds): the table carries the blocks, so less block mass, rail mass, friction, price and preload, and more
# rigidity, damping and load rating never make a design worse.  The drive's limits (motor torques, where
# less friction can raise a deceleration torque) are not bounded this way (DRIVE_KEYS: checked per pair).
GUIDE_BEST = {"normal_rigidity": np.nanmax, "tangential_rigidity": np.nanmax, "friction_force": np.nanmin,
              "friction_coefficient": np.nanmin, "friction_viscous": np.nanmin, "damping": np.nanmax,
              "block_mass": np.nanmin,
              "rail_mass_per_length": np.nanmin, "block_price": np.nanmin, "rail_price_per_length": np.nanmin,
              "dynamic_load_rating": np.nanmax, "preload": np.nanmin,
              # carriage (issue 25): a higher static or moment rating never loads a block more
              "static_load_rating": np.nanmax, "moment_roll": np.nanmax, "moment_pitch": np.nanmax,
              "moment_yaw": np.nanmax,
              # the longest rating basis, an empty cell read as the model reads it (model.params)
              "rating_distance": lambda v: np.max(np.nan_to_num(v, nan=GUIDE_RATING_DISTANCE))}


@dataclass(frozen=True)
class Constraint:
    """``value(out) sense limit``; ``direction`` is how the value moves with the nut preload."""

    name: str  # limit key or 'margin_<check>'
    key: str  # model output
    sense: str  # '<=' or '>='
    limit: float  # SI
    direction: int  # 0 independent of preload, +1 nondecreasing, -1 nonincreasing, CONVEX (met on an interval)
    label: str
    unit: str
    factor: float  # SI per display unit

    @property
    def profile(self) -> bool:
        return self.key in PROFILE

    @property
    def convex(self) -> bool:
        """Satisfied on an interval of preloads (motor torque margins, ``>=``)."""
        return self.direction == CONVEX

    @property
    def upper_type(self) -> bool:
        """Satisfied for preloads below a threshold (drag, life)."""
        if self.convex:
            return False
        return (self.sense == "<=" and self.direction > 0) or (self.sense == ">=" and self.direction < 0)

    @property
    def lower_type(self) -> bool:
        """Satisfied for preloads above a threshold (lift-off, minimum stiffness/frequency)."""
        if self.convex:
            return False
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


SCREEN_CHUNK = 4_000_000  # combinations per structured screening block (memory)


def _shaped(d, shape, dtype) -> dict:
    """Each column of ``d`` reshaped to ``shape`` (broadcast layout); float columns cast to ``dtype``."""
    return {k: (v.reshape(shape).astype(dtype) if v.dtype.kind == "f" else v.reshape(shape)) for k, v in d.items()}


def _as_dtype(ps: dict, dtype) -> dict:
    """A parameter dict with its arrays cast to ``dtype`` (float32 screening)."""
    if np.dtype(dtype) == np.float64:
        return ps
    dt = np.dtype(dtype).type
    return {k: (v.astype(dtype) if isinstance(v, np.ndarray) else dt(v) if isinstance(v, float) else v)
            for k, v in ps.items()}


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


# Checks the search's preload range holds by construction (build_space), at a margin up to 1: not constraints.
RANGE_CHECKS = frozenset({"nut_preload"})


def build_constraints(problem: Problem) -> tuple[Constraint, ...]:
    out = []
    for key, value in problem.limits:
        lim = LIMITS[key]
        out.append(Constraint(key, lim.output, lim.sense, value, lim.preload, key.replace("_", " "), lim.unit,
                              lim.factor))
    for check, m in problem.margins:
        if check in RANGE_CHECKS and m <= 1.0:
            continue  # the search's preload range holds it (build_space)
        if m > 0:
            k = f"margin_{check}"
            out.append(Constraint(k, k, ">=", m, CHECK_RECORDS[check].preload, model.CHECK_LABELS[check], "", 1.0))
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
            total = total + w * (v / N_PER_UM if key in STIFFNESS_OUTPUTS else v)
        return total


def objective_spec(kind: str, problem: Problem | None = None) -> ObjectiveSpec:
    if kind == "stiffness":
        return ObjectiveSpec((("k_total", 1.0),), "minimum axial stiffness", "N/um")
    if kind == "frequency":
        return ObjectiveSpec((("f1", 1.0),), "minimum first natural frequency", "Hz")
    if kind == "tool_stiffness":
        return ObjectiveSpec((("k_tool", 1.0),), "minimum stiffness at the tool", "N/um")
    if kind == "kv":
        return ObjectiveSpec((("kv", 1.0),), "minimum achievable position-loop gain Kv", "1/s")
    if kind == "weighted":
        ob = problem.objective
        scale = dict(ob.scale)
        terms = []
        for k, w in ob.weights:
            s = scale[k] / N_PER_UM if k == "stiffness" else scale[k]
            terms.append(("k_total" if k == "stiffness" else "f1", w / s))
        return ObjectiveSpec(tuple(terms), "weighted objective " + ob.label, "-")
    raise ValueError(f"no scalar objective for '{kind}'")


def respond(p, x, mounting, preload, drive_block: bool = True, chain: bool = True) -> dict:
    """:func:`axisopt.model.axis_response` on numpy, without the outputs no limit or objective uses
    (axial-torsional frequency, damping ratio); ``drive_block`` and ``chain`` as there."""
    with np.errstate(divide="ignore"):
        return model.axis_response(p, x, mounting, preload, extras=False, drive_block=drive_block, chain=chain)


# Outputs the motor and coupling change (all others are the same for every drive of a mechanical combination).
DRIVE_KEYS = frozenset({"cost", "inertia_ratio", "regen_power"} | {f"margin_{c}" for c in model.DRIVE_CHECKS})
# Outputs the coupling's torsional stiffness changes (it is in series in the stiffness chain); the motor's
# inertia enters only the axial-torsional modes, which no limit or objective reads.
COUPLING_KEYS = frozenset({"k_coupling", "k_total", "f_axial", "f1", "k_tool", "kv"})


def respond_drive(p, preload) -> dict:
    """:func:`axisopt.model.drive_response` on numpy: the motor-torque limits without the stiffness chain."""
    with np.errstate(divide="ignore"):
        return model.drive_response(p, preload)


# text columns the model reads through a rule (a bearing set's arrangement: its rows per load direction)
_TEXT_COLUMNS = frozenset(c.name for cols in COLUMNS.values() for c in cols if c.kind == "str")


def _arrays(t, cols):
    return {c: (np.asarray(t[c]).astype(str) if c in _TEXT_COLUMNS else t.number(c)) for c in cols}


@dataclass
class Space:
    """Filtered part tables of a problem, as numpy arrays, with per-nut preload ranges."""

    problem: Problem
    mountings: tuple
    screws: object  # PartTable aligned with nuts (one screw row per nut)
    nuts: object
    bearings: object
    guides: object
    preload_lo: np.ndarray  # (N,) effective preload range
    preload_hi: np.ndarray
    fits: np.ndarray  # (N, B) bearing fits the screw
    s_arr: dict = field(repr=False, default_factory=dict)
    n_arr: dict = field(repr=False, default_factory=dict)
    b_arr: dict = field(repr=False, default_factory=dict)
    g_arr: dict = field(repr=False, default_factory=dict)  # guide columns, each guide repeated D times
    motors: object = None  # PartTable of the searched motors (None: no drive search)
    couplings: object = None
    drives: tuple = ((None, None),)  # (motor position, coupling position) pairs; None: axis values
    m_arr: dict | None = field(repr=False, default=None)  # motor columns over the G*D axis
    c_arr: dict | None = field(repr=False, default=None)
    # (motor, coupling) pairs never formed: a coupling another beats on every count, or one that cannot carry
    # the motor's peak torque (a limit of the pair alone)
    pairs_left_out: int = 0
    _cache: dict = field(repr=False, default_factory=dict)

    @property
    def n_drives(self) -> int:
        return len(self.drives)

    @property
    def pruned_by_dominance(self) -> int:
        """Combinations left out before the search by :attr:`pairs_left_out` (not in :attr:`size`)."""
        return int(self.size // self.n_drives * self.pairs_left_out)

    @property
    def shape(self) -> tuple:
        return (len(self.mountings), len(self.nuts), len(self.bearings), len(self.guides) * self.n_drives)

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
    def coupling_stiffnesses(self) -> np.ndarray:
        """The distinct torsional stiffnesses [N m/rad] of the searched drive pairs (the axis value for a
        pair without a coupling), ascending."""
        if self.c_arr is None:
            return np.array([float(self.problem.axis.coupling_stiffness)])
        return np.unique(self.c_arr["torsional_stiffness"])

    def params_structured(self, mounting: str, nut_slice=slice(None), dtype=float, mechanics: bool = False,
                          coupling_stiffness: float | None = None, bearings=None) -> dict:
        """Parameters broadcast over (nuts, bearings, guide-and-drive, positions); with ``bearings`` (bearing
        numbers aligned with the nut numbers ``nut_slice``) over ((nut, bearing) pairs, 1, guide-and-drive,
        positions) instead.  ``mechanics``: over the
        guides alone, without the drive, for the outputs the drive does not change (every output but
        :data:`DRIVE_KEYS` and :data:`COUPLING_KEYS`).  The axis values stand in for motor and coupling,
        except the coupling's torsional stiffness, which is in the stiffness chain: ``coupling_stiffness``,
        by default the stiffest searched coupling, so that the stiffness and frequency are upper bounds
        over every drive pair (the screening relaxes their limits with them; exact solves use the pair)."""
        if mechanics and self.m_arr is not None and coupling_stiffness is None:
            coupling_stiffness = float(self.coupling_stiffnesses()[-1])
        nkey = (nut_slice.start, nut_slice.stop) if isinstance(nut_slice, slice) else \
            np.asarray(nut_slice, dtype=np.int64).tobytes()
        key = ("ps", mounting, nkey, np.dtype(dtype).name, mechanics, coupling_stiffness)
        if bearings is None and key in self._cache:
            return self._cache[key]
        s, nt, b = self._nut_bearing_arrays(nut_slice, dtype, bearings)
        D = self.n_drives if mechanics else 1
        g = _shaped({k: v[::D] for k, v in self.g_arr.items()}, (1, 1, -1, 1), dtype)
        mo = None if self.m_arr is None or mechanics else _shaped(self.m_arr, (1, 1, -1, 1), dtype)
        cp = None if self.c_arr is None or mechanics else _shaped(self.c_arr, (1, 1, -1, 1), dtype)
        ps = model.axis_params(self.problem.axis_for(mounting), s, nt, b, g, mo, cp)
        if mechanics and coupling_stiffness is not None:
            ps["coupling_stiffness"] = coupling_stiffness
        ps = _as_dtype(ps, dtype)
        if bearings is None:  # pair layouts are built once each (the explanation's scored blocks): not kept
            if len(self._cache) > 64:
                self._cache.clear()
            self._cache[key] = ps
        return ps

    def params_optimistic_guide(self, mounting: str, nut_sel, guide_type: str, dtype=float) -> dict:
        """Parameters over (nuts ``nut_sel``, bearings, one guide, positions) where the one guide takes, column
        by column, the most favourable value of the searched guides of ``guide_type`` (:data:`GUIDE_BEST`).
        No mechanical limit and no objective value of any (nut, bearing, guide) combination is better than
        with this guide, so the (nut, bearing) results bound every guide (and every drive: the axis values
        stand in for motor and coupling, with the stiffest searched coupling in the stiffness chain)."""
        D = self.n_drives
        sel = self.g_arr["type"][::D] == guide_type
        s, nt, b = self._nut_bearing_arrays(nut_sel, dtype)
        g = {k: np.array([GUIDE_BEST[k](v[::D][sel])]) for k, v in self.g_arr.items() if k in GUIDE_BEST}
        g["type"] = np.array([guide_type])
        g = _shaped(g, (1, 1, 1, 1), dtype)
        ps = model.axis_params(self.problem.axis_for(mounting), s, nt, b, g, None, None)
        if self.m_arr is not None:
            ps["coupling_stiffness"] = float(self.coupling_stiffnesses()[-1])
            # the cheapest searched (motor, coupling) pair: the cost is a lower bound over every drive
            price = np.nan_to_num(self.m_arr["price"][:D])
            if self.c_arr is not None:
                price = price + np.nan_to_num(self.c_arr["price"][:D])
            ps["motor_price"], ps["coupling_price"] = float(price.min()), 0.0
        return _as_dtype(ps, dtype)

    def params_drive_pairs(self, mounting: str, nut_sel) -> dict:
        """Parameters over (nuts ``nut_sel``, bearings, drive pairs, 1) with the first guide's columns: for the
        drive block (:func:`axisopt.model.drive.drive`), which takes the guide only through the moving mass
        and the drag torque passed to it (the explanation's interval bounds over the guides)."""
        D = self.n_drives
        s, nt, b = self._nut_bearing_arrays(nut_sel, float)
        g = _shaped({k: v[:1] for k, v in self.g_arr.items()}, (1, 1, 1, 1), float)
        mo = None if self.m_arr is None else _shaped({k: v[:D] for k, v in self.m_arr.items()}, (1, 1, -1, 1), float)
        cp = None if self.c_arr is None else _shaped({k: v[:D] for k, v in self.c_arr.items()}, (1, 1, -1, 1),
                                                     float)
        return model.axis_params(self.problem.axis_for(mounting), s, nt, b, g, mo, cp)

    def _nut_bearing_arrays(self, nut_sel, dtype, bearings=None) -> tuple:
        """Screw and nut columns of the nuts ``nut_sel`` on the first axis, every bearing on the second (or,
        with ``bearings`` aligned with the nuts, those bearings on the first axis too)."""
        s = _shaped({k: v[nut_sel] for k, v in self.s_arr.items()}, (-1, 1, 1, 1), dtype)
        nt = _shaped({k: v[nut_sel] for k, v in self.n_arr.items()}, (-1, 1, 1, 1), dtype)
        if bearings is not None:
            return s, nt, _shaped({k: v[bearings] for k, v in self.b_arr.items()}, (-1, 1, 1, 1), dtype)
        return s, nt, _shaped(self.b_arr, (1, -1, 1, 1), dtype)

    def nuts_per_screen(self) -> int:
        """Nuts per structured screening block: each covers every bearing and (mechanical) guide."""
        _, _, B, G = self.shape
        Gm = G // (self.n_drives if self.m_arr is not None else 1)
        return max(1, SCREEN_CHUNK // max(B * Gm, 1))

    def params_flat(self, mounting: str, n, b, g) -> dict:
        def pick(d, i):
            return {k: v[i][:, None] for k, v in d.items()}
        return model.axis_params(self.problem.axis_for(mounting), pick(self.s_arr, n), pick(self.n_arr, n),
                                 pick(self.b_arr, b), pick(self.g_arr, g),
                                 None if self.m_arr is None else pick(self.m_arr, g),
                                 None if self.c_arr is None else pick(self.c_arr, g))

    def params_drives(self, mounting: str, n, b, g, dtype=float) -> dict:
        """Parameters over (K mechanical combinations, D drive pairs, 1 position): screw, nut, bearing and guide
        columns of the combinations (nut ``n``, bearing ``b``, mechanical guide ``g``) shaped (K, 1, 1), the
        searched (motor, coupling) pairs (1, D, 1); element (k, d) is guide-and-drive ``g[k] * D + d``."""
        D = self.n_drives

        def pick(d, i):
            return {k: v[i][:, None, None] for k, v in d.items()}

        def pairs(d):
            return None if d is None else {k: v[:D][None, :, None] for k, v in d.items()}

        ps = model.axis_params(self.problem.axis_for(mounting), pick(self.s_arr, n), pick(self.n_arr, n),
                               pick(self.b_arr, b), pick(self.g_arr, np.asarray(g) * D), pairs(self.m_arr),
                               pairs(self.c_arr))
        return _as_dtype(ps, dtype)

    def part_rows(self, n, b, g):
        """(screw, nut, bearing, guide, motor, coupling) rows of part-axis numbers; ``g`` is the guide-and-
        drive index (motor and coupling None where the axis values stand in)."""
        gi, di = divmod(int(g), self.n_drives)
        mi, ci = self.drives[di]
        return (self.screws.row(n), self.nuts.row(n), self.bearings.row(b), self.guides.row(gi),
                None if mi is None else self.motors.row(mi), None if ci is None else self.couplings.row(ci))


def vendor_filled(t: PartTable, table: str) -> PartTable:
    """The rows of a part table with a vendor value in every column the model would otherwise estimate
    (``catalog.COLUMNS``: an optional column with an ``estimate``)."""
    from ..catalog import COLUMNS

    keep = np.ones(len(t), dtype=bool)
    for c in COLUMNS[table]:
        if c.estimate and c.name in t:
            keep &= np.isfinite(t.number(c.name))
    return t.take(keep)


# Spaces built in this process, by what they are made of (the catalog object and the problem's choices that
# filter it): a study's cases share the catalog and most of their restrictions, and filtering the part tables
# is a few ms a case.  Each problem gets its own Space (its axis, its parameter cache) on the shared,
# read-only part tables and arrays.
_SPACES: dict = {}
SPACES_KEPT = 4


def build_space(problem: Problem) -> Space:
    """The filtered part tables of ``problem`` as a :class:`Space` (reused from an earlier problem on the same
    catalog object with the same restrictions, preload range, reduction ratio and coupling margin)."""
    key = (id(problem.catalog), problem.restrictions, tuple(problem.mountings), problem.preload_min,
           problem.preload_max, float(problem.axis.reduction_ratio),
           float(problem.margin_map.get("coupling_torque", 1.0)))
    hit = _SPACES.get(key)
    if hit is None or hit[0] is not problem.catalog:
        sp = _build_space(problem)
        if len(_SPACES) >= SPACES_KEPT:
            _SPACES.pop(next(iter(_SPACES)))
        _SPACES[key] = hit = (problem.catalog, sp)
    return replace(hit[1], problem=problem, _cache={})


def _build_space(problem: Problem) -> Space:
    cat = problem.catalog
    r = problem.restrictions
    nuts, bearings, guides = cat.rows("nuts"), cat.rows("bearings"), cat.rows("guides")
    screws = cat.rows("screws")
    if r.vendors is not None:
        screws = screws.take(screws.isin("vendor", r.vendors))
        nuts = nuts.take(nuts.isin("vendor", r.vendors))
        bearings = bearings.take(bearings.isin("vendor", r.vendors))
        guides = guides.take(guides.isin("vendor", r.vendors))
    # provenance: a slot the problem names parts for ('require') takes them whatever their status
    def by_status(t, slot):
        if r.required(slot):
            return t
        if "status" not in t:
            return t if USER_STATUS in r.status else t.take(np.zeros(len(t), dtype=bool))
        return t.take(t.isin("status", tuple(r.status)))

    screws, nuts = by_status(screws, "screw"), by_status(nuts, "nut")
    bearings, guides = by_status(bearings, "bearing"), by_status(guides, "guide")
    if r.estimated == "exclude":  # vendor values only: no row with an empty cell the model would estimate
        screws, nuts = vendor_filled(screws, "screws"), vendor_filled(nuts, "nuts")
        bearings, guides = vendor_filled(bearings, "bearings"), vendor_filled(guides, "guides")
    if r.nut_types is not None:
        nuts = nuts.take(nuts.isin("type", r.nut_types))
    if r.bearing_arrangements is not None:
        bearings = bearings.take(bearings.isin("arrangement", r.bearing_arrangements))
    if r.bearing_preload is not None:
        bearings = bearings.take(bearings.isin("preload_class", r.bearing_preload))
    if r.guide_types is not None:
        guides = guides.take(guides.isin("type", r.guide_types))
    if r.guide_preload is not None:
        guides = guides.take(guides.isin("preload_level", r.guide_preload)
                             | guides.isin("preload_class", r.guide_preload))
    screws, nuts = _filtered(screws, r, "screw"), _filtered(nuts, r, "nut")
    bearings, guides = _filtered(bearings, r, "bearing"), _filtered(guides, r, "guide")
    nuts = nuts.take(nuts.isin("screw_id", set(screws.ids)))
    # the problem's preload bounds are for preloaded nuts; a single nut keeps its catalog range
    single = nuts["type"] == "single"
    lo = np.where(single, nuts.number("preload_min"), np.maximum(nuts.number("preload_min"), problem.preload_min))
    hi = np.where(single, nuts.number("preload_max"), np.minimum(nuts.number("preload_max"), problem.preload_max))
    # the vendors' preload ceiling (check nut_preload: 10 % Ca) bounds the range of a preloaded nut, as the
    # vendors' own preload ranges do: the search never goes above it, so it needs no constraint of its own
    hi = np.where(single, hi, np.minimum(hi, pnut.preload_ceiling(nuts.number("dynamic_load_rating"))))
    keep = lo <= hi
    nuts, lo, hi = nuts.take(keep), lo[keep], hi[keep]
    # an empty part slot leaves no combination at all: a one-line error naming it (not an "infeasible"
    # result whose explanation has nothing to score)
    for t, what, filters in ((nuts, "screw and nut", "vendors, nut_types, status, require/exclude; "
                               "continuous.nut_preload and the 10 % Ca preload ceiling for preloaded nuts"),
                              (bearings, "support bearing", "vendors, bearing_arrangements, bearing_preload, "
                               "status, require/exclude"),
                              (guides, "linear guide", "vendors, guide_types, guide_preload, status, "
                               "require/exclude")):
        if len(t) == 0:
            raise InputError(f"the search has nothing to choose from: no {what} is left after the filters "
                             f"(catalog: {filters})", source=problem.source)
    screws_al = cat.rows("screws").by_id(list(nuts["screw_id"]))
    # the bearing journal rule is the model's margin_bearing_fit check; no extra pairing rule here
    fits = np.ones((len(nuts), len(bearings)), dtype=bool)
    sp = Space(problem=problem, mountings=tuple(problem.mountings), screws=screws_al, nuts=nuts,
               bearings=bearings, guides=guides, preload_lo=lo, preload_hi=hi, fits=fits)
    sp.s_arr = _arrays(screws_al, _SCREW_COLS)
    sp.n_arr = _arrays(nuts, _NUT_COLS)
    sp.n_arr["type"] = nuts["type"].astype(str)
    sp.b_arr = _arrays(bearings, _BEARING_COLS)
    sp.g_arr = _arrays(guides, _GUIDE_COLS)
    sp.g_arr["type"] = guides["type"].astype(str)
    _add_drives(sp, problem)
    return sp


def _filtered(t, r, slot, series=None, vendors=None):
    """Rows of a part table the problem allows in ``slot``: vendor and series filters, require, exclude."""
    if vendors is not None:
        t = t.take(t.isin("vendor", vendors))
    if series is not None:
        t = t.take(t.isin("series", series))
    req, exc = r.required(slot), r.excluded(slot)
    if req:
        t = t.take(t.isin("id", req))
    if exc:
        t = t.take(~t.isin("id", exc))
    return t


def coupling_dominated(cp) -> np.ndarray:
    """Couplings another coupling beats on every count the model uses: at least its rated torque,
    torsional stiffness and maximum speed, at most its inertia and price, and better on one of them
    (mass and bore do not enter the model; a dominated coupling can never be the better choice)."""
    a = {c: np.asarray(cp[c], dtype=float)
         for c in ("rated_torque", "torsional_stiffness", "max_speed", "inertia", "price")}
    ge = ((a["rated_torque"][:, None] >= a["rated_torque"][None]) & (a["torsional_stiffness"][:, None]
          >= a["torsional_stiffness"][None]) & (a["max_speed"][:, None] >= a["max_speed"][None])
          & (a["inertia"][:, None] <= a["inertia"][None]) & (a["price"][:, None] <= a["price"][None]))
    gt = ((a["rated_torque"][:, None] > a["rated_torque"][None]) | (a["torsional_stiffness"][:, None]
          > a["torsional_stiffness"][None]) | (a["max_speed"][:, None] > a["max_speed"][None])
          | (a["inertia"][:, None] < a["inertia"][None]) | (a["price"][:, None] < a["price"][None]))
    return (ge & gt).any(axis=0)


def _add_drives(sp: Space, problem: Problem) -> None:
    """The (motor, coupling) pairs the search chooses from, spread over the guide axis."""
    r = problem.restrictions
    cat = problem.catalog
    if not r.drive or len(cat.rows("motors")) == 0:
        return
    motors = _filtered(cat.rows("motors"), r, "motor", r.motor_series, r.motor_vendors)
    if r.max_motor_flange is not None:  # a motor without a listed flange cannot be shown to fit
        motors = motors.take(motors.number("flange") <= r.max_motor_flange * (1 + 1e-9))
    if r.estimated == "exclude":
        motors = vendor_filled(motors, "motors")
    couplings = _filtered(cat.rows("couplings"), r, "coupling", r.coupling_series)
    n_couplings = len(couplings)
    if len(couplings) and not r.required("coupling"):
        couplings = couplings.take(~coupling_dominated(couplings))
    ratio = problem.axis.reduction_ratio
    need = problem.margin_map.get("coupling_torque", 1.0)
    pairs = []
    for mi in range(len(motors)):
        if len(couplings) == 0:
            pairs.append((mi, None))
            continue
        peak = float(motors.number("peak_torque")[mi]) * ratio
        # the coupling-torque check depends on the pair only: pairs that fail it are never formed
        ok = couplings.number("rated_torque") >= need * peak * (1.0 - 1e-12)
        pairs.extend((mi, int(ci)) for ci in np.nonzero(ok)[0])
    if not pairs:
        why = ("no motor is left after the motor filters" if len(motors) == 0 else
               "no coupling left after the filters carries the peak torque of any allowed motor")
        raise InputError(f"the drive search has nothing to choose from: {why} (catalog: motor_vendors, "
                         "motor_series, max_motor_flange, require/exclude)", source=problem.source)
    sp.motors, sp.couplings = motors, couplings
    sp.drives = tuple(pairs)
    sp.pairs_left_out = len(motors) * max(n_couplings, 1) - len(pairs)
    D = len(pairs)
    sp.g_arr = {k: np.repeat(v, D) for k, v in sp.g_arr.items()}
    G = len(sp.guides)
    mpos = np.array([m for m, _ in pairs], dtype=np.int64)
    sp.m_arr = {k: np.tile(motors.number(k)[mpos], G) for k in _MOTOR_COLS}
    if len(couplings):
        cpos = np.array([c for _, c in pairs], dtype=np.int64)
        sp.c_arr = {k: np.tile(couplings.number(k)[cpos], G) for k in _COUPLING_COLS}


def subset(p: dict, j, k: int) -> dict:
    """The parameters of rows ``j`` of a flat layout of ``k`` combinations (the duty cycle is shared)."""
    return {kk: (v[j] if kk != "duty" and np.ndim(v) and np.shape(v)[0] == k else v) for kk, v in p.items()}


def _interval_min_abs(t_lo, t_hi):
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
    ends = [(_interval_min_abs(a0, b0), _interval_min_abs(a1, b1))
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


def _golden_best(value, a, b, steps=GOLDEN_STEPS):
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


def convex_feasible_top(c: Constraint, p: dict, x1, mounting: str, lo, top):
    """For a convex (interval) limit: the largest preload in [lo, top] meeting it, per combination.
    Returns (exists, preload).  Met at ``top``: top.  Else met at ``lo``: threshold search from lo
    (:func:`kary_threshold`; the limit's interval contains lo and ends below top).  Else: its most favourable
    preload by golden section, then the threshold search from there."""
    K = len(lo)
    lo, top = np.asarray(lo, float), np.asarray(top, float)

    def value(pj, pre):
        return _vec(c.value(respond_drive(pj, pre[:, None])), len(pre))

    exists = c.ok(value(p, top)).astype(bool)
    pb = top.copy()
    j = np.nonzero(~exists)[0]
    if len(j):
        pj = subset(p, j, K)
        start = np.where(c.ok(value(pj, lo[j])), lo[j], np.nan)
        g = np.nonzero(np.isnan(start))[0]
        if len(g):
            pg = subset(pj, g, len(j))
            best = _golden_best(lambda pre: value(pg, pre), lo[j][g], top[j][g])
            start[g] = np.where(c.ok(value(pg, best)), best, np.nan)
        has = np.isfinite(start)
        h = np.nonzero(has)[0]
        if len(h):
            P = search_points(len(h))
            pr = repeat_rows(subset(pj, h, len(j)), len(h), P - 1)
            pb[j[h]] = kary_threshold(lambda pre: c.ok(value(pr, pre.reshape(-1))), start[h], top[j][h], P)
        exists[j] = has
    return exists, pb


def convex_interval(c: Constraint, p: dict, x1, mounting: str, lo, hi):
    """For a convex limit: (exists, low end, high end) of the preloads in [lo, hi] meeting it, found without
    assuming anything but convexity (golden section for a feasible point, then a bisection to each side)."""
    K = len(lo)
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)

    def value(pj, pre):
        return _vec(c.value(respond_drive(pj, pre[:, None])), len(pre))

    ok_lo, ok_hi = (c.ok(value(p, v)).astype(bool) for v in (lo, hi))
    start = np.where(ok_lo, lo, hi)
    exists = ok_lo | ok_hi
    g = np.nonzero(~exists)[0]  # met at neither end: look for the most favourable preload in between
    if len(g):
        pg = subset(p, g, K)
        best = _golden_best(lambda pre: value(pg, pre), lo[g], hi[g])
        exists[g] = c.ok(value(pg, best)).astype(bool)
        start[g] = best
    ends = []
    for edge, ok_edge in ((lo, ok_lo), (hi, ok_hi)):
        end = edge.copy()
        j = np.nonzero(exists & ~ok_edge)[0]  # the interval stops short of this edge: bisect for its end
        if len(j):
            pj = subset(p, j, K)
            a, z = start[j], edge[j]
            for _ in range(BISECTION_STEPS):
                mid = 0.5 * (a + z)
                good = c.ok(value(pj, mid)).astype(bool)
                a = np.where(good, mid, a)
                z = np.where(good, z, mid)
            end[j] = a
        ends.append(end)
    return exists, ends[0], ends[1]


def repeat_rows(p: dict, k: int, r: int) -> dict:
    """A flat layout of ``k`` combinations with every row repeated ``r`` times (row i*r + j is row i)."""
    return {kk: (np.repeat(v, r, axis=0) if kk != "duty" and np.ndim(v) and np.shape(v)[0] == k else v)
            for kk, v in p.items()}


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

    Assumes the preload structure in the module docstring: a threshold search (:func:`kary_threshold`: up to
    63 preloads per vectorized round for few combinations, bisection for many) finds the largest preload meeting
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
    cvx = [c for c in constraints if c.convex]
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
            P = search_points(len(j))
            pr = repeat_rows(subset(p, j, k), len(j), P - 1)
            upc = [c for c in up if not c.profile]

            def good(pre, pr=pr, upc=upc, x1=x1, mounting=mounting):
                return _ok_all(upc, respond(pr, x1, mounting, pre.reshape(-1, 1)), pre.size)

            a[j] = kary_threshold(good, a[j], bb[j], P)
        pstar = np.where(ok_up_hi, hi[:, 0], a)
        ok &= ok_up_lo
        for c in cvx:  # lower the preload into each motor-torque interval (drag and life stay met)
            j = np.nonzero(ok)[0]
            if len(j):
                ex, top = convex_feasible_top(c, subset(p, j, k), x1, mounting, lo[j, 0], pstar[j])
                ok[j] &= ex
                pstar[j] = np.where(ex, top, pstar[j])
        out = respond(p, x, mounting, pstar[:, None])
        ok &= _ok_all(cvx, out, k)
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
