"""search.counterbalance / search.twin_drive (a problem's options, axisopt.design.choices): each
option read as the single axis key, a bad one refused in one line naming the file, line, key and the
option's index, exit 2; a list where it makes no sense (on the axis, in a design, beside the single
key, a Pareto objective) refused the same way; a good list solves and says which arrangement won, in
the text and the JSON."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
VERTICAL = (ROOT / "problems" / "vertical_problem.yaml").read_text(encoding="utf-8")


def _problem(search: str, text: str = VERTICAL) -> str:
    return text + f"search:\n  {search}\n"


@pytest.mark.parametrize(
    "search, key, words",
    [
        (
            "counterbalance: [none, {kind: counterweight, mass: 400 kg}]",
            "search.counterbalance.mass",
            "option 1: 400 kg is heavier than the head",
        ),
        (
            "counterbalance: [none, {kind: counterweight, mass: -5 kg}]",
            "search.counterbalance.mass",
            "option 1: must be positive",
        ),
        (
            "counterbalance: [{kind: counterweight, mass: .nan kg}, none]",
            "search.counterbalance.mass",
            "option 0",
        ),
        (
            "counterbalance: [none, {kind: counterweight, mass: 1e300 kg}]",
            "search.counterbalance.mass",
            "option 1",
        ),
        (
            "counterbalance: [none, {kind: counterweight, mass: 200 mm}]",
            "search.counterbalance.mass",
            "unit",
        ),
        (
            "counterbalance: [none, {kind: counterweight, mas: 200 kg}]",
            "search.counterbalance.mas",
            "did you mean 'mass'",
        ),
        ("counterbalance: [none, {kind: spring}]", "search.counterbalance.kind", "option 1"),
        (
            "counterbalance: [none, {kind: cylinder, force: 2 kN, mass: 3 kg}]",
            "search.counterbalance.mass",
            "does not apply",
        ),
        (
            "counterbalance: [none, 250 kg]",
            "search.counterbalance",
            "option 1: expected 'none' or a mapping",
        ),
        ("counterbalance: none", "search.counterbalance", "expected a list of options"),
        ("counterbalance: []", "search.counterbalance", "expected a list of options"),
        ("counterbalance: [none, none]", "search.counterbalance", "listed twice"),
        ("counterbalanse: [none]", "search.counterbalanse", "did you mean 'counterbalance'"),
        (
            "twin_drive: [none, {span: 2 m, cross_stroke: 1 m}]",
            "search.twin_drive",
            "option 1: a twin drive is a horizontal gantry's",
        ),
    ],
)
def test_bad_option_is_one_line_exit_2(tmp_path, capsys, search, key, words):
    assert main(["solve", write_file(tmp_path, "p.yaml", _problem(search))]) == 2
    err = one_line_error(capsys)
    assert "p.yaml" in err and "line " in err and key in err and words in err, err


def test_option_list_beside_the_axis_key_is_refused(tmp_path, capsys):
    text = VERTICAL.replace(
        "  orientation: vertical\n",
        "  orientation: vertical\n  counterbalance: {kind: counterweight, mass: 200 kg}\n",
    )
    assert (
        main(["solve", write_file(tmp_path, "p.yaml", _problem("counterbalance: [none]", text))])
        == 2
    )
    err = one_line_error(capsys)
    assert "axis.counterbalance and search.counterbalance both given" in err, err


def test_a_list_on_the_axis_is_refused(tmp_path, capsys):
    text = VERTICAL.replace(
        "  orientation: vertical\n",
        "  orientation: vertical\n  counterbalance: [none, {kind: counterweight, mass: 200 kg}]\n",
    )
    assert main(["solve", write_file(tmp_path, "p.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert "axis.counterbalance" in err and "mapping" in err, err


def test_options_in_a_design_are_refused(tmp_path, capsys):
    text = """name: a Z
axis: {stroke: 500 mm, moving_mass: 300 kg, mounting: fixed-supported, orientation: vertical, max_speed: 24 m/min,
       axial_load: 3000 N, acceleration: 3 m/s^2}
parts: {screw: HIWIN-G-25x5-b3p175, nut: HIWIN-R25-05K4-FDC, bearing: HIWIN-7205B-DB-H, guide: HIWIN-HG20-ZA}
search: {counterbalance: [none]}
"""  # noqa: E501
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert "search" in err and "unknown key" in err, err


def test_pareto_with_options_names_each_point_arrangement(tmp_path, capsys):
    text = VERTICAL.replace(
        "objective: tool_stiffness", "objective: {mode: pareto, pareto: [stiffness, cost]}"
    )
    path = write_file(
        tmp_path,
        "p.yaml",
        _problem("counterbalance: [none, {kind: counterweight, mass: 200 kg}]", text),
    )
    # one solve (it takes seconds) for both: the JSON to a file, the text on stdout
    rj = tmp_path / "r.json"
    assert main(["solve", path, "--json", str(rj)]) == 0
    out = capsys.readouterr().out
    res = json.loads(rj.read_text(encoding="utf-8"))
    points = res["pareto"]["points"]
    assert points and all(pt["arrangement"] in ("none", "counterweight 200 kg") for pt in points)
    assert "arrangements tried; front points by arrangement" in out and "arrangement" in out


def test_options_solve_and_name_the_winner(tmp_path, capsys):
    path = write_file(
        tmp_path,
        "p.yaml",
        _problem(
            "counterbalance: [none, {kind: counterweight, mass: 250 kg}, {kind: cylinder, force: "
            "2500 N}]"
        ),
    )
    # one solve (three arrangements, the longest of this file) for both: the JSON to a file, the
    # text on stdout
    rj = tmp_path / "r.json"
    assert main(["solve", path, "--json", str(rj)]) == 0
    out = capsys.readouterr().out
    res = json.loads(rj.read_text(encoding="utf-8"))
    assert res["arrangement"]["of"] == 3 and res["status"] == "optimal"
    chosen = res["arrangement"]["chosen"]
    assert chosen in ("none", "counterweight 250 kg", "cylinder 2500 N")
    assert f"arrangement: {chosen} (best of 3 arrangements)" in out, out
