"""Design YAML and the evaluate command: every bad input is one line naming file and key, exit
code 2."""

import json
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
GOOD = (ROOT / "problems" / "vmc_x_design.yaml").read_text()
DESIGNS = sorted((ROOT / "problems").glob("*design*.yaml")) + sorted(
    (ROOT / "problems").glob("paper_*.yaml")
)


@pytest.mark.parametrize("path", DESIGNS, ids=lambda p: p.name)
def test_evaluate_runs_on_every_shipped_design(path, capsys):
    assert main(["evaluate", str(path)]) == 0
    out = capsys.readouterr().out
    assert "weakest link" in out and "checks" in out


def test_evaluate_json_and_plot(tmp_path, capsys):
    js, png = tmp_path / "r.json", tmp_path / "r.png"
    assert (
        main(
            [
                "evaluate",
                str(ROOT / "problems" / "vmc_x_design.yaml"),
                "--json",
                str(js),
                "--plot",
                str(png),
            ]
        )
        == 0
    )
    data = json.loads(js.read_text())
    for key in (
        "min_axial_stiffness_N_per_um",
        "min_natural_frequency_Hz",
        "moving_mass_kg",
        "total_mass_kg",
        "cost",
        "drag_torque_Nm",
        "positions_mm",
        "axial_stiffness_N_per_um",
        "natural_frequency_Hz",
    ):
        assert key in data
    assert len(data["positions_mm"]) == len(data["axial_stiffness_N_per_um"]) >= 3
    assert min(data["axial_stiffness_N_per_um"]) == pytest.approx(
        data["min_axial_stiffness_N_per_um"]
    )
    assert png.stat().st_size > 1000


def test_evaluate_json_to_stdout_is_pure_json(capsys):
    assert main(["evaluate", str(ROOT / "problems" / "teaching_design.yaml"), "--json", "-"]) == 0
    json.loads(capsys.readouterr().out)


BAD = [
    ("stroke: 800 mm", "stroke: 800", "axis.stroke", "no unit"),
    ("stroke: 800 mm", "strok: 800 mm", "axis.strok", "unknown key"),
    (
        "  moving_mass: 450 kg",
        "  moving_mass: 450 kg\n  movingmass: 3 kg",
        "axis.movingmass",
        "unknown key",
    ),
    ("nut: HIWIN-R40-20K4-FDC", "nut: HIWIN-R40-20K4-FDX", "parts.nut", "unknown nut id"),
    ("stroke: 800 mm", "stroke: -800 mm", "axis.stroke", "must be positive"),
    ("mounting: fixed-supported", "mounting: fixed-floating", "axis.mounting", "not one of"),
    ("stroke: 800 mm", "stroke: 800 kg", "axis.stroke", "not a unit of length"),
    ("nut_preload: 3000 N", "nut_preload: 90000 N", "parts.nut_preload", "outside"),
    ("nut: HIWIN-R40-20K4-FDC", "nut: HIWIN-R25-05K4-FDC", "parts.nut", "fits screw"),
    ("axis:\n", "axis: [1, 2\n", "line", "malformed YAML"),
    ("  stroke: 800 mm\n", "", "axis", "missing required key 'axis.stroke'"),
    ("guide_blocks: 4", "guide_blocks: four", "axis.guide_blocks", "number"),
]


@pytest.mark.parametrize("old, new, key, words", BAD, ids=[b[3] + "-" + b[2] for b in BAD])
def test_bad_design_is_one_line_error_exit_2(tmp_path, capsys, old, new, key, words):
    assert old in GOOD
    bad = tmp_path / "bad.yaml"
    bad.write_text(GOOD.replace(old, new, 1))
    assert main(["evaluate", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "Traceback" not in err
    assert str(bad) in err and key in err and words in err, err


def test_missing_file_and_usage_errors(tmp_path, capsys):
    assert main(["evaluate", str(tmp_path / "nope.yaml")]) == 2
    assert "nope.yaml" in capsys.readouterr().err
    assert main(["evaluate"]) == 2
    assert main(["frobnicate"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2


def test_empty_and_non_mapping_yaml(tmp_path, capsys):
    for text in ("", "- a\n- b\n", "just text\n"):
        p = tmp_path / "x.yaml"
        p.write_text(text)
        assert main(["evaluate", str(p)]) == 2
        assert str(p) in capsys.readouterr().err


@pytest.mark.parametrize("path", DESIGNS, ids=lambda p: p.name)
def test_methods_and_frf_run_on_every_shipped_design(path, tmp_path, capsys):
    js = tmp_path / "r.json"
    assert (
        main(
            [
                "evaluate",
                str(path),
                "--methods",
                "--frf",
                str(tmp_path / "frf.png"),
                "--json",
                str(js),
            ]
        )
        == 0
    )
    data = json.loads(js.read_text())
    assert {r["component"] for r in data["stiffness_methods"]["methods"]} >= {
        "nut",
        "bearings",
        "screw",
    }
    assert (tmp_path / "frf.png").stat().st_size > 0 and data["frf"]


@pytest.mark.parametrize(
    ("edit", "key"),
    [
        (("  stroke: 800 mm", "  stroke: 800 mm\n  temperature_rise: -3 K"), "temperature_rise"),
        (("  stroke: 800 mm", "  stroke: 800 mm\n  temperature_rise: 3 mm"), "temperature_rise"),
        (("  stroke: 800 mm", "  stroke: 800 mm\n  temperature_rise: 1e300 K"), "temperature_rise"),
        (("  stroke: 800 mm", "  stroke: 800 mm\n  pretension: lots"), "pretension"),
        (
            ("  stroke: 800 mm", "  stroke: 800 mm\n  coupling_stiffness: 75 N/m"),
            "coupling_stiffness",
        ),
        (
            ("  stroke: 800 mm", "  stroke: 800 mm\n  nut_bracket_stiffness: 0 N/um"),
            "nut_bracket_stiffness",
        ),
        (
            ("  stroke: 800 mm", "  stroke: 800 mm\n  bearing_housing_stiffness: .nan N/um"),
            "bearing_housing_stiffness",
        ),
    ],
)
def test_new_axis_keys_reject_bad_values(tmp_path, capsys, edit, key):
    p = tmp_path / "d.yaml"
    p.write_text(GOOD.replace(*edit), encoding="utf-8")
    assert main(["evaluate", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and key in err and str(p) in err


def test_frf_bad_extension_is_one_line(tmp_path, capsys):
    assert (
        main(
            [
                "evaluate",
                str(ROOT / "problems" / "vmc_x_design.yaml"),
                "--frf",
                str(tmp_path / "x.txt"),
            ]
        )
        == 2
    )
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_bearing_that_does_not_fit_the_screw_end_fails_its_check(tmp_path, capsys):
    """HIWIN Table 8.9/8.10: a 40 mm screw takes 25-30 mm journals (BK30/FK30, WBK30, SFA30); a
    WBK15 set (15 mm bore) on it fails the fit check."""
    p = tmp_path / "d.yaml"
    assert "bearing: NSK-30TAC62B-DFF-C9" in GOOD
    p.write_text(
        GOOD.replace("bearing: NSK-30TAC62B-DFF-C9", "bearing: HIWIN-WBK15-DF"), encoding="utf-8"
    )
    js = tmp_path / "r.json"
    assert main(["evaluate", str(p), "--json", str(js)]) == 0
    fit = json.loads(js.read_text())["checks"]["bearing_fit"]
    assert fit["pass"] is False
    # the physical values behind it: a 15 mm bore against the 25-30 mm the 40 mm screw end takes
    assert (fit["needed"], fit["available_min"], fit["available"], fit["unit"]) == (
        pytest.approx(15),
        pytest.approx(25),
        pytest.approx(30),
        "mm",
    )
    # --fail-on-check turns the failed check into exit 1 with one line naming it; without it: exit 0
    capsys.readouterr()
    assert main(["evaluate", str(p), "--fail-on-check"]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "bearing_fit" in err
    assert main(["evaluate", str(ROOT / "problems" / "vmc_x_design.yaml"), "--fail-on-check"]) == 0


def test_checks_carry_physical_values_in_vendor_units(tmp_path, capsys):
    """Each check's needed value recomputed by hand from the design file (24 m/min on a 20 mm lead
    is 1200 rpm at the screw and, direct drive, at the motor; DN = 40 mm x 1200 rpm, HIWIN's D x n;
    required life 20 000 h; guide travel = 20 000 h x mean speed 8 m/min = 9 600 km), and margin =
    available / needed."""
    js = tmp_path / "r.json"
    assert main(["evaluate", str(ROOT / "problems" / "vmc_x_design.yaml"), "--json", str(js)]) == 0
    checks = json.loads(js.read_text())["checks"]
    assert checks["critical_speed"]["unit"] == "rpm" and checks["critical_speed"][
        "needed"
    ] == pytest.approx(1200)
    assert checks["motor_speed"]["needed"] == pytest.approx(1200)
    assert checks["dn"]["needed"] == pytest.approx(40 * 1200) and checks["dn"]["unit"] == "mm.rpm"
    assert (
        checks["nut_life"]["needed"] == pytest.approx(20_000) and checks["nut_life"]["unit"] == "h"
    )
    assert checks["screw_length"]["needed"] == pytest.approx(1100)  # span of the design
    assert (
        checks["guide_life"]["needed"] == pytest.approx(9600)
        and checks["guide_life"]["unit"] == "km"
    )
    for name, c in checks.items():
        if c["margin"] is not None and c["needed"] and name != "bearing_fit":
            assert c["margin"] == pytest.approx(c["available"] / c["needed"], rel=1e-9), name
    assert "brake_holding" not in checks  # a horizontal axis needs no brake
    out = capsys.readouterr().out
    assert all(len(line) <= 100 for line in out.splitlines()), max(out.splitlines(), key=len)


@pytest.mark.parametrize(
    ("names", "text"),
    [
        ("nut:hertz", "n_balls"),
        ("bearings:palmgren", "ball_diameter"),
        ("nut:magic", "unknown stiffness method"),
    ],
)
def test_named_method_without_data_is_one_line_error(capsys, names, text):
    assert main(["evaluate", str(ROOT / "problems" / "vmc_x_design.yaml"), "--methods", names]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and text in err and "--methods" in err


def test_named_method_with_data_prints_it(capsys):
    assert (
        main(
            [
                "evaluate",
                str(ROOT / "problems" / "vmc_x_design.yaml"),
                "--methods",
                "nut:catalog,screw:eq7",
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert "catalog eq. 9" in out and "eq. 7-8" in out and "Hertz" not in out


def test_colour_only_on_request_or_terminal(monkeypatch, capsys):
    """Plain text when captured (not a terminal); AXISOPT_COLOR=always colours FAIL red and pass
    green; NO_COLOR wins over a terminal."""
    pytest.importorskip("rich")
    design = str(ROOT / "problems" / "paper_3_1_3_d40.yaml")  # fails critical speed and nut life
    assert main(["evaluate", design]) == 0
    assert "\x1b[" not in capsys.readouterr().out
    monkeypatch.setenv("AXISOPT_COLOR", "always")
    assert main(["evaluate", design]) == 0
    out = capsys.readouterr().out
    assert "\x1b[1;31mFAIL\x1b[0m" in out and "\x1b[32mpass\x1b[0m" in out
    monkeypatch.setenv("AXISOPT_COLOR", "")
    monkeypatch.setenv("NO_COLOR", "1")
    monkeypatch.setattr("sys.stdout.isatty", lambda: True, raising=False)
    assert main(["evaluate", design]) == 0
    assert "\x1b[" not in capsys.readouterr().out
