"""Friction that depends on the load the axis carries and on its temperature.

* ``nut_axial_friction``: the nut's loss grows with the axial force it transmits.  A screw of
  efficiency eta needs the torque T = F_a p / (2 pi eta) to push F_a, of which F_a p / (2 pi)
  (1/eta - 1) is friction (the nut load torque of the reference notes, sec. 1.2; THK and HIWIN give
  eta = 0.9-0.95 for ball screws, 0.3-0.7 for sliding lead screws).  At the table that is a friction
  k_a |F_a| sgn(v), k_a = 1/eta - 1, the same both ways for a given |F_a|: a table averaged over the
  direction loses it, so it is fitted and tested signed (``sgn(v) |F_a|``).  In tables from the
  ``axial_load`` column (the load on the nut, k_a = 1/eta - 1).  In time records from the force the
  drive supplies, the record's effort f = F_a / eta: the loss is (1 - eta) |f| sgn(v) (``ka`` there
  is 1 - eta; measured, its own instrument); a candidate only when the record has an
  ``external_force`` (otherwise |f| hardly varies apart from the Coulomb and inertia columns).
* ``guide_load_friction`` (time records with a ``normal_load`` column): mu N sgn(v), the rolling
  friction of the guide carriages growing with the normal load on them (seed Table 9; mu 0.001-0.005
  for ball and roller carriages, Thomson / Schaeffler).  Tables have ``load_dependent_friction``.
* ``viscous_temperature`` (records and friction tables with a ``temperature`` column): the viscous
  friction follows the lubricant's viscosity, which falls about exponentially with temperature
  (Reynolds' viscosity law, mu(T) = mu_0 exp(-beta (T - T_0))): F_v(T) = F_v(20 degC) exp(-beta (T -
  20 degC)).  Fitted as c v (exp(-beta (T - 20 degC)) - 1) beside the baseline F_v v, beta by a 1-D
  search (0.005-0.2 /K; mineral greases and oils about 0.02-0.05 /K).
* ``coulomb_temperature``: the Coulomb level changing linearly with temperature, g (T - 20 degC)
  sgn(v) (grease consistency, seal and preload change with warming; an estimate of the law: linear
  over the range of a warm-up).

Temperature effects are told apart from ``friction_drift`` (a level that settles with the time from
each run's start) by their law: a validation run that starts warm keeps the warm friction under a
temperature law and restarts cold under a time law.
"""

from __future__ import annotations

import math

import numpy as np

from ... import mathx as mx
from ..fit import Param
from .base import Effect, Shape, Term, TimeModel, register_effect

T_REF = 293.15  # [K] the reference temperature of the temperature laws (20 degC)
BETA_RANGE = (0.005, 0.2)  # [1/K] search range of the viscosity-temperature coefficient
# k_a = 1/eta - 1 up to a sliding lead screw of efficiency 0.3 (estimate of the range)
AXIAL_RATIO_MAX = 2.5
LOSS_MAX = 0.7  # 1 - eta, the same screws


# ---------------------------------------------------------------------------------- time-record
# columns
def _axial_column(sig, proc, shape):
    return np.sign(sig["v"]) * np.abs(sig["effort"])


def _needs_external(ctx) -> str:
    ext = ctx.rows.sig.get("fext")
    if ext is None:
        return "no external_force column (the nut's load varies with it)"
    f = np.abs(ctx.rows.record.effort)
    if float(np.ptp(ext)) < 0.2 * float(np.percentile(f, 95)):
        return "the external force varies by less than 20 % of the effort"
    return ""


def _axial_implausible(value, fc, fv) -> list:
    v = value("ka")
    if 0.0 < v <= LOSS_MAX:
        return []
    return [f"ka = {v:.4g} outside 0..{LOSS_MAX} (1 - eta of a screw of efficiency 0.3-1)"]


def _normal_column(sig, proc, shape):
    return np.sign(sig["v"]) * sig["normal"]


def _needs_normal(ctx) -> str:
    n = ctx.rows.sig.get("normal")
    if n is None:
        return "no normal_load column"
    if float(np.ptp(n)) <= 0.0:
        return "the normal load is constant (its friction is part of the Coulomb level)"
    return ""


def _normal_implausible(value, fc, fv) -> list:
    v = value("mu_g")
    return [] if 0.0 < v <= 0.05 else [f"mu = {v:.4g} outside 0..0.05 (rolling guides 0.001-0.005)"]


def _viscous_t_column(sig, proc, shape):
    return sig["v"] * (np.exp(-shape["beta"] * (sig["temperature"] - T_REF)) - 1.0)


def _beta_search(rows, r0, rss) -> dict:
    """beta of the pure law F_v(T) = F_v(20 degC) exp(-beta (T - 20 degC)): the baseline's viscous
    column replaced by v exp(-beta (T - 20 degC)) and the RSS of that fit minimised over beta (log
    grid, then golden section).  A free constant viscous part beside the exponential trades with
    beta over the few tens of kelvin of a warm-up; the joint fit then frees it at this beta."""
    from .disturbance import golden

    W = rows.columns(("M", "Fc", "offset"), {})
    y = rows.y

    def cost(logb):
        col = (
            rows.columns(("Fvt",), {"beta": math.exp(logb)})[:, 0] + rows.columns(("Fv",), {})[:, 0]
        )
        A = np.column_stack([W, col])
        # columns scaled to unit norm, as the records' least squares does
        sc = np.linalg.norm(A, axis=0)
        sc[sc == 0] = 1.0
        th, *_ = np.linalg.lstsq(A / sc, y, rcond=None)
        e = y - A @ (th / sc)
        return float(e @ e)

    grid = np.linspace(math.log(BETA_RANGE[0]), math.log(BETA_RANGE[1]), 16)
    vals = [cost(g) for g in grid]
    k = int(np.argmin(vals))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    return {"beta": math.exp(golden(cost, lo, hi, 20))}


def _coulomb_t_column(sig, proc, shape):
    return np.sign(sig["v"]) * (sig["temperature"] - T_REF)


def _needs_temperature(ctx) -> str:
    t = ctx.rows.sig.get("temperature")
    if t is None:
        return "no temperature column"
    if float(np.ptp(t[ctx.rows.keep])) < 1.0:
        return "the temperature varies by less than 1 K"
    return ""


def _viscous_t_implausible(value, fc, fv) -> list:
    v = value("Fvt")
    return (
        []
        if 0.0 < v <= 5.0 * max(fv, 1e-9)
        else [
            f"Fvt = {v:.4g} outside 0..{5.0 * fv:.4g} (the viscous friction at 20 degC, up to 5x "
            "the record's)"
        ]
    )


def _coulomb_t_implausible(value, fc, fv) -> list:
    v = value("dFc_dT")
    return (
        []
        if abs(v) <= 0.1 * fc
        else [f"dFc/dT = {v:.4g} beyond +-{0.1 * fc:.4g} per K (10 % of Coulomb per K)"]
    )


@register_effect
class NutAxialFriction(Effect):
    """Nut friction growing with the axial force it transmits, k_a |F_a| sgn(v), k_a = 1/eta - 1."""

    name = "nut_axial_friction"
    title = "nut friction growing with the axial force (screw efficiency)"
    kinds = ("friction",)
    signature = (
        "residual proportional to sgn(v) |F_axial|, the same sign as the motion in both directions"
    )
    needs = (("friction", "axial_load"),)
    time = TimeModel(
        "nut friction grows with the axial force it transmits (screw efficiency: ka = 1 - eta of "
        "the drive force)",
        (Term("ka", "nut loss per drive force, 1 - eta", "ratio", _axial_column, simulated=False),),
        skip=_needs_external,
        implausible=_axial_implausible,
        evidence="constant-speed passes at two or more process forces in both directions: the "
        "friction grows with |F| the same way both ways",
        needs=("fext",),
    )

    def params(self, ctx):
        return [
            Param(
                "nut_axial_ratio",
                "nut friction per axial force k_a = 1/eta - 1",
                "-",
                "dimensionless",
                0.05,
                -10.0,
                10.0,
                typical=0.1,
                plausible=(0.0, AXIAL_RATIO_MAX),
                plausible_note="1/eta - 1 of a screw of efficiency 0.3 (lead screw) to 1",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.axial_ratio = P["nut_axial_ratio"]

    def describe(self, v, plant):
        k = v["nut_axial_ratio"]
        return (
            f"nut friction grows with the axial force: {k:.4f} N per N (screw efficiency "
            f"{1.0 / (1.0 + k):.3f} under load)"
        )


@register_effect
class GuideLoadFriction(Effect):
    """Guide rolling friction growing with a recorded normal load (time records)."""

    name = "guide_load_friction"
    title = "guide friction growing with the normal load"
    time = TimeModel(
        "guide friction grows with the normal load on the carriages (mu N)",
        (Term("mu_g", "guide friction coefficient mu", "ratio", _normal_column, simulated=False),),
        skip=_needs_normal,
        implausible=_normal_implausible,
        evidence="constant-speed passes with two payloads (or vertical forces): the friction grows "
        "with N, the axial force unchanged",
        needs=("normal",),
    )


class _TemperatureEffect(Effect):
    kinds = ("friction",)
    needs = (("friction", "temperature"),)


@register_effect
class ViscousTemperature(_TemperatureEffect):
    """The viscous friction following the lubricant's viscosity with temperature."""

    name = "viscous_temperature"
    title = "viscous friction falls with temperature (lubricant viscosity)"
    signature = "residual proportional to v, growing with the temperature difference"
    time = TimeModel(
        "viscous friction follows the lubricant's viscosity with temperature: Fv(T) = Fvt "
        "exp(-beta (T - 20 C))",
        (Term("Fvt", "viscous friction at 20 degC", "damping", _viscous_t_column),),
        shape=Shape(
            "beta",
            "viscosity-temperature coefficient (1-D search of the pure law)",
            "per_kelvin",
            search=_beta_search,
        ),
        skip=_needs_temperature,
        implausible=_viscous_t_implausible,
        evidence="friction curves at two temperatures (cold and warm): the slope with speed "
        "changes, the level at low speed does not",
        needs=("temperature",),
    )

    def params(self, ctx):
        return [
            Param(
                "viscous_at_20C",
                "viscous friction at 20 degC",
                "N.s/m",
                "damping",
                max(ctx.plant.viscous, 100.0),
                0.0,
                1e9,
                typical=max(ctx.plant.viscous, 100.0),
                plausible=(0.0, 1e7),
                plausible_note="a positive viscous friction",
            ),
            Param(
                "viscosity_beta",
                "viscosity-temperature coefficient beta",
                "1/K",
                "thermal_expansion",
                0.03,
                1e-4,
                0.5,
                typical=0.03,
                plausible=BETA_RANGE,
                plausible_note="lubricants 0.005-0.2 /K (mineral greases about 0.02-0.05)",
            ),
        ]

    def starts(self, ctx):
        return [{"viscosity_beta": b} for b in (0.01, 0.03, 0.08)]

    def apply(self, kind, q, P, Z, plant):
        q.viscous = P["viscous_at_20C"] * mx.exp(-P["viscosity_beta"] * (Z["temperature"] - T_REF))

    def describe(self, v, plant):
        b = v["viscosity_beta"]
        return (
            f"viscous friction {v['viscous_at_20C']:.0f} N.s/m at 20 degC, halving every "
            f"{math.log(2.0) / b:.3g} K (lubricant viscosity)"
        )


@register_effect
class CoulombTemperature(_TemperatureEffect):
    """The Coulomb level changing linearly with temperature."""

    name = "coulomb_temperature"
    title = "Coulomb friction changes with temperature"
    signature = "residual proportional to sgn(v) (T - T_ref)"
    time = TimeModel(
        "Coulomb friction changes with temperature: dFc/dT (T - 20 C) sgn(v)",
        (
            Term(
                "dFc_dT",
                "Coulomb friction change per kelvin",
                "effort_per_kelvin",
                _coulomb_t_column,
            ),
        ),
        skip=_needs_temperature,
        implausible=_coulomb_t_implausible,
        evidence="slow passes at two temperatures: the level at low speed changes, the slope does "
        "not",
        needs=("temperature",),
    )

    def params(self, ctx):
        fc = max(ctx.plant.coulomb, 10.0)
        return [
            Param(
                "coulomb_per_kelvin",
                "Coulomb friction change per kelvin [N/K]",
                "-",
                "dimensionless",
                0.0,
                -1e6,
                1e6,
                typical=0.01 * fc,
                plausible=(-0.1 * fc, 0.1 * fc),
                plausible_note="up to 10 % of the Coulomb level per kelvin",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.coulomb_t = P["coulomb_per_kelvin"] * (Z["temperature"] - T_REF)

    def describe(self, v, plant):
        return f"Coulomb friction changes by {v['coulomb_per_kelvin']:.3g} N per K"
