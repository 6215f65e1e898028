"""``axisopt init design|problem|study [--machine vmc|lathe|gantry|vertical|boring|laser] [--out
FILE] [--force]``: a commented YAML template for a named machine type that loads, solves or
evaluates as it is written.

The templates say what each value means and in which unit, and in particular where the process
(cutting) force goes: ``axis.axial_load`` (the largest force: nut stiffness under load, lift-off,
buckling, life with ``mean_axial_load``, the motor's steady thrust) and a duty-cycle entry's
``force:`` (the force during that entry only: the motor's peak and RMS torque over the cycle).  Each
machine's limits and catalog restrictions were chosen so that its problem is feasible and solves in
seconds; its design holds the parts of that problem's optimum (rounded preload), so ``evaluate``
passes every check.
"""

from __future__ import annotations

import sys
from pathlib import Path

from ..errors import InputError
from .common import EXIT_OK

KINDS = ("design", "problem", "study", "machine")
MACHINES = ("vmc", "lathe", "gantry", "vertical", "boring", "laser")

_FORCE_NOTE = """\
  # Where the process (cutting) force goes -- two places, forces in N or kN:
  #  axial_load:  the LARGEST external axial force on the table (cutting, clamping).
  #               Used for the nut stiffness under load, preload lift-off, buckling and
  #               the motor's steady thrust; mean_axial_load (default a third of it)
  #               sets the nut and bearing L10 life.
  #  duty_cycle force: the force during that move or dwell only, e.g.
  #               {move: 400 mm, speed: 2 m/min, force: 2500 N}; used for the motor's
  #               peak and RMS torque over the cycle.  Without a duty_cycle the cycle is
  #               a rapid move over the stroke and back with no process force.
  #               An entry may name its own moving_mass (a workpiece loaded or
  #               unloaded), at most axis.moving_mass: {dwell: 5 s, moving_mass: 300 kg}.
  # Inertia (moving_mass x acceleration), guide friction and, on a vertical axis,
  # gravity are added by the model: leave them out of these forces.
  # The cut's other two components load the guides (block loads, static safety,
  # guide life), with the point where the cut acts:
  #  normal_load: onto the rails;  cross_load: across them (0 N unless given:
  #               the guides are then sized without them, and solve says so);
  #  tool_height: cutting point above the guide mounting plane;
  #  tool_offset: cutting point across the rails from the carriage centre."""
# a lathe's template only: the rule of thumb is for turning (other processes split their forces
# otherwise)
_TURNING_NOTE = """
  #  Unknown?  Turning rule of thumb (Isakov, Cutting Tool Engineering 2013):
  #  feed Ff = 0.5 Fc and passive Fp = 0.25 Fc of the tangential force Fc; a rough
  #  guide, not a measurement."""

_MOUNT_NOTE = """\
  # Mounting stiffness: the machine's own parts, in series with the support bearings and the
  # nut.  Give your housings' and nut bracket's axial stiffness (FEM or measured) when known;
  # left out, each is an estimate named in every result that rests on it:
  # bearing_housing_stiffness: 20000 N/um  # one support-bearing housing (default: 26 x the
  #                                        #   bearing set, IBC's units against their bare sets)
  # nut_bracket_stiffness: 2000 N/um       # nut bracket to the table (default: 4 x the nut,
  #                                        #   THK's 80 % nut-mounting allowance once more)
"""

# Per machine: title, name, the axis section (after 'axis:'), the problem's objective to continuous
# sections, the design's parts, and the study's sweep.
_MACHINE = {
    "vmc": dict(
        title="vertical machining centre, X axis",
        name="vmc-x",
        description="VMC X axis: 450 kg table and workpiece, 800 mm stroke, 24 m/min rapids.",
        axis="""\
  stroke: 800 mm              # nut travel (required)
  moving_mass: 450 kg         # table, fixture, heaviest part (required)
  mounting: fixed-supported   # fixed-free | fixed-supported | fixed-fixed (required)
  orientation: horizontal     # horizontal | vertical (gravity on the screw, holding brake)
  max_speed: 24 m/min         # rapid traverse (required)
  mean_speed: 8 m/min         # for the life (default: half of max_speed)
  acceleration: 3 m/s^2       # of the moves (default 0)
{force}
  axial_load: 3000 N          # largest process force (required)
  mean_axial_load: 800 N      # mean process force, for the life
  normal_load: 1500 N         # cut onto the rails (face milling: cutter thrust); assumed
  cross_load: 1500 N          # cut across the rails; our assumption: half the feed force each
  tool_height: 300 mm         # cutting point above the guide mounting plane
  tool_offset: 100 mm         # cutting point across the rails from the carriage centre
  duty_cycle:                 # the motor is sized on this cycle
    - {{move: 300 mm}}                                # rapid approach at max_speed and acceleration
    - {{move: 400 mm, speed: 2 m/min, force: 2500 N}} # cutting feed against 2.5 kN
    - {{dwell: 1 s}}                                  # spindle stop
    - {{move: -700 mm}}                               # rapid return
    - {{dwell: 5 s}}                                  # tool and part change
  required_life: 20000 h      # nut, bearing, guide life needed (default 20000 h)
  guide_blocks: 4             # carriages in total (default 4)
  rails: 2                    # (default 2)
  table_length: 600 mm        # rail length = stroke + table_length (default 500 mm)
""",
        problem="""\
objective: frequency          # maximise the lowest 1st natural frequency over the stroke
limits:
  max_cost: 7000 EUR          # parts, motor and coupling included (illustrative prices)
  max_drag_torque: 2.5 N.m    # nut preload and bearing drag
  min_life: 20000 h
  min_stiffness: 150 N/um     # lowest axial stiffness over the stroke
  margins:                    # vendor checks: available / needed at least this (default 1)
    critical_speed: 1.25
    buckling: 2.0
catalog:                      # parts the search may choose (axisopt parts)
  mountings: [fixed-supported, fixed-fixed]  # tries each
  vendors: [HIWIN, THK, NSK]
  nut_types: [double]         # preloaded double nuts: no backlash
  motor_series: [Sigma-7 SGM7G]
  require: {coupling: [RINGFEDER-GWB-AKN-60, RINGFEDER-GWB-AKN-80]}
continuous:
  nut_preload: {min: 200 N, max: 20 kN}
""",
        parts="""\
  screw: HIWIN-G-50x20-b6p35
  nut: HIWIN-R50-20K4-FDC-b635
  bearing: NSK-40TAC90B-DFF-C9
  guide: HIWIN-HG20-ZA
  motor: SGM7G-20A
  coupling: RINGFEDER-GWB-AKN-80
  nut_preload: 3700 N
""",
        sweep=("axis.moving_mass", "[300 kg, 450 kg, 600 kg]", "light, usual and heavy workpieces"),
    ),
    "lathe": dict(
        title="turning centre, Z axis",
        name="lathe-z",
        description="Lathe Z axis: 250 kg carriage and turret, 600 mm stroke, 30 m/min, 5 kN feed "
        "force.",
        axis="""\
  stroke: 600 mm              # nut travel (required)
  moving_mass: 250 kg         # carriage, cross slide, turret (required)
  mounting: fixed-supported   # fixed-free | fixed-supported | fixed-fixed (required)
  orientation: horizontal     # slant bed: no gravity along the screw
  max_speed: 30 m/min         # rapid traverse (required)
  acceleration: 5 m/s^2       # of the moves (default 0)
{force}
  axial_load: 5000 N          # largest process force: roughing feed force Ff
  mean_axial_load: 1500 N     # mean process force, for the life
  normal_load: 10000 N        # tangential force Fc onto the rails (rule of thumb: Ff / 0.5)
  cross_load: 2500 N          # passive (radial) force Fp across the rails (0.25 Fc)
  tool_height: 250 mm         # tool tip above the guide mounting plane
  tool_offset: 150 mm         # tool tip across the rails from the carriage centre
  duty_cycle:                 # the motor is sized on this cycle
    - {{move: 150 mm}}                                   # rapid approach
    - {{move: 400 mm, speed: 0.5 m/min, force: 4000 N}}  # roughing pass against 4 kN
    - {{move: -400 mm}}                                  # rapid back
    - {{move: 400 mm, speed: 0.2 m/min, force: 1000 N}}  # finishing pass against 1 kN
    - {{move: -550 mm}}                                  # rapid return
    - {{dwell: 10 s}}                                    # part change
  required_life: 20000 h      # nut, bearing, guide life needed (default 20000 h)
  table_length: 400 mm        # rail length = stroke + table_length (default 500 mm)
""",
        problem="""\
objective: stiffness          # maximise the lowest axial stiffness over the stroke
limits:
  max_cost: 5000 EUR          # parts, motor and coupling included (illustrative prices)
  max_drag_torque: 2 N.m      # nut preload and bearing drag
  min_life: 20000 h
  margins:                    # vendor checks: available / needed at least this (default 1)
    critical_speed: 1.25
catalog:                      # parts the search may choose (axisopt parts)
  mountings: [fixed-supported, fixed-fixed]  # tries each
  vendors: [HIWIN, THK, NSK]
  nut_types: [double]         # preloaded double nuts: no backlash
  motor_series: [Sigma-7 SGM7G]
  require: {coupling: [RINGFEDER-GWB-AKN-60, RINGFEDER-GWB-AKN-80]}
continuous:
  nut_preload: {min: 200 N, max: 20 kN}
""",
        parts="""\
  screw: HIWIN-G-40x20-b6p35
  nut: HIWIN-R40-20K4-FDC
  bearing: NSK-30TAC62B-DFF-C9
  guide: HIWIN-HG30-ZA
  motor: SGM7A-50A
  coupling: RINGFEDER-GWB-AKN-80
  nut_preload: 2600 N
""",
        sweep=("axis.axial_load", "[3000 N, 5000 N, 6000 N]", "light, medium and heavy roughing"),
    ),
    "gantry": dict(
        title="twin-drive gantry, long X axis",
        name="gantry-x",
        description="Twin-drive gantry X: 500 kg bridge, 300 kg cross carriage, drives 2 m apart, "
        "30 m/min.",
        axis="""\
  stroke: 2000 mm             # nut travel (required)
  moving_mass: 500 kg         # the bridge (required); its cross carriage below
  twin_drive: {{span: 2000 mm, cross_stroke: 1600 mm, cross_mass: 300 kg}}  # screw, motor each side
  mounting: fixed-supported   # fixed-free | fixed-supported | fixed-fixed (required)
  orientation: horizontal     # horizontal | vertical (gravity on the screw, holding brake)
  max_speed: 30 m/min         # rapid traverse (required)
  mean_speed: 10 m/min        # for the life (default: half of max_speed)
  acceleration: 2 m/s^2       # of the moves (default 0)
{force}
  axial_load: 5000 N          # largest process force (required)
  mean_axial_load: 1500 N     # mean process force, for the life
  normal_load: 2500 N         # cut onto the rails; our assumption: half the feed force
  cross_load: 2500 N          # cut across the rails; our assumption: half the feed force
  tool_height: 600 mm         # cutting point above the guide mounting plane (spindle)
  tool_offset: 500 mm         # cutting point across the rails from the carriage centre (Y travel)
  duty_cycle:                 # the motor is sized on this cycle
    - {{move: 500 mm}}                                 # rapid approach
    - {{move: 1000 mm, speed: 5 m/min, force: 3000 N}} # milling pass against 3 kN
    - {{move: -1500 mm}}                               # rapid return
    - {{dwell: 10 s}}                                  # tool and part change
  required_life: 15000 h      # nut, bearing, guide life needed (default 20000 h)
  table_length: 800 mm        # rail length = stroke + table_length (default 500 mm)
""",
        problem="""\
objective: stiffness          # maximise the lowest axial stiffness over the stroke
limits:
  max_cost: 15000 EUR         # parts, motor and coupling included (illustrative prices)
  max_drag_torque: 5 N.m      # nut preload and bearing drag
  min_life: 15000 h
  margins:                    # vendor checks: available / needed at least this (default 1)
    critical_speed: 1.2
catalog:                      # parts the search may choose (axisopt parts)
  mountings: [fixed-supported, fixed-fixed]  # tries each
  vendors: [HIWIN, NSK]       # NSK's light-preload support sets (HIWIN's WBK sets miss 15 000 h)
  nut_types: [double]         # preloaded double nuts: no backlash
  require: {motor: [HC202, HC352, HC452, HC702], coupling: [RINGFEDER-GWB-AKN-300]}
continuous:
  nut_preload: {min: 200 N, max: 30 kN}
""",
        parts="""\
  screw: HIWIN-G-63x40-b6p35
  nut: HIWIN-R63-40K2-FDC
  bearing: NSK-50TAC100B-DFF-C9  # light preload (C9): a standard-preload set misses 15 000 h here
  guide: HIWIN-RG35-ZA        # roller 35: the cut 600 mm up, 500 mm across tilts the gantry
  motor: HC702
  coupling: RINGFEDER-GWB-AKN-300
  nut_preload: 2500 N
""",
        sweep=("axis.stroke", "[1500 mm, 1750 mm, 2000 mm]", "machine sizes"),
    ),
    "vertical": dict(
        title="vertical Z axis (gravity on the screw, holding brake)",
        name="vertical-z",
        description="Vertical Z: 300 kg head on a 240 kg counterweight, 500 mm stroke, 24 m/min, "
        "brake 2x.",
        axis="""\
  stroke: 500 mm              # nut travel (required)
  moving_mass: 300 kg         # spindle head (required)
  mounting: fixed-supported   # fixed-free | fixed-supported | fixed-fixed (required)
  orientation: vertical       # gravity acts along the screw; the motor needs a holding brake
  brake_safety: 2             # brake torque / gravity torque (default 2)
  counterbalance: {{kind: counterweight, mass: 240 kg, efficiency: 0.95}}  # 80 % of the head
  max_speed: 24 m/min         # rapid traverse (required)
  acceleration: 3 m/s^2       # of the moves (default 0)
{force}
  axial_load: 3000 N          # largest process force: drilling thrust
  mean_axial_load: 1000 N     # mean process force, for the life
  normal_load: 2000 N         # milling force pressing the head onto the column; our assumption
  cross_load: 1500 N          # milling force across the rails; our assumption
  tool_height: 350 mm         # spindle nose out from the rail mounting plane
  tool_offset: 0 mm           # on the carriage centre line
  duty_cycle:                 # the motor is sized on this cycle (- is down)
    - {{move: -200 mm}}                                # rapid down
    - {{move: -250 mm, speed: 2 m/min, force: 2000 N}} # drilling feed against 2 kN
    - {{dwell: 1 s}}
    - {{move: 450 mm}}                                 # rapid up
    - {{dwell: 5 s}}                                   # tool change, held by the motor
  required_life: 20000 h      # nut, bearing, guide life needed (default 20000 h)
  table_length: 400 mm        # rail length = stroke + table_length (default 500 mm)
""",
        problem="""\
objective: stiffness          # maximise the lowest axial stiffness over the stroke
limits:
  max_cost: 6000 EUR          # parts, motor and coupling included (illustrative prices)
  max_drag_torque: 2 N.m      # nut preload and bearing drag
  min_life: 20000 h
catalog:                      # parts the search may choose (axisopt parts)
  mountings: [fixed-supported, fixed-fixed]  # tries each
  vendors: [HIWIN, THK, NSK]
  nut_types: [double]         # preloaded double nuts: no backlash
  motor_series: [Sigma-7 SGM7G, MELDAS HC (2000 r/min)]   # motors with a holding brake listed
  require: {coupling: [RINGFEDER-GWB-AKN-150]}
continuous:
  nut_preload: {min: 200 N, max: 20 kN}
""",
        parts="""\
  screw: HIWIN-G-63x20-b6p35
  nut: HIWIN-R63-20K5-FDC-b635
  bearing: NSK-50TAC100B-DFF-C9
  guide: HIWIN-HG15-ZA
  motor: HC452
  coupling: RINGFEDER-GWB-AKN-150
  nut_preload: 2850 N
""",
        sweep=("limits.max_cost", "[5000 EUR, 6000 EUR, 8000 EUR]", "budgets"),
    ),
    "boring": dict(
        title="horizontal boring-mill table, long heavy X axis",
        name="boring-table",
        description="Boring-mill table: 2 t table and workpiece, 3 m stroke, 15 m/min, 15 kN feed "
        "force.",
        axis="""\
  stroke: 3000 mm             # nut travel (required)
  moving_mass: 2000 kg        # table and the heaviest workpiece (required)
  mounting: fixed-supported   # fixed-free | fixed-supported | fixed-fixed (required)
  orientation: horizontal
  max_speed: 15 m/min         # rapid traverse (required); the life's mean speed: the duty cycle's
  acceleration: 1 m/s^2       # of the moves (default 0)
{force}
  axial_load: 15 kN           # largest process force: roughing with a long boring bar
  mean_axial_load: 5 kN       # mean process force, for the life
  normal_load: 10 kN          # cut onto the rails; our assumption
  cross_load: 6 kN            # cut across the rails; our assumption
  tool_height: 700 mm         # cutting point above the guide mounting plane
  tool_offset: 300 mm         # cutting point across the rails from the carriage centre
  cg_height: 300 mm           # table and workpiece's centre of gravity above the guide plane
  duty_cycle:                 # the motor is sized on this cycle
    - {{move: 1000 mm}}                                  # rapid approach
    - {{move: 1500 mm, speed: 0.5 m/min, force: 12 kN}}  # boring pass against 12 kN
    - {{move: -2500 mm}}                                 # rapid return
    - {{dwell: 20 s}}                                    # measuring, tool change
  required_life: 20000 h      # nut, bearing, guide life needed (default 20000 h)
  guide_blocks: 6             # three blocks per rail under a long table
  rails: 2
  table_length: 1600 mm       # rail length = stroke + table_length
  table_width: 1250 mm
  block_spacing: 1200 mm      # outer block to outer block along a rail
  rail_spacing: 1000 mm
""",
        problem="""\
objective: stiffness          # maximise the lowest axial stiffness over the stroke
limits:
  min_life: 20000 h
  max_backlash: 10 um         # a gearbox may be chosen: its backlash at the table
  margins:                    # vendor checks: available / needed at least this (default 1)
    critical_speed: 1.2       # on top of the vendors' own 0.8: a 3 m screw whirls
catalog:                      # parts the search may choose (axisopt parts)
  mountings: [fixed-supported, fixed-fixed]  # tries each
  nut_types: [double]         # preloaded double nuts: no backlash
  drive: yes                  # motor, coupling and a planetary gearbox (or none) are chosen too
continuous:
  nut_preload: {min: 200 N, max: 40 kN}
""",
        parts="""\
  screw: HIWIN-G-100x20-b9p525
  nut: HIWIN-R100-20T4-FDI
  bearing: NSK-80TAC03AM-DFF-M
  guide: HIWIN-HG30-ZA
  motor: SGM7A-70A
  coupling: SFU-140SS-1000N
  reduction: BK-NPT035-MF-8   # Beckhoff planetary 8:1 (axisopt parts reductions)
  nut_preload: 13500 N
""",
        sweep=("axis.moving_mass", "[1500 kg, 2000 kg, 2500 kg]", "workpiece masses"),
    ),
    "laser": dict(
        title="high-dynamics laser-cutting axis (1.5 g, jerk-limited)",
        name="laser-y",
        description="Laser-cutting Y axis: 100 kg carriage and head, 1 m stroke, 80 m/min, 1.5 g, "
        "no cutting force.",
        axis="""\
  stroke: 1000 mm             # nut travel (required)
  moving_mass: 100 kg         # carriage with the cutting head and its Z (required)
  mounting: fixed-supported   # fixed-free | fixed-supported | fixed-fixed (required)
  orientation: horizontal
  max_speed: 80 m/min         # rapid traverse (required)
  mean_speed: 10 m/min        # for the life (default: half of max_speed)
  acceleration: 15 m/s^2      # 1.5 g
  jerk: 300 m/s^3             # jerk-limited (S-curve) moves
{force}
  axial_load: 200 N           # no cut: gas jet and cable chain; our assumption
  mean_axial_load: 100 N
  normal_load: 0 N            # no cutting force on the guides
  cross_load: 0 N
  tool_height: 150 mm
  duty_cycle:                 # the motor is sized on this cycle: a contour
    - {{move: 800 mm}}                    # rapid
    - {{move: -200 mm, speed: 20 m/min}}  # contouring
    - {{move: 400 mm, speed: 10 m/min}}   # contouring
    - {{move: -1000 mm}}                  # rapid return
    - {{dwell: 0.5 s}}                    # pierce
  required_life: 20000 h      # nut, bearing, guide life needed (default 20000 h)
  table_length: 500 mm        # rail length = stroke + table_length
""",
        problem="""\
objective: frequency          # maximise the lowest 1st natural frequency (contouring bandwidth)
limits:
  min_life: 20000 h
  margins:                    # vendor checks: available / needed at least this (default 1)
    critical_speed: 1.25
catalog:                      # parts the search may choose (axisopt parts)
  mountings: [fixed-supported, fixed-fixed]  # tries each
  nut_types: [double]         # preloaded double nuts: no backlash
  drive: yes                  # motor and coupling chosen too (direct: no backlash allowed)
continuous:
  nut_preload: {min: 200 N, max: 20 kN}
""",
        parts="""\
  screw: HIWIN-G-40x40-b6p35
  nut: HIWIN-R40-40K2-FDC
  bearing: NSK-30TAC62B-DF-C9
  guide: NBS-SNC15-P1
  motor: SGM7G-20A
  coupling: RINGFEDER-GWB-AKN-30
  nut_preload: 1000 N
""",
        sweep=("axis.acceleration", "[10 m/s^2, 12 m/s^2, 15 m/s^2]", "accelerations"),
    ),
}

_HEADER = """\
# axisopt {kind}: {title}
# Written by 'axisopt init {kind} --machine {machine}'.
# {next}
# Every quantity carries its unit ("800 mm", "3 m/s^2", "4 kN"); a bare number is refused.
# Editor completion and checks: axisopt schema {kind} --out axisopt-{kind}.json
# (docs/files.md, "Editor support").
"""
_NEXT = {
    "design": "Evaluate it: axisopt evaluate FILE",
    "problem": "Solve it: axisopt solve FILE (exit 0 optimal, 1 infeasible)",
    "study": "Run it: axisopt study FILE --out DIR",
}


def template(kind: str, machine: str = "vmc") -> str:
    """The commented YAML text of a ``kind`` file (design, problem, study) for ``machine``; a
    machine file (``kind`` 'machine'): ``machine`` is its kind, vmc | moving-column | gantry."""
    if kind not in KINDS:
        raise InputError(f"unknown file kind '{kind}'; use one of {', '.join(KINDS)}")
    if kind == "machine":
        from ..machine.templates import TEMPLATES

        if machine not in TEMPLATES:
            raise InputError(
                f"unknown machine kind '{machine}'; use one of {', '.join(TEMPLATES)}",
                where="--kind",
            )
        return TEMPLATES[machine]
    if machine not in _MACHINE:
        raise InputError(
            f"unknown machine '{machine}'; use one of {', '.join(MACHINES)}", where="--machine"
        )
    m = _MACHINE[machine]
    head = _HEADER.format(kind=kind, title=m["title"], machine=machine, next=_NEXT[kind])
    force = _FORCE_NOTE + (_TURNING_NOTE if machine == "lathe" else "")
    axis = "axis:\n" + m["axis"].format(force=force) + _MOUNT_NOTE
    if kind == "design":
        return (
            f"{head}name: {m['name']}\ndescription: >\n  {m['description']}\n{axis}"
            "parts:                        # catalog ids (axisopt parts lists them)\n"
            f"{m['parts']}"
        )
    problem = f"name: {m['name']}\ndescription: >\n  {m['description']}\n{axis}{m['problem']}"
    if kind == "problem":
        return head + problem
    key, values, what = m["sweep"]
    base = "".join(("  " + line) if line else line for line in problem.splitlines(True))
    return (
        f"{head}name: {m['name']}-study\ndescription: >\n  {m['description']}\n  Swept over "
        f"{what}.\n"
        f"base:                         # a problem as 'init problem' writes (or base: FILE)\n"
        f"{base}sweep:                        # each key a dotted path into the base problem\n"
        f"  {key}: {values}   # {what}\n"
    )


def register(sub) -> None:
    p = sub.add_parser(
        "init", help="write a commented design, problem or study YAML for a machine type"
    )
    p.add_argument("kind", choices=KINDS, help="the kind of YAML file")
    p.add_argument(
        "--machine",
        choices=MACHINES,
        default="vmc",
        help="machine type: vmc (machining centre X), lathe (Z), gantry (long X), vertical (Z), "
        "boring (boring-mill table, 3 m, 2 t), laser (1.5 g contouring); default vmc",
    )
    p.add_argument(
        "--kind",
        choices=("vmc", "moving-column", "gantry"),
        default="vmc",
        dest="machine_kind",
        help="init machine: the machine's kind (default vmc): a VMC (X on Y, Z on the column), a "
        "moving-column machine, a gantry with a twin-drive bridge and a counterbalanced Z",
    )
    p.add_argument(
        "--out",
        metavar="FILE",
        help="file to write ('-' for stdout; default <machine>_<kind>.yaml in this directory)",
    )
    p.add_argument("--force", action="store_true", help="overwrite an existing file")
    p.set_defaults(func=cmd_init)


def cmd_init(args) -> int:
    which = args.machine_kind if args.kind == "machine" else args.machine
    text = template(args.kind, which)
    out = args.out or f"{which.replace('-', '_')}_{args.kind}.yaml"
    if out == "-":
        sys.stdout.write(text)
        return EXIT_OK
    path = Path(out)
    if path.exists() and not args.force:
        raise InputError(
            "file exists; use --force to overwrite it, or --out another file", source=str(path)
        )
    if path.is_dir():
        raise InputError("is a directory; give a file name", source=str(path))
    from ..fileio import write_text_atomic

    write_text_atomic(str(path), text, what=f"{args.kind} YAML")
    nxt = {
        "design": "axisopt evaluate",
        "problem": "axisopt solve",
        "study": "axisopt study",
        "machine": "axisopt machine solve",
    }[args.kind]
    title = f"{which} machine" if args.kind == "machine" else f"a {_MACHINE[args.machine]['title']}"
    print(f"{args.kind} template for {title} written to {path}")
    print(f"next: {nxt} {path}")
    return EXIT_OK
