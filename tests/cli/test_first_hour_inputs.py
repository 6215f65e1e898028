"""The files a new user wrote (issue 57), rebuilt: values that contradict one another refused in one
line (exit 2), unit slips warned about or refused with the likely meaning, and a file given to the
wrong command named as what it is with the command to use.  Each case is the teaching problem with
one line changed, as the user did."""

from __future__ import annotations

import shutil
import warnings
from pathlib import Path

import pytest
from cli_helpers import one_line_error

from axisopt.cli import main
from axisopt.errors import ImplausibleInput, InputError
from axisopt.problem import load_problem
from axisopt.units import STANDARD_GRAVITY, parse_quantity

ROOT = Path(__file__).resolve().parents[2]
TEACHING = ROOT / "problems" / "teaching_problem.yaml"
DESIGN = ROOT / "problems" / "teaching_design.yaml"
STUDY = ROOT / "problems" / "studies" / "gantry_weights.yaml"


def _changed(tmp_path, old: str, new: str, name="p.yaml") -> str:
    text = TEACHING.read_text(encoding="utf-8")
    assert old in text
    p = tmp_path / name
    p.write_text(text.replace(old, new), encoding="utf-8")
    return str(p)


@pytest.fixture
def no_search(monkeypatch):
    import axisopt.search as search

    monkeypatch.setattr(
        search, "solve", lambda *a, **k: (_ for _ in ()).throw(AssertionError("solved"))
    )


@pytest.mark.parametrize(
    "old, new, words",
    [
        (
            "mean_speed: 8 m/min",
            "mean_speed: 45 m/min",
            "'axis.mean_speed': 45 m/min is faster than axis.max_speed",
        ),
        (
            "axial_load: 2000 N",
            "axial_load: 2000 N\n  mean_axial_load: 2500 N",
            "'axis.mean_axial_load': 2500 N is more than the largest axial load",
        ),
        ("max_cost: 3500 EUR", "max_moving_mass: 100 kg", "below axis.moving_mass (120 kg"),
        ("acceleration: 3 m/s^2", "acceleration: 3 m/s2", "write a power with '^': '3 m/s^2'"),
        ("axial_load: 2000 N", "axial_load: 3,000 N", "without digit groups: '3000 N'"),
        ("max_cost: 3500 EUR", "max_cost: 3500 \u20ac", "write the currency as EUR: '3500 EUR'"),
        ("max_cost: 3500 EUR", "max_cost: 3500 euro", "write the currency as EUR"),
        (
            "acceleration: 3 m/s^2",
            "acceleration: 1,5 m/s^2",
            "write the decimal point: '1.5 m/s^2'",
        ),
    ],
)
def test_refused_in_one_line_before_the_search(tmp_path, capsys, no_search, old, new, words):
    assert main(["solve", _changed(tmp_path, old, new)]) == 2
    assert words in one_line_error(capsys)


@pytest.mark.parametrize(
    "old, new, words",
    [
        (
            "min_life: 12000 h",
            "min_life: 20000 s",
            "'limits.min_life': 5.56 h is far below machine-tool practice",
        ),
        ("axial_load: 2000 N", "axial_load: 3 MN", "'axis.axial_load': 3,000,000 N is far above"),
        ("moving_mass: 120 kg", "moving_mass: 350000 kg", "350,000 kg is far above"),
        (
            "min_life: 12000 h",
            "min_life: 12000 h\n  min_stiffness: 60 N/mm",
            "'limits.min_stiffness'",
        ),
    ],
)
def test_unit_slips_are_warned(tmp_path, old, new, words):
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        load_problem(_changed(tmp_path, old, new))
    msgs = [str(w.message) for w in got if issubclass(w.category, ImplausibleInput)]
    assert any(words in m for m in msgs), msgs


def test_shipped_problems_warn_of_nothing():
    for f in sorted((ROOT / "problems").glob("*_problem.yaml")):
        with warnings.catch_warnings():
            warnings.simplefilter("error", ImplausibleInput)
            load_problem(f)


def test_g_is_standard_gravity_for_an_acceleration(tmp_path):
    assert parse_quantity("0.4 g", "acceleration") == pytest.approx(0.4 * 9.80665)
    assert STANDARD_GRAVITY == 9.80665  # ISO 80000-3 / CGPM 1901
    assert parse_quantity("400 g", "mass") == pytest.approx(0.4)  # grams where a mass is asked
    p = load_problem(_changed(tmp_path, "acceleration: 3 m/s^2", "acceleration: 0.4 g"))
    assert p.axis.acceleration == pytest.approx(3.92266)


@pytest.mark.parametrize(
    "argv, words",
    [
        (["solve", str(DESIGN)], "a design file, not a problem: use `axisopt evaluate"),
        (["solve", str(STUDY)], "a study file, not a problem: use `axisopt study"),
        (["study", str(TEACHING)], "a problem file, not a study: use `axisopt solve"),
        (["study", str(DESIGN)], "a design file, not a study"),
        (["evaluate", str(STUDY)], "a study file, not a design: use `axisopt study"),
        (["evaluate", str(TEACHING)], "a problem file, not a design"),
        (
            ["evaluate", str(ROOT / "problems" / "data" / "table_x_stiffness.csv")],
            "a CSV file, not a design YAML",
        ),
        (["compare", str(DESIGN), str(STUDY)], "a study file, not a design or problem"),
    ],
)
def test_wrong_kind_of_file_named_with_the_command(argv, words, capsys):
    assert main(argv) == 2
    assert words in one_line_error(capsys)


def test_csv_copied_to_yaml_name_still_refused(tmp_path, capsys):
    f = tmp_path / "data.yaml"
    shutil.copy(ROOT / "problems" / "data" / "table_x_stiffness.csv", f)
    assert main(["evaluate", str(f)]) == 2
    one_line_error(capsys)
    with pytest.raises(InputError):
        load_problem(f)


def test_a_duty_cycle_force_in_kn_for_n_is_warned(tmp_path):
    text = (ROOT / "problems" / "duty_cycle_problem.yaml").read_text(encoding="utf-8")
    assert "force: 2500 N}" in text
    f = tmp_path / "dc.yaml"
    f.write_text(text.replace("force: 2500 N}", "force: 2500 kN}"), encoding="utf-8")
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        load_problem(f)
    assert any("'axis.duty_cycle': 2,500,000 N is far above" in str(w.message) for w in got)
