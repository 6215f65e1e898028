"""Every output of the axis model, declared once: its SI unit, whether it is a profile over the
stroke, how it moves with the nut preload, and which parts of a design change it.

The CasADi Function's output list (:data:`PROFILE_OUTPUTS`, :data:`SCALAR_OUTPUTS` in
:mod:`.function`), the preload structure the search's exact 1-D solve rests on
(:data:`OUTPUT_PRELOAD`), the outputs the stiffness chain computes (:data:`CHAIN_OUTPUTS`:
``chain=False`` leaves them out), the regenerated-energy sum (:data:`REGEN_OUTPUTS`) and the outputs
a drive or a coupling changes (:data:`DRIVE_OUTPUTS`, :data:`COUPLING_OUTPUTS`) derive from
:data:`OUTPUT_TABLE`.  The vendor checks' ``margin_``, ``available_`` and ``needed_`` outputs derive
from :data:`axisopt.model.limits.CHECK_TABLE`.

A new output: one :class:`Output` here plus the physics that computes it (``model.response`` and
below).
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType

# a preload direction: the output is convex in the nut preload (met on an interval of preloads)
CONVEX = 2


@dataclass(frozen=True)
class Output:
    """One model output.

    name     : its key in the model's outputs (``Evaluation.values``, ``axis_response``)
    unit     : its SI unit, as pint reads it ("" for a ratio)
    doc      : what it is
    profile  : given per position over the stroke (a limit reads its minimum or maximum)
    preload  : how it moves with the nut preload: +1 nondecreasing, -1 nonincreasing,
               :data:`CONVEX`, 0 independent
    chain    : computed with the stiffness chain and the axial modes (left out when ``chain=False``)
    extra    : the drive-train frequencies and the damping (left out when ``extras=False``: no limit
               or objective reads them)
    regen    : the regenerated-energy sum over the duty cycle (left out when ``regen=False``)
    drive    : the motor, coupling or reduction changes it (every other output is the same for every
               drive of a mechanical combination); those without ``chain`` the drive block computes
               on its own (``model.drive_response``)
    coupling : the coupling's torsional stiffness changes it (in series in the stiffness chain)
    """

    name: str
    unit: str
    doc: str
    profile: bool = False
    preload: int = 0
    chain: bool = False
    extra: bool = False
    regen: bool = False
    drive: bool = False
    coupling: bool = False


def _p(name, unit, doc, **kw) -> Output:
    return Output(name, unit, doc, profile=True, **kw)


def _s(name, unit, doc, **kw) -> Output:
    return Output(name, unit, doc, **kw)


# How outputs move with the nut preload (the search's exact 1-D solve rests on it; default ==
# exhaustive in tests/search checks it): the minimum stiffness and frequency, the drag torque and
# the nut lift-off margin rise with the preload, the nut life falls.  The heat balance (model.heat)
# makes the temperature rise grow with the preload (nut drag x speed), and with it the thermal
# growth.  The positioning budget's deflection falls with the preload; its other rows are
# independent of it (the thermal row at the nut's highest preload).  The nut's drag brakes
# every move: the energy the motor returns falls with the preload.
OUTPUT_TABLE = (
    # profiles over the stroke
    _p("k_screw", "N/m", "axial stiffness of the screw shaft at the nut", chain=True),
    _p("k_screw_bearings", "N/m", "screw shaft and support sets in series", chain=True),
    _p("k_torsion", "N/m", "torsional stiffness of the screw seen axially at the nut", chain=True),
    _p(
        "k_drive",
        "N/m",
        "axial stiffness of the drive chain (screw, sets, nut, mounts)",
        preload=1,
        chain=True,
    ),
    _p(
        "k_total",
        "N/m",
        "axial stiffness of the feed axis at the table",
        preload=1,
        chain=True,
        coupling=True,
    ),
    _p(
        "f_axial",
        "Hz",
        "first axial natural frequency of the table on the drive chain",
        preload=1,
        chain=True,
        coupling=True,
    ),
    _p(
        "f1",
        "Hz",
        "first natural frequency (the least of the axial and, on a gantry, the gantry modes)",
        preload=1,
        chain=True,
        coupling=True,
    ),
    _p("m_eff", "kg", "effective moving mass of the axial mode", chain=True),
    _p("thermal_displacement", "m", "thermal displacement of the nut along the stroke", chain=True),
    _p(
        "f_axial_torsional",
        "Hz",
        "first coupled axial-torsional natural frequency",
        coupling=True,
        extra=True,
    ),
    _p(
        "f_axial_torsional_2",
        "Hz",
        "second coupled axial-torsional natural frequency",
        coupling=True,
        extra=True,
    ),
    _p(
        "damping_ratio",
        "",
        "modal damping ratio of the first axial mode",
        coupling=True,
        extra=True,
    ),
    _p("zeta_guides", "", "damping ratio share of the guides", coupling=True, extra=True),
    _p("zeta_nut", "", "damping ratio share of the nut", coupling=True, extra=True),
    _p(
        "zeta_bearings",
        "",
        "damping ratio share of the support bearings",
        coupling=True,
        extra=True,
    ),
    _p("zeta_structure", "", "damping ratio share of the structure", extra=True),
    _p(
        "k_tool",
        "N/m",
        "stiffness in the feed direction at the cutting point",
        preload=1,
        chain=True,
        coupling=True,
    ),
    _p("kv", "1/s", "achievable position-loop gain", preload=1, chain=True, coupling=True),
    _p("f_gantry", "Hz", "first gantry (bridge) natural frequency", chain=True),
    _p("f_racking", "Hz", "racking natural frequency of a twin-drive gantry", chain=True),
    _p("k_racking", "N*m/rad", "racking stiffness of a twin-drive gantry", chain=True),
    # scalars
    _s("k_nut", "N/m", "axial stiffness of the nut at its preload", preload=1, chain=True),
    _s("k_nut_unloaded", "N/m", "catalog stiffness of the nut", chain=True),
    _s("k_bearing", "N/m", "axial stiffness of the support sets", chain=True),
    _s(
        "k_coupling",
        "N/m",
        "torsional stiffness of the coupling seen axially",
        chain=True,
        coupling=True,
    ),
    _s("c_bracket", "m/N", "compliance of the nut bracket", chain=True),
    _s("c_housing", "m/N", "compliance of the support-set housings", chain=True),
    _s("f_table", "Hz", "natural frequency of the table on the nut alone", chain=True),
    _s(
        "drag_torque",
        "N*m",
        "drag torque at the rapid speed (nut, support bearings and guides)",
        preload=1,
    ),
    _s("drag_nut", "N*m", "drag torque of the preloaded nut", preload=1),
    _s("drag_bearings", "N*m", "drag torque of the support bearings"),
    _s("drag_guides", "N*m", "drag torque of the guides at the screw"),
    _s("moving_mass", "kg", "moving mass the drive carries"),
    _s("total_mass", "kg", "total mass of the axis parts"),
    _s("screw_mass", "kg", "mass of the screw shaft"),
    _s("cost", "EUR", "cost of the parts", drive=True),
    _s("max_axial_force", "N", "largest axial force on the nut over the duty cycle"),
    _s("mean_axial_force", "N", "cubic-mean axial force on the nut"),
    _s("guide_friction", "N", "friction force of the guides"),
    _s("pretension", "N", "screw pretension of a fixed-fixed mounting"),
    _s("thermal_force", "N", "thermal force of a fixed-fixed screw beyond its pretension"),
    _s("bearing_static_load", "N", "largest static axial load on the support set"),
    _s("screw_compression", "N", "largest compressive force on the screw"),
    _s(
        "backlash",
        "m",
        "lost motion at the table (nut play and a reduction's backlash)",
        drive=True,
    ),
    _s("life", "s", "nut L10 life", preload=-1),
    _s("bearing_life", "s", "support-set L10 life"),
    _s("guide_life", "m", "guide block L10 travel"),
    _s("screw_speed", "rad/s", "screw speed at the rapid speed"),
    _s("critical_speed", "rad/s", "critical (whirling) speed of the screw"),
    _s("buckling_load", "N", "buckling load of the screw"),
    _s("yield_load", "N", "permissible tensile-compressive load of the screw (THK P2)"),
    _s("dn", "m*rad/s", "DN value at the rapid speed"),
    _s("nut_lift_off_force", "N", "axial force at which a half of the preloaded nut unloads"),
    _s("bearing_max_load", "N", "largest axial load on the support set"),
    _s("load_inertia", "kg*m**2", "load inertia at the motor", drive=True),
    _s("total_inertia", "kg*m**2", "load and rotor inertia at the motor", drive=True),
    _s("inertia_ratio", "", "load-to-rotor inertia ratio", drive=True),
    _s("motor_speed", "rad/s", "motor speed at the rapid speed", drive=True),
    _s("peak_torque", "N*m", "peak motor torque of the duty cycle", drive=True),
    _s("rms_torque", "N*m", "RMS motor torque of the duty cycle", drive=True),
    _s("thrust_torque", "N*m", "motor torque under the largest process force", drive=True),
    _s("mean_thrust_torque", "N*m", "motor torque under the mean process force", drive=True),
    _s(
        "unbalance_torque",
        "N*m",
        "steady load torque of an unbalanced (vertical) axis at the motor",
        drive=True,
    ),
    _s("holding_torque", "N*m", "torque that holds a vertical axis at rest", drive=True),
    _s("friction_torque", "N*m", "friction torque at the motor", drive=True),
    _s("gravity_torque", "N*m", "gravity torque at the motor of a vertical axis", drive=True),
    _s(
        "regen_energy",
        "J",
        "energy the motor returns over the duty cycle",
        preload=-1,
        regen=True,
        drive=True,
    ),
    _s(
        "regen_power",
        "W",
        "mean power the motor returns over the duty cycle",
        preload=-1,
        regen=True,
        drive=True,
    ),
    _s("output_peak_torque", "N*m", "peak output torque of the reduction", drive=True),
    _s("output_rms_torque", "N*m", "RMS output torque of the reduction", drive=True),
    _s("duty_time", "s", "duration of the duty cycle"),
    _s("guide_max_load", "N", "largest guide block load"),
    _s("guide_static_safety", "", "static safety factor of the most loaded guide block"),
    _s("guide_mean_load", "N", "cubic-mean guide block load"),
    _s("nut_static_safety", "", "static safety factor of the nut"),
    _s("k_pitch", "N*m/rad", "pitch stiffness of the table on its blocks", chain=True),
    _s("k_yaw", "N*m/rad", "yaw stiffness of the table on its blocks", chain=True),
    _s("f_pitch", "Hz", "pitch natural frequency of the table", chain=True),
    _s("f_yaw", "Hz", "yaw natural frequency of the table", chain=True),
    _s("c_rocking", "m/N", "compliance at the tool from the table pitching and yawing", chain=True),
    _s("friction_power", "W", "friction heat of the nut and support bearings", preload=1),
    _s("heat_transfer", "W/K", "heat transfer coefficient of the screw's thermal network"),
    _s("heat_balance_rise", "K", "temperature rise of the heat balance", preload=1),
    _s("temperature_rise", "K", "temperature rise of the screw the model takes", preload=1),
    _s(
        "thermal_growth",
        "m",
        "largest thermal growth of the screw at the nut",
        preload=1,
        chain=True,
    ),
    _s("c_unit_bearing", "m/N", "compliance of a rotating-nut unit's bearing", chain=True),
    _s("screw_sag", "m", "sag of a horizontal screw under its own weight"),
    _s("screw_slenderness", "", "bearing span over the nominal screw diameter"),
    _s("unit_bearing_life", "s", "L10 life of a rotating-nut unit's bearing"),
    _s("gantry_moving_mass", "kg", "moving mass of the whole gantry"),
    _s(
        "lead_error",
        "m",
        "positioning budget: lead error of the screw's grade over the stroke",
        chain=True,
    ),
    _s("thermal_error", "m", "positioning budget: thermal growth", chain=True),
    _s(
        "elastic_error",
        "m",
        "positioning budget: deflection at the tool",
        preload=-1,
        chain=True,
        coupling=True,
    ),
    _s(
        "abbe_error", "m", "positioning budget: Abbe error of the guides' pitch and yaw", chain=True
    ),
    _s("lost_motion", "m", "positioning budget: lost motion", chain=True, drive=True),
    _s(
        "positioning_error",
        "m",
        "positioning budget: worst-case total",
        preload=-1,
        chain=True,
        coupling=True,
        drive=True,
    ),
    _s(
        "repeatability",
        "m",
        "repeatability (ISO 230-2: reversal + noise band)",
        chain=True,
        drive=True,
    ),
)
OUTPUTS = MappingProxyType({o.name: o for o in OUTPUT_TABLE})
PROFILE = tuple(o.name for o in OUTPUT_TABLE if o.profile)
SCALAR = tuple(o.name for o in OUTPUT_TABLE if not o.profile)
OUTPUT_PRELOAD = MappingProxyType({o.name: o.preload for o in OUTPUT_TABLE if o.preload})
CHAIN_OUTPUTS = frozenset(o.name for o in OUTPUT_TABLE if o.chain)
EXTRA_OUTPUTS = frozenset(o.name for o in OUTPUT_TABLE if o.extra)
REGEN_OUTPUTS = frozenset(o.name for o in OUTPUT_TABLE if o.regen)
DRIVE_OUTPUTS = frozenset(o.name for o in OUTPUT_TABLE if o.drive)
COUPLING_OUTPUTS = frozenset(o.name for o in OUTPUT_TABLE if o.coupling)
