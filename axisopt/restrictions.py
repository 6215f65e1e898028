"""Which catalog parts, mountings and drive parts a search may use: a problem's ``catalog:`` section
(:class:`Restrictions`, read by :func:`read_restrictions`; the keys in :data:`RESTRICTIONS_SPEC`).

The drive (motor, coupling, reduction) is searched whenever the catalogs have motors and the axis a
motion to size it on, unless the problem says ``drive: no``; a drive left out carries its reason
(``Restrictions.drive_left_out``), which every answer states.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType

from .catalog.columns import DRIVE_SLOTS, MECH_SLOTS, PART_SLOTS, STATUSES, USER_STATUS
from .catalog.grades import grade_table
from .catalog.loading import Catalog
from .design import MOUNTINGS, Axis
from .yamlio import Key, Section, Spec

SLOTS = PART_SLOTS  # a design's part slots (catalog.columns: MECH_SLOTS, then DRIVE_SLOTS)
SLOT_TABLE = MappingProxyType(
    {
        "screw": "screws",
        "nut": "nuts",
        "bearing": "bearings",
        "guide": "guides",
        "motor": "motors",
        "coupling": "couplings",
        "reduction": "reductions",
    }
)

DEFAULT_STATUS = ("vendor", "stiffness-derived", USER_STATUS)


@dataclass(frozen=True)
class Restrictions:
    """Which catalog parts and mountings the search may use (None: no restriction)."""

    mountings: tuple = ()
    vendors: tuple | None = None
    nut_types: tuple | None = None
    bearing_arrangements: tuple | None = None
    bearing_preload: tuple | None = None
    guide_types: tuple | None = None
    guide_preload: tuple | None = None
    # parts you can buy: catalog rows with vendor ratings, and user-catalog rows; 'derived' and
    # 'paper' rows (a preload class or stack a vendor does not list, the seed's catalog [21] nuts)
    # only when asked for
    status: tuple = DEFAULT_STATUS
    require: tuple = ()  # ((slot, (ids...)), ...)
    exclude: tuple = ()
    drive: bool = False  # motor and coupling are search choices
    # why the drive is not searched ('' when it is): stated on its own line in every answer
    drive_left_out: str = ""
    motor_vendors: tuple | None = None
    motor_series: tuple | None = None
    coupling_series: tuple | None = None
    # a searched drive chooses a reduction part too (or none: the axis's reduction values)
    reductions: bool = True
    max_motor_flange: float | None = None  # [m]
    estimated: str = "allow"  # 'exclude': no part whose empty catalog cell the model would estimate
    # lead accuracy grades the search may give a screw (None: those it is made in)
    screw_grades: tuple | None = None

    def required(self, slot):
        return dict(self.require).get(slot)

    def excluded(self, slot):
        return dict(self.exclude).get(slot, ())


SLOT_IDS_SPEC = Spec(
    "slots",
    "part ids per slot",
    {slot: Key("names", f"{slot} ids from the catalogs") for slot in SLOTS},
)
_CATALOG_NAMES = "(each one the catalogs hold)"
ESTIMATED_CHOICES = ("allow", "exclude")
RESTRICTIONS_SPEC = Spec(
    "catalog",
    "which catalog parts and mountings the search may use",
    {
        "mountings": Key(
            "names",
            "screw mountings to search (default: [axis.mounting])",
            choices=MOUNTINGS,
            minimum=1,
        ),
        "vendors": Key("names", f"vendors of the mechanical parts {_CATALOG_NAMES}", minimum=1),
        "nut_types": Key("names", f"nut types {_CATALOG_NAMES}", minimum=1),
        "bearing_arrangements": Key("names", f"bearing arrangements {_CATALOG_NAMES}", minimum=1),
        "bearing_preload": Key("names", f"bearing preload classes {_CATALOG_NAMES}", minimum=1),
        "guide_types": Key("names", f"guide types {_CATALOG_NAMES}", minimum=1),
        "guide_preload": Key(
            "names", f"guide preload levels or vendor classes {_CATALOG_NAMES}", minimum=1
        ),
        "status": Key(
            "names",
            "row provenance (catalogs/SOURCES.md; default: vendor, stiffness-derived, user)",
            choices=STATUSES,
            minimum=1,
        ),
        "require": Key("section", "only these part ids per slot", spec=SLOT_IDS_SPEC),
        "exclude": Key("section", "never these part ids per slot", spec=SLOT_IDS_SPEC),
        "drive": Key(
            "choice",
            "motor, coupling and reduction are search choices (default: yes when the catalogs have "
            "motors and the axis an acceleration or duty cycle; 'no' is stated in every answer)",
            choices=(True, False, "yes", "no"),
        ),
        "motor_vendors": Key("names", f"motor vendors {_CATALOG_NAMES}", minimum=1),
        "motor_series": Key("names", f"motor series {_CATALOG_NAMES}", minimum=1),
        "coupling_series": Key("names", f"coupling series {_CATALOG_NAMES}", minimum=1),
        "reductions": Key(
            "choice",
            "a searched drive chooses a reduction (reductions.csv) or none, beside motor and "
            "coupling (default yes; no: the axis's reduction values only)",
            choices=(True, False, "yes", "no"),
        ),
        "max_motor_flange": Key(
            "quantity",
            "the motor's (square) flange size at most this",
            kind="length",
            positive=True,
            example="130 mm",
        ),
        "screw_grades": Key(
            "names",
            "lead accuracy grades (JIS B 1192: C0 C1 C2 C3 C5 C7 C8 C10) a screw may have, "
            "among those its series is made in (catalogs/screw_grades.csv); default: the search "
            "chooses among them when a positioning limit is set, else the cheapest",
            minimum=1,
        ),
        "estimated": Key(
            "choice",
            "parts whose empty catalog cell the model fills with an estimate (a support bearing's "
            "starting torque, a motor's torque-speed corner points): 'allow' (default; results say "
            "when one binds) or 'exclude' (vendor values only)",
            choices=ESTIMATED_CHOICES,
        ),
    },
)


def _catalog_names(sec: Section, key: str, known) -> tuple | None:
    """A non-empty list of names under ``key``, each one of ``known()`` (None when the key is
    absent)."""
    vals = sec.read(key)
    if vals is None:
        return None
    if not vals:
        raise sec.error(key, f"list at least one value, or leave '{key}' out to allow all")
    names = known()
    for v in vals:
        if v not in names:
            raise sec.error(key, f"'{v}' is not in the catalog ({', '.join(map(str, names))})")
    return tuple(vals)


def _default_drive(catalog: Catalog, axis: Axis) -> tuple:
    """(searched, why not): the drive is sized whenever the catalogs have motors and the axis a
    motion to size it on (an acceleration or a duty cycle), unless the problem says 'drive: no'."""
    if not len(catalog.rows("motors")):
        return False, "the catalogs have no motors (motors.csv)"
    if axis.acceleration <= 0 and not axis.duty_cycle:
        return False, (
            "axis.acceleration is 0 and there is no axis.duty_cycle: no inertia torque to size a "
            "motor on"
        )
    return True, ""


def _refuse_unit_with_scale(row, part_id: str, axis: Axis, s: Section, slot: str) -> None:
    """A required driven rotating-nut unit (the nut row's ``rotating`` flag 1) on an axis with
    ``feedback: linear_scale``: a one-line error, as evaluate refuses the design (the search leaves
    such units out when they are merely offered: search.parts)."""
    try:
        unit = float(row["rotating"]) == 1.0
    except (KeyError, TypeError, ValueError):
        unit = False
    if unit and axis.feedback == "linear_scale":
        raise s.error(
            slot,
            f"nut '{part_id}' is a driven rotating-nut unit: axis.feedback: linear_scale is not "
            "supported on it (its standing screw's positioning rows are the unit's; use the motor "
            "encoder)",
        )


def read_restrictions(sec: Section | None, catalog: Catalog, axis: Axis) -> Restrictions:
    has_motors = len(catalog.rows("motors")) > 0
    default, why = _default_drive(catalog, axis)
    if sec is None:
        return Restrictions(mountings=(axis.mounting,), drive=default, drive_left_out=why)
    kw: dict = {}
    drive = sec.read("drive")
    # the drive is searched unless the problem says 'drive: no' (or nothing can size it: the reason
    # is stated)
    if drive is not None:
        kw["drive"] = drive in (True, "yes")
        kw["drive_left_out"] = "" if kw["drive"] else "catalog.drive: no"
    else:
        # a motor/coupling filter or requirement asks for the drive (an axis without motion is then
        # an error)
        req = sec.node.value.get("require")
        asked = any(
            sec.has(k)
            for k in ("motor_vendors", "motor_series", "coupling_series", "max_motor_flange")
        ) or (
            req is not None
            and isinstance(req.value, dict)
            and bool(set(DRIVE_SLOTS) & set(req.value))
        )
        kw["drive"], kw["drive_left_out"] = (True, "") if asked else (default, why)
    if kw["drive"] and not has_motors:
        raise sec.error("drive", "the catalogs have no motors (motors.csv)")
    for key, table, col in (
        ("motor_vendors", "motors", "vendor"),
        ("motor_series", "motors", "series"),
        ("coupling_series", "couplings", "series"),
    ):
        vals = _catalog_names(sec, key, lambda t=table, c=col: sorted(set(catalog.rows(t)[c])))
        if vals is not None:
            kw[key] = vals
    grades = _catalog_names(sec, "screw_grades", lambda: list(grade_table().names))
    if grades is not None:
        kw["screw_grades"] = grades
    est = sec.read("estimated")
    if est is not None:
        kw["estimated"] = est
    reds = sec.read("reductions")
    if reds is not None:
        kw["reductions"] = reds in (True, "yes")
    flange = sec.read("max_motor_flange")
    if flange is not None:
        kw["max_motor_flange"] = flange
    mounts = sec.read("mountings")
    if mounts is not None:
        for m in mounts:
            if m not in MOUNTINGS:
                raise sec.error("mountings", f"'{m}' is not one of {', '.join(MOUNTINGS)}")
        if not mounts:
            raise sec.error("mountings", "list at least one mounting")
        kw["mountings"] = tuple(dict.fromkeys(mounts))
    else:
        kw["mountings"] = (axis.mounting,)
    vendors_all = sorted(
        set().union(*(set(catalog.rows(SLOT_TABLE[t])["vendor"]) for t in MECH_SLOTS))
    )
    for key, table, col in (
        ("vendors", None, "vendor"),
        ("nut_types", "nuts", "type"),
        ("bearing_arrangements", "bearings", "arrangement"),
        ("bearing_preload", "bearings", "preload_class"),
        ("guide_types", "guides", "type"),
        ("guide_preload", "guides", None),
        ("status", "status", None),
    ):

        def known(table=table, col=col):
            if table is None:
                return vendors_all
            if table == "status":
                return STATUSES
            if col is None:
                g = catalog.rows("guides")
                return sorted(set(g["preload_level"]) | set(g["preload_class"]))
            return sorted(set(catalog.rows(table)[col]))

        vals = _catalog_names(sec, key, known)
        if vals is not None:
            kw[key] = vals
    for key in ("require", "exclude"):
        s = sec.read(key)
        if s is None:
            continue
        out = []
        for slot in s.keys():
            if slot not in SLOTS:
                raise s.error(slot, f"unknown part slot '{slot}'; use {', '.join(SLOTS)}")
            ids = s.read(slot, [])
            # as 'vendors: []': an empty list would allow no part at all
            if key == "require" and not ids:
                raise s.error(slot, "list at least one part id (or leave the slot out)")
            for i in ids:
                row = catalog.part(SLOT_TABLE[slot], i, source=s.source, key=s.where(slot))
                if key == "require" and slot == "nut":
                    _refuse_unit_with_scale(row, i, axis, s, slot)
            out.append((slot, tuple(ids)))
        s.done()
        kw[key] = tuple(out)
    sec.done()
    if not kw["drive"] and any(slot in DRIVE_SLOTS for slot, _ in kw.get("require", ())):
        raise sec.error("require", "motor/coupling/reduction parts are required but 'drive' is off")
    if not kw.get("reductions", True) and any(
        slot == "reduction" for slot, _ in kw.get("require", ())
    ):
        raise sec.error("require", "reduction parts are required but 'reductions' is off")
    return Restrictions(**kw)
