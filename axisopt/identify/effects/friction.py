"""Friction effects: Stribeck rise, viscous and load-dependent friction, a direction difference,
quadratic drag, and -- in time records only -- a Coulomb level varying along the stroke and a ripple
periodic in position.

In time records (:mod:`..idim`) each is a few regression columns fitted jointly with the rigid
baseline :math:`f = M \\ddot q + F_v \\dot q + F_c \\operatorname{sgn}\\dot q + f_0` (Gautier's
inverse dynamic identification model); every physical range is relative to the baseline's own
friction.
"""

from __future__ import annotations

import math

import numpy as np

from ... import mathx as mx
from ..fit import Param
from .base import Effect, Shape, Term, TimeModel, register_effect, replace_part

# the ripple's period is the lead / k for one of these k (chosen by RSS)
RIPPLE_HARMONICS = (1, 2, 3)


def _stribeck_bounds(sig, proc) -> tuple:
    """Search range of the Stribeck velocity: from the record's speed threshold (at least 1e-4 of
    the peak speed) to half the peak speed."""
    vmax = float(np.max(np.abs(sig["v"])))
    return max(proc.vmin, 1e-4 * vmax), 0.5 * vmax


def _stribeck_implausible(value, fc, fv) -> list:
    v = value("Fs")
    return (
        []
        if 0.0 <= v <= 2.0 * fc
        else [f"Fs = {v:.4g} outside 0..{2 * fc:.4g} (breakaway up to 3x Coulomb)"]
    )


def _asymmetry_implausible(value, fc, fv) -> list:
    v = value("dFv")
    return (
        [f"dFv = {v:.4g} beyond +-{fv:.4g} (the whole viscous coefficient)"] if abs(v) > fv else []
    )


def _drag_implausible(value, fc, fv) -> list:
    v = value("Cq")
    return (
        [f"Cq = {v:.4g} not positive (a drag that falls with v|v| is no drag)"] if v <= 0.0 else []
    )


@register_effect
class Stribeck(Effect):
    name = "stribeck"
    title = "Stribeck friction rise at low speed"
    kinds = ("friction",)
    signature = "positive bump at |v| below a few v_s"
    time = TimeModel(
        "friction rises at low speed (Stribeck)",
        (
            Term(
                "Fs",
                "Stribeck excess Fs - Fc",
                "effort",
                lambda sig, proc, shape: (
                    np.sign(sig["v"]) * np.exp(-np.abs(sig["v"]) / shape["vs"])
                ),
            ),
        ),
        shape=Shape("vs", "Stribeck velocity (1-D search)", "speed", bounds=_stribeck_bounds),
        implausible=_stribeck_implausible,
        evidence="a friction curve with many constant speeds below 10 mm/s in both directions: the "
        "rise at low speed",
    )

    def _speeds(self, ctx):
        return np.concatenate(
            [np.abs(o.feature("velocity")) for o in ctx.obs if o.kind == "friction"]
        )

    def params(self, ctx):
        v = self._speeds(ctx)
        fc = max(ctx.plant.coulomb, 10.0)
        vs = float(np.quantile(v, 0.25))
        return [
            Param(
                "stribeck_rise",
                "breakaway minus Coulomb friction, F_s - F_c",
                "N",
                "force",
                0.3 * fc,
                0.0,
                1e6,
                typical=fc,
                plausible=(0.0, 2.0 * fc),
                plausible_note="breakaway up to three times the Coulomb level",
            ),
            Param(
                "stribeck_velocity",
                "Stribeck velocity v_s",
                "mm/s",
                "speed",
                vs,
                1e-3 * float(v.min()),
                10.0 * float(v.max()),
                typical=vs,
                plausible=(1e-4, 1e-2),
                plausible_note="0.1-10 mm/s on a table",
            ),
        ]

    def starts(self, ctx):
        v = self._speeds(ctx)
        return [{"stribeck_velocity": float(np.quantile(v, q))} for q in (0.05, 0.15, 0.5)]

    def apply(self, kind, q, P, Z, plant):
        q.stribeck = q.stribeck + P["stribeck_rise"] * mx.exp(
            -((Z["velocity"] / P["stribeck_velocity"]) ** 2)
        )

    def describe(self, v, plant):
        return (
            f"friction rises by {v['stribeck_rise']:.1f} N below about "
            f"{v['stribeck_velocity'] * 1e3:.2g} mm/s (Stribeck)"
        )


def _top_friction_speed(ctx) -> float:
    """The largest |velocity| of the friction data [m/s]: the scale of the speed-dependent friction
    effects."""
    return max(
        float(np.max(np.abs(o.feature("velocity")))) for o in ctx.obs if o.kind == "friction"
    )


@register_effect
class Viscous(Effect):
    name = "viscous"
    title = "viscous (speed-proportional) friction differs from catalog"
    kinds = ("friction",)
    signature = "residual linear and odd in v"
    evidence = (
        "steady-state friction at constant speeds over a decade or more up to the top speed: a "
        "straight line in v"
    )

    def params(self, ctx):
        v = _top_friction_speed(ctx)
        typ = max(ctx.plant.coulomb, 10.0) / v
        return [
            Param(
                "viscous_coefficient",
                "viscous friction coefficient of the axis",
                "N.s/m",
                "damping",
                max(ctx.plant.viscous, 0.1 * typ),
                0.0,
                1e9,
                typical=typ,
                plausible=(0.0, 20.0 * typ),
                plausible_note="viscous force at the top test speed up to 20x the axis's Coulomb "
                "friction",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.viscous = P["viscous_coefficient"]

    def describe(self, v, plant):
        return (
            f"viscous friction {v['viscous_coefficient']:.0f} N.s/m (design {plant.viscous:.0f} "
            "N.s/m)"
        )

    def calibrate(self, v, design):
        blocks = design.axis.guide_blocks
        return (
            replace_part(design, "guide", friction_viscous=v["viscous_coefficient"] / blocks),
            f"guide viscous friction -> {v['viscous_coefficient'] / blocks:.1f} N.s/m per block",
        )


@register_effect
class LoadDependentFriction(Effect):
    name = "load_dependent_friction"
    title = "guide friction growing with block load (seed Table 9)"
    kinds = ("friction",)
    signature = "residual proportional to sgn(v) N"
    needs = (("friction", "normal_load"),)

    def params(self, ctx):
        return [
            Param(
                "friction_coefficient",
                "guide rolling friction coefficient mu",
                "-",
                "dimensionless",
                max(ctx.plant.mu, 1e-3),
                0.0,
                0.5,
                typical=3e-3,
                plausible=(1e-3, 5e-3),
                plausible_note="ball/roller carriages 0.001-0.005",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.mu = P["friction_coefficient"]

    def describe(self, v, plant):
        return (
            f"guide friction grows with load: mu = {v['friction_coefficient']:.4f} (design "
            f"{plant.mu:.4f})"
        )

    def calibrate(self, v, design):
        return (
            replace_part(design, "guide", friction_coefficient=v["friction_coefficient"]),
            f"guide friction coefficient -> {v['friction_coefficient']:.4f}",
        )


@register_effect
class DirectionAsymmetry(Effect):
    name = "direction_asymmetry"
    title = "friction differs between the two directions of travel"
    kinds = ("friction",)
    signature = "constant offset between + and - travel"
    # in a time record: viscous friction differing by direction, dFv = Fv(v>0) - Fv(v<0).  A Coulomb
    # asymmetry (Fc(v>0) - Fc(v<0))/2 is a constant while moving and cannot be told from the offset
    # on moving rows
    time = TimeModel(
        "viscous friction differs by direction",
        (
            Term(
                "dFv",
                "viscous asymmetry Fv+ - Fv-",
                "damping",
                lambda sig, proc, shape: 0.5 * np.abs(sig["v"]),
            ),
        ),
        implausible=_asymmetry_implausible,
        evidence="constant-speed runs at several speeds in both directions: the slopes differ",
    )

    def applicable(self, ctx):
        return any(
            o.kind == "friction" and np.ptp(np.sign(o.feature("velocity"))) > 0 for o in ctx.obs
        )

    def params(self, ctx):
        return [
            Param(
                "direction_difference",
                "friction in + travel minus friction in - travel",
                "N",
                "force",
                0.0,
                -1e6,
                1e6,
                typical=max(ctx.plant.coulomb, 10.0),
                plausible=(-max(ctx.plant.coulomb, 10.0), max(ctx.plant.coulomb, 10.0)),
                plausible_note="a direction difference up to the axis's whole Coulomb friction",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.asymmetry = q.asymmetry + P["direction_difference"]

    def describe(self, v, plant):
        return (
            f"friction {abs(v['direction_difference']):.1f} N higher in "
            f"{'+' if v['direction_difference'] > 0 else '-'} travel (gravity on an inclined axis, "
            f"seal or cable drag)"
        )


# [m/s] below this top speed a v|v| drag (churning, seals) is the less plausible reading (estimate)
DRAG_SPEED = 0.05


def _drag_regime(vmax: float) -> str:
    """Churning and seal drag that grows with v|v| shows at tens of mm/s and above (an estimate:
    DRAG_SPEED)."""
    if vmax >= DRAG_SPEED:
        return ""
    return (
        f"a drag growing with v|v| at a top speed of {vmax * 1e3:.3g} mm/s is the less plausible "
        f"reading: lubricant churning and seal drag show from about {DRAG_SPEED * 1e3:.0f} mm/s "
        "(an estimate)"
    )


@register_effect
class QuadraticDrag(Effect):
    name = "quadratic_drag"
    title = "drag growing with the square of speed"
    kinds = ("friction",)
    signature = "residual odd in v and growing faster than v: c v|v| (seals, lubricant churning)"
    time = TimeModel(
        "drag growing with v|v| (seals, lubricant churning)",
        (
            Term(
                "Cq",
                "quadratic drag c v|v|",
                "drag2",
                lambda sig, proc, shape: sig["v"] * np.abs(sig["v"]),
            ),
        ),
        implausible=_drag_implausible,
        evidence="steady-state friction at constant speeds up to the maximum: the curve bends "
        "upward with v|v|",
        regime=_drag_regime,
    )

    def params(self, ctx):
        v = _top_friction_speed(ctx)
        fc = max(ctx.plant.coulomb, 10.0)
        return [
            Param(
                "drag_coefficient",
                "quadratic drag coefficient c of c v|v|",
                "N.s^2/m^2",
                "mass_per_length",
                0.1 * fc / v**2,
                -1e12,
                1e12,
                typical=fc / v**2,
                plausible=(0.0, 20.0 * fc / v**2),
                plausible_note="a positive drag, at the top test speed up to 20x the axis's "
                "Coulomb friction",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.drag = P["drag_coefficient"]

    def describe(self, v, plant):
        return (
            f"drag grows with v|v|: c = {v['drag_coefficient']:.4g} N.s^2/m^2 (seals, lubricant "
            "churning); evaluate has no such term"
        )


# ------------------------------------------------------------------------------ time records only
def _stroke_xi(sig, proc):
    """The position as xi = 2 x/stroke - 1 over the design's stroke (Legendre's interval)."""
    return 2.0 * sig["q"] / proc.stroke_q - 1.0


def _position_skip(ctx) -> str:
    return "the record covers less than 10 % of the stroke" if ctx.span < 0.1 * ctx.stroke_q else ""


def _position_implausible(value, fc, fv) -> list:
    return [
        f"{t} = {value(t):.4g} beyond +-{fc:.4g} (the whole Coulomb friction)"
        for t in ("c1", "c2")
        if abs(value(t)) > fc
    ]


@register_effect
class PositionFriction(Effect):
    """Coulomb level varying with position: sgn(v) P1(xi), sgn(v) P2(xi) (Legendre polynomials)."""

    name = "position_friction"
    title = "Coulomb friction varies along the stroke"
    time = TimeModel(
        "Coulomb friction varies along the stroke",
        (
            Term(
                "c1",
                "Coulomb vs position, P1 coefficient",
                "effort",
                lambda sig, proc, shape: np.sign(sig["v"]) * _stroke_xi(sig, proc),
            ),
            Term(
                "c2",
                "Coulomb vs position, P2 coefficient",
                "effort",
                lambda sig, proc, shape: (
                    np.sign(sig["v"]) * (1.5 * _stroke_xi(sig, proc) ** 2 - 0.5)
                ),
            ),
        ),
        skip=_position_skip,
        implausible=_position_implausible,
        evidence="a slow constant-speed pass over the whole stroke in both directions: the level "
        "follows the position",
    )


def _ripple(trig, friction: bool):
    def column(sig, proc, shape):
        w = trig(2.0 * math.pi * sig["q"] / shape["period"])
        return np.sign(sig["v"]) * w if friction else w

    return column


def _ripple_skip(ctx) -> str:
    if ctx.lead_q > 0 and ctx.span >= 2.0 * ctx.lead_q:
        return ""
    return "the record covers less than two leads" if ctx.lead_q > 0 else "no lead known"


def _ripple_implausible(value, fc, fv) -> list:
    out = []
    force, fric = math.hypot(value("rs"), value("rc")), math.hypot(value("ks"), value("kc"))
    if force > fc:
        out.append(
            f"a force ripple of amplitude {force:.4g} beyond {fc:.4g} (the whole Coulomb friction)"
        )
    if fric > fc:
        out.append(
            f"a friction ripple of amplitude {fric:.4g} beyond {fc:.4g} (the friction would "
            "reverse)"
        )
    return out


@register_effect
class LeadRipple(Effect):
    """A force ripple sin, cos(2 pi q/P) (the same both ways: lead error, run-out) and a friction
    ripple sgn(v) sin, sgn(v) cos(2 pi q/P) (ball recirculation), P the lead / k for k in
    :data:`RIPPLE_HARMONICS` (the best by RSS); each pair's amplitude up to the Coulomb level."""

    name = "lead_ripple"
    title = "force or friction ripple periodic in position"
    time = TimeModel(
        "force or friction ripple periodic in position at the lead or a harmonic (lead error, ball "
        "recirculation)",
        (
            Term("rs", "force ripple, sin(2 pi q/P) coefficient", "effort", _ripple(np.sin, False)),
            Term("rc", "force ripple, cos(2 pi q/P) coefficient", "effort", _ripple(np.cos, False)),
            Term(
                "ks",
                "friction ripple, sgn(v) sin(2 pi q/P) coefficient",
                "effort",
                _ripple(np.sin, True),
            ),
            Term(
                "kc",
                "friction ripple, sgn(v) cos(2 pi q/P) coefficient",
                "effort",
                _ripple(np.cos, True),
            ),
        ),
        shape=Shape(
            "period",
            "ripple period (the lead or a harmonic)",
            "position",
            choices=lambda proc: [proc.lead_q / k for k in RIPPLE_HARMONICS],
        ),
        skip=_ripple_skip,
        implausible=_ripple_implausible,
        evidence="the force over a slow constant-speed pass at two speeds: the ripple keeps its "
        "period in millimetres",
    )
