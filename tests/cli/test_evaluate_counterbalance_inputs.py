"""A counterbalance refused in one line naming file, line and key, exit 2 (design and problem
files): heavier than the head, negative / zero / NaN / inf / 1e300 / wrong-unit values, an unknown
kind, a typo in a sub-key, a key of the other kind, a counterbalance on a horizontal axis; a good
one evaluates and solves."""

from __future__ import annotations

from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
BASE = """name: counterbalanced Z
axis:
  stroke: 500 mm
  moving_mass: 300 kg
  mounting: fixed-supported
  orientation: {orientation}
  max_speed: 24 m/min
  axial_load: 3000 N
  acceleration: 3 m/s^2
  counterbalance: {cb}
parts:
  screw: HIWIN-G-25x5-b3p175
  nut: HIWIN-R25-05K4-FDC
  bearing: HIWIN-7205B-DB-H
  guide: HIWIN-HG20-ZA
"""


def _text(cb: str, orientation: str = "vertical") -> str:
    return BASE.format(cb=cb, orientation=orientation)


@pytest.mark.parametrize(
    "cb, key, words",
    [
        ("{kind: counterweight, mass: 320 kg}", "counterbalance.mass", "heavier than the head"),
        ("{kind: counterweight, mass: -5 kg}", "counterbalance.mass", "must be positive"),
        ("{kind: counterweight, mass: 0 kg}", "counterbalance.mass", "must be positive"),
        ("{kind: counterweight, mass: .nan kg}", "counterbalance.mass", ""),
        ("{kind: counterweight, mass: .inf kg}", "counterbalance.mass", ""),
        ("{kind: counterweight, mass: 1e300 kg}", "counterbalance.mass", ""),
        ("{kind: counterweight, mass: 200 mm}", "counterbalance.mass", "unit"),
        ("{kind: counterweight, mass: 200}", "counterbalance.mass", "unit"),
        (
            "{kind: counterweight, mass: 200 kg, efficiency: 1.2}",
            "counterbalance.efficiency",
            "at most",
        ),
        (
            "{kind: counterweight, mass: 200 kg, efficiency: 0}",
            "counterbalance.efficiency",
            "positive",
        ),
        (
            "{kind: counterweight, mass: 200 kg, efficiency: .nan}",
            "counterbalance.efficiency",
            "finite",
        ),
        (
            "{kind: counterweight, mass: 200 kg, chain_mass: -1 kg}",
            "counterbalance.chain_mass",
            "negative",
        ),
        ("{kind: counterweight, mas: 200 kg}", "counterbalance.mas", "did you mean 'mass'"),
        ("{kind: counterweight}", "counterbalance", "needs its mass"),
        (
            "{kind: counterweight, mass: 200 kg, force: 3 kN}",
            "counterbalance.force",
            "does not apply",
        ),
        ("{kind: spring, mass: 200 kg}", "counterbalance.kind", "is not one of"),
        ("{mass: 200 kg}", "counterbalance", "missing required key 'axis.counterbalance.kind'"),
        ("{kind: cylinder, force: -3 kN}", "counterbalance.force", "must be positive"),
        ("{kind: cylinder, force: 3 kN, force_at_end: .inf kN}", "counterbalance.force_at_end", ""),
        ("{kind: cylinder, force: 3 kN, tolerance: -5 %}", "counterbalance.tolerance", "negative"),
        (
            "{kind: cylinder, force: 3 kN, tolerance: 80 %}",
            "counterbalance.tolerance",
            "at most 50 %",
        ),
        ("{kind: cylinder, force: 3 kN, mass: 200 kg}", "counterbalance.mass", "does not apply"),
        ("{kind: cylinder, forse: 3 kN}", "counterbalance.forse", "did you mean 'force'"),
        ("450 kg", "counterbalance", "mapping"),
    ],
)
def test_bad_counterbalance_is_one_line_exit_2(tmp_path, capsys, cb, key, words):
    assert main(["evaluate", write_file(tmp_path, "d.yaml", _text(cb))]) == 2
    err = one_line_error(capsys)
    assert "d.yaml" in err and "line " in err and f"axis.{key}" in err and words in err, err


@pytest.mark.parametrize("orientation", ["horizontal", "wall"])
def test_counterbalance_on_a_horizontal_axis_is_refused(tmp_path, capsys, orientation):
    text = _text("{kind: counterweight, mass: 200 kg}", orientation)
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert "axis.counterbalance" in err and "vertical" in err and orientation in err, err


def test_counterbalance_in_a_problem_is_read_the_same_way(tmp_path, capsys):
    text = (
        (ROOT / "problems" / "vertical_problem.yaml")
        .read_text(encoding="utf-8")
        .replace(
            "  orientation: vertical\n",
            "  orientation: vertical\n  counterbalance: {kind: counterweight, mass: 400 kg}\n",
        )
    )
    assert main(["solve", write_file(tmp_path, "p.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert (
        "p.yaml" in err and "axis.counterbalance.mass" in err and "heavier than the head" in err
    ), err


@pytest.mark.parametrize(
    "cb",
    [
        "{kind: counterweight, mass: 250 kg, efficiency: 0.95}",
        "{kind: cylinder, force: 2500 N, force_at_end: 2800 N, tolerance: 5 %}",
        "{kind: none}",
    ],
)
def test_good_counterbalance_evaluates(tmp_path, capsys, cb):
    assert main(["evaluate", write_file(tmp_path, "d.yaml", _text(cb))]) == 0
    out = capsys.readouterr().out
    if "none" in cb:
        assert "counterbalance:" not in out
        return
    line = " ".join(out.split("counterbalance: ")[1].split(" at rest")[:2])
    # the balance force and the net weight on the screw, with units
    assert (
        "counterweight 250 kg" in line or "cylinder 2,500..2,800 N" in line
    ) and "the screw carries" in line
    taken = 250 * 9.80665 if "counterweight" in cb else 2500 * 0.95
    assert f"{taken:,.0f} N" in line, line


def test_counterbalance_in_json(tmp_path, capsys):
    import json

    path = write_file(
        tmp_path, "d.yaml", _text("{kind: counterweight, mass: 250 kg, efficiency: 0.9}")
    )
    assert main(["evaluate", path, "--json", "-"]) == 0
    cb = json.loads(capsys.readouterr().out)["counterbalance"]
    assert cb["force_rising_N"] == pytest.approx(250 * 9.80665 * 0.9)
    assert cb["force_lowering_N"] == pytest.approx(250 * 9.80665 / 0.9)
    assert cb["net_weight_on_screw_N"] == pytest.approx(cb["head_weight_N"] - 250 * 9.80665)
