"""Measured-table reader (:mod:`axisopt.identify.tables.data`): units converted and the test type
detected, strict one-line errors naming file, line and column, excluded rows, the friction sign
convention."""

import re

import numpy as np
import pytest
from identify_helpers import DESIGN, SPEEDS, coulomb, friction_table, write

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.identify import read_dataset


def test_units_convert_and_kind_is_detected(tmp_path):
    p = write(
        tmp_path,
        "position [m],force [kN],displacement [mm],temperature [degC]\n0.1,2,0.01,20\n"
        "0.2,-2,-0.012,21\n",
    )
    ds = read_dataset(p)
    assert ds.kind == "stiffness"
    assert ds.columns["position"][1] == pytest.approx(0.2)
    assert ds.columns["force"][0] == pytest.approx(2000.0)
    assert ds.columns["displacement"][1] == pytest.approx(-12e-6)
    assert ds.columns["temperature"][1] - ds.columns["temperature"][0] == pytest.approx(1.0)
    fr = read_dataset(
        write(tmp_path, "velocity [m/min],drag_torque [N.m]\n1.2,0.5\n-1.2,-0.5\n", "f.csv")
    )
    assert fr.kind == "friction" and fr.columns["velocity"][0] == pytest.approx(0.02)
    frf = read_dataset(
        write(
            tmp_path,
            "frequency [Hz],position [mm],magnitude [um/N],phase [deg]\n100,0,0.01,-90\n",
            "g.csv",
        )
    )
    assert frf.kind == "frf" and frf.columns["imag"][0] == pytest.approx(-1e-8)


@pytest.mark.parametrize(
    "text,where,what",
    [
        ("position [mm],force [N]\n0,1\n", "line 1", "missing column(s) displacement"),
        (
            "position [mm],force [N],displacement [blorp]\n0,1,2\n",
            "line 1, column 3",
            "unknown unit",
        ),
        (
            "position [mm],force [N],displacement [um]\n0,1,2\n0,abc,2\n",
            "line 3, column 2 (force)",
            "not a number",
        ),
        (
            "position [mm],force [N],displacement [um]\n0,1,nan\n",
            "line 2, column 3 (displacement)",
            "not a finite",
        ),
        (
            "position [mm],force [N],displacement [um]\n0,,2\n",
            "line 2, column 2 (force)",
            "empty cell",
        ),
        (
            "position [mm],force [N],displacment [um]\n0,1,2\n",
            "line 1, column 3",
            "did you mean 'displacement'",
        ),
        (
            "position [mm],force [N],displacement [um],direction\n0,1,2,0\n",
            "line 2, column 4",
            "+1 or -1",
        ),
        ("position,force [N],displacement [um]\n0,1,2\n", "line 1, column 1", "needs a unit"),
        ("velocity [mm/s]\n1\n", "line 1", "friction_force or drag_torque"),
    ],
)
def test_bad_files_give_one_line_errors(tmp_path, text, where, what, capsys):
    p = write(tmp_path, text)
    with pytest.raises(InputError) as exc:
        read_dataset(p)
    msg = str(exc.value)
    assert str(p) in msg and where in msg and what in msg
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and where in err


def test_excluded_rows_are_reported(tmp_path):
    p = write(
        tmp_path, "velocity [mm/s],friction_force [N],exclude\n1,10,0\n0,3,0\n-1,-10,1\n2,11,0\n"
    )
    ds = read_dataset(p)
    assert ds.n == 2
    assert ds.excluded == [
        (3, "velocity 0: friction direction undefined"),
        (4, "marked exclude = 1"),
    ]


# ------------------------------------------------------------------------------------------------
# inputs
def test_friction_magnitudes_with_signed_speed_are_refused(tmp_path, plant, capsys):
    """Magnitudes with a negative speed fitted a 39.6 N 'Coulomb' level: now a one-line error with
    the convention, exit 2."""
    fc = coulomb(plant)
    p = friction_table(
        tmp_path / "mag.csv", lambda v: np.sign(v) * fc + plant.viscous * v, magnitudes=True
    )
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert re.search(
        r"line \d+, column 2 \(friction_force\).*negative at negative velocity", err
    ), err


def test_vertical_axis_positive_both_ways_is_accepted(tmp_path, plant):
    """A weight larger than the friction makes the force positive in both directions, but unequal:
    read."""
    fc = coulomb(plant)
    p = friction_table(
        tmp_path / "vertical.csv", lambda v: np.sign(v) * fc + plant.viscous * v + 3 * fc
    )
    assert read_dataset(p).n == 2 * 2 * len(SPEEDS)
