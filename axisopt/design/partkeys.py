"""The YAML keys of the parts: one slot per part table (a catalog id or an inline mapping) and, for
an inline (custom) part, the columns of its catalog table with their units."""

from __future__ import annotations

from ..catalog.columns import CHOICES, COLUMNS, OPTIONAL_COLUMNS, SCHEMA
from ..yamlio import Key, Spec


def _part_key(table: str, col: str, kind: str) -> Key:
    """How an inline part gives catalog column ``col`` (the catalog loader's column kinds and
    choices)."""
    doc = col.replace("_", " ")
    if kind == "str":
        optional = col in ("vendor", "series")
        return Key(
            "string",
            doc + (" (default: custom)" if optional else ""),
            required=not optional,
            default="custom" if optional else None,
            choices=CHOICES.get((table, col)),
        )
    optional = col in OPTIONAL_COLUMNS.get(table, ())
    if kind == "int":  # a count (>= 1), or an optional 0/1 flag (the nut's ``rotating``)
        return Key(
            "number",
            doc + (" (optional: 0 or 1)" if optional else ""),
            required=not optional,
            integer=True,
            minimum=0 if optional else 1,
        )
    if kind == "dimensionless":
        # an efficiency: at most 1
        top = next((c.at_most for c in COLUMNS[table] if c.name == col), None)
        return Key(
            "number",
            doc + (" (optional: the vendor lists none)" if optional else ""),
            required=not optional,
            minimum=0,
            maximum=top,
        )
    return Key(
        "quantity",
        doc + (" (optional: the vendor lists none)" if optional else ""),
        required=not optional,
        kind=kind,
        non_negative=True,
    )


# An inline (custom) part: the columns of its catalog table, with units.
PART_SPECS = {
    table: Spec(
        table[:-1],
        f"a custom {table[:-1]}: the columns of catalogs/{table}.csv, with units",
        {col: _part_key(table, col, kind) for col, kind in cols.items()},
    )
    for table, cols in SCHEMA.items()
}


def _slot(table: str, doc: str, required: bool) -> Key:
    return Key(
        "one_of",
        doc,
        required=required,
        options=(
            Key("string", f"a {table[:-1]} id from the catalogs"),
            Key("number", integer=True),
            Key("section", spec=PART_SPECS[table]),
        ),
    )


PARTS_SPEC = Spec(
    "parts",
    "one part per slot: a catalog id, or an inline mapping of a custom part",
    {
        "screw": _slot("screws", "ball screw", True),
        "nut": _slot("nuts", "ball nut (fits the screw)", True),
        "bearing": _slot("bearings", "support bearing set", True),
        "guide": _slot("guides", "linear guide block and rail", True),
        "motor": _slot(
            "motors", "servo motor (optional; needs axis.acceleration or axis.duty_cycle)", False
        ),
        "coupling": _slot("couplings", "shaft coupling (optional)", False),
        "reduction": _slot(
            "reductions",
            "reduction between motor and coupling: planetary gearbox or belt stage (optional; "
            "without it the axis's reduction_ratio, reduction_efficiency and reduction_inertia, "
            "direct drive by default)",
            False,
        ),
        "nut_preload": Key(
            "quantity",
            "nut preload within the nut's range (default: the catalog's)",
            kind="force",
            non_negative=True,
        ),
        "screw_grade": Key(
            "string",
            "lead accuracy grade of the screw, one its series is made in (JIS B 1192: C0 C1 C2 C3 "
            "C5 C7 C8 C10; catalogs/screw_grades.csv; default: the cheapest, C5 for the shipped "
            "screws)",
        ),
    },
)
