"""A catalog part's repr, table and HTML in vendor units (issue 42 item 4): the numbers a published
catalog row holds, in the units of its catalog file (catalogs/SOURCES.md names each row's vendor
page), not SI."""

import csv
import math
from pathlib import Path

import pytest

from axisopt.catalog.columns import SCHEMA
from axisopt.catalog.loading import default_catalog
from axisopt.catalog.partrow import table_of, vendor_units
from axisopt.units import split_header

CATALOGS = Path(__file__).resolve().parents[2] / "catalogs"

# vendor rows: HIWIN ballscrew catalog (H-BS Table 6.5), THK General Catalog (BNFN, BK support
# units), HIWIN HG guides, a Yaskawa Sigma-7 motor (YSK-S7)
PARTS = [
    ("screws", "THK-BNFN-16x5"),
    ("nuts", "HIWIN-R40-20K4-FDC"),
    ("nuts", "THK-BNFN1605-5"),
    ("bearings", "THK-BK40"),
    ("guides", "HIWIN-HG15-ZA"),
    ("motors", "SGM7G-13A"),
]


def _csv_row(table, part_id):
    with open(CATALOGS / f"{table}.csv", encoding="utf-8") as fh:
        return next(r for r in csv.DictReader(fh) if r["id"] == part_id)


def _repr_values(text):
    """{column: (figure, unit)} of a Row repr's column lines."""
    out = {}
    for line in text.splitlines()[1:]:
        col, rest = line.strip().rstrip(")").split(None, 1)
        figure, _, unit = rest.partition(" ")
        out[col] = (figure, unit)
    return out


@pytest.mark.parametrize("table, part_id", PARTS)
def test_row_repr_shows_the_catalog_numbers_in_vendor_units(table, part_id):
    row = default_catalog().part(table, part_id)
    text = repr(row)
    assert text.startswith(f"Row({table[:-1]} '{part_id}':") and table_of(row) == table
    shown = _repr_values(text)
    frame = row.to_frame().set_index("column")
    html = row._repr_html_()
    checked = 0
    for header, cell in _csv_row(table, part_id).items():
        col, unit = split_header(header)
        if unit is None or not cell.strip() or SCHEMA[table].get(col) in (None, "str", "int"):
            continue
        unit = "" if unit == "-" else unit
        figure, shown_unit = shown[col]
        assert float(figure) == pytest.approx(float(cell), rel=1e-12) and shown_unit == unit, col
        assert (
            frame.loc[col, "value"] == pytest.approx(float(cell), rel=1e-12)
            and frame.loc[col, "unit"] == unit
        )
        assert f"<td>{figure}</td>" in html
        checked += 1
    assert checked >= 5


def test_vendor_units_are_the_catalog_headers():
    # load ratings in kN and rotor inertia in kg.cm^2 as the vendors print them, not the SI the rows
    # hold
    assert vendor_units("nuts")["dynamic_load_rating"] == ("kN", 1e3)
    unit, factor = vendor_units("motors")["rotor_inertia"]
    assert unit == "kg.cm^2" and math.isclose(factor, 1e-4)
    assert vendor_units("reductions")["ratio"] == ("", 1.0)
    assert vendor_units("screws")["lead"] == ("mm", 1e-3)


def test_an_empty_optional_cell_is_left_out():
    row = default_catalog().part("nuts", "HIWIN-R40-20K4-FDC")
    assert math.isnan(row["rotating"]) and "rotating" not in _repr_values(repr(row))
