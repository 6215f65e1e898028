"""An infeasible screw answer whose own advice finds no design change proposes another drive type
(search.drivedefault.type_change, issue 54): the 2 t boring table at 45 m/min rapids (no screw of
the catalogs turns fast enough at 3 m, held at both ends, with a nut that carries the cut) gets a
rack and pinion with the rapid speed it reaches, and the problem so changed re-solves to a
design."""

from __future__ import annotations

from pathlib import Path

import axisopt
from axisopt.search.drivedefault import round_down

ROOT = Path(__file__).resolve().parents[2]


def test_round_down_keeps_three_significant_figures():
    assert round_down(39.98) == 39.9
    assert round_down(0.012349) == 0.0123
    assert round_down(450.0) == 450.0


def test_infeasible_boring_table_gets_a_drive_type_that_re_solves(tmp_path):
    text = (ROOT / "problems" / "boring_table_problem.yaml").read_text(encoding="utf-8")
    fast = text.replace("max_speed: 20 m/min", "max_speed: 45 m/min", 1)
    path = tmp_path / "boring45.yaml"
    path.write_text(fast, encoding="utf-8")
    # without sensitivities the screw answer runs no advice of its own: the drive type's is the one
    res = axisopt.solve(path, sensitivities=False)
    assert res.status == "infeasible"
    changes = {c.key: c for c in res.infeasibility.design_changes}
    types = changes["search.drive_types"]
    assert types.edit == "add" and types.values == ("screw", "rack_pinion")
    speed = changes.get("axis.max_speed")
    assert speed is not None and 20.0 < speed.to < 45.0 and speed.value == 45.0
    # the change made in the problem file, solved again: a rack-and-pinion design
    changed = fast.replace("max_speed: 45 m/min", f"max_speed: {speed.to:g} m/min", 1)
    changed += "search:\n  drive_types: [screw, rack_pinion]\n"
    path.write_text(changed, encoding="utf-8")
    again = axisopt.solve(path)
    assert again.best is not None and again.best.drive_type == "rack_pinion"
    assert types.note.startswith("a rack and pinion: rack " + again.best.parts["rack"])
