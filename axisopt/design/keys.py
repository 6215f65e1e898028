"""The YAML keys of a design file, one table per section: ``axis`` (:data:`AXIS_SPEC`, with the duty
cycle's moves and dwells), ``parts`` (:data:`PARTS_SPEC`; an inline custom part: :data:`PART_SPECS`)
and the file (:data:`DESIGN_SPEC`).  The readers read by these tables (:mod:`.reader`) and
``axisopt schema`` writes them out as a JSON Schema.
"""

from __future__ import annotations

from ..catalog.grades import SCALE_GRADES
from ..yamlio import Key, Spec
from .axis import BRAKE_MODES, MOUNTINGS, ORIENTATIONS
from .partkeys import PARTS_SPEC
from .sectionkeys import (
    COUNTERBALANCE_SPEC,
    DWELL_SPEC,
    MOVE_SPEC,
    SEGMENT_LIMIT,
    TWIN_SPEC,
    axis_q,
)

# Each table below is the one declaration of its section's keys: the readers read them by it
# (Section.read) and `axisopt schema` writes it out as a JSON Schema.  Unset axis keys take the Axis
# defaults (.axis).


# Upper bounds where a value beyond them leaves the model's range: a screw 100 K above ambient is
# not in operation, and the linear thermal model (constant alpha, elastic bearing sets) no longer
# holds.  Plausible drive ranges: a belt or gear stage of a feed drive reduces by at most about 1:20
# either way (1:50 allowed); an inertia-ratio limit beyond 1000 or a brake safety factor beyond 10
# is no limit at all.
AXIS_SPEC = Spec(
    "axis",
    "what the machine asks of the axis (every dimensional value with its unit)",
    {
        "stroke": axis_q("length", "travel of the table", required=True),
        "moving_mass": axis_q(
            "mass", "table + workpiece, without nut and guide blocks", required=True
        ),
        "mounting": Key(
            "choice",
            "screw end supports (a problem: the default mounting)",
            required=True,
            choices=MOUNTINGS,
        ),
        "max_speed": axis_q("speed", "rapid traverse speed", required=True),
        "axial_load": axis_q(
            "force", "largest external axial (cutting) load", required=True, zero=True
        ),
        "start_offset": axis_q("length", "fixed bearing to nut at stroke start, l0"),
        "end_margin": axis_q("length", "nut at stroke end to the far bearing", zero=True),
        "mean_speed": axis_q("speed", "mean speed for the life (default: half of max_speed)"),
        "mean_axial_load": axis_q(
            "force", "mean axial load for the life (default: a third of axial_load)", zero=True
        ),
        "acceleration": axis_q("acceleration", "acceleration of the moves", zero=True),
        "required_life": axis_q(
            "time",
            "required life of the nut, bearings and guides (problem default: its "
            "limits.min_life, else 20000 h)",
        ),
        "load_factor": Key(
            "number",
            "load factor fw of the life calculation (default: THK A-704 Table 19 by max_speed, the "
            "upper end of its row: 1.2 up to 15 m/min, 1.5 to 60, 2 to 120, else 3.5)",
            minimum=1.0,
            maximum=10.0,
        ),
        "guide_blocks": Key(
            "number", "guide blocks carrying the table", integer=True, minimum=1, maximum=64
        ),
        "rails": Key("number", "guide rails", integer=True, minimum=1, maximum=8),
        "table_length": axis_q("length", "table length (rail length = stroke + table_length)"),
        "normal_load": axis_q(
            "force",
            "cutting force pressing onto the guide blocks, besides gravity (default 0 N: "
            "solve then says the guides were sized without it)",
            zero=True,
        ),
        "lubricant_viscosity": axis_q(
            "kinematic_viscosity", "lubricant viscosity at working temperature"
        ),
        "motor_inertia": axis_q("inertia", "motor rotor inertia (when no motor part is chosen)"),
        "bearing_housing_stiffness": axis_q(
            "stiffness",
            "one support-bearing housing (default, an estimate: 26 x "
            "the bearing set, IBC's units against their bare sets)",
        ),
        "nut_bracket_stiffness": axis_q(
            "stiffness",
            "nut bracket / table connection (default, an estimate: 4 x the "
            "nut, THK's 80 % nut-mounting allowance taken once more)",
        ),
        "coupling_stiffness": axis_q(
            "torsional_stiffness", "coupling torsional stiffness (when no coupling part)"
        ),
        "coupling_inertia": axis_q("inertia", "coupling inertia (when no coupling part)"),
        "temperature_rise": axis_q(
            "temperature_difference",
            "screw temperature rise in operation (default: the "
            "heat balance of the duty cycle when the axis has one, else 3 K)",
            zero=True,
            maximum=(100.0, "100 K"),
        ),
        "pretension": Key(
            "one_of",
            "fixed-fixed screw pretension (default auto: absorbs pretension_rise)",
            options=(
                Key("choice", choices=("auto",)),
                Key("quantity", kind="force", non_negative=True),
            ),
        ),
        "pretension_rise": axis_q(
            "temperature_difference",
            "design temperature rise the auto pretension of a "
            "fixed-fixed screw absorbs, E A alpha dT (default 3 K: THK A-715 plans for 2-5 degC; "
            "HIWIN-style guidance about 3 degC)",
            zero=True,
            maximum=(10.0, "10 K"),
        ),
        "orientation": Key(
            "choice", "axis orientation", choices=ORIENTATIONS, default="horizontal"
        ),
        "positions": Key(
            "number",
            "nut positions evaluated over the stroke",
            integer=True,
            minimum=3,
            maximum=2001,
        ),
        "jerk": axis_q("jerk", "jerk limit (default: trapezoidal moves)"),
        "duty_cycle": Key(
            "list",
            "moves and dwells (default: the rapid move over the stroke and back)",
            minimum=1,
            maximum=SEGMENT_LIMIT,
            items=Key(
                "one_of", options=(Key("section", spec=MOVE_SPEC), Key("section", spec=DWELL_SPEC))
            ),
        ),
        "reduction_ratio": Key(
            "number",
            "motor turns per screw turn (2: a 2:1 belt or gear; when no reduction part)",
            positive=True,
            minimum=0.02,
            maximum=50.0,
        ),
        "reduction_efficiency": Key(
            "number", "efficiency of the reduction, in (0, 1]", positive=True, maximum=1.0
        ),
        "reduction_inertia": axis_q("inertia", "inertia of the reduction at the motor shaft"),
        "max_inertia_ratio": Key(
            "number",
            "largest load / rotor inertia ratio at the motor",
            positive=True,
            maximum=1000.0,
        ),
        "brake": Key(
            "one_of",
            "holding brake (auto: vertical axes)",
            default="auto",
            options=(Key("choice", choices=BRAKE_MODES), Key("choice", choices=(True, False))),
        ),
        "brake_safety": Key(
            "number",
            "brake holding torque / holding torque at the heaviest stop (THK A-745)",
            positive=True,
            minimum=1.0,
            maximum=10.0,
        ),
        "heat_transfer": axis_q(
            "heat_transfer",
            "film coefficient of the screw shaft for the heat balance "
            "(default: Jungnickel's rotating shaft in still air, 3.75 omega^0.7 r^0.4, over the "
            "cycle, with free convection)",
        ),
        "rms_torque_ratio": Key(
            "number",
            "largest RMS torque / rated torque of the motor (default: the motor "
            "vendor's rule, model.motorrule: Yaskawa and Siemens 1, Mitsubishi 0.8 (MDS-D-SVJ3 "
            "sec. 7-1 eq. 7-10), FANUC 0.9; e.g. 0.8 to hold every motor to Mitsubishi's)",
            positive=True,
            maximum=1.0,
        ),
        "torque_limit": axis_q(
            "torque",
            "the drive's torque (current) limit at the motor shaft (default: none, the "
            "motor's peak torque): what the motor gives at most, through the coupling and a "
            "reduction to its emergency-stop torque (apexdyna current limitation; SEW)",
        ),
        "cut_while_accelerating": Key(
            "choice",
            "the largest process force acts while the axis accelerates (default "
            "no: the cut at feed speed and the inertia in the rapid are separate load cases "
            "of the nut lift-off check, THK A-725; yes: both at once)",
            choices=(True, False),
            default=False,
        ),
        "feedback": Key(
            "choice",
            "position feedback: motor_encoder (semi-closed loop; default) or linear_scale (a scale "
            "on the table closes the loop: its grade's error in place of the screw's lead and "
            "thermal rows of the positioning budget; needs scale_grade)",
            choices=("motor_encoder", "linear_scale"),
            default="motor_encoder",
        ),
        "scale_grade": Key(
            "choice",
            "the linear scale's accuracy grade (grades.SCALE_GRADES: AMO LMB +-3 / +-5 um/m, "
            "HIWIN PMS magnetic +-20 um/m)",
            choices=tuple(SCALE_GRADES),
        ),
        "controller": Key(
            "choice",
            "the position loop's structure, for diagnose's time records: pd (a PD position "
            "controller) or p_pi_cascade (position P, velocity PI); default: fitted from the "
            "record's reference column",
            choices=("pd", "p_pi_cascade"),
        ),
        "pitch_compensation": Key(
            "choice",
            "the controller compensates the screw's pitch error (a semi-closed loop): "
            "the lead row becomes what compensation leaves, the fluctuation v_u about the "
            "representative travel (THK A-677; C7-C10: the error per 300 mm); default no",
            choices=(True, False),
            default=False,
        ),
        "rise_without_cycle": Key(
            "choice",
            "the screw's temperature rise where the axis gives no duty_cycle and no "
            "temperature_rise: practice (THK A-715's 2-5 degC planning range: 3 K; default) or "
            "balance (the heat balance of the default cycle, continuous rapids: conservative)",
            choices=("practice", "balance"),
            default="practice",
        ),
        "buckling_nut_end": Key(
            "choice",
            "how the nut holds the shaft in the buckling check: fixed (a long nut in a "
            "rigid bracket, THK A-726's examples; default) or supported (a pinned end, MiSUMi "
            "'Selection of Ball Screws 2': half the load)",
            choices=("fixed", "supported"),
            default="fixed",
        ),
        # carriage: the cutting force's cross component and where it acts, the centre of gravity,
        # the block pattern; heights above the guide mounting plane (the screw axis is taken to lie
        # in it)
        "cross_load": axis_q(
            "force",
            "cutting force across the rail (feed: axial_load, normal: normal_load; default "
            "0 N: solve then says the guides were sized without it)",
            zero=True,
        ),
        "tool_height": axis_q(
            "length",
            "cutting point above the guide mounting plane (default 0.4 x table_length)",
            zero=True,
        ),
        "tool_offset": axis_q(
            "length", "cutting point across the rail from the carriage centre", zero=True
        ),
        "guide_pitch": axis_q(
            "angle",
            "running pitch of the guides over the stroke (e.g. 10 arcsec; default 0): its "
            "Abbe error at the tool_height enters the positioning budget (THK A-716)",
            zero=True,
            maximum=(0.01, "0.01 rad"),
        ),
        "guide_yaw": axis_q(
            "angle",
            "running yaw of the guides over the stroke (default 0): its Abbe error at the "
            "tool_offset enters the positioning budget (THK A-716)",
            zero=True,
            maximum=(0.01, "0.01 rad"),
        ),
        "cg_height": axis_q(
            "length",
            "moving mass's centre of gravity above the guide mounting plane "
            "(default 0.2 x table_length)",
            zero=True,
        ),
        "cg_offset": axis_q(
            "length",
            "moving mass's centre of gravity across the rail from the carriage centre",
            zero=True,
        ),
        "table_width": axis_q("length", "table width across the rails (default: table_length)"),
        "block_spacing": axis_q(
            "length",
            "outer block to outer block along a rail, at most table_length "
            "(default 0.6 x table_length)",
        ),
        "rail_spacing": axis_q(
            "length", "outer rail to outer rail, at most table_width (default 0.6 x table_width)"
        ),
        "pitch_inertia": axis_q(
            "inertia",
            "moving mass about the cross axis in the mounting plane (default: a box "
            "table_length long, 2 x cg_height high)",
        ),
        "yaw_inertia": axis_q(
            "inertia",
            "moving mass about the normal axis (default: a box table_length x table_width)",
        ),
        "guide_static_safety": Key(
            "number",
            "least guide static safety C0 / largest block load (default 5: THK, "
            "with vibrations or impacts)",
            minimum=1.0,
            maximum=100.0,
        ),
        "nut_static_safety": Key(
            "number",
            "least nut static safety C0a / largest axial force (default 5: THK, with "
            "vibrations or impacts)",
            minimum=1.0,
            maximum=100.0,
        ),
        "bearing_static_safety": Key(
            "number",
            "least support-bearing static safety: static rating of the rows / "
            "largest axial load on them (default: the rating's vendor's, NSK 1/0.7 on its "
            "limiting load, THK 1 on its permissible load, else Rexroth's 4 for machine "
            "tools)",
            minimum=1.0,
            maximum=100.0,
        ),
        "nut_lift_off_safety": Key(
            "number",
            "least nut lift-off force (2.83 x preload) / largest axial force (default "
            "1: THK A-687, HIWIN F 3.6)",
            minimum=1.0,
            maximum=100.0,
        ),
        "counterbalance": Key(
            "section",
            "vertical axes: a counterweight {kind: counterweight, mass: 450 kg, efficiency: "
            "0.95} or a balance cylinder {kind: cylinder, force: 5000 N, force_at_end: 5600 N, "
            "tolerance: 5 %} taking the head's weight (default: none)",
            spec=COUNTERBALANCE_SPEC,
        ),
        "twin_drive": Key(
            "section",
            "a twin-drive gantry: two drives under one bridge (default: one drive)",
            spec=TWIN_SPEC,
        ),
    },
)
AXIS_KINDS = {name: k.kind for name, k in AXIS_SPEC.keys.items() if k.type == "quantity"}
AXIS_REQUIRED = tuple(name for name, k in AXIS_SPEC.keys.items() if k.required)
AXIS_NUMBERS = (
    "reduction_ratio",
    "max_inertia_ratio",
    "brake_safety",
    "reduction_efficiency",
    "guide_static_safety",
    "nut_static_safety",
    "rms_torque_ratio",
    "bearing_static_safety",
    "nut_lift_off_safety",
)


NAME_KEY = Key("string", "name of the file's subject (default: the file name)")
DESCRIPTION_KEY = Key("string", "free text")
CATALOGS_KEY = Key("names", "extra catalog directories, relative to this file")
DESIGN_SPEC = Spec(
    "design",
    "an axis design: the machine's requirements and one part per slot",
    {
        "name": NAME_KEY,
        "description": DESCRIPTION_KEY,
        "catalogs": CATALOGS_KEY,
        "axis": Key("section", required=True, spec=AXIS_SPEC),
        "parts": Key("section", required=True, spec=PARTS_SPEC),
    },
)


__all__ = [
    "AXIS_SPEC",
    "DESIGN_SPEC",
    "NAME_KEY",
    "DESCRIPTION_KEY",
    "CATALOGS_KEY",
    "AXIS_KINDS",
    "AXIS_NUMBERS",
]
