"""The axis and design descriptions: :class:`Axis` (what the machine asks of the axis, SI, with the
defaults of the values no catalog row carries) and :class:`Design` (an axis with one chosen part per
slot).  Frozen dataclasses; the YAML keys are declared in :mod:`.keys`, read in :mod:`.reader`,
written in :mod:`.writer`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

from ..catalog.columns import DRIVE_SLOTS, MECH_SLOTS, PART_SLOTS
from ..display import fmt, one_line
from ..physics import motion
from ..physics.checks import load_factor_default
from ..physics.gantry import side_shares

MOUNTINGS = ("fixed-free", "fixed-supported", "fixed-fixed")

# Defaults of the axis values no catalog row carries, with their sources (docs/assumptions.md).
# Bearing housing and nut bracket: no vendor publishes a value for the machine's own parts (THK
# "set the rigidity as high as possible"; THK and NSK rigidities exclude them).  Never rigid:
# without a YAML value the housing is 26 x its bearing set (IBC's bearing units against their bare
# sets, physics.bearings.housing_stiffness_default) and the bracket 4 x its nut (THK's 80 %
# nut-mounting allowance taken once more, physics.nut.bracket_stiffness_default), both named as
# estimates in every result.  Load factor fw: THK A-704 Table 19 by the axis's max speed
# (physics.checks.load_factor_default).  Nut lift-off: the preload holds up to 2^(3/2) x preload
# (THK A-687, HIWIN H-BS F 3.6); no vendor asks a margin on top, on a vertical axis neither (the
# largest axial force already carries the weight; THK A-737).  Coupling: RINGFEDER GWB AKN size 60
# metal-bellows coupling (Tech Paper EN 08.2019): 75e3 N.m/rad, 0.29e-3 kg.m^2, 75 N.m, a mid-size
# feed-drive coupling (our pick of size).  Temperature rise: THK A-715 sets the negative target
# travel for a 2-5 degC rise; 3 K is used.  Pretension of a fixed-fixed screw: the force that
# absorbs a stated design rise, not the heat balance's whole rise: THK A-715 "set a negative target
# value for the reference travel distance assuming a temperature increase of 2 to 5 degC (-0.02 mm
# to -0.06 mm/m)"; the HIWIN-style guidance of Guangyang (gyballscrew.com, "The influence of ball
# screw pretension") "a temperature rise of about 3 degC as the reference for the compensation value
# T", under 5 degC.  3 K is used.
COUPLING_STIFFNESS = 75e3
COUPLING_INERTIA = 0.29e-3
TEMPERATURE_RISE = 3.0
PRETENSION_RISE = 3.0
# horizontal: gravity presses the table onto the rails; vertical: gravity acts along the rail (on
# the screw); wall: the rails on a vertical wall, the feed horizontal, gravity across the rails (a
# lateral block load)
ORIENTATIONS = ("horizontal", "vertical", "wall")
G = 9.80665
# Drive defaults.  Inertia ratio: THK A-720 eq. 49 asks J_M >= J / C with C "normally between 3 to
# 10" (its transfer examples use 10); 5, the tighter half of that range, is our default for
# machine-tool axes.  Brake safety: no vendor figure was retrieved; 2 x the gravity torque is our
# assumption, set axis.brake_safety.
MAX_INERTIA_RATIO = 5.0
BRAKE_SAFETY = 2.0
# RMS torque / rated torque where a motor row names no vendor rule (model.motorrule holds the
# vendors' rules): Mitsubishi MDS-D-SVJ3/SPJ3 Specifications Manual sec. 7-1 (3), eq. 7-10, "Trms <=
# 0.8 Tst" (stall torque), taken against the rated torque, which is at most the stall torque: the
# harshest of the vendors' rules.
RMS_TORQUE_RATIO = 0.8
# Carriage.  Static safety factors: THK's current selection pages give the lower limit of f_S "with
# vibrations or impacts" as 5 for the LM Guide (thk.com/in/en/products/lm_guide/selection/0005/,
# Table 10) and for the ball screw (LM Guide Actuator pages, "Ball Screw Unit/Bearing Unit": 5); a
# feed axis of a cutting machine has both (THK names "vibrations due to a cutting load" and
# acceleration).  The older General Catalog prints 2.5 to 7 for machine tools with vibration or
# impact; HIWIN G99TE20 Table 1-1: 3 to 5.
GUIDE_STATIC_SAFETY = 5.0
NUT_STATIC_SAFETY = 5.0
NUT_LIFT_OFF_SAFETY = 1.0
# Geometry defaults where the YAML gives none (our assumptions, stated in docs/assumptions.md):
# blocks set in from the table ends (spacing 0.6 x table length), rails 0.6 x table width apart, a
# table + workpiece box as wide as it is long, 0.4 x its length high with the centre of gravity at
# half that height and the cutting point on top.
SPACING_SHARE = 0.6
CG_HEIGHT_SHARE = 0.2
TOOL_HEIGHT_SHARE = 0.4
BRAKE_MODES = ("auto", "yes", "no")
# Counterbalance of a vertical axis: a counterweight on a chain over a sprocket, or a balance
# cylinder.  Chain efficiency over its sprocket when not given: 0.95, an estimate (roller-chain
# drives are quoted at 0.95-0.98; the lower end, so the counterweight's pull lifting is not
# overstated).
COUNTERBALANCE_KINDS = ("none", "counterweight", "cylinder")
CHAIN_EFFICIENCY = 0.95


@dataclass(frozen=True)
class Counterbalance:
    """A vertical axis's counterbalance (SI).  ``counterweight``: ``mass`` on a chain over a
    sprocket of ``efficiency``, with the chain's ``chain_mass`` moving too; ``cylinder``: ``force``
    at the stroke's start and ``force_at_end`` at its end (None: a regulator keeps it constant),
    within +/- ``tolerance`` (a fraction), its ``piston_mass`` moving with the head."""

    kind: str
    mass: float = 0.0  # counterweight [kg]
    efficiency: float = CHAIN_EFFICIENCY  # chain or cable over its sprocket or pulley [-]
    chain_mass: float = 0.0  # [kg]
    force: float = 0.0  # cylinder force at the stroke's start [N]
    force_at_end: float | None = None  # ... at its end [N]; None: the same (constant pressure)
    tolerance: float = 0.0  # pressure tolerance, +/- a fraction [-]
    piston_mass: float = 0.0  # [kg]

    @property
    def force_end(self) -> float:
        """The cylinder's force at the stroke's end [N] (``force`` when not given)."""
        return self.force if self.force_at_end is None else self.force_at_end


@dataclass(frozen=True)
class TwinDrive:
    """A twin-drive gantry (:mod:`axisopt.model.gantry`): two synchronised screw drives with the
    same parts, ``span`` apart, under a bridge (the axis's ``moving_mass``) with a cross carriage of
    ``cross_mass`` moving ``cross_stroke`` across it, centred between the drives.  SI units."""

    span: float  # between the two drives (screw axes) [m]
    cross_stroke: float  # the cross carriage's travel, centred on the bridge, at most span [m]
    cross_mass: float = 0.0  # cross carriage with its head [kg]
    # bridge about its centre [kg m^2]; None: from its parts
    bridge_yaw_inertia: float | None = None
    # both uprights (at the drives) [kg]; None: half the bridge (an estimate)
    upright_mass: float | None = None
    # the side a model of this axis is: 'governing' (nearest the cross carriage at the end of
    # its stroke: the limits are checked on it) or 'far' (the other side at that moment); not a YAML
    # key (model.evaluate's side)
    side: str = "governing"

    @property
    def force_share(self) -> float:
        """This side's share of a force on the cross carriage at the end of its stroke [-]: r =
        1/2 + s/2L on the governing side, 1 - r on the far side."""
        r = float(side_shares(self.cross_stroke, self.span))
        return 1.0 - r if self.side == "far" else r


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
    load_factor: float | None = None  # fw; None: THK A-704 Table 19 by max_speed (load_factor_eff)
    guide_blocks: int = 4
    rails: int = 2
    table_length: float = 0.5  # rail length = stroke + table_length [m]
    normal_load: float = 0.0  # external load on the guide blocks besides gravity [N]
    lubricant_viscosity: float = 32e-6  # at working temperature [m^2/s]
    motor_inertia: float = 1.0e-3  # motor rotor [kg m^2]
    # values outside the catalogs, YAML overridable; the defaults' sources are above the class one
    # support-bearing housing [N/m]; None: 26 x the bearing set (IBC units, an estimate)
    bearing_housing_stiffness: float | None = None
    # nut bracket / table connection [N/m]; None: 4 x the nut (THK's mounting allowance, an
    # estimate)
    nut_bracket_stiffness: float | None = None
    coupling_stiffness: float = COUPLING_STIFFNESS  # torsional [N m/rad]
    coupling_inertia: float = COUPLING_INERTIA  # [kg m^2]
    # screw temperature rise in operation [K]; None: the heat balance of the duty cycle (model.heat)
    # when the axis has one, TEMPERATURE_RISE otherwise
    temperature_rise: float | None = None
    # fixed-fixed screw pretension [N]; None: absorbs pretension_rise
    pretension: float | None = None
    # design rise the auto pretension absorbs [K]; None: PRETENSION_RISE
    pretension_rise: float | None = None
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
    # largest RMS torque / rated torque of the motor; None: the motor vendor's rule
    # (model.motorrule)
    rms_torque_ratio: float | None = None
    # the drive's torque limit at the motor shaft [N m]; None: the motor's peak
    torque_limit: float | None = None
    # the largest process force acts while accelerating (nut lift-off)
    cut_while_accelerating: bool = False
    # how the nut holds the shaft for buckling: fixed (THK) or supported (MiSUMi)
    buckling_nut_end: str = "fixed"
    # the temperature rise without a duty cycle (and no temperature_rise): "practice", THK A-715's
    # planning rise (TEMPERATURE_RISE), or "balance", the heat balance of the default cycle
    # (continuous rapids)
    rise_without_cycle: str = "practice"
    # position feedback: "motor_encoder" (semi-closed loop) or "linear_scale" (closed loop on
    # the table: the scale's grade, grades.SCALE_GRADES, in place of the screw's lead and thermal
    # rows); pitch-error compensation of a semi-closed loop (the controller's table: the lead row
    # becomes the residual, grades.compensated_error)
    feedback: str = "motor_encoder"
    scale_grade: str | None = None
    pitch_compensation: bool = False
    # the position loop's structure, for diagnose: "pd" or "p_pi_cascade" (None: fitted from a
    # record)
    controller: str | None = None
    # film coefficient of the screw surface [W/(m^2 K)]; None: Jungnickel
    heat_transfer: float | None = None
    # carriage: cutting force across the rail (the feed component is axial_load, the normal one
    # normal_load), where it acts and where the moving mass's centre of gravity is, the block
    # pattern (None: the defaults above, from the table's size) and the static safety the guides and
    # the nut must keep
    cross_load: float = 0.0  # [N]
    tool_height: float | None = None  # cutting point above the guide mounting plane [m]
    tool_offset: float = 0.0  # cutting point across the rail from the carriage centre [m]
    # the guides' running pitch and yaw over the stroke [rad] (the Abbe rows of the positioning
    # budget)
    guide_pitch: float = 0.0
    guide_yaw: float = 0.0
    # centre of gravity of the moving mass above the mounting plane [m]
    cg_height: float | None = None
    cg_offset: float = 0.0  # ... across the rail from the carriage centre [m]
    table_width: float | None = None  # [m]; None: table_length
    block_spacing: float | None = None  # outer block to outer block along a rail [m]
    rail_spacing: float | None = None  # outer rail to outer rail [m]
    # moving mass about the lateral axis in the mounting plane [kg m^2]
    pitch_inertia: float | None = None
    # moving mass about the vertical axis through the carriage centre [kg m^2]
    yaw_inertia: float | None = None
    guide_static_safety: float = GUIDE_STATIC_SAFETY  # least C0 / largest block load
    nut_static_safety: float = NUT_STATIC_SAFETY  # least C0a / largest axial force
    # least static safety of the support-bearing set on its static rating; None: the rating's
    # vendor's (catalogs bearings static_safety: NSK limiting load 1/0.7, THK permissible load 1,
    # else Rexroth's 4)
    bearing_static_safety: float | None = None
    # least nut lift-off force / largest axial force
    nut_lift_off_safety: float = NUT_LIFT_OFF_SAFETY
    # a vertical axis's counterweight or balance cylinder
    counterbalance: Counterbalance | None = None
    # a twin-drive gantry (two drives under one bridge, TwinDrive); None: one drive
    twin_drive: TwinDrive | None = None

    @property
    def load_factor_eff(self) -> float:
        """The load factor fw the life checks read: ``load_factor`` when given, else THK A-704 Table
        19's for the axis's top speed (:func:`axisopt.physics.checks.load_factor_default`)."""
        return load_factor_default(self.top_speed) if self.load_factor is None else self.load_factor

    @property
    def table_width_eff(self) -> float:
        return self.table_length if self.table_width is None else self.table_width

    @property
    def block_spacing_eff(self) -> float:
        return (
            SPACING_SHARE * self.table_length if self.block_spacing is None else self.block_spacing
        )

    @property
    def rail_spacing_eff(self) -> float:
        return (
            SPACING_SHARE * self.table_width_eff if self.rail_spacing is None else self.rail_spacing
        )

    @property
    def cg_height_eff(self) -> float:
        return CG_HEIGHT_SHARE * self.table_length if self.cg_height is None else self.cg_height

    @property
    def tool_height_eff(self) -> float:
        return (
            TOOL_HEIGHT_SHARE * self.table_length if self.tool_height is None else self.tool_height
        )

    @property
    def span(self) -> float:
        """Bearing-to-bearing length of the screw [m]."""
        return self.start_offset + self.stroke + self.end_margin

    @property
    def brake_used(self) -> bool:
        return self.brake == "yes" or (self.brake == "auto" and self.orientation == "vertical")

    @cached_property
    def phases(self) -> tuple:
        """Duty-cycle phases (:mod:`axisopt.physics.motion`); the default cycle is the rapid move.
        ``heat``: the heat balance sets the temperature rise (a duty cycle and no
        ``temperature_rise``)."""
        segs = self.duty_cycle or motion.rapid_cycle(
            self.stroke, self.max_speed, self.acceleration, self.jerk
        )
        phases = motion.cycle_phases(segs)
        # each drive: the governing side's share of the process force
        if self.twin_drive is not None:
            share = self.twin_drive.force_share
            phases = [replace(ph, force=share * ph.force) for ph in phases]
        return motion.Phases(phases, heat=self.rise_from_balance, given=bool(self.duty_cycle))

    @property
    def rise_from_balance(self) -> bool:
        """The heat balance (model.heat) sets the temperature rise: no temperature_rise given, and a
        duty cycle or ``rise_without_cycle: balance`` (the default cycle's balance)."""
        return self.temperature_rise is None and (
            bool(self.duty_cycle) or self.rise_without_cycle == "balance"
        )

    @property
    def top_speed(self) -> float:
        """The highest table speed commanded [m/s]: max_speed, or a duty-cycle move's speed if
        faster (the reader refuses such a move; kept as the maximum so the speed checks never read a
        slower value)."""
        return max(
            [self.max_speed] + [s.speed for s in self.duty_cycle if s.kind == "move" and s.speed]
        )

    @property
    def top_acceleration(self) -> float:
        """The highest acceleration commanded [m/s^2]: axis.acceleration or a duty-cycle move's own,
        if higher (the largest inertia force in the axial load, f_max, is taken at it)."""
        return max(
            [self.acceleration]
            + [s.acceleration for s in self.duty_cycle if s.kind == "move" and s.acceleration]
        )

    @property
    def mean_speed_eff(self) -> float:
        """The mean speed the life checks read [m/s]: ``mean_speed`` when given, else the duty
        cycle's travel over its time (THK A-730, dwells included), else half of max_speed."""
        if self.mean_speed is not None:
            return self.mean_speed
        cycle = motion.mean_speed(self.phases) if self.duty_cycle else 0.0
        return cycle if cycle > 0.0 else 0.5 * self.max_speed

    @property
    def mean_axial_load_eff(self) -> float:
        return self.mean_axial_load if self.mean_axial_load is not None else self.axial_load / 3.0


@dataclass(frozen=True)
class Design:
    """An axis with one chosen part per slot.  Parts are catalog rows (``parttable.Row``: a dict per
    part) in SI."""

    axis: Axis
    screw: object
    nut: object
    bearing: object
    guide: object
    nut_preload: float | None = None  # [N]; None: the catalog's quoted preload
    motor: object = None  # servo motor row, or None (the axis's motor_inertia; drive checks off)
    coupling: object = None  # coupling row, or None (the axis's coupling values)
    # reduction row (gearbox or belt stage), or None (the axis's reduction_* values)
    reduction: object = None
    # lead accuracy grade (C0..C10); None: the cheapest the screw is made in
    screw_grade: str | None = None
    name: str = "design"
    source: str = ""
    assumed: tuple = field(default=())  # axis keys left at their defaults, for reports

    @property
    def preload(self) -> float:
        """The nut preload [N]: ``nut_preload``, else the catalog's (a double nut's stiffness
        preload, a single nut's least preload)."""
        if self.nut_preload is not None:
            return self.nut_preload
        return (
            float(self.nut["stiffness_preload"])
            if self.nut["type"] == "double"
            else float(self.nut["preload_min"])
        )

    @property
    def grade(self) -> str:
        """The screw's lead accuracy grade: the design's, else the cheapest its series is made in
        (:meth:`axisopt.catalog.grades.GradeTable.cheapest`; C5 for every shipped series)."""
        if self.screw_grade is not None:
            return self.screw_grade
        from ..catalog.grades import grade_table

        t = grade_table()
        return t.cheapest(t.orderable(str(self.screw["vendor"]), str(self.screw["series"])))

    def part_ids(self) -> dict:
        """Slot -> catalog part id of each part the design has."""
        return {k: str(getattr(self, k)["id"]) for k in PART_SLOTS if getattr(self, k) is not None}

    def part_rows(self) -> list[dict]:
        """The parts as rows of (part, id, column, value, unit): each catalog value in the unit its
        vendor quotes (the shipped catalog file's header: mm, N/um, kN, kg.cm^2, EUR ...;
        :mod:`axisopt.catalog.partrow`), text as it is in the catalog, an empty optional cell left
        out; ``to_frame()`` is these rows as a table."""
        from ..catalog.partrow import row_rows

        tables = {
            "screw": "screws",
            "nut": "nuts",
            "bearing": "bearings",
            "guide": "guides",
            "motor": "motors",
            "coupling": "couplings",
            "reduction": "reductions",
        }
        rows = []
        for slot in PART_SLOTS:
            part = getattr(self, slot)
            if part is None:
                continue
            rows.extend(
                {"part": slot, "id": str(part["id"]), **r}
                for r in row_rows(part, tables[slot])
                if r["column"] != "id"
            )
        return rows

    def to_frame(self):
        """pandas DataFrame of the parts, one row per catalog value: ``part``, ``id``, ``column``,
        ``value`` and ``unit`` (the unit vendors quote; the axis's own inputs are in the repr and
        the design file)."""
        from ..display import frame

        return frame(self.part_rows(), ("part", "id", "column", "value", "unit"))

    def _repr_html_(self) -> str:
        from ..display import html_table

        return html_table(self.part_rows(), repr(self), max_rows=200)

    # the parts are catalog rows: a dataclass repr would print them whole
    def __repr__(self) -> str:
        a = self.axis
        parts = ", ".join(f"{k} {v}" for k, v in self.part_ids().items())
        return one_line(
            "Design",
            repr(self.name),
            {
                "": f"{a.mounting}, {a.orientation}",
                "stroke": fmt(a.stroke * 1e3, "mm"),
                "moving mass": fmt(a.moving_mass, "kg"),
                "max speed": fmt(a.max_speed * 60, "m/min"),
                "axial load": fmt(a.axial_load, "N"),
                "parts": f"{parts} (nut preload {fmt(self.preload, 'N')})",
            },
        )


__all__ = [
    "Axis",
    "Design",
    "PART_SLOTS",
    "MECH_SLOTS",
    "DRIVE_SLOTS",
    "MOUNTINGS",
    "ORIENTATIONS",
    "BRAKE_MODES",
    "G",
]
