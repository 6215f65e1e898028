"""Load and validate part catalogs (``catalogs/*.csv``) into SI pandas tables.

One strict reader (:func:`load_records`, the csv module, no pandas) validates every file; :func:`load_catalogs`
turns its records into the pandas tables the search uses, and ``axisopt parts`` lists the records as they are
(its start-up then imports neither pandas nor numpy).

Each CSV header carries the vendor's unit (``lead [mm]``); values are converted once here.
Errors (unknown unit, missing column, duplicate id, non-numeric cell, non-positive stiffness,
dangling reference) name the file, line and column.  A user catalog directory is merged after the
shipped one; its ids must not collide with the shipped ids.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING

from .errors import InputError
from .units import read_header

if TYPE_CHECKING:
    import pandas as pd

    from .parttable import PartTable, Row

SHIPPED_DIR = Path(__file__).resolve().parent.parent / "catalogs"

# ------------------------------------------------------------------ the part columns (one declaration)
@dataclass(frozen=True)
class Column:
    """One column of a part table: how the loader reads it and which model parameter it feeds.

    kind      : "str" (text), "int" (a count) or a :data:`axisopt.units.KINDS` kind (the header's unit converts)
    param     : the model parameter (:data:`axisopt.model.PARAM_NAMES`) the value goes to as it is; None for a
                column the model does not read, or reads through a rule (see ``model.params.axis_params``)
    positive  : must be > 0 (stiffness and the geometry the physics divides by); every other number >= 0
    optional  : the cell may be empty where the vendor lists no value (read as NaN)
    estimate  : for an optional column the model reads: what stands in where the cell is empty (an estimated,
                not a vendor, value; results say when it binds)
    estimated_when : row statuses (``status`` column) whose value in this column is not the vendor's table
                (derived by a rule or illustrative, catalogs/SOURCES.md); ``estimated_how`` says how
    derived_marker : a row whose ``source`` names this value as derived (``'<marker> ... derived'`` within
                one ``;``-separated part) holds an estimate here whatever its status
    at_most   : the largest meaningful value in SI (an efficiency: 1), or None
    blank     : for an optional column that is no estimate: what an empty cell (or the column left out of the
                header) means, e.g. the nut's ``rotating`` flag (empty: a nut on a rotating screw)
    applies   : a flag column of the same table: this column means something (and its estimate stands in)
                only on rows whose flag is 1 (the driven rotating-nut unit's columns)
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
        """How this column's value is estimated in a row of ``status`` and ``source`` ('' : the vendor's)."""
        if status in self.estimated_when:
            return self.estimated_how or f"{status} row, catalogs/SOURCES.md"
        if self.derived_marker and source:
            for part in str(source).split(";"):
                words = part.replace(",", " ").split()
                if self.derived_marker in words and "derived" in words[words.index(self.derived_marker):]:
                    return f"{part.strip()} (catalogs/SOURCES.md)"
        return ""


def _c(name, kind, param=None, **kw) -> Column:
    return Column(name, kind, param, **kw)


# Where a catalog value is not the vendor's (catalogs/SOURCES.md): every price is illustrative; rigidity is
# derived in 'stiffness-derived' and 'derived' rows, ratings and preload in 'derived' rows.
_CATALOG_ROWS = ("vendor", "stiffness-derived", "paper", "derived")
_PRICE = {"estimated_when": _CATALOG_ROWS, "estimated_how": "illustrative price (catalogs/SOURCES.md)"}
_RIGIDITY = {"estimated_when": ("stiffness-derived", "derived")}
_DERIVED = {"estimated_when": ("derived",)}
_TEXT = ("id", "vendor", "series")
_UNIT = {"optional": True, "applies": "rotating", "positive": True}
# the rotating-nut unit's own values (read through rules in model.params.rotating_nut_params): required on a
# rotating row (row_problem) except where an estimate stands in
_UNIT_COLUMNS = (
    _c("unit_inertia", "inertia", **_UNIT),
    _c("unit_max_speed", "angular_speed", **_UNIT,
       estimate="the screw vendor's DN rule for the nut's rotation, DN limit / d (THK A-697; H-BS 3.7.6)"),
    _c("unit_bearing_dynamic_load", "force", **_UNIT),
    _c("unit_bearing_static_load", "force", **_UNIT),
    _c("unit_bearing_rigidity", "stiffness", **_UNIT,
       estimate="11.2 N/um per kN of the unit bearing's Ca, the lowest of the ZKLF rows (H-BS 8.8.2)"),
    _c("unit_starting_torque", "torque", **_UNIT,
       estimate="support-set envelope 3.72e-3 x (0.05 Ca) x 2.5 d (catalogs/SOURCES.md)"),
)
# columns a rotating-nut row must fill (no estimate stands in for them)
UNIT_REQUIRED = tuple(c.name for c in _UNIT_COLUMNS if not c.estimate)
COLUMNS = MappingProxyType({
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
        _c("id", "str"), _c("vendor", "str"), _c("screw_id", "str"), _c("type", "str"),
        _c("stiffness", "stiffness", "nut_stiffness", positive=True, **_RIGIDITY),
        _c("stiffness_preload", "force", "nut_stiffness_preload", positive=True),
        _c("preload_min", "force", "nut_preload_min"), _c("preload_max", "force", "nut_preload_max"),
        _c("dynamic_load_rating", "force", "nut_dynamic_load", positive=True, **_DERIVED),
        _c("static_load_rating", "force", "nut_static_load", positive=True),
        _c("contact_angle", "angle"),
        _c("axial_play", "length", "nut_axial_play"), _c("mass", "mass", "nut_mass"),
        _c("price", "money", "nut_price", **_PRICE),
        # a driven rotating-nut unit (THK DIR/BLR, HIWIN AME): the nut turns in its own support bearing on a
        # stationary screw fixed at both ends (model.checks.unit_checks); the unit columns apply to its rows only
        _c("rotating", "int", optional=True, blank="0: a nut on a rotating screw"),
        *_UNIT_COLUMNS,
    ),
    "bearings": (
        *(_c(n, "str") for n in _TEXT), _c("arrangement", "str"), _c("rows", "int", positive=True),
        _c("bore", "length", "bearing_bore", positive=True), _c("outer_diameter", "length", positive=True),
        _c("contact_angle", "angle"), _c("preload_class", "str"),
        _c("preload", "force", "bearing_preload", **_DERIVED, derived_marker="preload"),
        _c("axial_rigidity", "stiffness", "bearing_stiffness", positive=True, **_RIGIDITY),
        _c("lift_off_load", "force", "bearing_lift_off", estimated_when=_CATALOG_ROWS,
           estimated_how="2.83 x preload (DB/DF/DFF, SKF-LF) or 2.08 x preload (DBD), catalogs/SOURCES.md"),
        _c("lift_off_load_strong", "force", optional=True, positive=True, estimated_when=_CATALOG_ROWS,  # DFT
           estimated_how="Hertz set rule, 8.49 x the DB pair's preload for 3 against 1 (IBC Table 2.2)",
           blank="the set lifts off at lift_off_load both ways (the weaker direction's value: conservative)"),
        _c("dynamic_load_rating", "force", "bearing_dynamic_load", positive=True, **_DERIVED),
        # the static (or limiting, or permissible) axial rating of the rows carrying the stronger direction, and
        # the least static safety its vendor asks on it (physics.bearings: NSK/HIWIN WBK limiting load 1/0.7,
        # THK permissible load 1); empty: a true C0a with no vendor figure, Rexroth's machine-tool S0 >= 4
        _c("static_load_rating", "force", "bearing_static_load", positive=True),
        _c("static_safety", "dimensionless", positive=True, optional=True,
           estimate="no vendor figure: Rexroth's machine-tool S0 >= 4 (R310RU 3301 p. 125)"),
        _c("limiting_speed", "angular_speed", "bearing_limiting_speed", **_DERIVED, derived_marker="speed"),
        _c("starting_torque", "torque", optional=True,
           estimate="vendor envelope 3.72e-3 x preload x mean diameter"),
        _c("f0", "dimensionless", "bearing_f0"), _c("f1", "dimensionless", "bearing_f1"),
        _c("mass", "mass", "bearing_mass"), _c("price", "money", "bearing_price", **_PRICE),
    ),
    "guides": (
        *(_c(n, "str") for n in _TEXT), _c("type", "str"), _c("size", "length", positive=True),
        _c("preload_class", "str"), _c("preload_level", "str"), _c("preload", "force", "guide_preload"),
        _c("normal_rigidity", "stiffness", "guide_normal_stiffness", positive=True, **_RIGIDITY),
        _c("tangential_rigidity", "stiffness", "guide_tangential_stiffness", positive=True, **_RIGIDITY),
        _c("dynamic_load_rating", "force", "guide_dynamic_load", positive=True, **_DERIVED),
        _c("static_load_rating", "force", "guide_static_load", positive=True),
        # the travel the dynamic rating is defined for: 50 km (THK, HIWIN, IKO, NBS ball blocks; IKO roller
        # blocks too) or 100 km (THK, HIWIN roller blocks, ISO 14728-1); catalogs/SOURCES.md per vendor
        _c("rating_distance", "distance", positive=True, optional=True,
           estimate="50 km, the shorter of the two rating bases (never kinder than the vendor's)"),
        _c("friction_force", "force", "guide_friction_force"),
        _c("friction_coefficient", "dimensionless", "guide_friction_coefficient"),
        _c("friction_viscous", "damping", "guide_friction_viscous"),
        _c("damping", "damping", "guide_damping"), _c("block_mass", "mass", "guide_block_mass"),
        _c("rail_mass_per_length", "mass_per_length", "guide_rail_mass_per_length"),
        _c("block_price", "money", "guide_block_price", **_PRICE),
        _c("rail_price_per_length", "money_per_length", "guide_rail_price_per_length", **_PRICE),
        # static permissible moments of one block (vendor tables: HIWIN MR/MP/MY, IKO T0/TX/TY, NBS M0X/M0Z/M0Y):
        # the block-load method needs them for one block per rail or one rail (THK K = C0 / M)
        _c("moment_roll", "torque", "guide_moment_roll", positive=True),
        _c("moment_pitch", "torque", "guide_moment_pitch", positive=True),
        _c("moment_yaw", "torque", "guide_moment_yaw", positive=True),
    ),
    # Drive parts (servo motors, shaft couplings, reductions).  Optional tables: a catalog directory may leave them out.
    "motors": (
        *(_c(n, "str") for n in _TEXT), _c("rated_power", "power", positive=True),
        _c("rated_torque", "torque", "motor_rated_torque", positive=True),
        _c("peak_torque", "torque", "motor_peak_torque", positive=True),
        _c("rated_speed", "angular_speed", positive=True),
        _c("max_speed", "angular_speed", "motor_max_speed", positive=True),
        _c("rotor_inertia", "inertia", positive=True),
        _c("rotor_inertia_brake", "inertia", optional=True), _c("brake_torque", "torque", optional=True),
        _c("mass", "mass", optional=True), _c("flange", "length", optional=True),
        _c("price", "money", "motor_price", **_PRICE),
        # intermittent (peak) zone of the vendor's torque-speed curve: peak torque flat up to the corner speed,
        # then falling linearly to its value at max speed (physics.drive.peak_torque_available)
        _c("peak_corner_speed", "angular_speed", optional=True,
           estimate="min(rated speed, max speed / 2): Mitsubishi MDS-D-SVJ3 sec. 7-1 (2)"),
        _c("peak_torque_at_max_speed", "torque", optional=True, estimate="rated torque (peak falls to rated)"),
        *(_c(n, "dimensionless", optional=True, at_most=1.0, estimate="no vendor rule: Mitsubishi's, the harshest")
          for n in ("rms_ratio", "unbalance_ratio")),  # the vendor's selection rule (model.motorrule)
    ),
    "couplings": (
        *(_c(n, "str") for n in _TEXT),
        _c("rated_torque", "torque", "coupling_rated_torque", positive=True),
        _c("torsional_stiffness", "torsional_stiffness", positive=True),
        _c("inertia", "inertia", positive=True),
        _c("max_speed", "angular_speed", "coupling_max_speed", positive=True),
        _c("bore_min", "length", positive=True), _c("bore_max", "length", positive=True),
        _c("mass", "mass", optional=True), _c("price", "money", "coupling_price", **_PRICE),
    ),
    # Reductions between motor and coupling (planetary gearbox on the motor flange, or a belt stage), optional:
    # ratio = motor turns per output turn; inertia at the input (the motor shaft); the torques, the torsional
    # stiffness and the backlash on the output side (Beckhoff AG2400/AG3400: T2N, T2B, Ct21, jt; n1Max)
    "reductions": (
        *(_c(n, "str") for n in _TEXT), _c("kind", "str"),
        _c("ratio", "dimensionless", "reduction_ratio", positive=True),
        _c("efficiency", "dimensionless", "reduction_efficiency", positive=True, at_most=1.0),
        _c("inertia", "inertia", "reduction_inertia", derived_marker="inertia"),  # belt: SOURCES.md
        _c("rated_torque", "torque", "reduction_rated_torque", positive=True),
        _c("accel_torque", "torque", "reduction_accel_torque", positive=True),
        # the emergency-stop torque (Beckhoff AG2400 "T2Em.stop ... 1000 times during the service life"): what the
        # motor's peak (or the drive's torque limit) through the ratio may reach at a collision or an E-stop
        _c("emergency_torque", "torque", optional=True,
           estimate="T2B (the acceleration torque, never above the emergency torque)"),
        _c("torsional_stiffness", "torsional_stiffness", positive=True, **_RIGIDITY),
        _c("backlash", "angle", "reduction_backlash"),
        _c("max_input_speed", "angular_speed", "reduction_max_speed", positive=True),
        _c("mass", "mass", optional=True), _c("price", "money", "reduction_price", **_PRICE),
    ),
})

# Columns a table may omit from its header; shipped rows carry them (tests/catalogs checks every row).
#   status: "vendor" (a catalog part, stiffness and load ratings from the vendor's table), "stiffness-derived"
#           (a catalog part with vendor ratings and preload whose rigidity the vendor gives no number for; computed
#           by a rule in catalogs/SOURCES.md), "paper" (stiffness from the seed paper) or "derived" (the part or
#           its ratings computed by a rule).  A row of a table without the column is "user".
#   source: the reference key of catalogs/SOURCES.md and the table or page, e.g. "H-BS Table 6.6".
PROVENANCE = MappingProxyType({"status": ("vendor", "stiffness-derived", "paper", "derived"), "source": None})
USER_STATUS = "user"
STATUSES = PROVENANCE["status"] + (USER_STATUS,)

SCHEMA = MappingProxyType({t: MappingProxyType({c.name: c.kind for c in cols}) for t, cols in COLUMNS.items()})
MAX_CATALOG_BYTES = 50_000_000
# Tables the axis model needs in every catalog; the drive tables may be absent (empty then).
REQUIRED_TABLES = ("screws", "nuts", "bearings", "guides")

# Columns that must be > 0 and columns whose cell may be left empty (read as NaN; the model then uses the
# column's ``estimate``, e.g. seed eq. 40 for a bearing set without a listed starting torque); derived from
# :data:`COLUMNS`.  Every other number of every table must not be negative (no part has a negative mass, price,
# play or friction); catalog rows and inline parts go through the same :func:`row_problem`.
_POSITIVE = {t: tuple(c.name for c in cols if c.positive) for t, cols in COLUMNS.items()}
OPTIONAL_COLUMNS = MappingProxyType({t: tuple(c.name for c in cols if c.optional) for t, cols in COLUMNS.items()
                                     if any(c.optional for c in cols)})
# Pairs (low, high) that a row must keep in order: a one-line error names the row otherwise.
_ORDERED = {
    "motors": (("rated_torque", "peak_torque"), ("rated_speed", "max_speed"),
               ("rotor_inertia", "rotor_inertia_brake"), ("peak_corner_speed", "max_speed"),
               ("peak_torque_at_max_speed", "peak_torque")),
    "couplings": (("bore_min", "bore_max"),),
    "nuts": (("preload_min", "preload_max"),),
    "reductions": (("rated_torque", "accel_torque"),),
}
# Largest meaningful values (an efficiency of at most 1), from COLUMNS
_AT_MOST = {t: tuple((c.name, c.at_most) for c in cols if c.at_most is not None) for t, cols in COLUMNS.items()}
# Screw-end sets of 60-degree bearings: DB/DF pairs, DBD/DFD (2 against 1), DBB/DFF (2 against 2), DBT/DFT (3
# against 1), as (rows of the stronger direction, the other's); vendors rate the stronger (NSK TAC B, HIWIN WBK)
ARRANGEMENT_ROWS = MappingProxyType({"DB": (1, 1), "DF": (1, 1), "DBD": (2, 1), "DFD": (2, 1), "DBB": (2, 2),
                                     "DFF": (2, 2), "DBT": (3, 1), "DFT": (3, 1)})
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


class Catalog:
    """The part tables in SI, indexed by part id, plus where each row came from.  ``motors``,
    ``couplings`` and ``reductions`` (the drive) are empty tables when no catalog directory has them.

    Each table is given as a :class:`~axisopt.parttable.PartTable` (what :func:`load_catalogs` builds, no
    pandas) or a pandas DataFrame indexed by part id.  ``cat.screws`` (and the other five) is the pandas table
    (built on first use); :meth:`rows` is the same table without pandas, as the search and the model read it.
    :meth:`replace` swaps tables (``cat.replace(guides=df)``)."""

    __slots__ = ("_given", "_rows", "_frames")

    def __init__(self, screws, nuts, bearings, guides, motors=None, couplings=None, reductions=None):
        given = dict(zip(TABLES, (screws, nuts, bearings, guides, motors, couplings, reductions)))
        self._given = {k: (_empty_table(k) if v is None else v) for k, v in given.items()}
        self._rows: dict = {}
        self._frames: dict = {}

    def replace(self, **tables) -> Catalog:
        """A catalog with some tables swapped (``cat.replace(guides=df)``)."""
        unknown = set(tables) - set(TABLES)
        if unknown:
            raise TypeError(f"unknown catalog table(s) {', '.join(sorted(unknown))}")
        return Catalog(**{**self._given, **tables})

    def rows(self, name: str) -> PartTable:
        """Table ``name`` as a :class:`~axisopt.parttable.PartTable` (no pandas)."""
        t = self._rows.get(name)
        if t is None:
            from .parttable import PartTable

            src = self._given[name]
            t = src if isinstance(src, PartTable) else PartTable.from_frame(src)
            self._rows[name] = t
        return t

    def table(self, name: str) -> pd.DataFrame:
        """Table ``name`` as a pandas DataFrame indexed by part id (imports pandas; the same object each time)."""
        df = self._frames.get(name)
        if df is None:
            from .parttable import PartTable

            src = self._given[name]
            df = src.to_frame() if isinstance(src, PartTable) else src
            self._frames[name] = df
        return df

    screws = property(lambda self: self.table("screws"), doc="screws (pandas DataFrame by part id)")
    nuts = property(lambda self: self.table("nuts"), doc="nuts (pandas DataFrame by part id)")
    bearings = property(lambda self: self.table("bearings"), doc="support bearings (pandas DataFrame by part id)")
    guides = property(lambda self: self.table("guides"), doc="linear guides (pandas DataFrame by part id)")
    motors = property(lambda self: self.table("motors"), doc="motors (pandas DataFrame by part id)")
    couplings = property(lambda self: self.table("couplings"), doc="couplings (pandas DataFrame by part id)")
    reductions = property(lambda self: self.table("reductions"), doc="reductions (pandas DataFrame by part id)")

    def __repr__(self) -> str:
        return "Catalog(" + ", ".join(f"{n}: {len(self.rows(n))}" for n in TABLES) + ")"

    def part(self, table: str, part_id: str, *, source: str | None = None, key: str | None = None) -> Row:
        """The row of ``part_id`` in ``table`` as a :class:`~axisopt.parttable.Row`; an unknown id is a one-line
        error with the closest id."""
        t = self.rows(table)
        i = t.position(part_id)
        if i is None:
            near = _closest(part_id, t.ids)
            hint = f"; did you mean '{near}'?" if near else ""
            raise InputError(f"unknown {table[:-1]} id '{part_id}'{hint}", source=source, where=key)
        return t.row(i)


def _table_columns(name: str) -> list[str]:
    """The columns of a loaded part table: the schema's, then where each row came from."""
    return list(SCHEMA[name]) + ["_source", *PROVENANCE]


def _empty_table(name: str) -> PartTable:
    from .parttable import PartTable

    return PartTable([], _table_columns(name), ids=[])


def _closest(word: str, options) -> str | None:
    from .yamlio import close_matches

    m = close_matches(str(word), [str(o) for o in options])
    return m[0] if m else None


def row_problem(name: str, rec: dict) -> tuple[str, str] | None:
    """The first thing wrong with one part of table ``name`` (numbers in SI, optional cells NaN), as
    (column, message), or None.  The one validation of catalog rows (:func:`load_catalogs`) and of parts
    written inline in a design (:func:`axisopt.design.inline_part`)."""
    from .units import PLAUSIBLE_MAX

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
    """A nut's ``rotating`` flag is 0 or 1 (empty: 0); a rotating-nut unit fills the unit columns no estimate
    stands in for (:data:`UNIT_REQUIRED`)."""
    flag = rec.get("rotating", math.nan)
    if flag == 1:
        missing = [c for c in UNIT_REQUIRED if math.isnan(rec.get(c, math.nan))]
        return (missing[0], "missing value (a rotating-nut unit needs it)") if missing else None
    return None if math.isnan(flag) or flag == 0 else ("rotating", "must be 0 or 1")


def _read_records(path: Path, name: str) -> list[dict]:
    """The rows of one CSV as validated records in SI (``status`` and ``source`` filled in for a table without
    them); the first problem raises a one-line :class:`InputError` naming the file, line and column."""
    schema = SCHEMA[name]
    src = str(path)
    try:
        from .fileio import read_input, refuse_nul  # regular files only, at most MAX_CATALOG_BYTES

        text = refuse_nul(read_input(path, "catalog", what="catalog", encoding="utf-8-sig"), src)
        with io.StringIO(text, newline="") as fh:
            reader = csv.reader(fh)
            try:
                rows = list(reader)
            except csv.Error as exc:
                raise InputError(f"malformed CSV ({exc})", source=src, where=f"line {reader.line_num}") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read catalog ({exc.__class__.__name__}: "
                         f"{getattr(exc, 'strerror', None) or exc})", source=src) from None
    if not rows:
        raise InputError("empty catalog file", source=src)
    header = rows[0]
    def unknown(col: str) -> str:
        near = _closest(col, schema)
        return f"unknown column '{col}'" + (f"; did you mean '{near}'?" if near else "")

    # the header by the strict unit-CSV rules (units.read_header): text and count columns take no unit
    kinds = {c: (None if k in ("str", "int") else k) for c, k in schema.items()} | dict.fromkeys(PROVENANCE)
    header_cols = read_header(header, line=1, source=src, kinds=kinds, unknown=unknown)
    # (name, SI factor or None, kind) per column
    cols = [(c.name, c.factor, "str" if c.name in PROVENANCE else schema[c.name]) for c in header_cols]
    seen = {c.name for c in header_cols}
    # an optional column with an estimate (or a meaning when empty, or one that applies only under a flag) may be
    # left out of the header: every row then takes the estimate (is empty)
    omitted = [c.name for c in COLUMNS[name]
               if c.optional and (c.estimate or c.blank or c.applies) and c.name not in seen]
    missing = [c for c in schema if c not in seen and c not in omitted]
    if missing:
        raise InputError(f"missing column(s) {', '.join(missing)}", source=src, where="line 1")

    records = []
    ids: dict[str, int] = {}
    for i, row in enumerate(rows[1:], start=2):
        if not row or all(not c.strip() for c in row):
            continue
        if len(row) != len(cols):
            raise InputError(f"has {len(row)} cells, header has {len(cols)}", source=src, where=f"line {i}")
        rec = dict.fromkeys(omitted, math.nan)
        for j, ((col, factor, kind), cell) in enumerate(zip(cols, row), start=1):
            cell = cell.strip()
            where = f"line {i}, column {j} ({col})"
            if kind == "str":
                if not cell:
                    raise InputError("empty cell", source=src, where=where)
                rec[col] = cell
                continue
            if not cell and col in OPTIONAL_COLUMNS.get(name, ()):
                rec[col] = math.nan
                continue
            try:
                val = float(cell)
            except ValueError:
                raise InputError(f"'{cell}' is not a number", source=src, where=where) from None
            if not math.isfinite(val):
                raise InputError(f"'{cell}' is not a finite number", source=src, where=where)
            if kind == "int":
                if val != int(val):
                    raise InputError(f"'{cell}' is not a whole number", source=src, where=where)
                rec[col] = int(val)
                continue
            rec[col] = val * factor
        names = [n for n, _, _ in cols]
        if "status" in rec and rec["status"] not in PROVENANCE["status"]:
            j = names.index("status") + 1
            raise InputError(f"status '{rec['status']}' is not one of {', '.join(PROVENANCE['status'])}",
                             source=src, where=f"line {i}, column {j} (status)")
        bad = row_problem(name, rec)
        if bad is not None:
            c, msg = bad
            j = names.index(c)
            if msg.startswith(c):  # an ordered pair: "<high> is below <low>"
                text = f"{msg} ({row[j].strip()})"
            elif msg.startswith("'"):  # a choice: the message shows the value
                text = f"{c} {msg}"
            else:
                text = f"{c} {msg}, got {row[j].strip()}"
            raise InputError(text, source=src, where=f"line {i}, column {j + 1} ({c})")
        if rec["id"] in ids:
            raise InputError(f"duplicate id '{rec['id']}' (first on line {ids[rec['id']]})", source=src,
                             where=f"line {i}, column 1 (id)")
        ids[rec["id"]] = i
        rec["_source"] = f"{src}:{i}"
        rec.setdefault("status", USER_STATUS)
        rec.setdefault("source", "")
        records.append(rec)
    return records


class PartRows:
    """The validated catalog rows as plain records (dicts in SI, keyed by column, plus ``_source``, ``status`` and
    ``source``), per table in file order: what :func:`load_records` returns and :func:`load_catalogs` builds its
    pandas tables from."""

    def __init__(self, tables: dict[str, list[dict]]):
        self._tables = tables
        self._ids = {name: {r["id"]: r for r in rows} for name, rows in tables.items()}

    def table(self, name: str) -> list[dict]:
        return self._tables[name]

    def part(self, table: str, part_id: str, *, source: str | None = None, key: str | None = None) -> dict:
        """The row of ``part_id`` (same error as :meth:`Catalog.part` for an unknown id)."""
        rows = self._ids[table]
        if part_id not in rows:
            near = _closest(part_id, rows)
            hint = f"; did you mean '{near}'?" if near else ""
            raise InputError(f"unknown {table[:-1]} id '{part_id}'{hint}", source=source, where=key)
        return rows[part_id]


def load_records(extra_dirs=(), *, shipped: bool = True) -> PartRows:
    """Read and validate the shipped catalogs and any user catalog directories (later ones add parts), without
    pandas: every check of :func:`load_catalogs` (which builds its tables from these records)."""
    dirs = ([SHIPPED_DIR] if shipped else []) + [Path(d) for d in extra_dirs]
    tables: dict[str, list[list[dict]]] = {name: [] for name in SCHEMA}
    for d in dirs:
        if not d.is_dir():
            raise InputError("catalog directory not found", source=str(d))
        for name in SCHEMA:
            p = d / f"{name}.csv"
            if p.exists():
                tables[name].append(_read_records(p, name))
    out: dict[str, list[dict]] = {}
    for name, parts in tables.items():
        if not parts:
            if name not in REQUIRED_TABLES:
                out[name] = []
                continue
            raise InputError(f"no {name}.csv found in catalog directories", source=", ".join(map(str, dirs)))
        rows = [r for part in parts for r in part]
        last: dict[str, dict] = {}
        first_dup = None
        for r in rows:  # each file's ids are unique already: a repeat comes from another directory
            if r["id"] in last and first_dup is None:
                first_dup = r["id"]
            last[r["id"]] = r
        if first_dup is not None:
            raise InputError(f"duplicate id '{first_dup}' across catalog directories",
                             source=last[first_dup]["_source"])
        out[name] = rows
    screws = {r["id"]: r for r in out["screws"]}
    for r in out["nuts"]:
        if r["screw_id"] not in screws:
            raise InputError(f"screw_id '{r['screw_id']}' is not in screws.csv", source=r["_source"],
                             where="column screw_id")
    for r in out["nuts"]:
        v = screws[r["screw_id"]]["vendor"]
        if r["vendor"] != v:
            raise InputError(f"nut '{r['id']}' of vendor {r['vendor']} is listed on screw '{r['screw_id']}' of "
                             f"vendor {v}: a nut runs only on its own vendor's shaft", source=r["_source"],
                             where="column screw_id")
    return PartRows(out)


def load_catalogs(extra_dirs=(), *, shipped: bool = True) -> Catalog:
    """Load the shipped catalogs and any user catalog directories (later ones add parts) as a :class:`Catalog`
    (its tables are built without pandas; ``cat.screws`` and the others give pandas tables on demand).

    A user directory may hold any subset of screws/nuts/bearings/guides CSVs.
    """
    from .parttable import PartTable

    rows = load_records(extra_dirs, shipped=shipped)
    return Catalog(**{name: PartTable(rows.table(name), _table_columns(name)) for name in SCHEMA})


_CACHE: dict[tuple, Catalog] = {}


def default_catalog(extra_dirs=()) -> Catalog:
    """Cached :func:`load_catalogs` (the tables are treated as read-only)."""
    key = tuple(str(Path(d).resolve()) for d in extra_dirs)
    if key not in _CACHE:
        _CACHE[key] = load_catalogs(extra_dirs)
    return _CACHE[key]
