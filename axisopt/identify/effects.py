"""Effect library: named physical extensions of the axis model, each a small declarative class.

An effect says which tests it shows in (``kinds``), its parameters (user units, bounds, plausible
range), how it changes the measurement model (``apply``: edits a :class:`~.measure.Terms` record with
CasADi-safe arithmetic) and how a calibrated design takes it (``calibrate``; ``None`` = evaluate cannot
represent it).  Register your own with :func:`register_effect`; it then competes like the built-ins.

Signatures and sizes: ``/work/shared/reference/model-discrepancy.md`` sec. 1 (numbers there).
"""

from __future__ import annotations

import math
from dataclasses import replace
from types import MappingProxyType

import numpy as np

from .. import mathx as mx
from .fit import Param

ALPHA_STEEL = 11.5e-6  # [1/K]


class Effect:
    """Base class.  Subclasses set ``name``, ``title``, ``kinds``, ``signature`` and implement
    ``params(ctx)`` and ``apply(kind, q, P, Z, plant)``."""

    name = "effect"
    title = ""
    kinds: tuple = ()
    signature = ""
    needs: tuple = ()  # (kind, column) pairs that must vary for the effect to be testable

    def applicable(self, ctx) -> bool:
        obs = [o for o in ctx.obs if o.kind in self.kinds]
        if not obs:
            return False
        if not self.needs:
            return True
        return any(o.kind == k and o.dataset.has(col, varying=True) for o in obs for k, col in self.needs)

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


_LIBRARY: dict[str, Effect] = {}


def register_effect(effect):
    """Add an effect (instance or class) to the library; returns it, so it works as a decorator."""
    inst = effect() if isinstance(effect, type) else effect
    if not isinstance(inst, Effect):
        raise TypeError("register_effect expects an Effect subclass or instance")
    _LIBRARY[inst.name] = inst
    return effect


def library() -> MappingProxyType:
    return MappingProxyType(_LIBRARY)


def _replace_part(design, slot, **values):
    part = getattr(design, slot).copy()
    for k, v in values.items():
        part[k] = v
    return replace(design, **{slot: part})


# ------------------------------------------------------------------------------ static stiffness
@register_effect
class SupportCondition(Effect):
    name = "support_condition"
    title = "declared support condition does not hold"
    kinds = ("stiffness", "frequency", "frf")
    signature = "arch in x after the screw modulus is refitted (model-discrepancy.md #2)"

    def params(self, ctx):
        kb = ctx.plant.k_bearing
        return [
            Param(
                "far_end_stiffness",
                "axial stiffness the far screw end actually carries",
                "N/um",
                "stiffness",
                0.5 * kb,
                0.0,
                100.0 * kb,
                typical=kb,
                plausible=(0.0, 1.5 * kb),
                plausible_note="between a free end (0) and the far bearing set's catalog stiffness + 50 %",
            )
        ]

    def starts(self, ctx):
        kb = ctx.plant.k_bearing
        return [{"far_end_stiffness": 0.2 * kb}, {"far_end_stiffness": 1.0 * kb}]

    def apply(self, kind, q, P, Z, plant):
        q.k_far = P["far_end_stiffness"]

    def describe(self, v, plant):
        k, kb = v["far_end_stiffness"], plant.k_bearing
        if plant.mounting == "fixed-fixed":
            return (
                "far bearing loose: it carries less than half its catalog stiffness"
                if k < 0.5 * kb
                else "far end stiffer than the declared fixed-fixed arrangement"
            )
        return (
            "floating end acts fixed (fixed-fixed behaviour)"
            if k >= 0.5 * kb
            else "floating end partly fixed (carries axial load)"
        )

    def calibrate(self, v, design):
        k, kb = v["far_end_stiffness"], float(design.bearing["axial_rigidity"])
        declared = design.axis.mounting
        new = "fixed-fixed" if k >= 0.5 * kb else ("fixed-free" if declared == "fixed-fixed" else declared)
        if new == declared:
            return None
        return replace(design, axis=replace(design.axis, mounting=new)), f"mounting {declared} -> {new}"


@register_effect
class HertzContact(Effect):
    name = "hertz_contact"
    title = "load-dependent nut contact stiffness (Hertz, preload lift-off at 2.83 x preload)"
    kinds = ("stiffness",)
    signature = "compliance vs |F| flat, knee near 2.83 Fa0, then F^(-1/3) (model-discrepancy.md #3)"

    def params(self, ctx):
        fa = ctx.plant.preload
        return [
            Param(
                "nut_preload",
                "effective nut preload (lift-off at 2.83 x this)",
                "N",
                "force",
                fa,
                0.02 * fa,
                50.0 * fa,
                typical=fa,
                plausible=(0.2 * fa, 1.5 * fa),
                plausible_note="a worn nut keeps 20 % of its preload or more; 50 % above the design is not "
                "assembled",
            )
        ]

    def starts(self, ctx):
        fa = ctx.plant.preload
        return [{"nut_preload": 0.4 * fa}, {"nut_preload": 2.5 * fa}]

    def apply(self, kind, q, P, Z, plant):
        q.hertz = True
        q.preload = P["nut_preload"]

    def describe(self, v, plant):
        return (
            f"nut stiffness falls with load; lift-off at {2**1.5 * v['nut_preload']:.0f} N "
            f"(preload {v['nut_preload']:.0f} N, design {plant.preload:.0f} N)"
        )

    def calibrate(self, v, design):
        lo, hi = float(design.nut["preload_min"]), float(design.nut["preload_max"])
        pre = min(max(v["nut_preload"], lo), hi)
        how = f"nut preload {design.preload:.0f} -> {pre:.0f} N"
        if pre != v["nut_preload"]:
            how += f" (clamped to the nut's range {lo:.0f}..{hi:.0f} N)"
        return replace(design, nut_preload=pre), how


@register_effect
class Backlash(Effect):
    name = "backlash"
    title = "backlash: lost motion at load reversal, constant over the stroke"
    kinds = ("stiffness",)
    signature = "step of +-b/2 with the load sign, flat in x (model-discrepancy.md #4)"

    def applicable(self, ctx):
        return any(o.kind == "stiffness" and np.ptp(np.sign(o.feature("force"))) > 0 for o in ctx.obs)

    def params(self, ctx):
        return [
            Param(
                "backlash",
                "lost motion at reversal (clearance)",
                "um",
                "length",
                2e-6,
                0.0,
                1e-3,
                typical=5e-6,
                plausible=(0.0, 30e-6),
                plausible_note="worn/unpreloaded nut 5-20 um",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.offset = q.offset + 0.5 * P["backlash"] * mx.sign(Z["force"])

    def describe(self, v, plant):
        return f"lost motion {v['backlash'] * 1e6:.1f} um at each load reversal, same at every position"


@register_effect
class FrictionHysteresis(Effect):
    name = "friction_hysteresis"
    title = "elastic lost motion from friction (grows with compliance along the stroke)"
    kinds = ("stiffness",)
    signature = "reversal error 2 F_f c(x), growing with x (model-discrepancy.md #5)"

    def applicable(self, ctx):
        return any(o.kind == "stiffness" and np.ptp(o.feature("direction")) > 0 for o in ctx.obs)

    def params(self, ctx):
        f0 = max(ctx.plant.coulomb, 20.0)
        return [
            Param(
                "hysteresis_friction",
                "friction force that the spring chain must overcome",
                "N",
                "force",
                0.5 * f0,
                0.0,
                1e5,
                typical=f0,
                plausible=(0.0, 5.0 * f0),
                plausible_note="at most five times the axis's friction force (guides, nut, bearings)",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.hysteresis = P["hysteresis_friction"]

    def describe(self, v, plant):
        return f"friction of {v['hysteresis_friction']:.0f} N winds up the drive: reversal error 2 F c(x)"


@register_effect
class ThermalDrift(Effect):
    name = "thermal_drift"
    title = "thermal drift of the screw (proportional to screw length to the nut)"
    kinds = ("stiffness",)
    signature = "residual proportional to x dT, growing over the test (model-discrepancy.md #10)"
    needs = (("stiffness", "temperature"), ("stiffness", "time"))

    @staticmethod
    def _by_temperature(ctx):
        return any(o.kind == "stiffness" and o.dataset.has("temperature", varying=True) for o in ctx.obs)

    def params(self, ctx):
        if self._by_temperature(ctx):
            return [
                Param(
                    "expansion_coefficient",
                    "thermal expansion of the screw",
                    "um/m/K",
                    "thermal_expansion",
                    ALPHA_STEEL,
                    -2e-4,
                    2e-4,
                    typical=1e-5,
                    plausible=(10e-6, 13e-6),
                    plausible_note="steel 11.5e-6 /K",
                )
            ]
        return [
            Param(
                "drift_rate",
                "growth of the screw per metre and hour",
                "um/m/h",
                "frequency",
                1e-6 / 3600.0,
                -1e-3 / 3600.0,
                1e-3 / 3600.0,
                typical=5e-6 / 3600.0,
                plausible=(-50e-6 / 3600.0, 50e-6 / 3600.0),
                plausible_note="a screw warming or cooling by up to about 4 K per hour",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        if "expansion_coefficient" in P:
            q.offset = q.offset + P["expansion_coefficient"] * Z["dtemp"] * Z["x"]
        else:
            q.offset = q.offset + P["drift_rate"] * Z["time"] * Z["x"]

    def describe(self, v, plant):
        if "expansion_coefficient" in v:
            return f"screw grows {v['expansion_coefficient'] * 1e6:.1f} um per metre and kelvin"
        return f"screw grows {v['drift_rate'] * 3.6e9:.1f} um per metre and hour"


@register_effect
class ComplianceOffset(Effect):
    name = "compliance_offset"
    title = "a component softer than its catalog value (constant compliance)"
    kinds = ("stiffness", "frequency", "frf")
    signature = "constant compliance offset, no x-dependence (model-discrepancy.md #11)"

    def params(self, ctx):
        c = 1.0 / ctx.plant.k_bearing + 1.0 / ctx.plant.k_nut
        return [
            Param(
                "extra_compliance",
                "extra series compliance (bearings, nut, housing or coupling)",
                "um/N",
                "compliance",
                0.1 * c,
                -0.9 * c,
                100.0 * c,
                typical=c,
                plausible=(-0.5 * c, 3.0 * c),
                plausible_note="a component up to 4x softer than its catalog value, or the chain up to 2x stiffer",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.c_extra = q.c_extra + P["extra_compliance"]

    def describe(self, v, plant):
        c = v["extra_compliance"]
        if c <= 0:
            return f"bearings and nut stiffer than catalog ({c * 1e6:.4f} um/N less compliance)"
        return (
            f"extra compliance {c * 1e6:.4f} um/N, a {1e-6 / c:.0f} N/um spring in series "
            f"(soft support bearing, nut, housing or coupling)"
        )

    def calibrate(self, v, design):
        k_b = float(design.bearing["axial_rigidity"])
        sets = 2.0 if design.axis.mounting == "fixed-fixed" else 1.0
        c_new = 1.0 / k_b + sets * v["extra_compliance"]
        if c_new <= 0:
            return None
        return (
            _replace_part(design, "bearing", axial_rigidity=1.0 / c_new),
            f"bearing axial rigidity {k_b / 1e6:.0f} -> {1e-6 / c_new:.0f} N/um "
            "(carries the extra compliance)",
        )


@register_effect
class PreloadLoss(Effect):
    name = "preload_loss"
    title = "nut preload loss: friction or stiffness trending down with cycle count"
    kinds = ("stiffness", "friction")
    signature = "residual trending with cycle, not with x, F or v (model-discrepancy.md #13)"
    needs = (("stiffness", "cycle"), ("friction", "cycle"))

    def params(self, ctx):
        cmax = max(
            float(np.max(o.dataset.columns["cycle"]))
            for o in ctx.obs
            if o.kind in self.kinds and "cycle" in o.dataset.columns
        )
        cmax = max(cmax, 1.0)
        return [
            Param(
                "preload_loss_rate",
                "preload lost per cycle",
                "percent",
                "dimensionless",
                0.05 / cmax,
                -0.5 / cmax,
                0.95 / cmax,
                typical=0.1 / cmax,
                plausible=(0.0, 0.8 / cmax),
                plausible_note="preload only falls with running, and not to nothing within one test",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        factor = 1.0 - P["preload_loss_rate"] * Z["cycle"]
        if kind == "friction":
            q.coulomb_factor = q.coulomb_factor * factor
        else:
            q.preload_factor = q.preload_factor * factor

    def describe(self, v, plant):
        return f"preload falls {v['preload_loss_rate'] * 100:.3g} % per cycle"


# ------------------------------------------------------------------------------ dynamics
@register_effect
class AddedMass(Effect):
    name = "added_mass"
    title = "moving mass differs from the design (frequencies off by a constant mass)"
    kinds = ("frequency", "frf")
    signature = "frequency ratio constant along the stroke"

    def params(self, ctx):
        m = ctx.plant.moving_mass
        return [
            Param(
                "added_mass",
                "mass moving with the table beyond the design's",
                "kg",
                "mass",
                0.1 * m,
                -0.8 * m,
                10.0 * m,
                typical=0.2 * m,
                plausible=(-0.5 * m, 1.0 * m),
                plausible_note="a workpiece or fixture up to the table's own mass; at most half of it missing",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.added_mass = q.added_mass + P["added_mass"]

    def describe(self, v, plant):
        return f"{v['added_mass']:+.1f} kg moving mass against the design's {plant.moving_mass:.1f} kg"

    def calibrate(self, v, design):
        m = design.axis.moving_mass + v["added_mass"]
        if m <= 0:
            return None
        return (
            replace(design, axis=replace(design.axis, moving_mass=m)),
            f"moving mass {design.axis.moving_mass:.1f} -> {m:.1f} kg",
        )


@register_effect
class ExtraMode(Effect):
    name = "extra_mode"
    title = "a resonance the axial model lacks (e.g. table pitch on the guides)"
    kinds = ("frf",)
    signature = "extra peak in the FRF residual that does not move with x (model-discrepancy.md #12)"

    def _peak(self, ctx):
        best = None
        for o, r in zip(ctx.obs, ctx.resid):
            if o.kind != "frf":
                continue
            n = o.n // 2
            om = o.Z[1, :n]
            mag = np.hypot(r[:n], r[n:])
            i = int(np.argmax(mag))
            lo, hi = float(om.min()), float(om.max())
            if best is None or mag[i] > best[1]:
                best = (float(om[i]), float(mag[i]), lo, hi)
        return best

    def params(self, ctx):
        wn, mag, lo, hi = self._peak(ctx)
        k = 1.0 / (2.0 * 0.03 * max(mag, 1e-12))
        return [
            Param(
                "mode_frequency",
                "natural frequency of the extra mode",
                "Hz",
                "frequency",
                wn / (2 * math.pi),
                lo / (2 * math.pi),
                hi / (2 * math.pi),
                typical=wn / (2 * math.pi),
            ),
            Param(
                "mode_damping",
                "damping ratio of the extra mode",
                "-",
                "dimensionless",
                0.03,
                1e-3,
                0.5,
                typical=0.03,
                plausible=(0.002, 0.2),
                plausible_note="structural modes 0.2-20 %",
            ),
            Param(
                "mode_stiffness",
                "modal stiffness of the extra mode",
                "N/um",
                "stiffness",
                k,
                1e-3 * k,
                1e4 * k,
                typical=k,
            ),
        ]

    def starts(self, ctx):
        _, mag, lo, hi = self._peak(ctx)
        k = 1.0 / (2.0 * 0.03 * max(mag, 1e-12))
        return [
            {"mode_frequency": f / (2 * math.pi), "mode_stiffness": k} for f in np.geomspace(lo, hi, 10)[1:-1]
        ]

    def apply(self, kind, q, P, Z, plant):
        q.modes = q.modes + [(P["mode_stiffness"], 2.0 * math.pi * P["mode_frequency"], P["mode_damping"])]

    def describe(self, v, plant):
        return (
            f"extra mode at {v['mode_frequency']:.0f} Hz (damping {v['mode_damping']:.3f}, "
            f"modal stiffness {v['mode_stiffness'] / 1e6:.0f} N/um)"
        )

    def calibrate(self, v, design):
        blocks = design.axis.guide_blocks
        m = design.axis.moving_mass + float(design.nut["mass"]) + blocks * float(design.guide["block_mass"])
        k_n = (2 * math.pi * v["mode_frequency"]) ** 2 * m / blocks
        return (
            _replace_part(design, "guide", normal_rigidity=k_n),
            f"guide normal rigidity -> {k_n / 1e6:.0f} N/um per block so the table mode sits at "
            f"{v['mode_frequency']:.0f} Hz",
        )


# ------------------------------------------------------------------------------ friction
@register_effect
class Stribeck(Effect):
    name = "stribeck"
    title = "Stribeck friction rise at low speed"
    kinds = ("friction",)
    signature = "positive bump at |v| below a few v_s (model-discrepancy.md #6)"

    def _speeds(self, ctx):
        return np.concatenate([np.abs(o.feature("velocity")) for o in ctx.obs if o.kind == "friction"])

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
    """The largest |velocity| of the friction data [m/s]: the scale of the speed-dependent friction effects."""
    return max(float(np.max(np.abs(o.feature("velocity")))) for o in ctx.obs if o.kind == "friction")


@register_effect
class Viscous(Effect):
    name = "viscous"
    title = "viscous (speed-proportional) friction differs from catalog"
    kinds = ("friction",)
    signature = "residual linear and odd in v (model-discrepancy.md #7)"

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
                plausible_note="viscous force at the top test speed up to 20x the axis's Coulomb friction",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.viscous = P["viscous_coefficient"]

    def describe(self, v, plant):
        return f"viscous friction {v['viscous_coefficient']:.0f} N.s/m (design {plant.viscous:.0f} N.s/m)"

    def calibrate(self, v, design):
        blocks = design.axis.guide_blocks
        return (
            _replace_part(design, "guide", friction_viscous=v["viscous_coefficient"] / blocks),
            f"guide viscous friction -> {v['viscous_coefficient'] / blocks:.1f} N.s/m per block",
        )


@register_effect
class LoadDependentFriction(Effect):
    name = "load_dependent_friction"
    title = "guide friction growing with block load (seed Table 9)"
    kinds = ("friction",)
    signature = "residual proportional to sgn(v) N (model-discrepancy.md #9)"
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
        return f"guide friction grows with load: mu = {v['friction_coefficient']:.4f} (design {plant.mu:.4f})"

    def calibrate(self, v, design):
        return (
            _replace_part(design, "guide", friction_coefficient=v["friction_coefficient"]),
            f"guide friction coefficient -> {v['friction_coefficient']:.4f}",
        )


@register_effect
class DirectionAsymmetry(Effect):
    name = "direction_asymmetry"
    title = "friction differs between the two directions of travel"
    kinds = ("friction",)
    signature = "constant offset between + and - travel"

    def applicable(self, ctx):
        return any(o.kind == "friction" and np.ptp(np.sign(o.feature("velocity"))) > 0 for o in ctx.obs)

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


@register_effect
class QuadraticDrag(Effect):
    name = "quadratic_drag"
    title = "drag growing with the square of speed"
    kinds = ("friction",)
    signature = "residual odd in v and growing faster than v: c v|v| (seals, lubricant churning)"

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
                plausible_note="a positive drag, at the top test speed up to 20x the axis's Coulomb friction",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.drag = P["drag_coefficient"]

    def describe(self, v, plant):
        return (f"drag grows with v|v|: c = {v['drag_coefficient']:.4g} N.s^2/m^2 (seals, lubricant churning); "
                "evaluate has no such term")


BUILTIN = tuple(_LIBRARY)
