"""Time-record reader (:mod:`axisopt.identify.records.record`): current records with a gain (motor
side and table equivalents), position in revolutions, bad input as one line naming file, line and
column, validation runs with other columns, a bad external-force column.

The records come from :mod:`axisopt.identify.records.synth`, a closed-loop simulator written apart
from the identification code (PD loop, exact stick-slip, 1 um quantisation, force noise, 1 kHz)."""

import json
import math

import numpy as np
import pytest
from identify_helpers import DESIGN, LEAD, assert_timesynth_axis, records, truth_for

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.synth import AxisTruth, simulate_axis


@pytest.fixture(scope="module")
def plant(plant):
    return assert_timesynth_axis(plant)


# ------------------------------------------------------------------------------------------- bad
# input
def _good(tmp_path, name="g.csv", n=400, header="time [s],position [mm],force [N]", pre=""):
    t = np.arange(n) / 1000.0
    x = 100 + 20 * np.sin(2 * np.pi * t)
    f = 50 * np.cos(2 * np.pi * t)
    body = "\n".join(f"{a:.4f},{b:.5f},{c:.4f}" for a, b, c in zip(t, x, f))
    p = tmp_path / name
    p.write_text(pre + header + "\n" + body + "\n")
    return p


def _edit(p, line, text):
    lines = p.read_text().splitlines()
    lines[line - 1] = text
    p.write_text("\n".join(lines) + "\n")
    return p


def _rewrite(src, dst, header=None, cell=None):
    lines = src.read_text().splitlines()
    if header:
        lines[0] = header
    if cell:
        row, col, val = cell
        cells = lines[row].split(",")
        cells[col] = val
        lines[row] = ",".join(cells)
    dst.write_text("\n".join(lines) + "\n")


def test_current_record_with_gain_reports_motor_side_and_table_equivalents(tmp_path, plant, capsys):
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0)
    eff = dict(
        effort="current", lead=LEAD, efficiency=plant.efficiency, gain=0.85, position_unit="rad"
    )
    est, val = records(tmp_path, truth, seed=41, est_s=10.0, val_s=6.0, **eff)
    out = tmp_path / "d.json"
    assert main(["diagnose", str(est), str(val), "--design", str(DESIGN), "--json", str(out)]) == 0
    text = capsys.readouterr().out
    assert "torque data" in text and "table side through lead 10 mm" in text
    d = json.loads(out.read_text())
    assert d["quantity"] == "torque"
    par = {p["name"]: p for p in d["baseline"]["IV"]["parameters"]}
    assert par["J"]["unit"] == "kg.m^2" and par["Fc"]["unit"] == "N.m"
    g = 2 * math.pi / LEAD
    assert par["J"]["value"] * g * g * plant.efficiency == pytest.approx(500.0, rel=0.10)
    assert par["Fc"]["value"] * g * plant.efficiency == pytest.approx(300.0, rel=0.10)
    # the same record with its gain line removed and the gain given on the command line
    for p in (est, val):
        p.write_text("\n".join(p.read_text().splitlines()[1:]) + "\n")
    assert (
        main(
            [
                "diagnose",
                str(est),
                str(val),
                "--design",
                str(DESIGN),
                "--gain",
                "0.85 N.m/A",
                "--json",
                str(out),
            ]
        )
        == 0
    )
    d2 = json.loads(out.read_text())
    assert d2["baseline"]["IV"]["parameters"][0]["value"] == pytest.approx(
        par["J"]["value"], rel=1e-9
    )


@pytest.mark.parametrize(
    "make,where,what",
    [
        (
            lambda d: _edit(_good(d), 51, "0.0100,100.1,3"),
            "line 51, column 1 (time)",
            "does not increase",
        ),
        (
            lambda d: _edit(_good(d), 7, "0.0050,nan,3"),
            "line 7, column 2 (position)",
            "not a finite number",
        ),
        (lambda d: _good(d, n=150), "g.csv", "150 samples; a time record needs at least 200"),
        (
            lambda d: _good(d, header="time [s],position [mm],current [A]"),
            "line 1, column 3",
            "needs a gain",
        ),
        (
            lambda d: _good(
                d, header="time [s],position [mm],current [A]", pre="# gain: 0.85 N.m\n"
            ),
            "line 1",
            "unit per ampere",
        ),
        (
            lambda d: _good(d, header="time [s],position [mm],force [N],speed [mm/s]"),
            "line 1, column 4",
            "unknown column 'speed'",
        ),
        (
            lambda d: _edit(_good(d), 9, "0.0070,1e308,3"),
            "line 9, column 2 (position)",
            "out of range",
        ),
        (
            lambda d: _edit(_good(d), 12, "0.0100,100,-1e300"),
            "line 12, column 3 (force)",
            "out of range",
        ),
    ],
)
def test_bad_input_is_one_line_naming_file_line_column(tmp_path, capsys, make, where, what):
    p = make(tmp_path)
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and str(p) in err and where in err and what in err, err


def test_malformed_gain_is_refused_on_any_record(tmp_path, capsys):
    """--gain is read only for current records, but a malformed one is still an error, not
    ignored."""
    assert main(["diagnose", str(_good(tmp_path)), "--design", str(DESIGN), "--gain", "abc"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "--gain" in err and "unit per ampere" in err, err


def test_validation_run_with_other_columns_is_refused(tmp_path, capsys):
    est = _good(tmp_path, "est.csv")
    val = _good(tmp_path, "val.csv", header="time [s],position [mm],torque [N.m]")
    assert main(["diagnose", str(est), str(val), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and str(val) in err and "column 3" in err and "est.csv" in err, err


def test_reader_errors_are_input_errors(tmp_path, plant):
    p = _edit(_good(tmp_path), 3, "0.0010,100,")
    with pytest.raises(InputError, match="line 3, column 3 .force.: empty cell"):
        diagnose_time_files([p], plant=plant)


@pytest.mark.parametrize(
    "header,cell,what",
    [
        (
            "time [s],position [mm],force [N],reference [mm],external_force [mm]",
            None,
            "line 1, column 5.*not a unit of force",
        ),
        (None, (3, 4, "abc"), "line 4, column 5 .external_force.: 'abc' is not a number"),
        (None, (3, 4, ""), "line 4, column 5 .external_force.: empty cell"),
    ],
)
def test_bad_external_force_is_one_line_exit_2(tmp_path, capsys, header, cell, what):
    import re

    truth = AxisTruth(process_force=100.0)
    src = tmp_path / "src.csv"
    simulate_axis(truth, duration=1.0, seed=1).write_csv(
        src, columns=("time", "position", "force", "reference", "external_force")
    )
    bad = tmp_path / "bad.csv"
    _rewrite(src, bad, header, cell)
    assert main(["diagnose", str(bad), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and re.search(what, err), err


def test_position_in_revolutions_is_accepted(tmp_path, plant):
    """The README lists [rev] for a motor-angle position: read like [rad], through the lead."""
    rec = simulate_axis(truth_for(9), duration=8.0, seed=9)
    rad, rev = tmp_path / "rad.csv", tmp_path / "rev.csv"
    rec.write_csv(rad, position_unit="rad")
    lines = rad.read_text().splitlines()
    head = (
        lines[0]
        .replace("position [rad]", "position [rev]")
        .replace("reference [rad]", "reference [rev]")
    )
    rows = []
    for ln in lines[1:]:
        c = ln.split(",")
        c[1], c[3] = f"{float(c[1]) / (2 * math.pi):.8g}", f"{float(c[3]) / (2 * math.pi):.8g}"
        rows.append(",".join(c))
    rev.write_text("\n".join([head] + rows) + "\n")
    a = diagnose_time_files([rad], plant=plant, candidates=["stribeck"])
    b = diagnose_time_files([rev], plant=plant, candidates=["stribeck"])
    assert b.baseline_ls.value("M") == pytest.approx(a.baseline_ls.value("M"), rel=1e-3)
