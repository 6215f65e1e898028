"""Issue 54's new inputs refused in one line, exit 2: a 3-against-1 set's stronger lift-off load not
positive or NaN in a user catalog, an unknown arrangement, and a belt stage's negative stiffness in
an inline part."""

from __future__ import annotations

from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.catalog.columns import SHIPPED_DIR
from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
VMC = (ROOT / "problems" / "vmc_x_design.yaml").read_text(encoding="utf-8")
LINES = (SHIPPED_DIR / "bearings.csv").read_text(encoding="utf-8").splitlines()
HEADER = LINES[0]
DFT = next(x for x in LINES if x.startswith("NSK-30TAC62B-DFT-C10,"))
COL = HEADER.split(",").index("lift_off_load_strong [N]")


def _row(value: str, arrangement: str = "DFT") -> str:
    cells = DFT.replace("NSK-30TAC62B-DFT-C10", "U-DFT").split(",")
    cells[COL] = value
    cells[3] = arrangement
    return ",".join(cells)


@pytest.mark.parametrize(
    ("row", "needle"),
    [
        (_row("0"), "lift_off_load_strong"),
        (_row("-5000"), "lift_off_load_strong"),
        (_row("nan"), "lift_off_load_strong"),
        (_row("56430", "DFX"), "arrangement"),
    ],
)
def test_bad_set_row_in_a_catalog_is_a_one_line_error(tmp_path, capsys, row, needle):
    (tmp_path / "cat").mkdir()
    write_file(tmp_path / "cat", "bearings.csv", HEADER + "\n" + row + "\n")
    text = "catalogs: [cat]\n" + VMC.replace("  bearing: NSK-30TAC62B-DFF-C9", "  bearing: U-DFT")
    path = write_file(tmp_path, "d.yaml", text)
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    assert "bearings.csv" in err and "line 2" in err and needle in err, err


def test_a_belt_stage_with_negative_stiffness_inline(tmp_path, capsys):
    part = (
        "  reduction:\n    id: U-B\n    kind: belt\n    ratio: 1.5\n    efficiency: 0.98\n"
        "    inertia: 10 kg.cm^2\n    rated_torque: 45 N.m\n    accel_torque: 45 N.m\n"
        "    torsional_stiffness: -8 N.m/arcmin\n    backlash: 0 arcmin\n    max_input_speed: 3000 "
        "rpm\n"
        "    price: 200 EUR\n"
    )
    path = write_file(tmp_path, "d.yaml", VMC.replace("parts:\n", "parts:\n" + part, 1))
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    assert "parts.reduction.torsional_stiffness" in err and "negative" in err, err
