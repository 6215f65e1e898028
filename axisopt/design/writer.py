"""A :class:`~axisopt.design.Design` written back as the mapping (and YAML text) a design file
holds, in vendor units: :func:`design_to_dict`, :func:`design_to_yaml`;
:func:`~axisopt.design.load_design` reads it back.
"""

from __future__ import annotations

import math
from dataclasses import fields

from ..catalog.columns import SCHEMA, SHIPPED_DIR, SLOT_TABLES
from ..units import DISPLAY_UNITS, unit_factor
from .axis import Axis, Design
from .keys import AXIS_KINDS
from .sectionkeys import TWIN_SPEC

TWIN_KINDS = {name: k.kind for name, k in TWIN_SPEC.keys.items()}


# other units a kind may be written in, where the display unit gives a long figure (3 arcsec is
# 0.000833333 deg)
OTHER_UNITS = {"angle": ("arcmin", "arcsec")}


def _q(value: float, kind: str) -> str:
    """``value`` [SI] in the kind's display unit, or in one of :data:`OTHER_UNITS` where its figure
    has fewer significant digits (then a figure of 1 or more, then the first unit)."""
    units = (DISPLAY_UNITS[kind],) + OTHER_UNITS.get(kind, ())
    figures = [(f"{value / unit_factor(u, kind):.12g}", i) for i, u in enumerate(units)]
    text, i = min(
        figures,
        key=lambda f: (len(f[0].lstrip("-0.").replace(".", "")), abs(float(f[0])) < 1, f[1]),
    )
    return f"{text} {units[i]}"


def design_to_dict(design: Design, *, inline_parts: bool = False) -> dict:
    """A design as the plain mapping a design YAML holds (vendor units).  ``load_design`` reads it
    back.

    Parts of the shipped catalogs are written as their ids unless ``inline_parts``; a part from a
    user catalog or from the YAML itself is written inline, so the file stands on its own.
    """
    a = design.axis
    axis: dict = {}
    for f in fields(Axis):
        if f.name in design.assumed:
            continue
        if f.name.startswith("reduction_") and design.reduction is not None:
            continue  # the reduction part sets them (the reader refuses both)
        v = getattr(a, f.name)
        if f.name in AXIS_KINDS:
            if v is not None:
                axis[f.name] = _q(v, AXIS_KINDS[f.name])
        elif f.name == "pretension":
            axis[f.name] = "auto" if v is None else _q(v, "force")
        elif v is None:
            continue  # a key left to its default (load_factor, bearing_static_safety)
        elif f.name == "load_factor":
            axis[f.name] = float(v)
        elif f.name == "duty_cycle":
            axis[f.name] = [_segment_dict(sg) for sg in v]
        elif f.name == "counterbalance":
            axis[f.name] = _counterbalance_dict(v)
        elif f.name == "twin_drive":
            axis[f.name] = {
                k: _q(getattr(v, k), TWIN_KINDS[k]) for k in TWIN_KINDS if getattr(v, k) is not None
            }
        else:
            axis[f.name] = v
    parts: dict = {}
    for slot, table in SLOT_TABLES:
        row = getattr(design, slot)
        if row is None:
            continue
        if not inline_parts and str(row.get("_source", "")).startswith(str(SHIPPED_DIR)):
            parts[slot] = str(row["id"])
            continue
        part = {}
        for col, kind in SCHEMA[table].items():
            v = row.get(col, math.nan) if hasattr(row, "get") else row[col]
            if kind == "str":
                part[col] = str(v)
            elif kind == "int" and not math.isfinite(float(v)):
                continue  # an optional flag left empty (the nut's rotating)
            elif kind == "int":
                part[col] = int(v)
            elif not math.isfinite(float(v)):
                continue  # an optional cell left empty
            elif kind == "dimensionless":
                part[col] = float(v)
            else:
                part[col] = _q(float(v), kind)
        parts[slot] = part
    if design.nut_preload is not None:
        parts["nut_preload"] = _q(design.nut_preload, "force")
    if design.screw_grade is not None:
        parts["screw_grade"] = design.screw_grade
    return {"name": design.name, "axis": axis, "parts": parts}


def _counterbalance_dict(cb) -> dict:
    if cb.kind == "counterweight":
        d = {"kind": cb.kind, "mass": _q(cb.mass, "mass"), "efficiency": float(cb.efficiency)}
        if cb.chain_mass:
            d["chain_mass"] = _q(cb.chain_mass, "mass")
        return d
    d = {"kind": cb.kind, "force": _q(cb.force, "force")}
    if cb.force_at_end is not None:
        d["force_at_end"] = _q(cb.force_at_end, "force")
    if cb.tolerance:
        d["tolerance"] = f"{cb.tolerance * 100:.12g} %"
    if cb.piston_mass:
        d["piston_mass"] = _q(cb.piston_mass, "mass")
    return d


def _segment_dict(sg) -> dict:
    if sg.kind == "dwell":
        d = {"dwell": f"{sg.duration:.12g} s"}
    else:
        d = {
            "move": _q(sg.distance, "length"),
            "speed": _q(sg.speed, "speed"),
            "acceleration": _q(sg.acceleration, "acceleration"),
        }
        if sg.jerk is not None:
            d["jerk"] = _q(sg.jerk, "jerk")
    if sg.force:
        d["force"] = _q(sg.force, "force")
    if sg.moving_mass is not None:
        d["moving_mass"] = _q(sg.moving_mass, "mass")
    return d


def design_to_yaml(design: Design, *, preload_note: str = "", **kw) -> str:
    """:func:`design_to_dict` as YAML text; ``preload_note`` (one line) is written as a comment
    beside the nut preload (how a saved optimum's preload was rounded,
    ``axisopt.report.partslist.order_preload``)."""
    import yaml

    text = yaml.safe_dump(design_to_dict(design, **kw), sort_keys=False, allow_unicode=True)
    note = " ".join(preload_note.split())
    if note and design.nut_preload is not None:
        line = f"  nut_preload: {_q(design.nut_preload, 'force')}\n"
        text = text.replace(line, f"{line[:-1]}  # {note}\n", 1)
    return text


__all__ = ["design_to_dict", "design_to_yaml"]
