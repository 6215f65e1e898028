"""The life checks' load table that ``evaluate`` prints (the rows the vendors' worked examples
list), against THK's vertical conveyance example (General Catalog A-736 to A-742): 50 kg lifted at
0.3 m/s with 0.2 s ramps over 600 mm, guide resistance f = 20 N.  THK: axial loads 585 / 510 / 435 N
up and 395 / 470 / 545 N down (A-739), travels 30 / 540 / 30 mm each way (A-741), Fm = 492 N
(A-742)."""

from __future__ import annotations

import json

import pytest
from test_checks_life_duty_cycle import DESIGN

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.model.lifetable import life_table


@pytest.fixture
def thk_design(tmp_path):
    path = tmp_path / "thk.yaml"
    path.write_text(DESIGN, encoding="utf-8")
    return path


@pytest.mark.published
def test_rows_are_thks_phase_loads_and_travels(thk_design):
    t = life_table(load_design(thk_design))
    assert t["from_cycle"]
    rows = sorted(t["rows"], key=lambda r: (-r["direction"], -r["acceleration"] * r["direction"]))
    # THK A-739 rounds g to 9.807 and prints whole newtons
    assert [r["load"] for r in rows] == pytest.approx([585, 510, 435, 395, 470, 545], abs=1.0)
    assert [r["travel"] * 1e3 for r in rows] == pytest.approx([30, 540, 30] * 2, abs=0.01)
    # one direction only on a vertical lift: every load is upward; THK A-742 Fm = 492 N
    assert t["cubic_mean"][0] == pytest.approx(492, abs=0.5)
    assert t["cubic_mean"][1] == 0.0
    # a single nut: its equivalent load is the larger directional mean (THK A-706)
    assert t["nut_equivalent"] == pytest.approx(t["cubic_mean"][0], rel=1e-12)


def test_evaluate_prints_and_saves_the_table(thk_design, tmp_path, capsys):
    assert main(["evaluate", str(thk_design)]) == 0
    text = capsys.readouterr().out
    block = text[
        text.index("life loads from the duty cycle's phases") : text.index("checks (margin")
    ]
    assert (
        "585" in block
        and "545" in block
        and "540.0 mm" in block
        and "cubic-mean load 492 N (+)" in block
    )
    assert all(len(line) <= 100 for line in block.splitlines())
    out = tmp_path / "ev.json"
    assert main(["evaluate", str(thk_design), "--json", str(out)]) == 0
    data = json.loads(out.read_text(encoding="utf-8"))["life_loads"]
    assert data["from_duty_cycle"] is True
    assert sorted(round(p["axial_load_N"]) for p in data["phases"]) == [
        395,
        435,
        470,
        510,
        545,
        585,
    ]
    assert data["cubic_mean_load_N"]["positive"] == pytest.approx(492, abs=0.5)


def test_without_a_cycle_the_table_says_so(tmp_path, capsys):
    text = DESIGN[: DESIGN.index("  duty_cycle:")] + DESIGN[DESIGN.index("parts:") :]
    path = tmp_path / "nocycle.yaml"
    path.write_text(text, encoding="utf-8")
    t = life_table(load_design(path))
    assert not t["from_cycle"] and [r["travel"] for r in t["rows"]] == [0.5, 0.5]
    assert main(["evaluate", str(path)]) == 0
    assert (
        "life loads from the mean axial load each way (no duty cycle) (THK A-725)"
        in capsys.readouterr().out
    )
