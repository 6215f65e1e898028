"""The discrete search space of a problem: the filtered part tables as numpy arrays, the numbering
of the combinations and the parameter layouts the stages evaluate the axis model on.

A combination is (mounting, nut, bearing arrangement, guide, drive); the nut fixes the screw and a
drive is a (motor, coupling, reduction) triple (the reduction None: the axis's reduction values).
The drive shares the last part axis with the guide: its index is ``g * D + d`` over G guides and D
drives, so combinations are numbered ``((m * N + n) * B + b) * (G D) + g D + d`` and every layout
below holds with "guide" read as "guide and drive".  Without drive search D = 1 (the axis's motor
inertia and coupling values, drive checks off).  :mod:`.parts` builds a :class:`Space`.

Two evaluation layouts use the same :func:`axisopt.model.axis_response`:

* *structured* (screening): nut/screw parameters shaped ``(N, 1, 1, 1)``, bearings ``(1, B, 1, 1)``,
  guides ``(1, 1, G, 1)``, positions on the last axis and the preload on a leading axis.  numpy
  broadcasting then computes each quantity only over the parts it depends on (the stiffness chain
  never touches the guides, the cost is a sum of per-part terms, ...).
* *flat* (exact evaluation of selected combinations): every parameter shaped ``(K, 1)``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ... import model
from ...model.accuracy import BUDGET_OUTPUTS
from ...model.limits import margin_output
from ...model.outputs import COUPLING_OUTPUTS, DRIVE_OUTPUTS
from ...problem import Problem

SCREEN_CHUNK = 4_000_000  # combinations per structured screening block (memory)


def shaped(d, shape, dtype) -> dict:
    """Each column of ``d`` reshaped to ``shape`` (broadcast layout); float columns cast to
    ``dtype``."""
    return {
        k: (v.reshape(shape).astype(dtype) if v.dtype.kind == "f" else v.reshape(shape))
        for k, v in d.items()
    }


def as_dtype(ps: dict, dtype) -> dict:
    """A parameter dict with its arrays cast to ``dtype`` (float32 screening)."""
    if np.dtype(dtype) == np.float64:
        return ps
    dt = np.dtype(dtype).type
    return {
        k: (v.astype(dtype) if isinstance(v, np.ndarray) else dt(v) if isinstance(v, float) else v)
        for k, v in ps.items()
    }


def respond(p, x, mounting, preload, request: model.Request) -> dict:
    """:func:`axisopt.model.axis_response` on numpy for ``request`` (a stage's:
    :attr:`Space.request`, or that narrowed with :meth:`~axisopt.model.Request.but`), division by
    zero silent."""
    with np.errstate(divide="ignore"):
        return model.axis_response(p, x, mounting, preload, request)


def respond_chain(p, x, mounting, preload, coupling_stiffnesses=None):
    """:func:`axisopt.model.chain_response` on numpy: the outputs the coupling's stiffness changes
    (:data:`COUPLING_KEYS`) without the rest of the model (a list, one per value of
    ``coupling_stiffnesses``)."""
    with np.errstate(divide="ignore"):
        return model.chain_response(p, x, mounting, preload, coupling_stiffnesses)


# Outputs the motor, coupling and reduction change that the drive block computes without the
# stiffness chain (model.drive_response; all others are the same for every drive of a mechanical
# combination, or, like the positioning budget's lost motion, computed with the chain on the whole
# design), and the drive checks' margins: declared in model.outputs.
DRIVE_KEYS = frozenset(o for o in DRIVE_OUTPUTS if o not in model.CHAIN_OUTPUTS) | {
    margin_output(c) for c in model.DRIVE_CHECKS
}
# Drive outputs whose value with the mechanics layout (no motor, coupling or reduction; the bounds:
# the cheapest drive's price) is the most favourable over every drive: the mechanical stages test
# them too, the drive stage again per drive (the cost is never more than with the cheapest drive,
# the lost motion never less than the nut's)
MECHANICS_BOUNDED = frozenset({"cost", "backlash"})
# Outputs the coupling's torsional stiffness changes (it is in series in the stiffness chain;
# model.outputs), which the explanation evaluates once per coupling stiffness; the motor's inertia
# enters only the axial-torsional modes, which no limit or objective reads.  The positioning
# budget's elastic row and total also change with it: the explanation's mechanical stage evaluates
# them with the axis's coupling value, so its ranking of the closest designs is approximate there
# (their misses are then computed on the whole design, exact).
COUPLING_KEYS = COUPLING_OUTPUTS - frozenset(BUDGET_OUTPUTS)


def respond_drive(p, preload, regen: bool = True) -> dict:
    """:func:`axisopt.model.drive_response` on numpy: the motor-torque limits without the stiffness
    chain (``regen``: also the regenerated energy and power)."""
    with np.errstate(divide="ignore"):
        return model.drive_response(p, preload, model.SCREEN.but(regen=regen))


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
    # guide columns, each guide repeated D times
    g_arr: dict = field(repr=False, default_factory=dict)
    motors: object = None  # PartTable of the searched motors (None: no drive search)
    couplings: object = None
    reductions: object = None  # PartTable of the searched reductions (None: none searched)
    # (motor, coupling, reduction) positions; None: axis values (no reduction: the axis's reduction
    # values)
    drives: tuple = ((None, None, None),)
    m_arr: dict | None = field(repr=False, default=None)  # motor columns over the G*D axis
    c_arr: dict | None = field(repr=False, default=None)
    # reduction columns over G*D (NaN: no reduction)
    r_arr: dict | None = field(repr=False, default=None)
    # (motor, coupling) pairs never formed: a coupling another beats on every count, or one that
    # cannot carry the motor's peak torque (a limit of the pair alone)
    pairs_left_out: int = 0
    # reductions never formed because their backlash, at the table through the shortest lead,
    # exceeds the problem's max_backlash (an infeasible result says so: the limit, not the catalog,
    # left them out)
    reductions_by_backlash: int = 0
    # the least lost motion at the table [m] of those reductions (their backlash through the
    # shortest lead; inf: none left out)
    backlash_left_least: float = float("inf")
    # the numbering of the combinations (:mod:`.parts` sets them once the tables are final)
    n_drives: int = 1  # drive pairs D
    shape: tuple = ()  # (mountings, nuts, bearings, guides x drives)
    size: int = 0  # combinations
    pruned_by_dominance: int = 0  # combinations left out by pairs_left_out (not in size)
    # nuts per structured screening block: about SCREEN_CHUNK (nut, bearing, guide)s
    nuts_per_block: int = 1
    # the distinct torsional stiffnesses [N m/rad] of the searched drive pairs (the axis value for a
    # pair without a coupling), ascending, and the model position grid of each mounting [m] (of the
    # problem's axis)
    coupling_k: np.ndarray = field(repr=False, default=None)
    grid: dict = field(repr=False, default_factory=dict)
    # the lead accuracy grade of each nut row (screw x grade: parts.screw_grade_rows), or None:
    # every screw at the cheapest grade it is made in (no positioning limit, no
    # catalog.screw_grades)
    grades: np.ndarray | None = field(repr=False, default=None)
    # what the stages ask the model for (:func:`respond`): every output a limit or objective can
    # read, the positioning budget (model.accuracy) only if a limit reads it (its extra
    # stiffness-chain points cost the screening time; search.parts sets it)
    request: model.Request = model.SCREEN
    _cache: dict = field(repr=False, default_factory=dict)

    def unravel(self, idx):
        return np.unravel_index(np.asarray(idx, dtype=np.int64), self.shape)

    def by_mounting(self, idx):
        """Split combination numbers by mounting: yields (mounting, sel, n, b, g, params, positions)
        with ``sel`` the rows of ``idx`` of that mounting and n, b, g their nut, bearing and guide
        numbers."""
        m_i, n_i, b_i, g_i = self.unravel(idx)
        for mi, mounting in enumerate(self.mountings):
            sel = np.nonzero(m_i == mi)[0]
            if len(sel) == 0:
                continue
            n, b, g = n_i[sel], b_i[sel], g_i[sel]
            yield mounting, sel, n, b, g, self.params_flat(mounting, n, b, g), self.grid[mounting]

    def positions(self, mounting: str) -> np.ndarray:
        """The model position grid of ``mounting`` [m] (:attr:`grid`)."""
        return self.grid[mounting]

    # ------------------------------------------------------------------ parameter dicts
    def coupling_stiffnesses(self) -> np.ndarray:
        """The distinct torsional stiffnesses [N m/rad] of the searched drive pairs, ascending
        (:attr:`coupling_k`)."""
        return self.coupling_k

    def params_structured(
        self,
        mounting: str,
        nut_slice=slice(None),
        dtype=float,
        mechanics: bool = False,
        coupling_stiffness: float | None = None,
        bearings=None,
    ) -> dict:
        """Parameters broadcast over (nuts, bearings, guide-and-drive, positions); with ``bearings``
        (bearing numbers aligned with the nut numbers ``nut_slice``) over ((nut, bearing) pairs, 1,
        guide-and-drive, positions) instead.  ``mechanics``: over the guides alone, without the
        drive, for the outputs the drive does not change (every output but :data:`DRIVE_KEYS` and
        :data:`COUPLING_KEYS`).  The axis values stand in for motor and coupling, except the
        coupling's torsional stiffness, which is in the stiffness chain: ``coupling_stiffness``, by
        default the stiffest searched coupling, so that the stiffness and frequency are upper bounds
        over every drive pair (the screening relaxes their limits with them; exact solves use the
        pair)."""
        if mechanics and self.m_arr is not None and coupling_stiffness is None:
            coupling_stiffness = float(self.coupling_k[-1])
        nkey = (
            (nut_slice.start, nut_slice.stop)
            if isinstance(nut_slice, slice)
            else np.asarray(nut_slice, dtype=np.int64).tobytes()
        )
        key = ("ps", mounting, nkey, np.dtype(dtype).name, mechanics, coupling_stiffness)
        if bearings is None and key in self._cache:
            return self._cache[key]
        s, nt, b = self.nut_bearing_arrays(nut_slice, dtype, bearings)
        D = self.n_drives if mechanics else 1
        g = shaped({k: v[::D] for k, v in self.g_arr.items()}, (1, 1, -1, 1), dtype)
        mo = None if self.m_arr is None or mechanics else shaped(self.m_arr, (1, 1, -1, 1), dtype)
        cp = None if self.c_arr is None or mechanics else shaped(self.c_arr, (1, 1, -1, 1), dtype)
        rd = None if self.r_arr is None or mechanics else shaped(self.r_arr, (1, 1, -1, 1), dtype)
        ps = model.axis_params(self.problem.axis_for(mounting), s, nt, b, g, mo, cp, rd)
        if mechanics and coupling_stiffness is not None:
            ps["coupling_stiffness"] = coupling_stiffness
        ps = as_dtype(ps, dtype)
        # pair layouts are built once each (the explanation's scored blocks): not kept
        if bearings is None:
            if len(self._cache) > 64:
                self._cache.clear()
            self._cache[key] = ps
        return ps

    def params_drives(
        self, mounting: str, nut_sel, bearings=None, dtype=float, drives=None
    ) -> dict:
        """Parameters over (nuts, bearings, guides, drives) for the drive block alone: the
        mechanical guides on the third axis, the searched drives on the fourth (the drive block
        reads no position), so that the mechanics the drive takes (moving mass, drag, guide
        friction) are evaluated once per guide and the drive block once per drive; element (.., g,
        d) is guide-and-drive ``g * D + d``.  ``nut_sel`` and ``bearings`` as in
        :meth:`params_structured`; ``drives``: those drive numbers only, in that order, on the
        fourth axis."""
        s, nt, b = self.nut_bearing_arrays(nut_sel, dtype, bearings)
        g = shaped({k: v[:: self.n_drives] for k, v in self.g_arr.items()}, (1, 1, -1, 1), dtype)
        ps = model.axis_params(
            self.problem.axis_for(mounting),
            s,
            nt,
            b,
            g,
            *self.drive_columns((1, 1, 1, -1), dtype, drives),
        )
        return as_dtype(ps, dtype)

    def drive_columns(self, shape, dtype=float, drives=None) -> tuple:
        """The searched drives' (motor, coupling, reduction) columns, each the D drives in order (or
        the drive numbers ``drives``) reshaped to ``shape`` (one -1 axis), or None where that part
        is not searched: the drive arguments of :func:`axisopt.model.axis_params` for a layout with
        the drives on one axis."""
        sel = slice(0, self.n_drives) if drives is None else drives
        return tuple(
            None if d is None else shaped({k: v[sel] for k, v in d.items()}, shape, dtype)
            for d in (self.m_arr, self.c_arr, self.r_arr)
        )

    def nut_numbers(self, nut_sel) -> np.ndarray:
        """The nut numbers a selection (a slice or an index array) takes."""
        return (
            np.arange(self.shape[1])[nut_sel]
            if isinstance(nut_sel, slice)
            else np.asarray(nut_sel, np.int64)
        )

    def nut_bearing_arrays(self, nut_sel, dtype=float, bearings=None) -> tuple:
        """Screw and nut columns of the nuts ``nut_sel`` on the first axis, every bearing on the
        second (or, with ``bearings`` aligned with the nuts, those bearings on the first axis
        too)."""
        s = shaped({k: v[nut_sel] for k, v in self.s_arr.items()}, (-1, 1, 1, 1), dtype)
        nt = shaped({k: v[nut_sel] for k, v in self.n_arr.items()}, (-1, 1, 1, 1), dtype)
        if bearings is not None:
            return (
                s,
                nt,
                shaped({k: v[bearings] for k, v in self.b_arr.items()}, (-1, 1, 1, 1), dtype),
            )
        return s, nt, shaped(self.b_arr, (1, -1, 1, 1), dtype)

    def params_flat(self, mounting: str, n, b, g) -> dict:
        def pick(d, i):
            return {k: v[i][:, None] for k, v in d.items()}

        ps = model.axis_params(
            self.problem.axis_for(mounting),
            pick(self.s_arr, n),
            pick(self.n_arr, n),
            pick(self.b_arr, b),
            pick(self.g_arr, g),
            None if self.m_arr is None else pick(self.m_arr, g),
            None if self.c_arr is None else pick(self.c_arr, g),
            None if self.r_arr is None else pick(self.r_arr, g),
        )
        return ps
