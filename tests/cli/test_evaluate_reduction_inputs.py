"""Bad reductions refused in one line on stderr, exit 2, naming the file and the line/key: a ratio
of 0, an efficiency above 1 (100 %), a NaN inertia, in a catalog CSV (user catalog directory) and in
an inline design part; a reduction part beside the axis's reduction values; reduction ids in a
problem's require/exclude."""

from __future__ import annotations

from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.catalog.columns import SHIPPED_DIR
from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
VMC = (ROOT / "problems" / "vmc_x_design.yaml").read_text(encoding="utf-8")
HEADER = (SHIPPED_DIR / "reductions.csv").read_text(encoding="utf-8").splitlines()[0]
GOOD = "U-1,User,belt 2:1,belt,2,95,1.5,40,80,,20,5,6000,1.2,150,vendor,user row"
INLINE = """  reduction:
    id: U-2
    kind: belt
    ratio: {ratio}
    efficiency: {eta}
    inertia: {inertia} kg.cm^2
    rated_torque: 40 N.m
    accel_torque: 80 N.m
    torsional_stiffness: 20000 N.m/rad
    backlash: 5 arcmin
    max_input_speed: 6000 rpm
    price: 150 EUR
"""


def _design_with(tmp_path, parts_extra: str, catalogs: str = "") -> str:
    text = VMC.replace("parts:\n", "parts:\n" + parts_extra, 1)
    if catalogs:
        text = f"catalogs: [{catalogs}]\n" + text
    return write_file(tmp_path, "d.yaml", text)


@pytest.mark.parametrize(
    ("row", "needle"),
    [
        (GOOD.replace(",belt,2,", ",belt,0,"), "column 5 (ratio): ratio must be positive, got 0"),
        (
            GOOD.replace(",95,", ",102,"),
            "column 6 (efficiency): efficiency must be at most 1 (= 100 %), got 102",
        ),
        (GOOD.replace(",1.5,40,", ",nan,40,"), "column 7 (inertia): 'nan' is not a finite number"),
    ],
)
def test_bad_reduction_row_in_a_catalog_is_a_one_line_error(tmp_path, capsys, row, needle):
    (tmp_path / "cat").mkdir()
    write_file(tmp_path / "cat", "reductions.csv", HEADER + "\n" + row + "\n")
    path = _design_with(tmp_path, "  reduction: U-1\n", "cat")
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    assert "reductions.csv" in err and "line 2" in err and needle in err, err


def test_a_user_belt_row_is_accepted(tmp_path, capsys):
    (tmp_path / "cat").mkdir()
    write_file(tmp_path / "cat", "reductions.csv", HEADER + "\n" + GOOD + "\n")
    path = _design_with(tmp_path, "  reduction: U-1\n", "cat")
    assert main(["evaluate", path]) in (0, 1)  # evaluated (1: a check fails)
    out = capsys.readouterr().out
    assert "reduction U-1 (User belt; 2:1, efficiency 0.95" in out


@pytest.mark.parametrize(
    ("ratio", "eta", "inertia", "needle"),
    [
        (0, 0.95, 1.5, "ratio"),
        (2, 1.2, 1.5, "efficiency"),
        (2, 0.95, ".nan", "inertia"),
    ],
)
def test_bad_inline_reduction_is_a_one_line_error(tmp_path, capsys, ratio, eta, inertia, needle):
    path = _design_with(tmp_path, INLINE.format(ratio=ratio, eta=eta, inertia=inertia))
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    assert "d.yaml" in err and needle in err, err


def test_reduction_part_and_axis_ratio_together_are_refused(tmp_path, capsys):
    path = _design_with(tmp_path, "  reduction: BK-TP010-MF-5\n")
    text = (
        Path(path)
        .read_text(encoding="utf-8")
        .replace("axis:\n", "axis:\n  reduction_ratio: 2\n", 1)
    )
    Path(path).write_text(text, encoding="utf-8")
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    assert "reduction" in err and "axis.reduction_ratio" in err, err


def test_unknown_reduction_id_names_the_closest(tmp_path, capsys):
    path = _design_with(tmp_path, "  reduction: BK-TP010-MF-6\n")
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    assert "unknown reduction id 'BK-TP010-MF-6'" in err and "did you mean" in err, err
