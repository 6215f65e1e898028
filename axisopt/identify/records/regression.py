"""The regression model of a time record (Gautier's inverse dynamic identification model, IDIM: A.
Janot, P.-O. Vandanjon, M. Gautier, IEEE Trans. Control Syst. Technol. 22 (2014) 132-145, sec. II),
in the coordinate of the record's effort (table [m] for force, motor angle [rad] for torque;
:mod:`.timerecord`):

.. math:: f = M \\ddot q + F_v \\dot q + F_c \\operatorname{sgn}\\dot q + f_0 \\;(+\\ \\text{effects})

the baseline's terms here (:data:`BASE_TERMS`), each effect's in its declaration (:mod:`.effects`,
``time``).

Processing: the position is low-pass filtered with a zero-phase Butterworth whose cut-off comes from
the data (:func:`.signal.choose_cutoff`), differentiated by central differences, every column of the
regression and the effort are low-pass filtered alike and every nd-th row kept (parallel
decimation); rows at low speed (``|v| < 0.5 %`` of the peak speed) and around reversals, where
sgn(v) of the estimate is not that of the axis, are left out.  An ``external_force`` column is added
to the effort before the regression.
"""  # noqa: E501

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...errors import InputError
from ..effects import Term, time_effects
from .record import TimeRecord
from .signal import choose_cutoff, decimation_factor, derivatives, lowpass

VMIN_REL = 0.005  # rows slower than this share of the peak speed are left out
SIGN_KEEP = 0.98  # a row is kept when the filtered sgn(v) is at least this far from zero

BASE_TERMS = (
    Term("M", "moving mass", "mass", lambda sig, proc, shape: sig["a"]),
    Term("Fv", "viscous friction", "damping", lambda sig, proc, shape: sig["v"]),
    Term("Fc", "Coulomb friction", "effort", lambda sig, proc, shape: np.sign(sig["v"])),
    Term(
        "offset",
        "offset (gravity, sensor, Coulomb asymmetry)",
        "effort",
        lambda sig, proc, shape: np.ones_like(sig["v"]),
    ),
)
BASE = tuple(t.name for t in BASE_TERMS)

# unit kind -> (unit, factor from SI) of the record's coordinate
UNITS = {
    "force": {
        "mass": ("kg", 1.0),
        "damping": ("N.s/m", 1.0),
        "effort": ("N", 1.0),
        "snap": ("kg.s^2", 1.0),
        "speed": ("mm/s", 1e3),
        "position": ("mm", 1e3),
        "drag2": ("N.s^2/m^2", 1.0),
        "frequency": ("Hz", 1.0),
        "time": ("s", 1.0),
        "ratio": ("-", 1.0),
        "per_kelvin": ("1/K", 1.0),
        "effort_per_kelvin": ("N/K", 1.0),
    },
    "torque": {
        "mass": ("kg.m^2", 1.0),
        "damping": ("N.m.s/rad", 1.0),
        "effort": ("N.m", 1.0),
        "snap": ("kg.m^2.s^2", 1.0),
        "speed": ("rad/s", 1.0),
        "position": ("rad", 1.0),
        "drag2": ("N.m.s^2/rad^2", 1.0),
        "frequency": ("Hz", 1.0),
        "time": ("s", 1.0),
        "ratio": ("-", 1.0),
        "per_kelvin": ("1/K", 1.0),
        "effort_per_kelvin": ("N.m/K", 1.0),
    },
}
SYMBOL = {"force": {"M": "M"}, "torque": {"M": "J"}}


def terms_by_name() -> dict:
    """Every term the regression knows: the baseline's and the registered effects'."""
    out = {t.name: t for t in BASE_TERMS}
    for eff in time_effects().values():
        out.update((t.name, t) for t in eff.columns)
    return out


def shape_params() -> dict:
    """Every shape parameter the registered effects search: name -> (label, unit kind)."""
    out = {}
    for eff in time_effects().values():
        if eff.shape is not None:
            out[eff.shape.name] = (eff.shape.label, eff.shape.unit)
            out.update((n, (lab, u)) for n, lab, u in eff.shape.also)
    return out


def term(name: str) -> Term:
    return terms_by_name()[name]


def unit_of(quantity: str, name: str) -> tuple:
    """(unit, factor from SI) of a term's parameter in a ``quantity`` ('force' | 'torque')
    record."""
    return UNITS[quantity][term(name).unit]


def symbol(quantity: str, name: str) -> str:
    """A term's symbol as printed (the mass of a torque record is an inertia, J)."""
    return SYMBOL[quantity].get(name, name)


# ------------------------------------------------------------------------------------- regression
# rows
@dataclass
class Processing:
    fs: float
    fc: float
    nd: int
    fdec: float
    f_motion: float
    rule: str
    vmin: float
    stroke_q: float  # stroke in the record's coordinate
    # the screw's lead in the record's coordinate (table [m] or motor angle 2 pi [rad])
    lead_q: float = 0.0
    # the design's turning parts (effects.orders): motor turns per screw turn, balls passing a
    # point of the nut per screw turn (0: unknown), the motor pulley's teeth of a belt stage (0:
    # none known)
    reduction: float = 1.0
    ball_order: float = 0.0
    belt_teeth: int = 0


@dataclass
class Rows:
    """Filtered full-rate signals of one record and the kept decimated rows."""

    record: TimeRecord
    sig: dict  # q, v, a, snap (full rate, filtered); t from the run's start
    keep: np.ndarray  # full-rate indices of the kept rows
    y: np.ndarray  # effort at the kept rows after the decimation filter
    proc: Processing
    # shape-free columns at the kept rows, by term
    cache: dict = field(default_factory=dict, repr=False)

    @property
    def n(self) -> int:
        return len(self.keep)

    def columns(self, terms, shape: dict) -> np.ndarray:
        """The regression columns of ``terms`` at the kept rows (:func:`matrix`): what an effect's
        own shape search (``Shape.search``) fits with, without importing this pipeline."""
        return matrix(self, terms, shape)


def full_matrix(sig: dict, terms, proc: Processing, shape: dict) -> np.ndarray:
    """The regression columns of ``terms`` at full rate."""
    table = terms_by_name()
    cols = []
    for t in terms:
        if t not in table:
            raise KeyError(t)
        cols.append(table[t].column(sig, proc, shape))
    return np.column_stack(cols)


def decimate(rows_full: np.ndarray, proc: Processing, keep: np.ndarray, segments=()) -> np.ndarray:
    """Parallel decimation: the same low-pass on every column (in each window of a long record),
    then the kept rows."""
    return lowpass(rows_full, proc.fs, proc.fdec, segments=segments)[keep]


def processing_for(rec: TimeRecord, stroke_q: float, lead_q: float = 0.0) -> Processing:
    fs = rec.fs
    cut = choose_cutoff(rec.q, fs, rec.segments)
    nd = decimation_factor(fs, cut.fc)
    fdec = 0.8 * fs / (2.0 * nd)
    q, v = derivatives(rec.q, fs, cut.fc, 1, rec.segments)
    vmin = VMIN_REL * float(np.max(np.abs(v)))
    return Processing(fs, cut.fc, nd, fdec, cut.f_motion, cut.rule, vmin, stroke_q, lead_q)


def signals(q: np.ndarray, proc: Processing, segments=()) -> dict:
    qf, v, a, j, snap = derivatives(q, proc.fs, proc.fc, 4, segments)
    return {"q": qf, "v": v, "a": a, "snap": snap}


def make_rows(rec: TimeRecord, proc: Processing) -> Rows:
    if abs(rec.fs - proc.fs) > 1e-3 * proc.fs:
        raise InputError(
            f"sampled at {rec.fs:.6g} Hz, the estimation run at {proc.fs:.6g} Hz (the same filters "
            "are applied to every run)",
            source=rec.source,
            where="column time",
        )
    segs = rec.segments
    sig = signals(rec.q, proc, segs)
    sig["t"] = rec.t - rec.t[0]  # time from the run's start
    sig["effort"] = rec.effort  # the force the drive transmits (measured: its own instrument)
    for key, val in (("fext", rec.external), *rec.aux.items()):
        if val is not None:
            sig[key] = val
    v = sig["v"]
    sf = lowpass(np.sign(v), proc.fs, proc.fdec, segments=segs)
    edge = int(2.0 * proc.fs / min(proc.fc, proc.fdec)) + proc.nd
    idx = np.concatenate([np.arange(a + edge, b - edge, proc.nd) for a, b in segs or ((0, rec.n),)])
    # a row is kept when the axis moves one way for a whole filter window around it: the zero-phase
    # filters smear starts and stops, where sgn(v) of the estimate leads the axis's
    w = int(proc.fs / proc.fdec)
    bad = (np.abs(v) < proc.vmin).astype(float)
    bad = np.convolve(bad, np.ones(2 * w + 1), mode="same") > 0
    keep = idx[~bad[idx] & (np.abs(sf[idx]) >= SIGN_KEEP)]
    if len(keep) < 20:
        raise InputError(
            f"only {len(keep)} usable rows after filtering and decimation (the axis must move: "
            f"speeds above {proc.vmin:.3g} in the record's unit/s)",
            source=rec.source,
        )
    f = rec.effort + rec.external if rec.external is not None else rec.effort
    # a known mass: its inertial force leaves the effort, M stays the axis's own
    if "payload" in rec.aux:
        f = f - rec.aux["payload"] * sig["a"]
    y = lowpass(f, proc.fs, proc.fdec, segments=segs)[keep]
    return Rows(rec, sig, keep, y, proc)


def matrix(rows: Rows, terms, shape: dict, sig: dict | None = None) -> np.ndarray:
    """The regression columns of ``terms`` at the kept rows (filtered and decimated).  On the
    record's own signals, the columns no shape parameter moves are filtered once and kept with the
    rows."""
    if sig is not None:
        return decimate(
            full_matrix(sig, terms, rows.proc, shape), rows.proc, rows.keep, rows.record.segments
        )
    fixed = _shape_free()
    cache = rows.cache
    need = [t for t in terms if t not in cache or t not in fixed]
    if need:
        new = decimate(
            full_matrix(rows.sig, need, rows.proc, shape),
            rows.proc,
            rows.keep,
            rows.record.segments,
        )
        got = dict(zip(need, new.T))
        cache.update((t, c) for t, c in got.items() if t in fixed)
    else:
        got = {}
    return np.column_stack([got[t] if t in got else cache[t] for t in terms])


def _shape_free() -> set:
    """Terms whose column no shape parameter changes: the baseline's and those of effects without a
    shape."""
    out = {t.name for t in BASE_TERMS}
    for eff in time_effects().values():
        if eff.shape is None:
            out.update(t.name for t in eff.columns)
    return out
