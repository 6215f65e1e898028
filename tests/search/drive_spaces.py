"""The random drive-type spaces the drive-type search tests share
(tests/search/test_drivetype_search.py, tests/search/test_drivedefault.py): the teaching axis with
random acceleration, speed and budget, three guides and three reductions kept, and random rack and
linear-motor rows (plausible SI values, fixed seeds)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from axisopt.drivecatalog import DriveTables
from axisopt.problem import load_problem

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


def racks(rng, n):
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


def lms(rng, n):
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


def drive_problem(tmp_path, rng, objective: str, types: str):
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
            "  require: {coupling: [RINGFEDER-GWB-AKN-30, RINGFEDER-GWB-AKN-60], guide: "
            "[HIWIN-HG15-ZA, HIWIN-HG20-ZB, HIWIN-HG25-ZA]}\n  exclude: {reduction: ["
            + ", ".join(OTHER_REDUCTIONS)
            + "]}",
        )
    )
    text += f"search:\n  drive_types: [{types}]\n"
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    prob = load_problem(path)
    tables = DriveTables(racks(rng, 3), lms(rng, 4))
    return replace(prob, drives=replace(prob.drives, tables=tables))
