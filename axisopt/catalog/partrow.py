"""A catalog part shown in the units its vendor quotes: the repr, table and HTML of a
:class:`~axisopt.catalog.parttable.Row` (which holds SI numbers).

Each column's unit is the one the shipped catalog file declares in its header
(``catalogs/nuts.csv``: ``dynamic_load_rating [kN]``, ``catalogs/motors.csv``:
``rotor_inertia [kg.cm^2]``): the vendor's unit, written once, there.  A column no shipped file has
takes the display unit of its kind (:data:`axisopt.units.DISPLAY_UNITS`).  The values are written
with ten significant digits, so a shipped row reads as its CSV line does.
"""

from __future__ import annotations

import csv
import functools
import math
from types import MappingProxyType

from ..units import DISPLAY_UNITS, split_header, unit_factor
from .columns import SCHEMA, SHIPPED_DIR

NO_UNIT = ("", "-")  # a header's unit of a plain number (``ratio [-]``)
COLUMNS = ("column", "value", "unit")  # the table of a row (:func:`row_rows`)


@functools.lru_cache(maxsize=None)
def vendor_units(table: str) -> MappingProxyType:
    """Column -> (unit, SI per unit) for the numeric columns of ``table`` ('screws', 'nuts' ...):
    the unit of the shipped catalog file's header, else the display unit of the column's kind; ('',
    1.0) for a plain number."""
    header = {}
    path = SHIPPED_DIR / f"{table}.csv"
    if path.is_file():
        with open(path, encoding="utf-8-sig", newline="") as fh:
            header = dict(split_header(h) for h in next(csv.reader(fh), []))
    out = {}
    for col, kind in SCHEMA[table].items():
        if kind in ("str", "int"):
            continue
        unit = header.get(col) or DISPLAY_UNITS.get(kind, "")
        out[col] = ("", 1.0) if unit in NO_UNIT else (unit, unit_factor(unit, kind))
    return MappingProxyType(out)


def table_of(row) -> str | None:
    """The catalog table (``screws``, ``nuts`` ...) whose required columns ``row`` has (the largest
    such table); None when none fits."""
    fits = [t for t, kinds in SCHEMA.items() if all(c in row for c in kinds if not _optional(t, c))]
    return max(fits, key=lambda t: len(SCHEMA[t]), default=None)


def _optional(table: str, column: str) -> bool:
    from .columns import OPTIONAL_COLUMNS

    return column in OPTIONAL_COLUMNS.get(table, ())


def _figure(v) -> str:
    return f"{v:.10g}"


def row_rows(row, table: str | None = None) -> list[dict]:
    """The row as (column, value, unit) records, numbers in vendor units (:func:`vendor_units`; an
    empty optional cell left out), text as it is; ``table`` defaults to :func:`table_of`."""
    table = table or table_of(row)
    units = vendor_units(table) if table is not None else {}
    out = []
    for col, v in row.items():
        if col.startswith("_"):
            continue
        if isinstance(v, float) and not math.isfinite(v):
            continue  # an empty optional cell
        if col in units and isinstance(v, (int, float)) and not isinstance(v, bool):
            unit, factor = units[col]
            out.append({"column": col, "value": float(f"{v / factor:.10g}"), "unit": unit})
        else:
            out.append({"column": col, "value": v, "unit": ""})
    return out


def row_repr(row, table: str | None = None) -> str:
    """``Row(screw 'HIWIN-G-32x40-b3p969':`` then one line per column, ``lead 40 mm`` ..."""
    table = table or table_of(row)
    rows = [r for r in row_rows(row, table) if r["column"] != "id"]
    width = max((len(r["column"]) for r in rows), default=0)
    what = f"{table[:-1]} " if table else ""
    lines = [
        f"  {r['column']:<{width}}  "
        f"{_figure(r['value']) if isinstance(r['value'], float) else r['value']}"
        + (f" {r['unit']}" if r["unit"] else "")
        for r in rows
    ]
    return f"Row({what}{str(row.name)!r}:\n" + "\n".join(lines) + ")"


def row_frame(row, table: str | None = None):
    """pandas DataFrame of :func:`row_rows` (columns ``column``, ``value``, ``unit``)."""
    from ..display import frame

    return frame(row_rows(row, table), COLUMNS)


def row_html(row, table: str | None = None) -> str:
    """An HTML table of :func:`row_rows`, each number as its catalog line writes it."""
    from ..display import html_table

    table = table or table_of(row)
    rows = [
        {**r, "value": _figure(r["value"]) if isinstance(r["value"], float) else str(r["value"])}
        for r in row_rows(row, table)
    ]
    return html_table(
        rows, f"{table[:-1] if table else 'part'} {row.name}", columns=COLUMNS, max_rows=100
    )


__all__ = ["vendor_units", "table_of", "row_rows", "row_repr", "row_frame", "row_html"]
