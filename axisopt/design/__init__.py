"""Axis and design descriptions (frozen dataclasses) and the strict design-YAML reader.

A design YAML has ``axis`` (the machine's requirements, every dimensional value with its unit),
``parts`` (catalog ids or inline custom parts) and optionally ``catalogs`` (extra catalog
directories, relative to the YAML file) and ``name``.

- :mod:`.axis`: :class:`Axis` and :class:`Design`, and the defaults of the axis values no catalog
  row carries
- :mod:`.keys`: the YAML keys, one table per section (read by the readers, written out by
  ``axisopt schema``)
- :mod:`.reader`: :func:`load_design` and the section readers the problem and study files share
- :mod:`.writer`: :func:`design_to_dict` / :func:`design_to_yaml`, what ``load_design`` reads back
"""

from __future__ import annotations

from .axis import (
    BRAKE_MODES,
    BRAKE_SAFETY,
    CG_HEIGHT_SHARE,
    CHAIN_EFFICIENCY,
    COUNTERBALANCE_KINDS,
    COUPLING_INERTIA,
    COUPLING_STIFFNESS,
    GUIDE_STATIC_SAFETY,
    MAX_INERTIA_RATIO,
    MOUNTINGS,
    NUT_STATIC_SAFETY,
    ORIENTATIONS,
    PART_SLOTS,
    PRETENSION_RISE,
    RMS_TORQUE_RATIO,
    SPACING_SHARE,
    TEMPERATURE_RISE,
    TOOL_HEIGHT_SHARE,
    Axis,
    Counterbalance,
    Design,
    G,
)
from .keys import AXIS_SPEC, CATALOGS_KEY, DESCRIPTION_KEY, DESIGN_SPEC, NAME_KEY
from .partkeys import PART_SPECS, PARTS_SPEC
from .reader import (
    catalog_for,
    fitting_nuts,
    inline_part,
    load_design,
    read_axis,
    read_duty_cycle,
    read_part,
    read_parts,
    rotating_nut,
)
from .sectionkeys import DWELL_SPEC, MOVE_SPEC
from .writer import design_to_dict, design_to_yaml

__all__ = [
    "Axis",
    "Counterbalance",
    "CHAIN_EFFICIENCY",
    "COUNTERBALANCE_KINDS",
    "Design",
    "MOUNTINGS",
    "load_design",
    "read_axis",
    "read_parts",
    "G",
    # besides: the defaults, the YAML key tables, the other readers and the writer
    "BRAKE_MODES",
    "BRAKE_SAFETY",
    "CG_HEIGHT_SHARE",
    "COUPLING_INERTIA",
    "COUPLING_STIFFNESS",
    "GUIDE_STATIC_SAFETY",
    "MAX_INERTIA_RATIO",
    "NUT_STATIC_SAFETY",
    "ORIENTATIONS",
    "PART_SLOTS",
    "PRETENSION_RISE",
    "RMS_TORQUE_RATIO",
    "SPACING_SHARE",
    "TEMPERATURE_RISE",
    "TOOL_HEIGHT_SHARE",
    "AXIS_SPEC",
    "CATALOGS_KEY",
    "DESCRIPTION_KEY",
    "DESIGN_SPEC",
    "DWELL_SPEC",
    "MOVE_SPEC",
    "NAME_KEY",
    "PART_SPECS",
    "PARTS_SPEC",
    "catalog_for",
    "fitting_nuts",
    "inline_part",
    "read_duty_cycle",
    "read_part",
    "rotating_nut",
    "design_to_dict",
    "design_to_yaml",
]
