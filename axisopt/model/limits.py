"""What a sizing problem may limit and which vendor checks the model runs: one declaration each.

A :class:`Limit` is a bound a problem file sets on a model output
(``limits: min_stiffness: 150 N/um``); a :class:`Check` is a vendor rule the model always evaluates
as a margin (available / needed, >= 1 passes).  Everything else is derived from these two tables:
the problem reader and its JSON schema, the search's constraints and the direction each moves with
the nut preload, the sensitivity report, the candidate's outputs, and the evaluation's check rows
with their units.  Adding a limit or a check is one entry here plus the physics that computes its
output (``model.checks`` for a check's margin and available/needed values).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

from .outputs import CONVEX, OUTPUT_PRELOAD

RPM = 60.0 / (2.0 * math.pi)  # rad/s -> rpm


@dataclass(frozen=True)
class Limit:
    """A bound on a model output that a problem may set.

    key      : the problem file's key under ``limits:``
    output   : the model output it bounds (minimum over the stroke for a profile output)
    sense    : '<=' or '>=' (output sense limit)
    kind     : quantity kind of the value (:data:`axisopt.units.KINDS`)
    unit     : display unit; ``factor`` is SI per display unit
    doc      : what it means, for the schema and ``--help``
    zero_ok  : 0 is an allowed value (otherwise it must be positive)
    default  : applies when a problem does not set it (None: no default)
    """

    key: str
    output: str
    sense: str
    kind: str
    unit: str
    factor: float
    doc: str
    zero_ok: bool = False
    default: float | None = None

    @property
    def preload(self) -> int:
        return OUTPUT_PRELOAD.get(self.output, 0)


LIMIT_TABLE = (
    Limit("max_moving_mass", "moving_mass", "<=", "mass", "kg", 1.0, "moving mass at most this"),
    Limit(
        "max_total_mass",
        "total_mass",
        "<=",
        "mass",
        "kg",
        1.0,
        "total mass of the axis parts at most this",
    ),
    Limit("max_cost", "cost", "<=", "money", "EUR", 1.0, "cost of the parts at most this"),
    Limit(
        "max_drag_torque",
        "drag_torque",
        "<=",
        "torque",
        "N.m",
        1.0,
        "drag torque (nut, support bearings and guides, at the rapid speed) at most this",
    ),
    Limit(
        "min_life",
        "life",
        ">=",
        "time",
        "h",
        3600.0,
        "nut L10 life at least this; without axis.required_life also the need of the nut, bearing "
        "and guide life checks",
    ),
    Limit(
        "min_stiffness",
        "k_total",
        ">=",
        "stiffness",
        "N/um",
        1e6,
        "axial stiffness at least this (minimum over the stroke)",
    ),
    Limit(
        "min_frequency",
        "f1",
        ">=",
        "frequency",
        "Hz",
        1.0,
        "first natural frequency at least this (minimum over the stroke)",
    ),
    # a machine-tool feed axis has no backlash: single nuts with axial play are allowed only when
    # the problem says max_backlash > 0
    Limit(
        "max_backlash",
        "backlash",
        "<=",
        "length",
        "um",
        1e-6,
        "axial play of the nut at most this (default 0: preloaded nuts only)",
        zero_ok=True,
        default=0.0,
    ),
    Limit(
        "max_inertia_ratio",
        "inertia_ratio",
        "<=",
        "dimensionless",
        "",
        1.0,
        "load / rotor inertia ratio at the motor at most this",
    ),
    Limit(
        "max_thermal_growth",
        "thermal_growth",
        "<=",
        "length",
        "um",
        1e-6,
        "thermal growth of the screw at the nut (largest over the stroke; heat balance of the duty "
        "cycle) at most this",
    ),
    Limit(
        "min_tool_stiffness",
        "k_tool",
        ">=",
        "stiffness",
        "N/um",
        1e6,
        "stiffness in the feed direction at the cutting point: the axial chain in series with the "
        "table pitching and yawing on its blocks (minimum over the stroke)",
    ),
    Limit(
        "max_regen_power",
        "regen_power",
        "<=",
        "power",
        "W",
        1.0,
        "mean power the motor returns to the drive over the duty cycle (braking, lowering) at most "
        "this: what the drive's regenerative resistor takes (Yaskawa Sigma-7 12.8.6)",
    ),
    Limit(
        "max_slenderness",
        "screw_slenderness",
        "<=",
        "dimensionless",
        "",
        1.0,
        "bearing span / nominal screw diameter at most this (Schneeberger: consult the maker above "
        "40, an intermediate support above 50; evaluate warns above 50)",
    ),
    Limit(
        "max_screw_sag",
        "screw_sag",
        "<=",
        "length",
        "mm",
        1e-3,
        "sag of a horizontal screw under its own weight at most this (beam deflection q L^4 / (k E "
        "I) on the root diameter, untensioned: conservative; 0 on a vertical axis)",
    ),
    Limit(
        "max_positioning_error",
        "positioning_error",
        "<=",
        "length",
        "um",
        1e-6,
        "positioning error at most this: lead error of the screw's grade over the stroke + thermal "
        "growth + deflection at the tool under axial_load + Abbe error of the guides' pitch and "
        "yaw + lost motion, added as a worst case (THK A-712..A-716); the search chooses the grade "
        "(catalog.screw_grades)",
    ),
    Limit(
        "max_repeatability",
        "repeatability",
        "<=",
        "length",
        "um",
        1e-6,
        "repeatability at most this (ISO 230-2 scatter: the reversal, lost motion, + a scale read "
        "head's noise band; the thermal drift is its own row of the budget)",
    ),
    Limit(
        "min_kv",
        "kv",
        ">=",
        "frequency",
        "1/s",
        1.0,
        "achievable position-loop gain Kv at least this (1/s or m/min/mm; minimum over the stroke, "
        "model.servo)",
    ),
)
LIMITS = MappingProxyType({lim.key: lim for lim in LIMIT_TABLE})


MARGIN = "margin_"  # a check's model output is MARGIN + its name (Check.output)


def margin_output(check: str) -> str:
    """The model output of check ``check``: its margin (available / needed), ``margin_<check>``."""
    return MARGIN + check


def check_name(output: str) -> str | None:
    """The check whose margin the model output (or constraint) ``output`` is; None: not a check's
    margin."""
    return output[len(MARGIN) :] if output.startswith(MARGIN) else None


@dataclass(frozen=True)
class Check:
    """A vendor check the model evaluates as ``margin_<name>`` = available / needed (>= 1 passes).

    label    : what the margin compares ('available / needed'), for tables and the search's
               constraints
    short    : a short name for tables with one column per design
    unit     : the unit vendors quote the compared values in; ``factor`` converts SI to it
    preload  : how the margin moves with the nut preload (see :data:`OUTPUT_PRELOAD`)
    drive    : a drive check: it applies only when the design has a motor (coupling checks: a
               coupling; reduction checks: a reduction)
    relaxable: a rule with a margin one may trade (False: a compatibility rule, parts that fit or
               not; an infeasible problem's explanation never proposes relaxing it)
    rotating_nut : a check of a driven rotating-nut unit (model.checks.unit_checks): shown for such
        a nut only
    set_by   : what of the axis sets its needed value, for the advice on an infeasible problem
               (search.advice): 'speed' (the rapid speed: the need grows in proportion),
               'acceleration' (with the moving mass), 'weight' (on a vertical axis: what a
               counterbalance relieves), 'ratio' (what a reduction's ratio changes: reflected
               inertia, torque, motor speed)
    """

    name: str
    label: str
    short: str
    unit: str
    factor: float
    preload: int = 0
    drive: bool = False
    relaxable: bool = True
    rotating_nut: bool = False
    set_by: tuple = ()

    @property
    def output(self) -> str:
        """The model output of this check: its margin, ``margin_<name>``."""
        return margin_output(self.name)


SPEED, ACCEL, WEIGHT, RATIO = "speed", "acceleration", "weight", "ratio"
TORQUE_SET_BY = (ACCEL, WEIGHT, RATIO)  # a motor or reduction torque

# How the margins move with the nut preload (``preload``): the nut lift-off margin rises with it,
# the nut life falls, and the motor and reduction torques are convex (the nut's drag raises the
# torque of some phases of the cycle and lowers that of others: deceleration, lowering a vertical
# axis).  Through the heat balance the bearing life, bearing lift-off, screw yield and buckling
# margins fall with it (independent without a duty cycle).
CHECK_TABLE = (
    Check(
        "critical_speed",
        "critical speed / max screw speed",
        "critical speed",
        "rpm",
        RPM,
        set_by=(SPEED,),
    ),
    Check(
        "buckling", "buckling load / max screw compression", "buckling load", "kN", 1e-3, preload=-1
    ),
    Check(
        "screw_yield",
        "yield load (THK P2) / max screw tension",
        "screw yield load",
        "kN",
        1e-3,
        preload=-1,
    ),
    Check(
        "nut_life",
        "nut L10 life / required life",
        "nut life",
        "h",
        1 / 3600,
        preload=-1,
        set_by=(WEIGHT,),
    ),
    Check(
        "bearing_life",
        "support bearing L10 life / required life",
        "bearing life",
        "h",
        1 / 3600,
        preload=-1,
        set_by=(WEIGHT,),
    ),
    Check("guide_life", "guide block L10 travel / required travel", "guide travel", "km", 1e-3),
    Check("dn", "DN limit / DN at max speed", "DN value", "mm.rpm", 1e3 * RPM, set_by=(SPEED,)),
    Check(
        "nut_lift_off",
        "nut lift-off force / largest load case",
        "nut lift-off",
        "kN",
        1e-3,
        preload=1,
        set_by=(ACCEL, WEIGHT),
    ),
    Check(
        "nut_preload",
        "preload ceiling (10 % Ca, THK A-687) / nut preload",
        "nut preload ceiling",
        "kN",
        1e-3,
        preload=-1,
    ),
    Check(
        "bearing_lift_off",
        "bearing lift-off load / max bearing load",
        "bearing lift-off",
        "kN",
        1e-3,
        preload=-1,
        set_by=(ACCEL, WEIGHT),
    ),
    Check(
        "bearing_speed",
        "bearing limiting speed / max screw speed",
        "bearing speed",
        "rpm",
        RPM,
        set_by=(SPEED,),
    ),
    Check(
        "bearing_fit",
        "bearing bore within the screw end's range",
        "bearing bore (max)",
        "mm",
        1e3,
        relaxable=False,
    ),
    Check(
        "screw_length",
        "screw max length / needed length",
        "screw length",
        "mm",
        1e3,
        relaxable=False,
    ),
    Check(
        "motor_peak_torque",
        "motor peak zone / peak torque (cycle, thrust)",
        "motor peak torque",
        "N.m",
        1.0,
        preload=CONVEX,
        drive=True,
        set_by=TORQUE_SET_BY,
    ),
    Check(
        "motor_rated_torque",
        "rated x RMS ratio / RMS torque, mean thrust",
        "motor rated torque",
        "N.m",
        1.0,
        preload=CONVEX,
        drive=True,
        set_by=TORQUE_SET_BY,
    ),
    Check(
        "motor_speed",
        "motor max speed / needed motor speed",
        "motor speed",
        "rpm",
        RPM,
        drive=True,
        set_by=(SPEED, RATIO),
    ),
    Check(
        "inertia_ratio",
        "inertia ratio limit / load-to-rotor ratio",
        "inertia ratio",
        "",
        1.0,
        drive=True,
        set_by=(RATIO,),
    ),
    Check(
        "brake_holding",
        "brake torque / safety x gravity torque",
        "brake holding",
        "N.m",
        1.0,
        drive=True,
        set_by=(WEIGHT,),
    ),
    Check(
        "coupling_torque",
        "coupling rated torque / motor peak torque",
        "coupling torque",
        "N.m",
        1.0,
        drive=True,
    ),
    Check(
        "coupling_speed",
        "coupling max speed / max screw speed",
        "coupling speed",
        "rpm",
        RPM,
        drive=True,
        set_by=(SPEED,),
    ),
    # a reduction part (Beckhoff AG2400/AG3400 Mechanical data): the output torques of the cycle
    # against T2B and T2N, the motor speed against n1Max; convex in the nut preload like the motor
    # torques
    Check(
        "reduction_accel_torque",
        "reduction T2B / peak output torque (cycle, thrust)",
        "reduction T2B",
        "N.m",
        1.0,
        preload=CONVEX,
        drive=True,
        set_by=TORQUE_SET_BY,
    ),
    Check(
        "reduction_rated_torque",
        "reduction T2N / RMS output torque, mean thrust",
        "reduction T2N",
        "N.m",
        1.0,
        preload=CONVEX,
        drive=True,
        set_by=TORQUE_SET_BY,
    ),
    Check(
        "reduction_speed",
        "reduction n1Max / max motor speed",
        "reduction speed",
        "rpm",
        RPM,
        drive=True,
        set_by=(SPEED,),
    ),
    Check(
        "reduction_emergency_torque",
        "reduction T2Stop / motor peak x ratio",
        "reduction T2Stop",
        "N.m",
        1.0,
        drive=True,
        set_by=(RATIO,),
    ),
    Check(
        "guide_static",
        "guide block C0 / (least f_S x largest block load)",
        "guide static",
        "kN",
        1e-3,
    ),
    Check("nut_static", "nut C0a / (least f_S x largest axial force)", "nut static", "kN", 1e-3),
    # the static set load (pretension, thermal force) rises with the nut preload through the heat
    # balance
    Check(
        "bearing_static",
        "bearing C0a / (least S0 x largest axial load)",
        "bearing static",
        "kN",
        1e-3,
        preload=-1,
    ),
    # a driven rotating-nut unit (model.checks.unit_checks): its speed, its built-in bearing, its
    # mounting
    Check(
        "unit_speed",
        "rotating-nut unit max speed / max nut speed",
        "unit speed",
        "rpm",
        RPM,
        rotating_nut=True,
        set_by=(SPEED,),
    ),
    Check(
        "unit_bearing_life",
        "unit bearing L10 life / required life",
        "unit bearing life",
        "h",
        1 / 3600,
        rotating_nut=True,
    ),
    Check(
        "unit_bearing_static",
        "unit bearing C0a / (S0 4 x largest axial force)",
        "unit bearing static",
        "kN",
        1e-3,
        rotating_nut=True,
    ),
    Check(
        "rotating_mount",
        "rotating-nut unit on a screw fixed at both ends",
        "rotating nut mount",
        "",
        1.0,
        relaxable=False,
        rotating_nut=True,
    ),
)
CHECK_RECORDS = MappingProxyType({c.name: c for c in CHECK_TABLE})


def checks_set_by(what: str) -> frozenset:
    """The names of the checks whose need ``what`` (:data:`SPEED`, :data:`ACCEL`, :data:`WEIGHT`,
    :data:`RATIO`) sets."""
    return frozenset(c.name for c in CHECK_TABLE if what in c.set_by)


def preload_direction(output: str) -> int:
    """How a model output (or ``margin_<check>``) moves with the nut preload."""
    if check_name(output) in CHECK_RECORDS:
        return CHECK_RECORDS[check_name(output)].preload
    return OUTPUT_PRELOAD.get(output, 0)
