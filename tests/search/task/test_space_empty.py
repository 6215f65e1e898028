"""Filters that leave a part slot empty (no guide, no bearing, no screw and nut) leave no
combination at
all: a one-line error naming the slot (exit code 2), not a traceback (the explanation had nothing to
score) nor an "infeasible" answer that says every limit is met by some combination."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from search_synthetic import add_drives, make_catalog, make_double, make_problem

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.model.goals import Objective
from axisopt.search import solve

ROOT = Path(__file__).resolve().parents[3]


def _problem(drive: bool, mode: str = "stiffness"):
    rng = np.random.default_rng(3)
    cat = make_catalog(rng)  # ball guides only
    if drive:
        make_double(cat)
        cat = add_drives(cat, rng)
    ob = (
        Objective(mode="pareto", pareto=("stiffness", "cost"))
        if mode == "pareto"
        else Objective(mode=mode)
    )
    p = make_problem(cat, limits={"max_cost": 100.0}, objective=ob)
    if drive:
        p = replace(p, restrictions=replace(p.restrictions, drive=True))
    return p


@pytest.mark.parametrize("method", ["default", "exhaustive"])
@pytest.mark.parametrize("drive", [False, True])
@pytest.mark.parametrize("mode", ["stiffness", "pareto"])
@pytest.mark.parametrize(
    "restriction,slot",
    [
        ({"guide_types": ("roller",)}, "linear guide"),
        ({"bearing_arrangements": ("DF",)}, "support bearing"),
        ({"nut_types": ("nope",)}, "screw and nut"),
    ],
)
def test_an_empty_part_slot_is_an_input_error(method, drive, mode, restriction, slot):
    p = _problem(drive, mode)
    p = replace(p, restrictions=replace(p.restrictions, **restriction))
    with pytest.raises(InputError, match=f"nothing to choose from: no {slot} is left"):
        solve(p, method, sensitivities=False)


def test_cli_vendor_without_guides(tmp_path, capsys):
    """THK lists screws, nuts and bearings but no guides: the teaching problem restricted to THK."""
    f = tmp_path / "thk.yaml"
    f.write_text(
        (ROOT / "problems" / "teaching_problem.yaml")
        .read_text()
        .replace("vendors: [HIWIN]", "vendors: [THK]")
    )
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "no linear guide is left" in err
