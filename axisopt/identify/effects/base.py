"""The one effect registry of both diagnosis pipelines, and how an effect is declared.

An effect is a named physical extension of the axis model, declared once as an :class:`Effect`
subclass that carries what each kind of measured data needs:

* reduced tables (:mod:`..diagnose`): the tests it shows in (``kinds``), its parameters
  (:class:`..fit.Param`: user units, bounds, plausible range), how it changes the measurement model
  (``apply``: edits a :class:`~..measure.Terms` record with CasADi-safe arithmetic), alternative
  starts of its shape parameters (``starts``), when it is testable (``applicable``) and how a
  calibrated design takes it (``calibrate``; ``None`` = evaluate cannot represent it);
* time records (:mod:`..idim`): ``time``, a :class:`TimeModel` -- its regression columns
  (:class:`Term`: parameter, label, unit kind, column), its shape parameter and how it is searched
  (:class:`Shape`), when the record can show it (``skip``) and the physical range of its fitted
  values (``implausible``).

An effect with no table ``kinds`` exists for time records only; one without ``time`` for tables
only.  Register your own with :func:`register_effect`; it then competes like the built-ins.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import Callable


@dataclass(frozen=True)
class Term:
    """One column of the time-record regression (:mod:`..timemodel`) and the parameter that
    multiplies it."""

    name: str
    label: str
    # unit kind of the parameter: mass, damping, effort, snap, drag2 (:data:`..timemodel.UNITS`)
    unit: str
    # (sig, proc, shape) -> the column at full rate; sig holds q, v, a, snap (filtered)
    column: Callable
    # IV instrument from the simulated closed loop; False: the measured column itself
    simulated: bool = True


@dataclass(frozen=True)
class Shape:
    """A shape parameter of a time-record effect: found on the least-squares residual, then held
    fixed.  Either ``bounds`` ((sig, proc) -> (lo, hi): log grid, then golden section), ``choices``
    (proc -> values: the one with the least residual) or ``search`` ((rows, r0, rss) -> {name:
    value, ...}: a scan of ``r0``, the residual of the model so far on the estimation rows, refined
    on ``rss(values)``, the joint fit's RSS);
    ``also``: further shape values a search returns, as (name, label, unit kind)."""

    name: str
    label: str
    unit: str
    bounds: Callable | None = None
    choices: Callable | None = None
    search: Callable | None = None
    also: tuple = ()


@dataclass(frozen=True)
class TimeModel:
    """What a time record needs of an effect: columns fitted jointly with the rigid baseline."""

    summary: str
    columns: tuple  # Term, in the order they enter the regression
    shape: Shape | None = None
    skip: Callable | None = None  # (ctx) -> why the record cannot show the effect ('' when it can)
    # (value, fc, fv) -> [texts]: fitted values outside the physical range
    implausible: Callable | None = None
    # (ctx) -> why the run is too short to resolve the effect ('' when it is not): not tried; an
    # input error when the effect is asked by name
    too_short: Callable | None = None
    evidence: str = ""  # the measurement that shows this effect apart from the others
    # (top table speed [m/s]) -> why the effect is implausible at such speeds, or ''
    regime: Callable | None = None
    # (name, label, unit kind, value -> SI): quantities shown beside the terms (an amplitude)
    derived: tuple = ()
    # its columns are one sin, cos pair whose phase is each run's own: a held-out run keeps the
    # amplitude and takes its own phase (:func:`..estimators.predict`)
    per_run: bool = False
    # (value, proc) -> why the record cannot resolve the fitted values ('' none)
    resolved: Callable | None = None
    # signals (keys of the record's ``sig``: fext, normal, temperature) it needs; a record without
    # them does not list the effect at all
    needs: tuple = ()
    name: str = ""  # the effect's name (filled in by register_effect)

    @property
    def terms(self) -> tuple:
        return tuple(t.name for t in self.columns)

    def why_implausible(self, value, fc: float, fv: float) -> list:
        """Texts for the fitted values (``value(term)``) outside the physical range; ``fc``, ``fv``:
        the baseline's Coulomb level and viscous coefficient (magnitudes), the scale of every
        range."""
        return list(self.implausible(value, fc, fv)) if self.implausible is not None else []


class Effect:
    """Base class.  Subclasses set ``name``, ``title``, ``kinds``, ``signature`` and implement
    ``params(ctx)`` and ``apply(kind, q, P, Z, plant)`` for tables, and/or set ``time``."""

    name = "effect"
    title = ""
    kinds: tuple = ()
    signature = ""
    needs: tuple = ()  # (kind, column) pairs that must vary for the effect to be testable
    # for tables: the measurement that shows it apart (time records: ``time.evidence``)
    evidence: str = ""
    time: TimeModel | None = None

    def applicable(self, ctx) -> bool:
        obs = [o for o in ctx.obs if o.kind in self.kinds]
        if not obs:
            return False
        if not self.needs:
            return True
        return any(
            o.kind == k and o.dataset.has(col, varying=True) for o in obs for k, col in self.needs
        )

    def params(self, ctx) -> list:
        raise NotImplementedError

    def starts(self, ctx) -> list:
        """Alternative initial values {name: SI} for a multi-start fit (shape parameters)."""
        return [{}]

    def apply(self, kind, q, P, Z, plant) -> None:
        raise NotImplementedError

    def describe(self, v: dict, plant) -> str:
        return self.title

    def calibrate(self, v: dict, design):
        """Return (design, how) or None when ``axisopt evaluate`` cannot represent the effect."""
        return None


_REGISTRY: dict[str, Effect] = {}

# The built-in time-record effects in the order they are tried and listed; an effect registered
# later follows.
TIME_ORDER = (
    "direction_asymmetry",
    "stribeck",
    "position_friction",
    "extra_mode",
    "lead_ripple",
    "quadratic_drag",
    "time_periodic",
    "local_friction",
    "friction_drift",
    "nut_axial_friction",
    "guide_load_friction",
    "viscous_temperature",
    "coulomb_temperature",
    "motor_cogging",
    "belt_mesh",
    "ball_pass",
)


def register_effect(effect):
    """Add an effect (instance or class) to the registry; returns it, so it works as a decorator."""
    inst = effect() if isinstance(effect, type) else effect
    if not isinstance(inst, Effect):
        raise TypeError("register_effect expects an Effect subclass or instance")
    if inst.time is not None and inst.time.name != inst.name:
        inst.time = replace(inst.time, name=inst.name)
    _REGISTRY[inst.name] = inst
    return effect


def unregister_effect(name: str) -> None:
    """Remove an effect from the registry (no error when it is not there)."""
    _REGISTRY.pop(name, None)


def library() -> MappingProxyType:
    """The effects reduced tables can show (those with table ``kinds``), by name, in registration
    order."""
    return MappingProxyType({n: e for n, e in _REGISTRY.items() if e.kinds})


def all_effects() -> MappingProxyType:
    """Every registered effect by name, tables' and time records' (a calibration file may name
    either)."""
    return MappingProxyType(dict(_REGISTRY))


def time_effects() -> dict:
    """The time-record declarations (:class:`TimeModel`) by effect name, built-ins in
    :data:`TIME_ORDER`."""
    names = [n for n in TIME_ORDER if n in _REGISTRY] + [
        n for n in _REGISTRY if n not in TIME_ORDER
    ]
    return {n: _REGISTRY[n].time for n in names if _REGISTRY[n].time is not None}


def replace_part(design, slot, **values):
    """``design`` with some values of one catalog part (``slot``: bearing, guide, nut, ...)
    replaced."""
    part = getattr(design, slot).copy()
    for k, v in values.items():
        part[k] = v
    return replace(design, **{slot: part})
