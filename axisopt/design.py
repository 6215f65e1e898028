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

from .catalog import CHOICES, OPTIONAL_COLUMNS, SCHEMA, SHIPPED_DIR, Catalog, default_catalog, row_problem
from .display import fmt, one_line
from .errors import InputError
from .parttable import Row
from .physics import motion
from .units import DISPLAY_UNITS, unit_factor
from .yamlio import Key, Section, Spec, read_yaml

MOUNTINGS = ("fixed-free", "fixed-supported", "fixed-fixed")

# Defaults of the axis values no catalog row carries, with their sources (docs/assumptions.md).
# Bearing housing and nut bracket: no vendor publishes a value (THK A-707: "set the rigidity as high as
# possible"; THK and NSK rigidities exclude them), so they are rigid unless the YAML gives them.
# Coupling: RINGFEDER GWB AKN size 60 metal-bellows coupling (Tech Paper EN 08.2019): 75e3 N.m/rad,
# 0.29e-3 kg.m^2, 75 N.m, a mid-size feed-drive coupling (our pick of size).
# Temperature rise: THK A-715 sets the negative target travel for a 2-5 degC rise; 3 K is used.
COUPLING_STIFFNESS = 75e3
COUPLING_INERTIA = 0.29e-3
TEMPERATURE_RISE = 3.0
# horizontal: gravity presses the table onto the rails; vertical: gravity acts along the rail (on the screw);
# wall: the rails on a vertical wall, the feed horizontal, gravity across the rails (a lateral block load)
ORIENTATIONS = ("horizontal", "vertical", "wall")
G = 9.80665
# Drive defaults.  Inertia ratio: THK A-720 eq. 49 asks J_M >= J / C with C "normally between 3 to 10" (its
# transfer examples use 10); 5, the tighter half of that range, is our default for machine-tool axes.  Brake
# safety: no vendor figure was retrieved; 2 x the gravity torque is our assumption, set axis.brake_safety.
MAX_INERTIA_RATIO = 5.0
BRAKE_SAFETY = 2.0
# RMS torque / rated torque: Mitsubishi MDS-D-SVJ3/SPJ3 Specifications Manual sec. 7-1 (3), eq. 7-10, "Trms <=
# 0.8 Tst" (stall torque); taken against the rated torque, which is at most the stall torque (issue 26).
RMS_TORQUE_RATIO = 0.8
# Carriage (issue 25).  Static safety factors: THK's current selection pages give the lower limit of f_S "with
# vibrations or impacts" as 5 for the LM Guide (thk.com/in/en/products/lm_guide/selection/0005/, Table 10) and
# for the ball screw (LM Guide Actuator pages, "Ball Screw Unit/Bearing Unit": 5); a feed axis of a cutting
# machine has both (THK names "vibrations due to a cutting load" and acceleration).  The older General Catalog
# prints 2.5 to 7 for machine tools with vibration or impact; HIWIN G99TE20 Table 1-1: 3 to 5.
GUIDE_STATIC_SAFETY = 5.0
NUT_STATIC_SAFETY = 5.0
# Geometry defaults where the YAML gives none (our assumptions, stated in docs/assumptions.md): blocks set in from the
# table ends (spacing 0.6 x table length), rails 0.6 x table width apart, a table + workpiece box as wide as it
# is long, 0.4 x its length high with the centre of gravity at half that height and the cutting point on top.
SPACING_SHARE = 0.6
CG_HEIGHT_SHARE = 0.2
TOOL_HEIGHT_SHARE = 0.4
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
    # screw temperature rise in operation [K]; None: the heat balance of the duty cycle (model.heat) when the axis
    # has one, TEMPERATURE_RISE otherwise
    temperature_rise: float | None = None
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
    rms_torque_ratio: float = RMS_TORQUE_RATIO  # largest RMS torque / rated torque of the motor
    heat_transfer: float | None = None  # film coefficient of the screw surface [W/(m^2 K)]; None: Jungnickel
    # carriage: cutting force across the rail (the feed component is axial_load, the normal one normal_load),
    # where it acts and where the moving mass's centre of gravity is, the block pattern (None: the defaults
    # above, from the table's size) and the static safety the guides and the nut must keep
    cross_load: float = 0.0  # [N]
    tool_height: float | None = None  # cutting point above the guide mounting plane [m]
    tool_offset: float = 0.0  # cutting point across the rail from the carriage centre [m]
    cg_height: float | None = None  # centre of gravity of the moving mass above the mounting plane [m]
    cg_offset: float = 0.0  # ... across the rail from the carriage centre [m]
    table_width: float | None = None  # [m]; None: table_length
    block_spacing: float | None = None  # outer block to outer block along a rail [m]
    rail_spacing: float | None = None  # outer rail to outer rail [m]
    pitch_inertia: float | None = None  # moving mass about the lateral axis in the mounting plane [kg m^2]
    yaw_inertia: float | None = None  # moving mass about the vertical axis through the carriage centre [kg m^2]
    guide_static_safety: float = GUIDE_STATIC_SAFETY  # least C0 / largest block load
    nut_static_safety: float = NUT_STATIC_SAFETY  # least C0a / largest axial force

    @property
    def table_width_eff(self) -> float:
        return self.table_length if self.table_width is None else self.table_width

    @property
    def block_spacing_eff(self) -> float:
        return SPACING_SHARE * self.table_length if self.block_spacing is None else self.block_spacing

    @property
    def rail_spacing_eff(self) -> float:
        return SPACING_SHARE * self.table_width_eff if self.rail_spacing is None else self.rail_spacing

    @property
    def cg_height_eff(self) -> float:
        return CG_HEIGHT_SHARE * self.table_length if self.cg_height is None else self.cg_height

    @property
    def tool_height_eff(self) -> float:
        return TOOL_HEIGHT_SHARE * self.table_length if self.tool_height is None else self.tool_height

    @property
    def span(self) -> float:
        """Bearing-to-bearing length of the screw [m]."""
        return self.start_offset + self.stroke + self.end_margin

    @property
    def brake_used(self) -> bool:
        return self.brake == "yes" or (self.brake == "auto" and self.orientation == "vertical")

    @cached_property
    def phases(self) -> tuple:
        """Duty-cycle phases (:mod:`axisopt.physics.motion`); the default cycle is the rapid move.  ``heat``:
        the heat balance sets the temperature rise (a duty cycle and no ``temperature_rise``)."""
        segs = self.duty_cycle or motion.rapid_cycle(self.stroke, self.max_speed, self.acceleration, self.jerk)
        return motion.Phases(motion.cycle_phases(segs), heat=self.temperature_rise is None and bool(self.duty_cycle),
                             given=bool(self.duty_cycle))

    @property
    def top_speed(self) -> float:
        """The highest table speed commanded [m/s]: max_speed, or a duty-cycle move's speed if faster (the
        reader refuses such a move; kept as the maximum so the speed checks never read a slower value)."""
        return max([self.max_speed] + [s.speed for s in self.duty_cycle if s.kind == "move" and s.speed])

    @property
    def top_acceleration(self) -> float:
        """The highest acceleration commanded [m/s^2]: axis.acceleration or a duty-cycle move's own, if higher
        (the largest inertia force in the axial load, f_max, is taken at it)."""
        return max([self.acceleration] + [s.acceleration for s in self.duty_cycle
                                          if s.kind == "move" and s.acceleration])

    @property
    def mean_speed_eff(self) -> float:
        """The mean speed the life checks read [m/s]: ``mean_speed`` when given, else the duty cycle's travel
        over its time (THK A-730, dwells included), else half of max_speed."""
        if self.mean_speed is not None:
            return self.mean_speed
        cycle = motion.mean_speed(self.phases) if self.duty_cycle else 0.0
        return cycle if cycle > 0.0 else 0.5 * self.max_speed

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

    def __repr__(self) -> str:  # the parts are catalog rows: a dataclass repr would print them whole
        a = self.axis
        parts = ", ".join(f"{k} {v}" for k, v in self.part_ids().items())
        return one_line("Design", repr(self.name), {
            "": f"{a.mounting}, {a.orientation}", "stroke": fmt(a.stroke * 1e3, "mm"),
            "moving mass": fmt(a.moving_mass, "kg"), "max speed": fmt(a.max_speed * 60, "m/min"),
            "axial load": fmt(a.axial_load, "N"), "parts": f"{parts} (nut preload {fmt(self.preload, 'N')})"})


PART_SLOTS = ("screw", "nut", "bearing", "guide", "motor", "coupling")


# ------------------------------------------------------------------------------ the YAML keys (one table)
# Each table below is the one declaration of its section's keys: the readers read them by it (Section.read)
# and `axisopt schema` writes it out as a JSON Schema.  Unset axis keys take the Axis defaults above.

def _axis_q(kind: str, doc: str, *, required: bool = False, zero: bool = False, maximum=None) -> Key:
    """An axis quantity: positive, or non-negative when ``zero``."""
    return Key("quantity", doc, required=required, kind=kind, positive=not zero, non_negative=zero,
               maximum=maximum)


_SEGMENT_LIMIT = 1000  # duty-cycle entries
_FORCE = Key("quantity", "axial (process) force during the entry", kind="force", non_negative=True, default=0.0)
MOVE_SPEC = Spec("move", "a move of the duty cycle", {
    "move": Key("quantity", "signed distance (+ forward, - back), at most the stroke", required=True,
                kind="length", example="400 mm"),
    "speed": Key("quantity", "top speed (default: axis.max_speed)", kind="speed", positive=True),
    "acceleration": Key("quantity", "acceleration (default: axis.acceleration)", kind="acceleration",
                        positive=True),
    "jerk": Key("quantity", "jerk limit (default: axis.jerk)", kind="jerk", positive=True),
    "force": _FORCE,
})
DWELL_SPEC = Spec("dwell", "a dwell of the duty cycle", {
    "dwell": Key("quantity", "duration", required=True, kind="time", positive=True, example="2 s"),
    "force": _FORCE,
})
# Upper bounds where a value beyond them leaves the model's range: a screw 100 K above ambient is not in
# operation, and the linear thermal model (constant alpha, elastic bearing sets) no longer holds.  Plausible
# drive ranges: a belt or gear stage of a feed drive reduces by at most about 1:20 either way (1:50 allowed);
# an inertia-ratio limit beyond 1000 or a brake safety factor beyond 10 is no limit at all.
AXIS_SPEC = Spec("axis", "what the machine asks of the axis (every dimensional value with its unit)", {
    "stroke": _axis_q("length", "travel of the table", required=True),
    "moving_mass": _axis_q("mass", "table + workpiece, without nut and guide blocks", required=True),
    "mounting": Key("choice", "screw end supports (a problem: the default mounting)", required=True,
                    choices=MOUNTINGS),
    "max_speed": _axis_q("speed", "rapid traverse speed", required=True),
    "axial_load": _axis_q("force", "largest external axial (cutting) load", required=True, zero=True),
    "start_offset": _axis_q("length", "fixed bearing to nut at stroke start, l0"),
    "end_margin": _axis_q("length", "nut at stroke end to the far bearing", zero=True),
    "mean_speed": _axis_q("speed", "mean speed for the life (default: half of max_speed)"),
    "mean_axial_load": _axis_q("force", "mean axial load for the life (default: a third of axial_load)", zero=True),
    "acceleration": _axis_q("acceleration", "acceleration of the moves", zero=True),
    "required_life": _axis_q("time", "required life of the nut, bearings and guides (problem default: its "
                             "limits.min_life, else 20000 h)"),
    "load_factor": Key("number", "load factor fw of the life calculation", minimum=1.0),
    "guide_blocks": Key("number", "guide blocks carrying the table", integer=True, minimum=1, maximum=64),
    "rails": Key("number", "guide rails", integer=True, minimum=1, maximum=8),
    "table_length": _axis_q("length", "table length (rail length = stroke + table_length)"),
    "normal_load": _axis_q("force", "external load on the guide blocks besides gravity", zero=True),
    "lubricant_viscosity": _axis_q("kinematic_viscosity", "lubricant viscosity at working temperature"),
    "motor_inertia": _axis_q("inertia", "motor rotor inertia (when no motor part is chosen)"),
    "bearing_housing_stiffness": _axis_q("stiffness", "one support-bearing housing (default: rigid)"),
    "nut_bracket_stiffness": _axis_q("stiffness", "nut bracket / table connection (default: rigid)"),
    "coupling_stiffness": _axis_q("torsional_stiffness", "coupling torsional stiffness (when no coupling part)"),
    "coupling_inertia": _axis_q("inertia", "coupling inertia (when no coupling part)"),
    "temperature_rise": _axis_q("temperature_difference", "screw temperature rise in operation (default: the "
                                "heat balance of the duty cycle when the axis has one, else 3 K)", zero=True,
                           maximum=(100.0, "100 K")),
    "pretension": Key("one_of", "fixed-fixed screw pretension (default auto: absorbs temperature_rise)",
                      options=(Key("choice", choices=("auto",)),
                               Key("quantity", kind="force", non_negative=True))),
    "orientation": Key("choice", "axis orientation", choices=ORIENTATIONS, default="horizontal"),
    "positions": Key("number", "nut positions evaluated over the stroke", integer=True, minimum=3,
                     maximum=2001),
    "jerk": _axis_q("jerk", "jerk limit (default: trapezoidal moves)"),
    "duty_cycle": Key("list", "moves and dwells (default: the rapid move over the stroke and back)",
                      minimum=1, maximum=_SEGMENT_LIMIT,
                      items=Key("one_of", options=(Key("section", spec=MOVE_SPEC), Key("section", spec=DWELL_SPEC)))),
    "reduction_ratio": Key("number", "motor turns per screw turn (2: a 2:1 belt or gear)", positive=True,
                           minimum=0.02, maximum=50.0),
    "reduction_efficiency": Key("number", "efficiency of the reduction, in (0, 1]", positive=True, maximum=1.0),
    "reduction_inertia": _axis_q("inertia", "inertia of the reduction at the motor shaft"),
    "max_inertia_ratio": Key("number", "largest load / rotor inertia ratio at the motor", positive=True,
                             maximum=1000.0),
    "brake": Key("one_of", "holding brake (auto: vertical axes)", default="auto",
                 options=(Key("choice", choices=BRAKE_MODES), Key("choice", choices=(True, False)))),
    "brake_safety": Key("number", "brake holding torque / gravity torque", positive=True, minimum=1.0,
                        maximum=10.0),
    "heat_transfer": _axis_q("heat_transfer", "film coefficient of the screw surface for the heat balance "
                             "(default: Jungnickel's rotating shaft in still air, 3.75 omega^0.7 r^0.4)"),
    "rms_torque_ratio": Key("number", "largest RMS torque / rated torque of the motor (default 0.8: Mitsubishi "
                            "MDS-D-SVJ3 sec. 7-1 eq. 7-10, Trms <= 0.8 x stall torque)", positive=True,
                            maximum=1.0),
    # carriage (issue 25): the cutting force's cross component and where it acts, the centre of gravity, the
    # block pattern; heights above the guide mounting plane (the screw axis is taken to lie in it)
    "cross_load": _axis_q("force", "cutting force across the rail (feed: axial_load, normal: normal_load)",
                          zero=True),
    "tool_height": _axis_q("length", "cutting point above the guide mounting plane (default 0.4 x table_length)",
                           zero=True),
    "tool_offset": _axis_q("length", "cutting point across the rail from the carriage centre", zero=True),
    "cg_height": _axis_q("length", "moving mass's centre of gravity above the guide mounting plane "
                         "(default 0.2 x table_length)", zero=True),
    "cg_offset": _axis_q("length", "moving mass's centre of gravity across the rail from the carriage centre",
                         zero=True),
    "table_width": _axis_q("length", "table width across the rails (default: table_length)"),
    "block_spacing": _axis_q("length", "outer block to outer block along a rail, at most table_length "
                             "(default 0.6 x table_length)"),
    "rail_spacing": _axis_q("length", "outer rail to outer rail, at most table_width (default 0.6 x table_width)"),
    "pitch_inertia": _axis_q("inertia", "moving mass about the cross axis in the mounting plane (default: a box "
                             "table_length long, 2 x cg_height high)"),
    "yaw_inertia": _axis_q("inertia", "moving mass about the normal axis (default: a box table_length x "
                           "table_width)"),
    "guide_static_safety": Key("number", "least guide static safety C0 / largest block load (default 5: THK, "
                               "with vibrations or impacts)", minimum=1.0, maximum=100.0),
    "nut_static_safety": Key("number", "least nut static safety C0a / largest axial force (default 5: THK, with "
                             "vibrations or impacts)", minimum=1.0, maximum=100.0),
})
_AXIS_KINDS = {name: k.kind for name, k in AXIS_SPEC.keys.items() if k.type == "quantity"}
_AXIS_REQUIRED = tuple(name for name, k in AXIS_SPEC.keys.items() if k.required)
_AXIS_NUMBERS = ("reduction_ratio", "max_inertia_ratio", "brake_safety", "reduction_efficiency",
                 "guide_static_safety", "nut_static_safety", "rms_torque_ratio")


def read_axis(sec: Section) -> tuple[Axis, tuple]:
    """Read an ``axis:`` section.  Returns the Axis and the names of keys left at their defaults."""
    sec = sec.declared(AXIS_SPEC)
    kw = {}
    for name in _AXIS_KINDS:
        v = sec.read(name)
        if v is not None:
            kw[name] = v
    kw["mounting"] = sec.read("mounting")
    if sec.has("pretension"):
        node = sec.raw("pretension")
        if node.value != "auto":
            kw["pretension"] = sec.quantity("pretension", "force", non_negative=True)
    kw["orientation"] = sec.read("orientation")
    if sec.has("brake") and isinstance(sec.raw("brake").value, bool):  # YAML reads a bare yes/no as a boolean
        kw["brake"] = "yes" if sec.raw("brake").value else "no"
    else:
        kw["brake"] = sec.choice("brake", BRAKE_MODES, AXIS_SPEC.keys["brake"].default)
    for name in _AXIS_NUMBERS:
        v = sec.read(name)
        if v is not None:
            kw[name] = float(v)
    if sec.has("duty_cycle"):
        kw["duty_cycle"] = read_duty_cycle(sec, kw)
    for name in ("guide_blocks", "rails", "positions"):
        v = sec.read(name)
        if v is not None:
            kw[name] = int(v)
    v = sec.read("load_factor")
    if v is not None:
        kw["load_factor"] = float(v)
    _check_carriage(sec, kw)
    sec.done()
    assumed = tuple(f.name for f in fields(Axis) if f.name not in kw)
    return Axis(**kw), assumed


def _check_carriage(sec: Section, kw: dict) -> None:
    """The block pattern fits the table; at least two blocks on every rail (the table's rocking stiffness comes
    from the block spacing: no vendor text gives one block's moment rigidity)."""
    length = kw.get("table_length", Axis.table_length)
    width = kw.get("table_width", length)
    if kw.get("block_spacing", 0.0) > length * (1 + 1e-9):
        raise sec.error("block_spacing", f"{kw['block_spacing'] * 1e3:g} mm is larger than the table "
                        f"(table_length {length * 1e3:g} mm)")
    if kw.get("rail_spacing", 0.0) > width * (1 + 1e-9):
        raise sec.error("rail_spacing", f"{kw['rail_spacing'] * 1e3:g} mm is larger than the table "
                        f"(table_width {width * 1e3:g} mm)")
    blocks, rails = kw.get("guide_blocks", Axis.guide_blocks), kw.get("rails", Axis.rails)
    if blocks % rails or blocks < 2 * rails:
        key = "guide_blocks" if sec.has("guide_blocks") else "rails"
        raise sec.error(key, f"{blocks} blocks on {rails} rail(s): give every rail the same number of blocks, "
                        "at least two")


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
        s = Section(item, sec.source, f"{where}[{i}]", DWELL_SPEC if s.has("dwell") else MOVE_SPEC)
        force = s.read("force")
        if s.has("dwell"):
            out.append(motion.Segment("dwell", duration=s.read("dwell"), force=force))
        else:
            dist = s.read("move")
            if dist == 0:
                raise s.error("move", "a move needs a distance (signed: + forward, - back)")
            if abs(dist) > kw.get("stroke", math.inf) * (1 + 1e-9):
                raise s.error("move", f"{abs(dist) * 1e3:g} mm is longer than the stroke")
            speed = s.read("speed", kw.get("max_speed"))
            top = kw.get("max_speed")
            if top is not None and speed > top * (1 + 1e-9):  # the speed checks are taken at max_speed
                raise s.error("speed", f"{speed * 60:g} m/min is faster than axis.max_speed ({top * 60:g} m/min); "
                              "raise max_speed to the fastest move (critical speed, DN and bearing speed are "
                              "checked at it)")
            acc = s.read("acceleration", kw.get("acceleration", 0.0))
            if not acc:
                raise s.error("move", "needs an acceleration (here or in axis.acceleration)")
            jerk = s.read("jerk", kw.get("jerk"))
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
    return inline_part(Section(node, sec.source, sec.key_path(key), PART_SPECS[table]), table)


def _part_key(table: str, col: str, kind: str) -> Key:
    """How an inline part gives catalog column ``col`` (the catalog loader's column kinds and choices)."""
    doc = col.replace("_", " ")
    if kind == "str":
        optional = col in ("vendor", "series")
        return Key("string", doc + (" (default: custom)" if optional else ""), required=not optional,
                   default="custom" if optional else None, choices=CHOICES.get((table, col)))
    if kind == "int":
        return Key("number", doc, required=True, integer=True, minimum=1)
    if kind == "dimensionless":
        return Key("number", doc, required=True, minimum=0)
    optional = col in OPTIONAL_COLUMNS.get(table, ())
    return Key("quantity", doc + (" (optional: the vendor lists none)" if optional else ""),
               required=not optional, kind=kind, non_negative=True)


# An inline (custom) part: the columns of its catalog table, with units.
PART_SPECS = {table: Spec(table[:-1], f"a custom {table[:-1]}: the columns of catalogs/{table}.csv, with units",
                          {col: _part_key(table, col, kind) for col, kind in cols.items()})
              for table, cols in SCHEMA.items()}


def inline_part(sec: Section, table: str):
    sec = sec.declared(PART_SPECS[table])
    rec = {}
    for col, kind in SCHEMA[table].items():
        v = sec.read(col)
        if kind == "int":
            v = int(v)
        elif kind == "dimensionless":
            v = float(v)
        elif kind != "str" and v is None:
            v = math.nan
        rec[col] = v
    sec.done()
    bad = row_problem(table, rec)  # the catalog loader's rules: positive geometry, choices, ordered pairs
    if bad is not None:
        col, msg = bad
        raise sec.error(col, msg if msg.startswith(col) else f"{col} {msg}")
    rec["_source"] = f"{sec.source}:{sec.node.line}"
    return Row(rec, rec["id"])


def _slot(table: str, doc: str, required: bool) -> Key:
    return Key("one_of", doc, required=required,
               options=(Key("string", f"a {table[:-1]} id from the catalogs"), Key("number", integer=True),
                        Key("section", spec=PART_SPECS[table])))


PARTS_SPEC = Spec("parts", "one part per slot: a catalog id, or an inline mapping of a custom part", {
    "screw": _slot("screws", "ball screw", True),
    "nut": _slot("nuts", "ball nut (fits the screw)", True),
    "bearing": _slot("bearings", "support bearing set", True),
    "guide": _slot("guides", "linear guide block and rail", True),
    "motor": _slot("motors", "servo motor (optional; needs axis.acceleration or axis.duty_cycle)", False),
    "coupling": _slot("couplings", "shaft coupling (optional)", False),
    "nut_preload": Key("quantity", "nut preload within the nut's range (default: the catalog's)", kind="force",
                       non_negative=True),
})
NAME_KEY = Key("string", "name of the file's subject (default: the file name)")
DESCRIPTION_KEY = Key("string", "free text")
CATALOGS_KEY = Key("names", "extra catalog directories, relative to this file")
DESIGN_SPEC = Spec("design", "an axis design: the machine's requirements and one part per slot", {
    "name": NAME_KEY, "description": DESCRIPTION_KEY, "catalogs": CATALOGS_KEY,
    "axis": Key("section", required=True, spec=AXIS_SPEC), "parts": Key("section", required=True, spec=PARTS_SPEC),
})


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
    pre = sec.read("nut_preload")
    sec.done()
    nut, screw = parts["nut"], parts["screw"]
    if nut["screw_id"] != screw["id"]:
        raise sec.error("nut", f"nut '{nut['id']}' fits screw '{nut['screw_id']}', not '{screw['id']}'; "
                        + fitting_nuts(catalog, screw["id"]))
    if pre is not None and not (nut["preload_min"] - 1e-9 <= pre <= nut["preload_max"] + 1e-9):
        raise sec.error("nut_preload", f"{pre:.0f} N is outside nut '{nut['id']}' range "
                        f"{nut['preload_min']:.0f}..{nut['preload_max']:.0f} N")
    parts["nut_preload"] = pre
    return parts


def fitting_nuts(catalog: Catalog, screw_id: str, shown: int = 6) -> str:
    """'nuts for it: A, B (+3 more; axisopt parts nuts --fits ID)' -- what a refused nut could be instead."""
    nuts = catalog.rows("nuts")
    ids = [str(i) for i in nuts.ids[nuts["screw_id"] == screw_id]]
    if not ids:
        return f"the catalogs have no nut for '{screw_id}'"
    more = f" (+{len(ids) - shown} more)" if len(ids) > shown else ""
    return f"nuts for it: {', '.join(ids[:shown])}{more} (axisopt parts nuts --fits {screw_id})"


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
    root = Section(read_yaml(path), str(path), spec=DESIGN_SPEC)
    catalog = catalog_for(root, path.parent)
    name = root.read("name", path.stem)
    root.read("description")
    axis, assumed = read_axis(root.read("axis"))
    psec = root.read("parts")
    parts = read_parts(psec, catalog)
    root.done()
    if parts.get("motor") is not None and axis.acceleration <= 0 and not axis.duty_cycle:
        raise psec.error("motor", "sizing a motor needs axis.acceleration (or an axis.duty_cycle)")
    return Design(axis=axis, name=name, source=str(path), assumed=assumed, **parts)


__all__ = ["Axis", "Design", "MOUNTINGS", "load_design", "read_axis", "read_parts", "G"]


def _q(value: float, kind: str) -> str:
    unit = DISPLAY_UNITS[kind]
    return f"{value / unit_factor(unit, kind):.12g} {unit}"


def design_to_dict(design: Design, *, inline_parts: bool = False) -> dict:
    """A design as the plain mapping a design YAML holds (vendor units).  ``load_design`` reads it back.

    Parts of the shipped catalogs are written as their ids unless ``inline_parts``; a part from a user
    catalog or from the YAML itself is written inline, so the file stands on its own.
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
        if not inline_parts and str(row.get("_source", "")).startswith(str(SHIPPED_DIR)):
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
