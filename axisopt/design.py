"""Axis and design descriptions (frozen dataclasses) and the strict design-YAML reader.

A design YAML has ``axis`` (the machine's requirements, every dimensional value with its unit),
``parts`` (catalog ids or inline custom parts) and optionally ``catalogs`` (extra catalog
directories, relative to the YAML file) and ``name``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from functools import cached_property
from pathlib import Path

from .catalog import OPTIONAL_COLUMNS, SCHEMA, Catalog, default_catalog, row_problem
from .errors import InputError
from .physics import motion
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
# Drive defaults.  Inertia ratio: THK A-720 eq. 49 asks J_M >= J / C with C "normally between 3 to 10" (its
# transfer examples use 10); 5, the tighter half of that range, is our default for machine-tool axes.  Brake
# safety: no vendor figure was retrieved; 2 x the gravity torque is our assumption, set axis.brake_safety.
MAX_INERTIA_RATIO = 5.0
BRAKE_SAFETY = 2.0
BRAKE_MODES = ("auto", "yes", "no")


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
    # drive: motion and duty, reduction, drive limits
    jerk: float | None = None  # [m/s^3]; None: trapezoidal moves
    duty_cycle: tuple = ()  # motion.Segment; empty: the rapid move over the stroke and back
    reduction_ratio: float = 1.0  # motor turns per screw turn (2: a 2:1 belt or gear reduction)
    reduction_efficiency: float = 1.0
    reduction_inertia: float = 0.0  # reduction at the motor shaft [kg m^2]
    max_inertia_ratio: float = MAX_INERTIA_RATIO  # load / rotor inertia at the motor
    brake: str = "auto"  # holding brake: auto (vertical axes), yes, no
    brake_safety: float = BRAKE_SAFETY  # brake holding torque / gravity torque

    @property
    def span(self) -> float:
        """Bearing-to-bearing length of the screw [m]."""
        return self.start_offset + self.stroke + self.end_margin

    @property
    def brake_used(self) -> bool:
        return self.brake == "yes" or (self.brake == "auto" and self.orientation == "vertical")

    @cached_property
    def phases(self) -> tuple:
        """Duty-cycle phases (:mod:`axisopt.physics.motion`); the default cycle is the rapid move."""
        segs = self.duty_cycle or motion.rapid_cycle(self.stroke, self.max_speed, self.acceleration, self.jerk)
        return motion.cycle_phases(segs)

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
    motor: object = None  # servo motor row, or None (the axis's motor_inertia; drive checks off)
    coupling: object = None  # coupling row, or None (the axis's coupling values)
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
        return {k: str(getattr(self, k)["id"]) for k in PART_SLOTS if getattr(self, k) is not None}


PART_SLOTS = ("screw", "nut", "bearing", "guide", "motor", "coupling")


_AXIS_KINDS = {
    "stroke": "length", "moving_mass": "mass", "max_speed": "speed", "axial_load": "force",
    "start_offset": "length", "end_margin": "length", "mean_speed": "speed", "mean_axial_load": "force",
    "acceleration": "acceleration", "required_life": "time", "table_length": "length",
    "normal_load": "force", "lubricant_viscosity": "kinematic_viscosity", "motor_inertia": "inertia",
    "bearing_housing_stiffness": "stiffness", "nut_bracket_stiffness": "stiffness",
    "coupling_stiffness": "torsional_stiffness", "coupling_inertia": "inertia",
    "temperature_rise": "temperature_difference", "jerk": "jerk", "reduction_inertia": "inertia",
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
    if sec.has("brake") and isinstance(sec.raw("brake").value, bool):  # YAML reads a bare yes/no as a boolean
        kw["brake"] = "yes" if sec.raw("brake").value else "no"
    else:
        kw["brake"] = sec.choice("brake", BRAKE_MODES, "auto")
    # plausible ranges: a belt or gear stage of a feed drive reduces by at most about 1:20 either way (1:50
    # allowed); an inertia-ratio limit beyond 1000 or a brake safety factor beyond 10 is no limit at all
    for name, low, high in (("reduction_ratio", 0.02, 50.0), ("max_inertia_ratio", None, 1000.0),
                            ("brake_safety", 1.0, 10.0)):
        v = sec.number(name, minimum=low, maximum=high)
        if v is not None:
            if not (math.isfinite(v) and v > 0):
                raise sec.error(name, f"must be a positive finite number, got {v}")
            kw[name] = float(v)
    v = sec.number("reduction_efficiency")
    if v is not None:
        if not (0 < v <= 1):
            raise sec.error("reduction_efficiency", f"must be in (0, 1], got {v}")
        kw["reduction_efficiency"] = float(v)
    if sec.has("duty_cycle"):
        kw["duty_cycle"] = read_duty_cycle(sec, kw)
    for name in ("guide_blocks", "rails", "positions"):
        v = sec.number(name, integer=True, minimum=1 if name != "positions" else 3,
                       maximum={"guide_blocks": 64, "rails": 8, "positions": 2001}[name])
        if v is not None:
            kw[name] = int(v)
    v = sec.number("load_factor", minimum=1.0)
    if v is not None:
        kw["load_factor"] = float(v)
    sec.done()
    assumed = tuple(f.name for f in fields(Axis) if f.name not in kw)
    return Axis(**kw), assumed


_SEGMENT_LIMIT = 1000  # duty-cycle entries


def read_duty_cycle(sec: Section, kw: dict) -> tuple:
    """``duty_cycle``: a list of moves ``{move: 400 mm, speed: 24 m/min, acceleration:, jerk:, force:}``
    (speed defaults to the axis max_speed, acceleration and jerk to the axis's) and dwells
    ``{dwell: 2 s, force:}``."""
    node = sec.raw("duty_cycle")
    where = sec.key_path("duty_cycle")
    if not isinstance(node.value, list) or not node.value:
        raise sec.error("duty_cycle", "expected a list of moves and dwells")
    if len(node.value) > _SEGMENT_LIMIT:
        raise sec.error("duty_cycle", f"has {len(node.value)} entries; at most {_SEGMENT_LIMIT}")
    out = []
    for i, item in enumerate(node.value):
        s = Section(item, sec.source, f"{where}[{i}]")
        if s.has("dwell") == s.has("move"):
            raise InputError("each entry is a 'move' or a 'dwell'", source=sec.source,
                             where=Section._loc(f"{where}[{i}]", item.line))
        force = s.quantity("force", "force", 0.0, non_negative=True)
        if s.has("dwell"):
            out.append(motion.Segment("dwell", duration=s.quantity("dwell", "time", positive=True), force=force))
        else:
            dist = s.quantity("move", "length")
            if dist == 0:
                raise s.error("move", "a move needs a distance (signed: + forward, - back)")
            if abs(dist) > kw.get("stroke", math.inf) * (1 + 1e-9):
                raise s.error("move", f"{abs(dist) * 1e3:g} mm is longer than the stroke")
            speed = s.quantity("speed", "speed", kw.get("max_speed"), positive=True)
            acc = s.quantity("acceleration", "acceleration", kw.get("acceleration", 0.0), positive=True)
            if not acc:
                raise s.error("move", "needs an acceleration (here or in axis.acceleration)")
            jerk = s.quantity("jerk", "jerk", kw.get("jerk"), positive=True)
            out.append(motion.Segment("move", distance=dist, speed=speed, acceleration=acc, jerk=jerk, force=force))
        s.done()
    return tuple(out)


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
    bad = row_problem(table, rec)  # the catalog loader's rules: positive geometry, choices, ordered pairs
    if bad is not None:
        col, msg = bad
        raise sec.error(col, msg if msg.startswith(col) else f"{col} {msg}")
    rec["_source"] = f"{sec.source}:{sec.node.line}"
    return pd.Series(rec, name=rec["id"])


def read_parts(sec: Section, catalog: Catalog) -> dict:
    parts = {
        "screw": read_part(sec, "screw", "screws", catalog),
        "nut": read_part(sec, "nut", "nuts", catalog),
        "bearing": read_part(sec, "bearing", "bearings", catalog),
        "guide": read_part(sec, "guide", "guides", catalog),
    }
    for slot, table in (("motor", "motors"), ("coupling", "couplings")):
        if sec.has(slot):
            parts[slot] = read_part(sec, slot, table, catalog)
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
    psec = root.section("parts", required=True)
    parts = read_parts(psec, catalog)
    root.done()
    if parts.get("motor") is not None and axis.acceleration <= 0 and not axis.duty_cycle:
        raise psec.error("motor", "sizing a motor needs axis.acceleration (or an axis.duty_cycle)")
    return Design(axis=axis, name=name, source=str(path), assumed=assumed, **parts)


__all__ = ["Axis", "Design", "MOUNTINGS", "load_design", "read_axis", "read_parts", "G"]


# Units used when a design is written back to YAML (vendor units, as users write them).
_OUT_UNITS = {
    "length": "mm", "mass": "kg", "time": "h", "force": "N", "stiffness": "N/um", "speed": "m/min",
    "acceleration": "m/s^2", "jerk": "m/s^3", "angle": "deg", "mass_per_length": "kg/m", "dn": "mm.rpm",
    "money_per_length": "EUR/m", "money": "EUR", "kinematic_viscosity": "mm^2/s", "inertia": "kg.m^2",
    "angular_speed": "rpm", "damping": "N.s/m", "torque": "N.m", "torsional_stiffness": "N.m/rad",
    "temperature_difference": "K", "power": "W",
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
        elif f.name == "duty_cycle":
            axis[f.name] = [_segment_dict(sg) for sg in v]
        else:
            axis[f.name] = v
    parts: dict = {}
    for slot, table in (("screw", "screws"), ("nut", "nuts"), ("bearing", "bearings"), ("guide", "guides"),
                        ("motor", "motors"), ("coupling", "couplings")):
        row = getattr(design, slot)
        if row is None:
            continue
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


def _segment_dict(sg) -> dict:
    if sg.kind == "dwell":
        d = {"dwell": f"{sg.duration:.12g} s"}
    else:
        d = {"move": _q(sg.distance, "length"), "speed": _q(sg.speed, "speed"),
             "acceleration": _q(sg.acceleration, "acceleration")}
        if sg.jerk is not None:
            d["jerk"] = _q(sg.jerk, "jerk")
    if sg.force:
        d["force"] = _q(sg.force, "force")
    return d


def design_to_yaml(design: Design, **kw) -> str:
    import yaml

    return yaml.safe_dump(design_to_dict(design, **kw), sort_keys=False, allow_unicode=True)
