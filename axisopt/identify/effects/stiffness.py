"""Effects on static stiffness (and frequency, FRF) tests: how the screw is supported, the nut's
contact, lost motion, friction windup, thermal growth, a soft component and preload loss.

Signatures (what each leaves in the residual) are in each class's ``signature``; the mechanics are
those of :mod:`..measure` (compliance chain 1/k_B + x/EA, double-nut Hertz contact with lift-off at
2^(3/2) times the preload).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ... import mathx as mx
from ..fit import Param
from .base import Effect, register_effect, replace_part

ALPHA_STEEL = 11.5e-6  # [1/K]


@register_effect
class SupportCondition(Effect):
    name = "support_condition"
    title = "declared support condition does not hold"
    kinds = ("stiffness", "frequency", "frf")
    signature = "arch in x after the screw modulus is refitted"

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
                plausible_note="between a free end (0) and the far bearing set's catalog stiffness "
                "+ 50 %",
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
        new = (
            "fixed-fixed"
            if k >= 0.5 * kb
            else ("fixed-free" if declared == "fixed-fixed" else declared)
        )
        if new == declared:
            return None
        return replace(
            design, axis=replace(design.axis, mounting=new)
        ), f"mounting {declared} -> {new}"


@register_effect
class HertzContact(Effect):
    name = "hertz_contact"
    title = "load-dependent nut contact stiffness (Hertz, preload lift-off at 2.83 x preload)"
    kinds = ("stiffness",)
    signature = "compliance vs |F| flat, knee near 2.83 Fa0, then F^(-1/3)"

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
                plausible_note="a worn nut keeps 20 % of its preload or more; 50 % above the "
                "design is not assembled",
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
    signature = "step of +-b/2 with the load sign, flat in x"

    def applicable(self, ctx):
        return any(
            o.kind == "stiffness" and np.ptp(np.sign(o.feature("force"))) > 0 for o in ctx.obs
        )

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
        return (
            f"lost motion {v['backlash'] * 1e6:.1f} um at each load reversal, same at every "
            "position"
        )


@register_effect
class FrictionHysteresis(Effect):
    name = "friction_hysteresis"
    title = "elastic lost motion from friction (grows with compliance along the stroke)"
    kinds = ("stiffness",)
    signature = "reversal error 2 F_f c(x), growing with x"

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
                plausible_note="at most five times the axis's friction force (guides, nut, "
                "bearings)",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.hysteresis = P["hysteresis_friction"]

    def describe(self, v, plant):
        return (
            f"friction of {v['hysteresis_friction']:.0f} N winds up the drive: reversal error 2 F "
            "c(x)"
        )


@register_effect
class ThermalDrift(Effect):
    name = "thermal_drift"
    title = "thermal drift of the screw (proportional to screw length to the nut)"
    kinds = ("stiffness",)
    signature = "residual proportional to x dT, growing over the test"
    needs = (("stiffness", "temperature"), ("stiffness", "time"))

    @staticmethod
    def _by_temperature(ctx):
        return any(
            o.kind == "stiffness" and o.dataset.has("temperature", varying=True) for o in ctx.obs
        )

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
    signature = "constant compliance offset, no x-dependence"

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
                plausible_note="a component up to 4x softer than its catalog value, or the chain "
                "up to 2x stiffer",
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
            replace_part(design, "bearing", axial_rigidity=1.0 / c_new),
            f"bearing axial rigidity {k_b / 1e6:.0f} -> {1e-6 / c_new:.0f} N/um "
            "(carries the extra compliance)",
        )


@register_effect
class PreloadLoss(Effect):
    name = "preload_loss"
    title = "nut preload loss: friction or stiffness trending down with cycle count"
    kinds = ("stiffness", "friction")
    signature = "residual trending with cycle, not with x, F or v"
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
                plausible_note="preload only falls with running, and not to nothing within one "
                "test",
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
