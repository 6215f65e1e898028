"""A problem's drive types: ``search: {drive_types: [screw, rack_pinion, linear_motor], rack_pinion:
{...},
linear_motor: {...}}``.  The search sizes each listed type from its catalog (the screw drive from
the usual tables, rack-and-pinion sets from ``racks.csv``, linear motors from ``linear_motors.csv``)
and the best design of any type wins (:mod:`axisopt.search.drivetype`).  Without ``drive_types`` the
drive is the screw."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..drivecatalog import DriveTables, default_drive_tables
from ..physics.rack import OVERLOAD_FACTORS
from ..yamlio import Key, Section, Spec

DRIVE_TYPES = ("screw", "rack_pinion", "linear_motor")
RACK_SPEC = Spec(
    "rack_pinion",
    "rack-and-pinion drives (catalogs racks.csv, with the motors and reductions)",
    {
        "twin_pinion": Key(
            "choice",
            "two electrically preloaded pinions per rack (no backlash): no, yes or search (both)",
            choices=("no", "yes", "search", True, False),
            default="search",
        ),
        "overload": Key(
            "choice",
            "impact from the driven machine (THK A-241 Table 4, JGMA 401-01): uniform 1.0, "
            "medium 1.25, large 1.75",
            choices=tuple(OVERLOAD_FACTORS),
            default="medium",
        ),
        "preload_bias": Key(
            "number",
            "twin pinion: bias force of each pinion as a fraction of the peak feed force",
            minimum=0.0,
            maximum=1.0,
            default=0.15,
        ),
    },
)
LM_SPEC = Spec(
    "linear_motor",
    "linear-motor drives (catalogs linear_motors.csv)",
    {
        "max_forcers": Key(
            "number",
            "forcers side by side on one track, their forces adding (Siemens 1FN3 5.2): "
            "the search tries 1 up to this",
            integer=True,
            minimum=1,
            maximum=4,
            default=2,
        ),
        "servo_bandwidth": Key(
            "quantity",
            "position-loop bandwidth the servo stiffness is estimated at",
            kind="frequency",
            positive=True,
            default=50.0,
            example="50 Hz",
        ),
        "brake": Key(
            "choice",
            "a holding brake or clamp on the carriage (a vertical linear-motor axis needs it or "
            "a counterbalance)",
            choices=("yes", "no", True, False),
            default="no",
        ),
    },
)
# A saved design of a rack-and-pinion or linear-motor drive: the problem's file with this section
# naming the chosen parts (`axisopt solve --save-design` writes it, `axisopt evaluate` reads it)
DRIVE_DESIGN_SLOTS = {
    "rack_pinion": ("rack", "reduction", "motor", "twin_pinion", "guide"),
    "linear_motor": ("linear_motor", "forcers", "guide"),
}
DRIVE_DESIGN_SPEC = Spec(
    "drive_design",
    "one rack-and-pinion or linear-motor design of the problem (solve's --save-design writes it, "
    "evaluate reads it)",
    {
        "type": Key("choice", "the drive type", required=True, choices=tuple(DRIVE_DESIGN_SLOTS)),
        "rack": Key("string", "rack-and-pinion set id (racks.csv)"),
        "reduction": Key("string", "gearbox id (reductions.csv)"),
        "motor": Key("string", "motor id (motors.csv)"),
        "twin_pinion": Key(
            "choice", "two preloaded pinions per rack", choices=("yes", "no", True, False)
        ),
        "linear_motor": Key("string", "linear motor id (linear_motors.csv)"),
        "forcers": Key("number", "forcers on the track", integer=True, minimum=1, maximum=4),
        "guide": Key("string", "guide id (guides.csv)", required=True),
    },
)


def read_drive_design(sec: Section | None) -> dict | None:
    """The ``drive_design:`` section as {slot: id} in the search's vocabulary (twin_pinion
    'yes'/'no', forcers a string), with its 'type'; None without one.  Each slot of the type must be
    given, no other."""
    if sec is None:
        return None
    kind = sec.read("type")
    out = {"type": kind}
    for slot in DRIVE_DESIGN_SLOTS[kind]:
        if not sec.has(slot):
            raise sec.error(slot, f"a {kind} design names its {slot}")
        v = sec.read(slot)
        out[slot] = (
            ("yes" if v in ("yes", True) else "no")
            if slot == "twin_pinion"
            else str(int(v))
            if slot == "forcers"
            else str(v)
        )
    others = [k for k in DRIVE_DESIGN_SPEC.keys if k != "type" and k not in out and sec.has(k)]
    if others:
        raise sec.error(others[0], f"a {kind} design has no {others[0]}")
    sec.done()
    return out


DRIVE_KEYS = {
    "drive_types": Key(
        "names", "drive types the search chooses among (default: screw)", choices=DRIVE_TYPES
    ),
    "rack_pinion": Key("section", spec=RACK_SPEC),
    "linear_motor": Key("section", spec=LM_SPEC),
}


@dataclass(frozen=True)
class DriveChoice:
    """The drive types a problem lets the search choose among, their options (SI) and their
    catalogs."""

    types: tuple
    twin_pinion: tuple = (0, 1)  # 0: one pinion, 1: a preloaded twin pinion
    overload_factor: float = 1.25
    preload_bias: float = 0.15
    max_forcers: int = 2
    servo_bandwidth: float = 50.0
    brake: bool = False
    tables: DriveTables | None = None

    @property
    def screw_only(self) -> bool:
        return self.types == ("screw",)


def read_drive_choice(
    sec: Section | None, axis, dirs=(), base: Path | None = None
) -> DriveChoice | None:
    """The ``search:`` section's drive-type keys (None: none given); ``dirs``: the problem's extra
    catalog directories.  A vertical linear-motor axis without a brake or a counterbalance is
    refused (the vendors forbid it: the motor holds nothing without current)."""
    if sec is None or not any(sec.has(k) for k in DRIVE_KEYS):
        return None
    types = tuple(sec.read("drive_types") or ("screw",))
    for t in types:
        if t not in DRIVE_TYPES:
            raise sec.error(
                "drive_types", f"'{t}' is not a drive type (one of {', '.join(DRIVE_TYPES)})"
            )
    if len(set(types)) < len(types):
        raise sec.error("drive_types", "a drive type is listed twice")
    kw = {}
    rs = sec.read("rack_pinion")
    if rs is not None:
        twin = rs.read("twin_pinion")
        kw["twin_pinion"] = {"no": (0,), "yes": (1,), "search": (0, 1), False: (0,), True: (1,)}[
            twin
        ]
        kw["overload_factor"] = OVERLOAD_FACTORS[rs.read("overload")]
        kw["preload_bias"] = float(rs.read("preload_bias"))
        rs.done()
    ls = sec.read("linear_motor")
    if ls is not None:
        kw["max_forcers"] = int(ls.read("max_forcers"))
        kw["servo_bandwidth"] = float(ls.read("servo_bandwidth"))
        kw["brake"] = ls.read("brake") in ("yes", True)
        ls.done()
    brake = kw.get("brake", False)
    if (
        "linear_motor" in types
        and axis.orientation == "vertical"
        and not brake
        and axis.counterbalance is None
    ):
        raise sec.error(
            "drive_types",
            "a linear motor on a vertical axis needs a brake or a counterbalance "
            "(search.linear_motor.brake: yes, or axis.counterbalance): it holds nothing without "
            "current",
        )
    base = Path(".") if base is None else base
    tables = default_drive_tables(tuple((base / d).resolve() for d in dirs))
    if "rack_pinion" in types and not tables.racks:
        raise sec.error("drive_types", "rack_pinion listed but no catalog has racks.csv rows")
    if "linear_motor" in types and not tables.linear_motors:
        raise sec.error(
            "drive_types", "linear_motor listed but no catalog has linear_motors.csv rows"
        )
    return DriveChoice(types=types, tables=tables, **kw)
