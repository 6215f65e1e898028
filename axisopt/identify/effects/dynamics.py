"""Effects on the dynamics: a moving mass that differs from the design, and a resonance the axial
model lacks (in an FRF as an extra peak; in a time record as a second mass behind a spring,
:math:`f = M\\ddot q + (m_1 m_2/k)\\, q^{(4)}` without damping and friction, reported as
:math:`f_r = \\sqrt{M/\\beta}/2\\pi`).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..fit import Param
from .base import Effect, Term, TimeModel, register_effect, replace_part

# a time record shows an extra mode only when its baseline residual spectrum peaks this far above
# its median (between 3x the motion bandwidth and the cut-off)
PEAK_RATIO = 5.0


def _mode_skip(ctx) -> str:
    """A mode needs a peak in the baseline residual's spectrum that does not follow the position (a
    ripple moves in frequency with the speed; a mode does not)."""
    freq, ratio = ctx.peak
    if ratio < PEAK_RATIO:
        return f"no residual spectral peak (at most {ratio:.1f}x the median, {freq:.0f} Hz)"
    line = ctx.steady_line()
    if line is not None:
        return (
            f"the residual's spectral peak is a steady line at {line[0]:.4g} Hz, one phase through "
            f"the run ({100 * line[1]:.0f} % of the residual): a periodic disturbance, not a "
            "resonance"
        )
    per = ctx.periodic_peak()
    if per is not None:
        u, f = ctx.position_unit
        return (
            f"the residual's spectral peak ({freq:.0f} Hz) follows the position: periodic over "
            f"{per[0] * f:.3g} {u}, {100 * per[1]:.0f} % of the residual (a ripple, not a "
            "resonance)"
        )
    return ""


def _mode_implausible(value, fc, fv) -> list:
    v = value("beta")
    return (
        [f"beta = {v:.4g} not positive (no mass-spring pair has m1 m2/k <= 0)"] if v <= 0.0 else []
    )


RESOLVED_FC = 0.8  # a resonance is resolved up to this share of the position filter's cut-off


def _mode_resolved(value, proc) -> str:
    """A resonance above 0.8x the position filter's cut-off is not resolved: there the filter bends
    the acceleration and the snap (|H|^2 below 86 %), and a term in the fourth derivative then fits
    the filter's and the sampling's own lag rather than a mode."""
    m, beta = value("M"), value("beta")
    if not (m > 0 and beta > 0):
        return ""
    fr = math.sqrt(m / beta) / (2.0 * math.pi)
    lim = RESOLVED_FC * proc.fc
    return (
        (
            f"a resonance at {fr:.3g} Hz, above {lim:.3g} Hz (0.8x the position filter's cut-off), "
            "where the record does not resolve one"
        )
        if fr > lim
        else ""
    )


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
                plausible_note="a workpiece or fixture up to the table's own mass; at most half of "
                "it missing",
            )
        ]

    def apply(self, kind, q, P, Z, plant):
        q.added_mass = q.added_mass + P["added_mass"]

    def describe(self, v, plant):
        return (
            f"{v['added_mass']:+.1f} kg moving mass against the design's {plant.moving_mass:.1f} kg"
        )

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
    signature = "extra peak in the FRF residual that does not move with x"
    time = TimeModel(
        "a second mass behind a spring (resonance)",
        # its IV instrument is the measured column itself: a rigid-body simulation has no mode
        (
            Term(
                "beta",
                "m1 m2/k of the extra mode",
                "snap",
                lambda sig, proc, shape: sig["snap"],
                simulated=False,
            ),
        ),
        skip=_mode_skip,
        implausible=_mode_implausible,
        resolved=_mode_resolved,
        evidence="a frequency response (tap test or sine sweep) of the table: a peak at the "
        "resonance",
    )

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
            {"mode_frequency": f / (2 * math.pi), "mode_stiffness": k}
            for f in np.geomspace(lo, hi, 10)[1:-1]
        ]

    def apply(self, kind, q, P, Z, plant):
        q.modes = q.modes + [
            (P["mode_stiffness"], 2.0 * math.pi * P["mode_frequency"], P["mode_damping"])
        ]

    def describe(self, v, plant):
        return (
            f"extra mode at {v['mode_frequency']:.0f} Hz (damping {v['mode_damping']:.3f}, "
            f"modal stiffness {v['mode_stiffness'] / 1e6:.0f} N/um)"
        )

    def calibrate(self, v, design):
        blocks = design.axis.guide_blocks
        m = (
            design.axis.moving_mass
            + float(design.nut["mass"])
            + blocks * float(design.guide["block_mass"])
        )
        k_n = (2 * math.pi * v["mode_frequency"]) ** 2 * m / blocks
        return (
            replace_part(design, "guide", normal_rigidity=k_n),
            f"guide normal rigidity -> {k_n / 1e6:.0f} N/um per block so the table mode sits at "
            f"{v['mode_frequency']:.0f} Hz",
        )
