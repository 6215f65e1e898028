"""Edge inputs found in review: rate units, non-finite numbers, BOM files, bad output paths, odd
YAML."""

import math
import shutil
from pathlib import Path

import pytest

from axisopt.catalog.columns import SHIPPED_DIR
from axisopt.catalog.loading import load_catalogs
from axisopt.cli import main
from axisopt.units import parse_quantity, unit_factor

ROOT = Path(__file__).resolve().parents[2]
DESIGN = ROOT / "problems" / "vmc_x_design.yaml"


@pytest.mark.parametrize(
    "unit, kind, si",
    [
        ("rpm", "angular_speed", 2 * math.pi / 60),
        ("1/min", "angular_speed", 2 * math.pi / 60),
        ("Hz", "angular_speed", 2 * math.pi),
        ("rad/s", "angular_speed", 1.0),
        ("deg/s", "angular_speed", math.pi / 180),
        ("Hz", "frequency", 1.0),
        ("rpm", "frequency", 1 / 60),
        ("rad/s", "frequency", 1 / (2 * math.pi)),
        ("1/s", "frequency", 1.0),
        ("kHz", "frequency", 1000.0),
    ],
)
def test_rates_count_cycles_and_radians_apart(unit, kind, si):
    # pint treats the radian as dimensionless; a cycle is 2 pi rad
    assert unit_factor(unit, kind) == pytest.approx(si, rel=1e-12)


def test_non_finite_quantity_is_an_error():
    with pytest.raises(Exception, match="not a finite number"):
        parse_quantity("1e400 mm", "length", source="a.yaml", key="axis.stroke")


def test_catalog_with_byte_order_mark_loads(tmp_path):
    d = tmp_path / "cat"
    shutil.copytree(SHIPPED_DIR, d)
    p = d / "guides.csv"
    p.write_bytes(b"\xef\xbb\xbf" + p.read_bytes())
    assert len(load_catalogs([d], shipped=False).guides) > 0


@pytest.mark.parametrize(
    "args, words",
    [
        (["--plot", "/nonexistent-dir/x.png"], "cannot write plot"),
        (["--plot", "x.xyz"], "extensions"),
        (["--json", "/nonexistent-dir/x.json"], "cannot write JSON"),
    ],
)
def test_bad_output_paths_are_one_line_errors(tmp_path, monkeypatch, capsys, args, words):
    monkeypatch.chdir(tmp_path)
    assert main(["evaluate", str(DESIGN), *args]) == 2
    err = capsys.readouterr().err.strip()
    assert words in err and "\n" not in err


def test_report_directory_that_is_a_file(tmp_path, capsys):
    f = tmp_path / "afile"
    f.write_text("x")
    data = ROOT / "problems" / "data"
    rc = main(
        [
            "diagnose",
            str(data / "table_x_stiffness.csv"),
            "--design",
            str(data / "table_x.yaml"),
            "--report",
            str(f),
        ]
    )
    assert rc == 2 and "cannot create output directory" in capsys.readouterr().err


def test_single_group_data_cannot_claim_held_out_gain(tmp_path, capsys):
    data = ROOT / "problems" / "data"
    lines = (data / "table_x_stiffness.csv").read_text().splitlines()
    one = tmp_path / "one.csv"
    one.write_text("\n".join(lines[:6]) + "\n")
    assert main(["diagnose", str(one), "--design", str(data / "table_x.yaml")]) == 2
    assert "at least 2 groups" in capsys.readouterr().err


@pytest.mark.parametrize(
    "text, words",
    [
        ("axis: &a [*a]\n", "self-referencing"),
        ("axis: !!python/object:os.system x\n", "malformed YAML"),
    ],
)
def test_hostile_yaml(tmp_path, capsys, text, words):
    p = tmp_path / "d.yaml"
    p.write_text(text)
    assert main(["evaluate", str(p)]) == 2
    assert words in capsys.readouterr().err


def test_empty_restriction_list_is_an_error(tmp_path, capsys):
    text = (
        (ROOT / "problems" / "teaching_problem.yaml")
        .read_text()
        .replace("vendors: [HIWIN]", "vendors: []")
    )
    p = tmp_path / "p.yaml"
    p.write_text(text)
    assert main(["solve", str(p)]) == 2
    assert "catalog.vendors" in capsys.readouterr().err


def test_diagnose_positions_off_the_stroke_are_refused(tmp_path, capsys):
    data = ROOT / "problems" / "data"
    lines = (data / "table_x_stiffness.csv").read_text().splitlines()
    col = [i for i, h in enumerate(lines[0].split(",")) if h.startswith("position")][0]
    row = lines[3].split(",")
    row[col] = "5000"
    lines[3] = ",".join(row)
    p = tmp_path / "off.csv"
    p.write_text("\n".join(lines) + "\n")
    assert main(["diagnose", str(p), "--design", str(data / "table_x.yaml")]) == 2
    assert "line 4, column position" in capsys.readouterr().err


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("  motor: SGM7G-13A", "  motor: SGM7G-13X", "SGM7G-13A"),  # unknown id: names the closest
        (
            "  axial_load: 3000 N\n",
            "  axial_load: 3000 N\n  duty_cycle:\n    - {dwell: -2 s}\n",
            "must be positive",
        ),
        (
            "  axial_load: 3000 N\n",
            "  axial_load: 3000 N\n  duty_cycle:\n    - {move: 100 mm, sped: 2 m/min}\n",
            "unknown key 'axis.duty_cycle[0].sped'",
        ),
        (
            "  axial_load: 3000 N\n",
            "  axial_load: 3000 N\n  duty_cycle:\n    - {move: 5 m}\n",
            "longer than the stroke",
        ),
        (
            "  axial_load: 3000 N\n",
            "  axial_load: 3000 N\n  duty_cycle:\n    - {move: 100 mm, dwell: 1 s}\n",
            "'move' or a 'dwell'",
        ),
        (
            "  axial_load: 3000 N\n",
            "  axial_load: 3000 N\n  reduction_efficiency: 1.5\n",
            "reduction_efficiency",
        ),
        ("  axial_load: 3000 N\n", "  axial_load: 3000 N\n  brake: maybe\n", "brake"),
    ],
)
def test_bad_drive_input_is_a_one_line_error(tmp_path, capsys, old, new, words):
    text = DESIGN.read_text()
    assert old in text
    bad = tmp_path / "d.yaml"
    bad.write_text(text.replace(old, new, 1))
    assert main(["evaluate", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert words in err and "\n" not in err and str(bad) in err


def test_motor_row_with_peak_below_rated_is_refused(tmp_path, capsys):
    d = tmp_path / "cat"
    shutil.copytree(SHIPPED_DIR, d)
    p = d / "motors.csv"
    lines = p.read_text().splitlines()
    cells = lines[1].split(",")
    cells[5] = "0.01"  # peak_torque below rated_torque
    lines[1] = ",".join(cells)
    p.write_text("\n".join(lines) + "\n")
    with pytest.raises(Exception, match="peak_torque") as exc:
        load_catalogs([d], shipped=False)
    assert "motors.csv" in str(exc.value) and "\n" not in str(exc.value)


def test_yaml_that_is_not_utf8_is_a_one_line_error(tmp_path, capsys):
    bad = tmp_path / "d.yaml"
    bad.write_bytes(DESIGN.read_text().encode("utf-16"))
    assert main(["evaluate", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert "cannot read file" in err and "UnicodeDecodeError" in err and "\n" not in err
