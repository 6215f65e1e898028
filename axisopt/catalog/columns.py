"""The part columns, declared once: each table's columns with their unit kind, the model parameter
they feed, positive / optional / estimated, the allowed choices and the provenance columns
(:data:`COLUMNS`), and the rules one part row must keep (:func:`row_problem`: the one validation of
catalog rows and of parts written inline in a design).  The reader of ``catalogs/*.csv`` is
:mod:`.loading`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

SHIPPED_DIR = Path(__file__).resolve().parent.parent.parent / "catalogs"


# ------------------------------------------------------------------ the part columns (one
# declaration)
@dataclass(frozen=True)
class Column:
    """One column of a part table: how the loader reads it and which model parameter it feeds.

    kind      : "str" (text), "int" (a count) or a :data:`axisopt.units.KINDS` kind (the header's
                unit converts)
    param     : the model parameter (:data:`axisopt.model.PARAM_NAMES`) the value goes to as it is;
                None for a column the model does not read, or reads through a rule (see
                ``model.params.axis_params``)
    positive  : must be > 0 (stiffness and the geometry the physics divides by); every other number
                >= 0
    optional  : the cell may be empty where the vendor lists no value (read as NaN)
    estimate  : for an optional column the model reads: what stands in where the cell is empty (an
                estimated, not a vendor, value; results say when it binds)
    estimated_when : row statuses (``status`` column) whose value in this column is not the vendor's
                table (derived by a rule or illustrative, catalogs/SOURCES.md); ``estimated_how``
                says how
    derived_marker : a row whose ``source`` names this value as derived (``'<marker> ... derived'``
                within one ``;``-separated part) holds an estimate here whatever its status
    at_most   : the largest meaningful value in SI (an efficiency: 1), or None
    blank     : for an optional column that is no estimate: what an empty cell (or the column left
                out of the header) means, e.g. the nut's ``rotating`` flag (empty: a nut on a
                rotating screw)
    applies   : a flag column of the same table: this column means something (and its estimate
                stands in) only on rows whose flag is 1 (the driven rotating-nut unit's columns)
    """

    name: str
    kind: str
    param: str | None = None
    positive: bool = False
    optional: bool = False
    estimate: str = ""
    estimated_when: tuple = ()
    estimated_how: str = ""
    derived_marker: str = ""
    at_most: float | None = None
    blank: str = ""
    applies: str = ""

    def estimated_in(self, status: str, source: str = "") -> str:
        """How this column's value is estimated in a row of ``status`` and ``source`` ('' : the
        vendor's)."""
        if status in self.estimated_when:
            return self.estimated_how or f"{status} row, catalogs/SOURCES.md"
        if self.derived_marker and source:
            for part in str(source).split(";"):
                words = part.replace(",", " ").split()
                if (
                    self.derived_marker in words
                    and "derived" in words[words.index(self.derived_marker) :]
                ):
                    return f"{part.strip()} (catalogs/SOURCES.md)"
        return ""


def _c(name, kind, param=None, **kw) -> Column:
    return Column(name, kind, param, **kw)


# Where a catalog value is not the vendor's (catalogs/SOURCES.md): every price is illustrative;
# rigidity is derived in 'stiffness-derived' and 'derived' rows, ratings and preload in 'derived'
# rows.
_CATALOG_ROWS = ("vendor", "stiffness-derived", "paper", "derived")
_PRICE = {
    "estimated_when": _CATALOG_ROWS,
    "estimated_how": "illustrative price (catalogs/SOURCES.md)",
}
_RIGIDITY = {"estimated_when": ("stiffness-derived", "derived")}
_DERIVED = {"estimated_when": ("derived",)}
_TEXT = ("id", "vendor", "series")
_UNIT = {"optional": True, "applies": "rotating", "positive": True}
# the rotating-nut unit's own values (read through rules in model.params.rotating_nut_params):
# required on a rotating row (row_problem) except where an estimate stands in
_UNIT_COLUMNS = (
    _c("unit_inertia", "inertia", **_UNIT),
    _c(
        "unit_max_speed",
        "angular_speed",
        **_UNIT,
        estimate="the screw vendor's DN rule for the nut's rotation, DN limit / d (THK A-697; H-BS "
        "3.7.6)",
    ),
    _c("unit_bearing_dynamic_load", "force", **_UNIT),
    _c("unit_bearing_static_load", "force", **_UNIT),
    _c(
        "unit_bearing_rigidity",
        "stiffness",
        **_UNIT,
        estimate="11.2 N/um per kN of the unit bearing's Ca, the lowest of the ZKLF rows (H-BS "
        "8.8.2)",
    ),
    _c(
        "unit_starting_torque",
        "torque",
        **_UNIT,
        estimate="support-set envelope 3.72e-3 x (0.05 Ca) x 2.5 d (catalogs/SOURCES.md)",
    ),
)
# columns a rotating-nut row must fill (no estimate stands in for them)
UNIT_REQUIRED = tuple(c.name for c in _UNIT_COLUMNS if not c.estimate)
COLUMNS = MappingProxyType(
    {
        "screws": (
            *(_c(n, "str") for n in _TEXT),
            _c("nominal_diameter", "length", "nominal_diameter", positive=True),
            _c("lead", "length", "lead", positive=True),
            _c("root_diameter", "length", "root_diameter", positive=True),
            _c("ball_diameter", "length", optional=True),
            _c("max_length", "length", "screw_max_length", positive=True),
            _c("mass_per_length", "mass_per_length", "screw_mass_per_length", positive=True),
            _c("dn_limit", "dn", "dn_limit", positive=True),
            _c("support_bore_min", "length", "support_bore_min", positive=True),
            _c("support_bore_max", "length", "support_bore_max", positive=True),
            _c("price_per_length", "money_per_length", "screw_price_per_length", **_PRICE),
            _c("price_fixed", "money", "screw_price_fixed", **_PRICE),
        ),
        "nuts": (
            _c("id", "str"),
            _c("vendor", "str"),
            _c("screw_id", "str"),
            _c("type", "str"),
            _c("stiffness", "stiffness", "nut_stiffness", positive=True, **_RIGIDITY),
            _c("stiffness_preload", "force", "nut_stiffness_preload", positive=True),
            _c("preload_min", "force", "nut_preload_min"),
            _c("preload_max", "force", "nut_preload_max"),
            _c("dynamic_load_rating", "force", "nut_dynamic_load", positive=True, **_DERIVED),
            _c("static_load_rating", "force", "nut_static_load", positive=True),
            _c("contact_angle", "angle"),
            _c("axial_play", "length", "nut_axial_play"),
            _c("mass", "mass", "nut_mass"),
            _c("price", "money", "nut_price", **_PRICE),
            # a driven rotating-nut unit (THK DIR/BLR, HIWIN AME): the nut turns in its own support
            # bearing on a stationary screw fixed at both ends (model.checks.unit_checks); the unit
            # columns apply to its rows only the nut body's length: the lead band is taken over the
            # thread the nut travels, stroke + this length (physics.accuracy,
            # model.params.grade_params)
            _c(
                "length",
                "length",
                positive=True,
                optional=True,
                estimate="envelope of the catalog's nuts, 2.75 (P + d) single, 5.1 (P + d) double",
                derived_marker="length",
            ),
            _c("rotating", "int", optional=True, blank="0: a nut on a rotating screw"),
            *_UNIT_COLUMNS,
        ),
        "bearings": (
            *(_c(n, "str") for n in _TEXT),
            _c("arrangement", "str"),
            _c("rows", "int", positive=True),
            _c("bore", "length", "bearing_bore", positive=True),
            _c("outer_diameter", "length", positive=True),
            _c("contact_angle", "angle"),
            _c("preload_class", "str"),
            _c("preload", "force", "bearing_preload", **_DERIVED, derived_marker="preload"),
            _c("axial_rigidity", "stiffness", "bearing_stiffness", positive=True, **_RIGIDITY),
            _c(
                "lift_off_load",
                "force",
                "bearing_lift_off",
                estimated_when=_CATALOG_ROWS,
                estimated_how="2.83 x preload (DB/DF/DFF, SKF-LF) or 2.08 x preload (DBD), "
                "catalogs/SOURCES.md",
            ),
            # DFT
            _c(
                "lift_off_load_strong",
                "force",
                optional=True,
                positive=True,
                estimated_when=_CATALOG_ROWS,
                estimated_how="Hertz set rule, 8.49 x the DB pair's preload for 3 against 1 (IBC "
                "Table 2.2)",
                blank="the set lifts off at lift_off_load both ways (the weaker direction's value: "
                "conservative)",
            ),
            _c("dynamic_load_rating", "force", "bearing_dynamic_load", positive=True, **_DERIVED),
            # the static (or limiting, or permissible) axial rating of the rows carrying the
            # stronger direction, and the least static safety its vendor asks on it
            # (physics.bearings: NSK/HIWIN WBK limiting load 1/0.7, THK permissible load 1); empty:
            # a true C0a with no vendor figure, Rexroth's machine-tool S0 >= 4
            _c("static_load_rating", "force", "bearing_static_load", positive=True),
            _c(
                "static_safety",
                "dimensionless",
                positive=True,
                optional=True,
                estimate="no vendor figure: Rexroth's machine-tool S0 >= 4 (R310RU 3301 p. 125)",
            ),
            _c(
                "limiting_speed",
                "angular_speed",
                "bearing_limiting_speed",
                **_DERIVED,
                derived_marker="speed",
            ),
            _c(
                "starting_torque",
                "torque",
                optional=True,
                estimate="vendor envelope 3.72e-3 x preload x mean diameter",
            ),
            _c("f0", "dimensionless", "bearing_f0"),
            _c("f1", "dimensionless", "bearing_f1"),
            _c("mass", "mass", "bearing_mass"),
            _c("price", "money", "bearing_price", **_PRICE),
        ),
        "guides": (
            *(_c(n, "str") for n in _TEXT),
            _c("type", "str"),
            _c("size", "length", positive=True),
            _c("preload_class", "str"),
            _c("preload_level", "str"),
            _c("preload", "force", "guide_preload"),
            _c(
                "normal_rigidity", "stiffness", "guide_normal_stiffness", positive=True, **_RIGIDITY
            ),
            _c(
                "tangential_rigidity",
                "stiffness",
                "guide_tangential_stiffness",
                positive=True,
                **_RIGIDITY,
            ),
            _c("dynamic_load_rating", "force", "guide_dynamic_load", positive=True, **_DERIVED),
            _c("static_load_rating", "force", "guide_static_load", positive=True),
            # the travel the dynamic rating is defined for: 50 km (THK, HIWIN, IKO, NBS ball blocks;
            # IKO roller blocks too) or 100 km (THK, HIWIN roller blocks, ISO 14728-1);
            # catalogs/SOURCES.md per vendor
            _c(
                "rating_distance",
                "distance",
                positive=True,
                optional=True,
                estimate="50 km, the shorter of the two rating bases (never kinder than the "
                "vendor's)",
            ),
            _c("friction_force", "force", "guide_friction_force"),
            _c("friction_coefficient", "dimensionless", "guide_friction_coefficient"),
            _c("friction_viscous", "damping", "guide_friction_viscous"),
            _c("damping", "damping", "guide_damping"),
            _c("block_mass", "mass", "guide_block_mass"),
            _c("rail_mass_per_length", "mass_per_length", "guide_rail_mass_per_length"),
            _c("block_price", "money", "guide_block_price", **_PRICE),
            _c(
                "rail_price_per_length", "money_per_length", "guide_rail_price_per_length", **_PRICE
            ),
            # static permissible moments of one block (vendor tables: HIWIN MR/MP/MY, IKO T0/TX/TY,
            # NBS M0X/M0Z/M0Y): the block-load method needs them for one block per rail or one rail
            # (THK K = C0 / M)
            _c("moment_roll", "torque", "guide_moment_roll", positive=True),
            _c("moment_pitch", "torque", "guide_moment_pitch", positive=True),
            _c("moment_yaw", "torque", "guide_moment_yaw", positive=True),
        ),
        # Drive parts (servo motors, shaft couplings, reductions).  Optional tables: a catalog
        # directory may leave them out.
        "motors": (
            *(_c(n, "str") for n in _TEXT),
            _c("rated_power", "power", positive=True),
            _c("rated_torque", "torque", "motor_rated_torque", positive=True),
            _c("peak_torque", "torque", "motor_peak_torque", positive=True),
            _c("rated_speed", "angular_speed", positive=True),
            _c("max_speed", "angular_speed", "motor_max_speed", positive=True),
            _c("rotor_inertia", "inertia", positive=True),
            _c("rotor_inertia_brake", "inertia", optional=True),
            _c("brake_torque", "torque", optional=True),
            _c("mass", "mass", optional=True),
            _c("flange", "length", optional=True),
            _c("price", "money", "motor_price", **_PRICE),
            # intermittent (peak) zone of the vendor's torque-speed curve: peak torque flat up to
            # the corner speed, then falling linearly to its value at max speed
            # (physics.drive.peak_torque_available)
            _c(
                "peak_corner_speed",
                "angular_speed",
                optional=True,
                estimate="min(rated speed, max speed / 2): Mitsubishi MDS-D-SVJ3 sec. 7-1 (2)",
            ),
            _c(
                "peak_torque_at_max_speed",
                "torque",
                optional=True,
                estimate="rated torque (peak falls to rated)",
            ),
            *(
                _c(
                    n,
                    "dimensionless",
                    optional=True,
                    at_most=1.0,
                    estimate="no vendor rule: Mitsubishi's, the harshest",
                )
                # the vendor's selection rule (model.motorrule)
                for n in ("rms_ratio", "unbalance_ratio")
            ),
        ),
        "couplings": (
            *(_c(n, "str") for n in _TEXT),
            _c("rated_torque", "torque", "coupling_rated_torque", positive=True),
            _c("torsional_stiffness", "torsional_stiffness", positive=True),
            _c("inertia", "inertia", positive=True),
            _c("max_speed", "angular_speed", "coupling_max_speed", positive=True),
            _c("bore_min", "length", positive=True),
            _c("bore_max", "length", positive=True),
            _c("mass", "mass", optional=True),
            _c("price", "money", "coupling_price", **_PRICE),
        ),
        # Reductions between motor and coupling (planetary gearbox on the motor flange, or a belt
        # stage), optional: ratio = motor turns per output turn; inertia at the input (the motor
        # shaft); the torques, the torsional stiffness and the backlash on the output side (Beckhoff
        # AG2400/AG3400: T2N, T2B, Ct21, jt; n1Max)
        "reductions": (
            *(_c(n, "str") for n in _TEXT),
            _c("kind", "str"),
            _c("ratio", "dimensionless", "reduction_ratio", positive=True),
            _c("efficiency", "dimensionless", "reduction_efficiency", positive=True, at_most=1.0),
            _c(
                "inertia", "inertia", "reduction_inertia", derived_marker="inertia"
            ),  # belt: SOURCES.md
            _c("rated_torque", "torque", "reduction_rated_torque", positive=True),
            _c("accel_torque", "torque", "reduction_accel_torque", positive=True),
            # the emergency-stop torque (Beckhoff AG2400 "T2Em.stop ... 1000 times during the
            # service life"): what the motor's peak (or the drive's torque limit) through the ratio
            # may reach at a collision or an E-stop
            _c(
                "emergency_torque",
                "torque",
                optional=True,
                estimate="T2B (the acceleration torque, never above the emergency torque)",
            ),
            _c("torsional_stiffness", "torsional_stiffness", positive=True, **_RIGIDITY),
            _c("backlash", "angle", "reduction_backlash"),
            _c("max_input_speed", "angular_speed", "reduction_max_speed", positive=True),
            _c("mass", "mass", optional=True),
            _c("price", "money", "reduction_price", **_PRICE),
        ),
    }
)

# Columns a table may omit from its header; shipped rows carry them (tests/catalogs checks every
# row).
#   status: "vendor" (a catalog part, stiffness and load ratings from the vendor's table),
#   "stiffness-derived"
#           (a catalog part with vendor ratings and preload whose rigidity the vendor gives no
#           number for; computed
#           by a rule in catalogs/SOURCES.md), "paper" (stiffness from the seed paper) or "derived"
#           (the part or
#           its ratings computed by a rule).  A row of a table without the column is "user".
#   source: the reference key of catalogs/SOURCES.md and the table or page, e.g. "H-BS Table 6.6".
PROVENANCE = MappingProxyType(
    {"status": ("vendor", "stiffness-derived", "paper", "derived"), "source": None}
)
USER_STATUS = "user"
STATUSES = PROVENANCE["status"] + (USER_STATUS,)

SCHEMA = MappingProxyType(
    {t: MappingProxyType({c.name: c.kind for c in cols}) for t, cols in COLUMNS.items()}
)

# Columns that must be > 0 and columns whose cell may be left empty (read as NaN; the model then
# uses the column's ``estimate``, e.g. seed eq. 40 for a bearing set without a listed starting
# torque); derived from :data:`COLUMNS`.  Every other number of every table must not be negative (no
# part has a negative mass, price, play or friction); catalog rows and inline parts go through the
# same :func:`row_problem`.
_POSITIVE = {t: tuple(c.name for c in cols if c.positive) for t, cols in COLUMNS.items()}
OPTIONAL_COLUMNS = MappingProxyType(
    {
        t: tuple(c.name for c in cols if c.optional)
        for t, cols in COLUMNS.items()
        if any(c.optional for c in cols)
    }
)
# Pairs (low, high) that a row must keep in order: a one-line error names the row otherwise.
_ORDERED = {
    "motors": (
        ("rated_torque", "peak_torque"),
        ("rated_speed", "max_speed"),
        ("rotor_inertia", "rotor_inertia_brake"),
        ("peak_corner_speed", "max_speed"),
        ("peak_torque_at_max_speed", "peak_torque"),
    ),
    "couplings": (("bore_min", "bore_max"),),
    "nuts": (("preload_min", "preload_max"),),
    "reductions": (("rated_torque", "accel_torque"),),
}
# Largest meaningful values (an efficiency of at most 1), from COLUMNS
_AT_MOST = {
    t: tuple((c.name, c.at_most) for c in cols if c.at_most is not None)
    for t, cols in COLUMNS.items()
}
# Screw-end sets of 60-degree bearings: DB/DF pairs, DBD/DFD (2 against 1), DBB/DFF (2 against 2),
# DBT/DFT (3 against 1), as (rows of the stronger direction, the other's); vendors rate the stronger
# (NSK TAC B, HIWIN WBK)
ARRANGEMENT_ROWS = MappingProxyType(
    {
        "DB": (1, 1),
        "DF": (1, 1),
        "DBD": (2, 1),
        "DFD": (2, 1),
        "DBB": (2, 2),
        "DFF": (2, 2),
        "DBT": (3, 1),
        "DFT": (3, 1),
    }
)
CHOICES = {
    ("nuts", "type"): ("single", "double"),
    ("guides", "type"): ("ball", "roller"),
    ("guides", "preload_level"): ("light", "medium", "heavy", "super-heavy"),
    ("bearings", "preload_class"): ("light", "medium", "heavy"),
    # the sets of 60-degree thrust bearings for screw ends (ARRANGEMENT_ROWS)
    ("bearings", "arrangement"): tuple(ARRANGEMENT_ROWS),
    ("reductions", "kind"): ("planetary", "belt"),
}
TABLES = ("screws", "nuts", "bearings", "guides", "motors", "couplings", "reductions")
# the part slots of a design, declared once (one per table, in TABLES' order): the mechanical parts,
# then the drive's (design.axis.PART_SLOTS, the problem's restrictions)
MECH_SLOTS = ("screw", "nut", "bearing", "guide")
DRIVE_SLOTS = ("motor", "coupling", "reduction")
PART_SLOTS = MECH_SLOTS + DRIVE_SLOTS
# each slot with its catalog table: (slot, table) in that order
SLOT_TABLES = tuple(zip(PART_SLOTS, TABLES))


def row_problem(name: str, rec: dict) -> tuple[str, str] | None:
    """The first thing wrong with one part of table ``name`` (numbers in SI, optional cells NaN), as
    (column, message), or None.  The one validation of catalog rows (:func:`load_catalogs`) and of
    parts written inline in a design (:func:`axisopt.design.inline_part`)."""
    from ..units import PLAUSIBLE_MAX, PLAUSIBLE_MIN

    for col, kind in SCHEMA[name].items():
        val = rec.get(col)
        if kind == "str":
            if not isinstance(val, str) or not val.strip():
                return col, "empty text"
            continue
        if val is None or (isinstance(val, float) and math.isnan(val)):
            if col in OPTIONAL_COLUMNS.get(name, ()):
                continue
            return col, "missing value"
        if not math.isfinite(val):
            return col, f"not a finite number ({val})"
        if col in _POSITIVE[name] and val <= 0:
            return col, "must be positive"
        if val < 0:
            return col, "must not be negative"
        if kind != "int" and abs(val) > PLAUSIBLE_MAX.get(kind, 1e12):
            return col, f"out of range (at most {PLAUSIBLE_MAX.get(kind, 1e12):g} in SI units)"
        if kind != "int" and 0 < abs(val) < PLAUSIBLE_MIN:
            # the YAML values' floor: a load rating of 1e-297 N overflowed the life formula's cube
            return col, f"too small to be meant (below {PLAUSIBLE_MIN:g} in SI units)"
    for col, top in _AT_MOST.get(name, ()):
        if rec[col] > top:
            return col, f"must be at most {top:g} (= {top * 100:g} %)"
    for (t, c), ok in CHOICES.items():
        if t == name and rec.get(c) not in ok:
            return c, f"'{rec.get(c)}' is not one of {', '.join(ok)}"
    for a, b in _ORDERED.get(name, ()):
        if rec[a] > rec[b]:  # NaN (an optional cell left empty) compares False
            return b, f"{b} is below {a}"
    if name == "nuts":
        return _unit_problem(rec)
    return None


def _unit_problem(rec: dict) -> tuple[str, str] | None:
    """A nut's ``rotating`` flag is 0 or 1 (empty: 0); a rotating-nut unit fills the unit columns no
    estimate stands in for (:data:`UNIT_REQUIRED`)."""
    flag = rec.get("rotating", math.nan)
    if flag == 1:
        missing = [c for c in UNIT_REQUIRED if math.isnan(rec.get(c, math.nan))]
        return (missing[0], "missing value (a rotating-nut unit needs it)") if missing else None
    return None if math.isnan(flag) or flag == 0 else ("rotating", "must be 0 or 1")
