"""search.drive_types and the drive-type catalogs: bad input refused in one line naming the file and
where, exit 2 (a pinion with zero teeth, a NaN force constant, a linear motor on a vertical axis
without a brake or a counterbalance, an unknown type, an objective the drive-type search does not
make); a good problem solves."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
ROUTER = (ROOT / "problems" / "router_rack_problem.yaml").read_text(encoding="utf-8")
LASER = (ROOT / "problems" / "laser_lm_problem.yaml").read_text(encoding="utf-8")


def _with_catalog(tmp_path, table: str, line_from: str, line_to: str, text: str) -> str:
    cat = tmp_path / "cat"
    cat.mkdir()
    src = (ROOT / "catalogs" / f"{table}.csv").read_text(encoding="utf-8").splitlines()
    header, row = src[0], next(r for r in src[1:] if r.startswith(line_from.split(",")[0]))
    row = row.replace(line_from, line_to).replace(row.split(",")[0], "USER-" + row.split(",")[0], 1)
    (cat / f"{table}.csv").write_text(header + "\n" + row + "\n", encoding="utf-8")
    return write_file(tmp_path, "p.yaml", "catalogs: [cat]\n" + text)


def test_a_pinion_with_zero_teeth(tmp_path, capsys):
    path = _with_catalog(
        tmp_path,
        "racks",
        "THK-GP6-20A,THK,GSR-R rack with GP pinion,spur,7,1.91,20,",
        "THK-GP6-20A,THK,GSR-R rack with GP pinion,spur,7,1.91,0,",
        ROUTER,
    )
    assert main(["solve", path]) == 2
    err = one_line_error(capsys)
    assert "racks.csv" in err and "line 2" in err and "teeth" in err and "positive" in err, err


def test_a_nan_force_constant(tmp_path, capsys):
    row = "HIWIN-LMCA6,HIWIN,LMC ironless (Appendix A example),ironless,62,187,"
    path = _with_catalog(tmp_path, "linear_motors", row + "33.8,", row + "nan,", LASER)
    assert main(["solve", path]) == 2
    err = one_line_error(capsys)
    assert "linear_motors.csv" in err and "force_constant" in err and "finite" in err, err


@pytest.mark.parametrize("extra, ok", [("", False), ("\n  linear_motor: {brake: yes}", True)])
def test_a_vertical_linear_motor_needs_a_brake_or_counterbalance(tmp_path, capsys, extra, ok):
    text = LASER.replace("orientation: horizontal", "orientation: vertical").replace(
        "  linear_motor: {max_forcers: 2, servo_bandwidth: 50 Hz}\n", ""
    )
    text = text.replace(
        "  drive_types: [linear_motor, rack_pinion]", "  drive_types: [linear_motor]" + extra
    )
    code = main(["solve", write_file(tmp_path, "p.yaml", text)])
    if ok:
        assert code in (0, 1)
        return
    assert code == 2
    err = one_line_error(capsys)
    assert "p.yaml" in err and "search.drive_types" in err and "brake or a counterbalance" in err, (
        err
    )


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("drive_types: [rack_pinion, linear_motor]", "drive_types: [rack_pinion, belt]", "belt"),
        (
            "drive_types: [rack_pinion, linear_motor]",
            "drive_types: [rack_pinion, rack_pinion]",
            "listed twice",
        ),
        (
            "rack_pinion: {twin_pinion: search, overload: medium}",
            "rack_pinion: {twin_pinion: search, overload: huge}",
            "huge",
        ),
        (
            "rack_pinion: {twin_pinion: search, overload: medium}",
            "rack_pinion: {twin_pinon: yes}",
            "twin_pinon",
        ),
        ("objective: stiffness", "objective: kv", "drive types"),
    ],
)
def test_bad_drive_type_keys(tmp_path, capsys, old, new, words):
    assert old in ROUTER
    assert main(["solve", write_file(tmp_path, "p.yaml", ROUTER.replace(old, new))]) == 2
    err = one_line_error(capsys)
    assert words in err, err


def test_the_router_solves_and_writes_json(tmp_path, capsys):
    out = tmp_path / "r.json"
    assert (
        main(["solve", str(ROOT / "problems" / "router_rack_problem.yaml"), "--json", str(out)])
        == 0
    )
    text = capsys.readouterr().out
    assert "rack and pinion" in text and "best design" in text
    d = json.loads(out.read_text(encoding="utf-8"))
    assert d["status"] == "optimal" and d["best"]["drive_type"] == "rack_pinion"
    assert all(v >= 1.0 for v in d["best"]["margins"].values())


def test_the_infeasible_laser_answers_with_a_verified_change(capsys):
    assert main(["solve", str(ROOT / "problems" / "infeasible_laser_lm_problem.yaml")]) == 1
    text = capsys.readouterr().out
    assert "design change: lower acceleration to" in text and "verified" in text
