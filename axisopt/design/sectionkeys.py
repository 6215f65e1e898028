"""The YAML keys of the axis's sub-sections, one table each: a duty cycle's moves and dwells, the
counterbalance (counterweight or cylinder, the keys of each kind) and the twin-drive gantry.
:mod:`.keys` nests them in the axis's table."""

from __future__ import annotations

from ..yamlio import Key, Spec
from .axis import COUNTERBALANCE_KINDS


def axis_q(kind: str, doc: str, *, required: bool = False, zero: bool = False, maximum=None) -> Key:
    """An axis quantity: positive, or non-negative when ``zero``."""
    return Key(
        "quantity",
        doc,
        required=required,
        kind=kind,
        positive=not zero,
        non_negative=zero,
        maximum=maximum,
    )


SEGMENT_LIMIT = 1000  # duty-cycle entries


_FORCE = Key(
    "quantity",
    "axial (process) force during the entry",
    kind="force",
    non_negative=True,
    default=0.0,
)


# a workpiece loaded or unloaded: the entry's own moving mass (no inheritance from the entry before:
# a cycle repeats, and each entry that differs from axis.moving_mass says so)
_MASS = Key(
    "quantity",
    "table + workpiece during the entry (default: axis.moving_mass, the heaviest the table "
    "carries: an entry may be lighter, e.g. the workpiece unloaded)",
    kind="mass",
    positive=True,
    example="300 kg",
)


MOVE_SPEC = Spec(
    "move",
    "a move of the duty cycle",
    {
        "move": Key(
            "quantity",
            "signed distance (+ forward, - back), at most the stroke",
            required=True,
            kind="length",
            example="400 mm",
        ),
        "speed": Key(
            "quantity", "top speed (default: axis.max_speed)", kind="speed", positive=True
        ),
        "acceleration": Key(
            "quantity",
            "acceleration (default: axis.acceleration)",
            kind="acceleration",
            positive=True,
        ),
        "jerk": Key("quantity", "jerk limit (default: axis.jerk)", kind="jerk", positive=True),
        "force": _FORCE,
        "moving_mass": _MASS,
    },
)


DWELL_SPEC = Spec(
    "dwell",
    "a dwell of the duty cycle",
    {
        "dwell": Key(
            "quantity", "duration", required=True, kind="time", positive=True, example="2 s"
        ),
        "force": _FORCE,
        "moving_mass": _MASS,
    },
)


COUNTERBALANCE_SPEC = Spec(
    "counterbalance",
    "a vertical axis's counterweight or balance cylinder",
    {
        "kind": Key(
            "choice",
            "counterweight (a mass on a chain over a sprocket), cylinder (a pneumatic or hydraulic "
            "balance cylinder) or none",
            required=True,
            choices=COUNTERBALANCE_KINDS,
        ),
        "mass": axis_q("mass", "counterweight: its mass, at most the axis's moving_mass"),
        "efficiency": Key(
            "number",
            "counterweight: efficiency of the chain or cable over its sprocket or pulley, in "
            "(0, 1] (default 0.95, an estimate)",
            positive=True,
            maximum=1.0,
        ),
        "chain_mass": axis_q(
            "mass",
            "counterweight: the chain's or cable's mass, moving with it (default 0 kg)",
            zero=True,
        ),
        "force": axis_q("force", "cylinder: its force on the head at the stroke's start"),
        "force_at_end": axis_q(
            "force",
            "cylinder: its force at the stroke's end (default: force, a constant-pressure "
            "regulator)",
        ),
        "tolerance": Key(
            "quantity",
            "cylinder: pressure tolerance, +/- (default 0 %)",
            kind="dimensionless",
            non_negative=True,
            maximum=(0.5, "50 %"),
            example="5 %",
        ),
        "piston_mass": axis_q(
            "mass", "cylinder: piston and rod, moving with the head (default 0 kg)", zero=True
        ),
    },
)


# the keys of each kind (the others are refused: a counterweight has no force)
COUNTERBALANCE_KEYS = {
    "none": ("kind",),
    "counterweight": ("kind", "mass", "efficiency", "chain_mass"),
    "cylinder": ("kind", "force", "force_at_end", "tolerance", "piston_mass"),
}


# A twin-drive gantry (model.gantry): two synchronised drives with the same parts under one bridge
# (the axis's moving_mass) with a cross carriage; the bounds keep machine-tool sizes (a bridge up to
# 50 m wide)
TWIN_SPEC = Spec(
    "twin_drive",
    "two synchronised screw drives (the same parts on both sides) under a bridge (the axis's "
    "moving_mass) with a cross carriage: a horizontal gantry only (refused on a vertical or wall "
    "axis).  Each drive is checked on the governing side with the cross carriage at the end of its "
    "stroke nearest it (its share 1/2 + cross_stroke / 2 span of the process force, half the "
    "bridge and that share of the cross carriage); the gantry's translation and racking (yaw) "
    "modes enter the 1st frequency; cost and mass count both drives",
    {
        "span": axis_q(
            "length", "between the two drives (screw axes)", required=True, maximum=(50.0, "50 m")
        ),
        "cross_stroke": axis_q(
            "length",
            "the cross carriage's travel across the bridge, centred, at most span",
            required=True,
            zero=True,
            maximum=(50.0, "50 m"),
        ),
        "cross_mass": axis_q(
            "mass",
            "cross carriage with its head (default 0 kg); axis.moving_mass is the bridge",
            zero=True,
            maximum=(1e5, "100 t"),
        ),
        "bridge_yaw_inertia": axis_q(
            "inertia",
            "bridge about its centre, normal axis (default: from its parts, a "
            "beam over span and the uprights at the drives)",
            maximum=(1e7, "1e7 kg.m^2"),
        ),
        "upright_mass": axis_q(
            "mass",
            "both uprights (side columns) of the bridge, at the drives, part of "
            "axis.moving_mass (default, an estimate: half of it, J = m L^2 / 6, conservative "
            "for the racking mode)",
            zero=True,
            maximum=(1e5, "100 t"),
        ),
    },
)
