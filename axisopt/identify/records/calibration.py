"""A time-record diagnosis (:class:`.idim.TimeDiagnosis`) as a calibration file, in the layout of
:mod:`.calibration` (which reads it and applies it for ``axisopt evaluate``): the final joint fit's
Coulomb friction as the baseline (force records: it is the table's) and every accepted effect with
its fitted terms, its searched shape values and its derived quantities, each with a unit of its
kind.  A value whose unit kind has no quantity kind in :data:`axisopt.units.KINDS` (the m1 m2/k of
an extra mode) is left out; the effects evaluate cannot represent are listed as not applied when the
file is read.
"""

from __future__ import annotations

import math

from ..calibration import FORMAT, calibrate_design, check_calibration_path, write_calibration
from .regression import shape_params, term

# unit kind of a time-record term -> (quantity kind, unit, factor from SI), per record quantity
KIND_UNITS = {
    "force": {
        "effort": ("force", "N", 1.0),
        "mass": ("mass", "kg", 1.0),
        "damping": ("damping", "N.s/m", 1.0),
        "drag2": ("mass_per_length", "kg/m", 1.0),
        "frequency": ("frequency", "Hz", 1.0),
        "time": ("time", "s", 1.0),
        "position": ("length", "mm", 1e3),
        "speed": ("speed", "mm/s", 1e3),
    },
    "torque": {
        "effort": ("torque", "N.m", 1.0),
        "mass": ("inertia", "kg.m^2", 1.0),
        "frequency": ("frequency", "Hz", 1.0),
        "time": ("time", "s", 1.0),
        "position": ("angle", "rad", 1.0),
        "speed": ("angular_speed", "rad/s", 1.0),
    },
}


def _entry(value: float, sigma: float, kind_unit) -> dict:
    kind, unit, f = kind_unit
    d = {"value": f"{value * f:.6g} {unit}", "kind": kind}
    if math.isfinite(sigma):
        d["sigma"] = f"{sigma * f:.3g} {unit}"
    return d


def time_calibration_dict(diag, design=None, sources=()) -> dict:
    """The calibration of a time-record diagnosis as a plain dict (YAML-ready); with ``design``,
    what evaluate applies and what it cannot represent."""
    units = KIND_UNITS[diag.quantity]
    est = diag.final
    std = dict(zip(est.terms, est.std))
    base = {}
    if diag.quantity == "force" and "Fc" in est.terms:
        base["coulomb_friction"] = _entry(est.value("Fc"), std["Fc"], units["effort"])
    shapes = shape_params()
    effects = []
    for c in diag.accepted:
        eff, params = c.effect, {}
        for t in eff.terms:
            if term(t).unit in units:
                params[t] = _entry(est.value(t), std[t], units[term(t).unit])
        names = [eff.shape.name, *(a[0] for a in eff.shape.also)] if eff.shape is not None else []
        for nm in names:
            if nm in est.shape and shapes[nm][1] in units:
                params[nm] = _entry(est.shape[nm], float("nan"), units[shapes[nm][1]])
        for nm, _label, kind, fn in eff.derived:
            if kind in units:
                params[nm] = _entry(fn(est.value), float("nan"), units[kind])
        if params:
            effects.append({"name": eff.name, "parameters": params})
    out = {
        "axisopt_calibration": FORMAT,
        "design": diag.design.get("name"),
        "data": [str(s) for s in sources],
        "verdict": ", ".join(diag.verdict) or "none",
        "baseline": base,
        "effects": effects,
    }
    if design is not None:
        _, applied, skipped = calibrate_design(design, out)
        out["applied"], out["not_applied"] = applied, skipped
    return out


def save_time_calibration(diag, path, design=None, sources=()) -> dict:
    """Save a time-record diagnosis as a calibration YAML (never over its data or design file)."""
    check_calibration_path(path, design, sources)
    return write_calibration(time_calibration_dict(diag, design, sources), path)
