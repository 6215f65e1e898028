"""The drive type as a search choice: on randomized rack and linear-motor catalogs mixed with the screw drive,
the default method's answer (bounded best-first per space, the screw search's proof) equals the exhaustive one
(every combination evaluated) and the ground truth of every combination evaluated alone in floats; the best
type wins by the shared tie rule."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from axisopt.drivecatalog import DriveTables
from axisopt.problem import load_problem
from axisopt.search import drivebest
from axisopt.search.drivetype import (
    OBJECTIVES,
    scalar_search,
    solve_drive_types,
    spaces,
)

ROOT = Path(__file__).resolve().parents[2]
TEACHING = (ROOT / "problems" / "teaching_problem.yaml").read_text(encoding="utf-8")
KEPT = (
    "BK-TP010-MF-5",
    "BK-NPT025-MF-7",
    "BK-NPT035-MF-10",
)  # the reductions the random spaces keep
OTHER_REDUCTIONS = [
    r.split(",")[0]
    for r in (ROOT / "catalogs" / "reductions.csv").read_text(encoding="utf-8").splitlines()[1:]
    if r and r.split(",")[0] not in KEPT
]


def _racks(rng, n):
    out = []
    for i in range(n):
        d = rng.uniform(0.025, 0.09)
        out.append(
            {
                "id": f"R{i}",
                "kind": "spur",
                "quality": 6.0,
                "module": d / 20,
                "teeth": 20.0,
                "helix_angle": 0.0,
                "pitch_diameter": d,
                "face_width": rng.uniform(0.01, 0.04),
                "permissible_force": rng.uniform(1e3, 2e4),
                "pitch_error": rng.uniform(5e-6, 6e-5),
                "pinion_price": rng.uniform(50, 300),
                "rack_price_per_length": rng.uniform(80, 500),
                "rack_mass_per_length": 3.0,
                "estimated": [],
            }
        )
    return tuple(out)


def _lms(rng, n):
    out = []
    for i in range(n):
        fc = rng.uniform(100, 1200)
        iron = rng.random() < 0.6
        out.append(
            {
                "id": f"L{i}",
                "kind": "iron-core" if iron else "ironless",
                "continuous_force": fc,
                "peak_force": fc * rng.uniform(2, 3.5),
                "force_constant": rng.choice([None, 40.0]),
                "continuous_current": None,
                "peak_current": None,
                "forcer_mass": rng.uniform(1, 15),
                "attraction_force": 5 * fc if iron else 0.0,
                "accuracy": rng.uniform(2e-6, 8e-6),
                "forcer_price": rng.uniform(800, 4000),
                "track_price_per_length": rng.uniform(300, 2000),
                "estimated": [],
            }
        )
    return tuple(out)


def _problem(tmp_path, rng, objective: str, types: str):
    acc = rng.uniform(1.0, 6.0)
    speed = rng.uniform(15, 40)
    cost = rng.uniform(3000, 12000)
    text = (
        TEACHING.replace("acceleration: 3 m/s^2", f"acceleration: {acc:.3f} m/s^2")
        .replace("max_speed: 30 m/min", f"max_speed: {speed:.2f} m/min")
        .replace("max_cost: 3500 EUR", f"max_cost: {cost:.0f} EUR")
        .replace("objective: stiffness", f"objective: {objective}")
        .replace(
            "  require: {coupling: [RINGFEDER-GWB-AKN-30, RINGFEDER-GWB-AKN-60]}",
            "  require: {coupling: [RINGFEDER-GWB-AKN-30, RINGFEDER-GWB-AKN-60], guide: [HIWIN-HG15-ZA, "
            "HIWIN-HG20-ZB, HIWIN-HG25-ZA]}\n  exclude: {reduction: ["
            + ", ".join(OTHER_REDUCTIONS)
            + "]}",
        )
    )
    text += f"search:\n  drive_types: [{types}]\n"
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    prob = load_problem(path)
    tables = DriveTables(_racks(rng, 3), _lms(rng, 4))
    return replace(prob, drives=replace(prob.drives, tables=tables))


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("objective", ["stiffness", "frequency"])
def test_default_equals_exhaustive_over_mixed_drive_types(tmp_path, seed, objective, monkeypatch):
    """Odd seeds open the rack space block by block (drivebest.LEVEL1_MIN lowered to 1)."""
    if seed % 2:
        monkeypatch.setattr(drivebest, "LEVEL1_MIN", 1)
        monkeypatch.setattr(drivebest, "LEVEL1_BATCH", 2)
    rng = np.random.default_rng(100 + seed)
    types = ["screw, rack_pinion, linear_motor", "rack_pinion, linear_motor"][seed // 2 % 2]
    prob = _problem(tmp_path, rng, objective, types)
    d = solve_drive_types(prob, "default", top=3)
    e = solve_drive_types(prob, "exhaustive", top=3)
    assert d.status == e.status
    if e.best is None:
        assert d.best is None and d.change
        return
    assert d.best.drive_type == e.best.drive_type and d.best.parts == e.best.parts
    assert d.best.objective == pytest.approx(e.best.objective, rel=1e-12)
    assert [x.parts for x in d.runners_up] == [x.parts for x in e.runners_up]
    # the ground truth of the new types: every combination alone, floats
    spec = OBJECTIVES[objective]
    truth = []
    for sp in spaces(prob):
        designs, _ = scalar_search(prob, sp, spec, 1)
        truth += designs
    screw = [t for t in e.types if t.drive_type == "screw" and t.best is not None]
    values = [t.objective for t in truth] + [t.best for t in screw]
    best = max(values) if spec[3] == "max" else min(values)
    assert e.best.objective == pytest.approx(best, rel=1e-12)


def test_the_type_follows_the_objective(tmp_path):
    """The same axes: the stiffest drive is a rack (its mesh and gearbox beat the servo's estimated stiffness),
    the highest first frequency at least once a linear motor's (no screw or mesh between motor and table): the
    choice is real, not a fixed preference."""
    won = {}
    for objective in ("stiffness", "frequency"):
        for seed in range(3):
            res = solve_drive_types(
                _problem(
                    tmp_path, np.random.default_rng(seed), objective, "rack_pinion, linear_motor"
                ),
                top=1,
            )
            if res.best is not None:
                won.setdefault(objective, set()).add(res.best.drive_type)
    assert won["stiffness"] == {"rack_pinion"} and "linear_motor" in won["frequency"], won
