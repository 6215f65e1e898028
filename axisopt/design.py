"""Axis and design descriptions (frozen dataclasses) and the strict design-YAML reader.

A design YAML has ``axis`` (the machine's requirements, every dimensional value with its unit),
``parts`` (catalog ids or inline custom parts) and optionally ``catalogs`` (extra catalog
directories, relative to the YAML file) and ``name``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from pathlib import Path

from .catalog import OPTIONAL_COLUMNS, SCHEMA, Catalog, default_catalog
from .units import unit_factor
from .yamlio import Section, read_yaml

MOUNTINGS = ("fixed-free", "fixed-supported", "fixed-fixed")

# Defaults of the axis values no catalog row carries, with their sources (README "What the model assumes").
# Bearing housing and nut bracket: no vendor publishes a value (THK A-707: "set the rigidity as high as
# possible"; THK and NSK rigidities exclude them), so they are rigid unless the YAML gives them.
# Coupling: RINGFEDER GWB AKN size 60 metal-bellows coupling (Tech Paper EN 08.2019): 75e3 N.m/rad,
# 0.29e-3 kg.m^2, 75 N.m, a mid-size feed-drive coupling (our pick of size).
# Temperature rise: THK A-715 sets the negative target travel for a 2-5 degC rise; 3 K is used.
COUPLING_STIFFNESS = 75e3
COUPLING_INERTIA = 0.29e-3
TEMPERATURE_RISE = 3.0
ORIENTATIONS = ("horizontal", "vertical")
G = 9.80665


@dataclass(frozen=True)
class Axis:
    """What the machine asks of the axis.  SI units."""

    stroke: float
    moving_mass: float  # table + workpiece, without nut and guide blocks [kg]
    mounting: str
    max_speed: float  # rapid traverse [m/s]
    axial_load: float  # largest external axial (cutting) load [N]
    start_offset: float = 0.13  # fixed bearing to nut at stroke start, l0 [m]
    end_margin: float = 0.15  # nut at stroke end to the far bearing [m]
    mean_speed: float | None = None  # for life; default half of max_speed [m/s]
    mean_axial_load: float | None = None  # for life; default a third of axial_load [N]
    acceleration: float = 0.0  # [m/s^2]
    required_life: float = 20000 * 3600.0  # [s]
    load_factor: float = 1.2  # fw
    guide_blocks: int = 4
    rails: int = 2
    table_length: float = 0.5  # rail length = stroke + table_length [m]
    normal_load: float = 0.0  # external load on the guide blocks besides gravity [N]
    lubricant_viscosity: float = 32e-6  # at working temperature [m^2/s]
    motor_inertia: float = 1.0e-3  # motor rotor [kg m^2]
    # values outside the catalogs, YAML overridable; the defaults' sources are above the class
    bearing_housing_stiffness: float | None = None  # one support-bearing housing [N/m]; None: rigid
    nut_bracket_stiffness: float | None = None  # nut bracket / table connection [N/m]; None: rigid
    coupling_stiffness: float = COUPLING_STIFFNESS  # torsional [N m/rad]
    coupling_inertia: float = COUPLING_INERTIA  # [kg m^2]
    temperature_rise: float = TEMPERATURE_RISE  # screw temperature rise in operation [K]
    pretension: float | None = None  # fixed-fixed screw pretension [N]; None: absorbs temperature_rise
    orientation: str = "horizontal"
    positions: int = 41  # nut positions evaluated over the stroke

    @property
    def span(self) -> float:
        """Bearing-to-bearing length of the screw [m]."""
        return self.start_offset + self.stroke + self.end_margin

    @property
    def mean_speed_eff(self) -> float:
        return self.mean_speed if self.mean_speed is not None else 0.5 * self.max_speed

    @property
    def mean_axial_load_eff(self) -> float:
        return self.mean_axial_load if self.mean_axial_load is not None else self.axial_load / 3.0


@dataclass(frozen=True)
class Design:
    """An axis with one chosen part per slot.  Parts are catalog rows (pandas Series) in SI."""

    axis: Axis
    screw: object
    nut: object
    bearing: object
    guide: object
    nut_preload: float | None = None  # None: the catalog's quoted preload
    name: str = "design"
    source: str = ""
    assumed: tuple = field(default=())  # axis keys left at their defaults, for reports

    @property
    def preload(self) -> float:
        if self.nut_preload is not None:
            return self.nut_preload
        return float(self.nut["stiffness_preload"]) if self.nut["type"] == "double" \
            else float(self.nut["preload_min"])

    def part_ids(self) -> dict:
        return {k: str(getattr(self, k)["id"]) for k in ("screw", "nut", "bearing", "guide")}


_AXIS_KINDS = {
    "stroke": "length", "moving_mass": "mass", "max_speed": "speed", "axial_load": "force",
    "start_offset": "length", "end_margin": "length", "mean_speed": "speed", "mean_axial_load": "force",
    "acceleration": "acceleration", "required_life": "time", "table_length": "length",
    "normal_load": "force", "lubricant_viscosity": "kinematic_viscosity", "motor_inertia": "inertia",
    "bearing_housing_stiffness": "stiffness", "nut_bracket_stiffness": "stiffness",
    "coupling_stiffness": "torsional_stiffness", "coupling_inertia": "inertia",
    "temperature_rise": "temperature_difference",
}
_AXIS_REQUIRED = ("stroke", "moving_mass", "mounting", "max_speed", "axial_load")
# Upper bounds where a value beyond them leaves the model's range: a screw 100 K above ambient is not in
# operation, and the linear thermal model (constant alpha, elastic bearing sets) no longer holds.
_AXIS_MAXIMUM = {"temperature_rise": (100.0, "100 K")}
_NON_NEGATIVE = ("end_margin", "mean_axial_load", "acceleration", "normal_load", "axial_load", "temperature_rise")


def read_axis(sec: Section) -> tuple[Axis, tuple]:
    """Read an ``axis:`` section.  Returns the Axis and the names of keys left at their defaults."""
    kw = {}
    for name, kind in _AXIS_KINDS.items():
        v = sec.quantity(name, kind, required=name in _AXIS_REQUIRED,
                         positive=name not in _NON_NEGATIVE, non_negative=name in _NON_NEGATIVE,
                         maximum=_AXIS_MAXIMUM.get(name))
        if v is not None:
            kw[name] = v
    kw["mounting"] = sec.choice("mounting", MOUNTINGS, required=True)
    if sec.has("pretension"):
        node = sec.raw("pretension")
        if node.value != "auto":
            kw["pretension"] = sec.quantity("pretension", "force", non_negative=True)
    kw["orientation"] = sec.choice("orientation", ORIENTATIONS, "horizontal")
    for name in ("guide_blocks", "rails", "positions"):
        v = sec.number(name, integer=True, minimum=1 if name != "positions" else 3)
        if v is not None:
            kw[name] = int(v)
    v = sec.number("load_factor", minimum=1.0)
    if v is not None:
        kw["load_factor"] = float(v)
    sec.done()
    assumed = tuple(f.name for f in fields(Axis) if f.name not in kw)
    return Axis(**kw), assumed


def read_part(sec: Section, key: str, table: str, catalog: Catalog):
    """A part slot: a catalog id, or an inline mapping with the catalog's columns (values with units)."""
    node = sec.raw(key, required=True)
    if isinstance(node.value, (str, int)) and not isinstance(node.value, bool):
        return catalog.part(table, str(node.value), source=sec.source, key=sec.where(key))
    if not isinstance(node.value, dict):
        raise sec.error(key, f"expected a catalog id or a mapping of {table[:-1]} properties")
    return inline_part(Section(node, sec.source, sec.key_path(key)), table)


def inline_part(sec: Section, table: str):
    import pandas as pd

    rec = {}
    for col, kind in SCHEMA[table].items():
        if kind == "str":
            rec[col] = sec.string(col, "custom" if col in ("vendor", "series") else None,
                                  required=col not in ("vendor", "series"))
        elif kind == "int":
            rec[col] = int(sec.number(col, required=True, integer=True, minimum=1))
        elif kind == "dimensionless":
            rec[col] = float(sec.number(col, required=True, minimum=0))
        else:
            optional = col in OPTIONAL_COLUMNS.get(table, ())
            v = sec.quantity(col, kind, required=not optional, non_negative=True)
            rec[col] = math.nan if v is None else v
    sec.done()
    rec["_source"] = f"{sec.source}:{sec.node.line}"
    return pd.Series(rec, name=rec["id"])


def read_parts(sec: Section, catalog: Catalog) -> dict:
    parts = {
        "screw": read_part(sec, "screw", "screws", catalog),
        "nut": read_part(sec, "nut", "nuts", catalog),
        "bearing": read_part(sec, "bearing", "bearings", catalog),
        "guide": read_part(sec, "guide", "guides", catalog),
    }
    pre = sec.quantity("nut_preload", "force", non_negative=True)
    sec.done()
    nut, screw = parts["nut"], parts["screw"]
    if nut["screw_id"] != screw["id"]:
        raise sec.error("nut", f"nut '{nut['id']}' fits screw '{nut['screw_id']}', not '{screw['id']}'")
    if pre is not None and not (nut["preload_min"] - 1e-9 <= pre <= nut["preload_max"] + 1e-9):
        raise sec.error("nut_preload", f"{pre:.0f} N is outside nut '{nut['id']}' range "
                        f"{nut['preload_min']:.0f}..{nut['preload_max']:.0f} N")
    parts["nut_preload"] = pre
    return parts


def catalog_for(root: Section, base_dir: Path) -> Catalog:
    dirs = root.string_list("catalogs", [])
    resolved = []
    for d in dirs:
        p = (base_dir / d).resolve()
        if not p.is_dir():
            raise root.error("catalogs", f"catalog directory '{d}' not found")
        resolved.append(p)
    return default_catalog(tuple(resolved))


def load_design(path) -> Design:
    """Read a design YAML file into a :class:`Design`; every error names the file and key."""
    path = Path(path)
    root = Section(read_yaml(path), str(path))
    catalog = catalog_for(root, path.parent)
    name = root.string("name", path.stem)
    root.string("description")
    axis, assumed = read_axis(root.section("axis", required=True))
    parts = read_parts(root.section("parts", required=True), catalog)
    root.done()
    return Design(axis=axis, name=name, source=str(path), assumed=assumed, **parts)


__all__ = ["Axis", "Design", "MOUNTINGS", "load_design", "read_axis", "read_parts", "G"]


# Units used when a design is written back to YAML (vendor units, as users write them).
_OUT_UNITS = {
    "length": "mm", "mass": "kg", "time": "h", "force": "N", "stiffness": "N/um", "speed": "m/min",
    "acceleration": "m/s^2", "angle": "deg", "mass_per_length": "kg/m", "dn": "mm.rpm",
    "money_per_length": "EUR/m", "money": "EUR", "kinematic_viscosity": "mm^2/s", "inertia": "kg.m^2",
    "angular_speed": "rpm", "damping": "N.s/m", "torque": "N.m", "torsional_stiffness": "N.m/rad",
    "temperature_difference": "K",
}


def _q(value: float, kind: str) -> str:
    unit = _OUT_UNITS[kind]
    return f"{value / unit_factor(unit, kind):.12g} {unit}"


def design_to_dict(design: Design, *, inline_parts: bool = False) -> dict:
    """A design as the plain mapping a design YAML holds (vendor units).  ``load_design`` reads it back.

    Catalog parts are written as their ids unless ``inline_parts`` (or the part came from the YAML).
    """
    a = design.axis
    axis: dict = {}
    for f in fields(Axis):
        if f.name in design.assumed:
            continue
        v = getattr(a, f.name)
        if f.name in _AXIS_KINDS:
            if v is not None:
                axis[f.name] = _q(v, _AXIS_KINDS[f.name])
        elif f.name == "pretension":
            axis[f.name] = "auto" if v is None else _q(v, "force")
        elif f.name == "load_factor":
            axis[f.name] = float(v)
        else:
            axis[f.name] = v
    parts: dict = {}
    for slot, table in (("screw", "screws"), ("nut", "nuts"), ("bearing", "bearings"), ("guide", "guides")):
        row = getattr(design, slot)
        if not inline_parts and "catalogs/" in str(row.get("_source", "catalogs/")):
            parts[slot] = str(row["id"])
            continue
        part = {}
        for col, kind in SCHEMA[table].items():
            v = row[col]
            if kind == "str":
                part[col] = str(v)
            elif kind == "int":
                part[col] = int(v)
            elif kind == "dimensionless":
                part[col] = float(v)
            elif math.isfinite(float(v)):
                part[col] = _q(float(v), kind)
        parts[slot] = part
    if design.nut_preload is not None:
        parts["nut_preload"] = _q(design.nut_preload, "force")
    return {"name": design.name, "axis": axis, "parts": parts}


def design_to_yaml(design: Design, **kw) -> str:
    import yaml

    return yaml.safe_dump(design_to_dict(design, **kw), sort_keys=False, allow_unicode=True)
