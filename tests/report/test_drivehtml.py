"""The HTML pages of drive-type answers (report.drivehtml): `solve --report` of a problem over drive
types and `evaluate --report` of a saved rack-and-pinion design show the designs' parts, numbers and
every margin with its verdict, and the margins figure as SVG; an infeasible answer shows its closest
designs."""

from __future__ import annotations

import re
from pathlib import Path

from axisopt.cli import main
from axisopt.problem import load_problem
from axisopt.search.drivefile import evaluate_drive_design
from axisopt.search.drivetype import solve_drive_types

ROOT = Path(__file__).resolve().parents[2]


def test_solve_and_evaluate_pages(tmp_path, capsys):
    router = ROOT / "problems" / "router_rack_problem.yaml"
    page = tmp_path / "s.html"
    saved = tmp_path / "d.yaml"
    assert (
        main(
            [
                "solve",
                str(router),
                "--no-sensitivity",
                "--report",
                str(page),
                "--save-design",
                str(saved),
            ]
        )
        == 0
    )
    best = solve_drive_types(load_problem(router), top=1).best
    html = page.read_text(encoding="utf-8")
    for v in best.parts.values():
        assert str(v) in html
    assert f"{best.stiffness:,.1f}" in html and "<svg" in html
    for k, v in best.margins.items():
        assert re.search(rf"{v:.3f}</td>\s*<td[^>]*>{'PASS' if v >= 1 else 'FAIL'}", html), k
    page2 = tmp_path / "e.html"
    assert main(["evaluate", str(saved), "--report", str(page2)]) == 0
    d = evaluate_drive_design(load_problem(saved))
    html2 = page2.read_text(encoding="utf-8")
    assert f"{d.cost:,.0f} EUR" in html2 and "max_backlash" in html2


def test_infeasible_page_shows_the_closest(tmp_path, capsys):
    page = tmp_path / "i.html"
    path = ROOT / "problems" / "infeasible_laser_lm_problem.yaml"
    assert main(["solve", str(path), "--no-sensitivity", "--report", str(page)]) == 1
    html = page.read_text(encoding="utf-8")
    assert "Closest designs (no design fits)" in html and "FAIL" in html
