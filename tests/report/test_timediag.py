"""Time-record diagnosis output (:mod:`axisopt.report.timediag`): the JSON carries the unexplained verdict."""

import json
from pathlib import Path

import numpy as np
import pytest

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.timesynth import AxisTruth, simulate_axis

DESIGN = Path(__file__).resolve().parents[2] / "problems" / "data" / "table_x.yaml"


@pytest.fixture(scope="module")
def plant():
    return plant_from_design(load_design(DESIGN))


def truth_for(seed, **kw):
    rng = np.random.default_rng(seed)
    sign = rng.choice([-1.0, 1.0])
    return AxisTruth(mass=rng.uniform(300, 900), viscous=rng.uniform(600, 2500), coulomb=rng.uniform(200, 600),
                     offset=sign * rng.uniform(20, 60), **kw)


def records(tmp_path, truth, seed, **csv):
    est, val = tmp_path / f"est{seed}.csv", tmp_path / f"val{seed}.csv"
    simulate_axis(truth, duration=12.0, seed=seed).write_csv(est, **csv)
    simulate_axis(truth, duration=8.0, seed=seed + 500).write_csv(val, **csv)
    return [est, val]


def test_json_carries_the_unexplained_verdict(tmp_path, plant, capsys):
    truth = truth_for(3, ripple=40.0, ripple_period=0.025)
    paths = records(tmp_path, truth, 3)
    assert main(["diagnose", *map(str, paths), "--design", str(DESIGN), "--json", "-"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["unexplained"]["remaining"] and d["unexplained"]["signatures"][0]["kind"] == "position_periodic"
    assert all(c["reason"] for c in d["not_accepted"])
