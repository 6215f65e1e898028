"""An infeasible machine names the axis with no design of its own, and its output stays whole."""

from test_tool_stiffness_published import MACHINE

from axisopt.cli import main
from axisopt.machine import load_machine, solve_machine


def test_an_axis_without_a_design_is_named(tmp_path, capsys):
    # X (the carried axis) asks for a life its parts do not reach at its loads
    head, sep, x_part = MACHINE.partition("  X:\n")
    text = head + sep + x_part.replace("min_life: 1000 h", "min_life: 250000 h")
    p = tmp_path / "m.yaml"
    p.write_text(text)
    res = solve_machine(load_machine(p))
    assert res.status == "infeasible" and res.best is None
    named = [n for n in res.notes if n.startswith("axis ")]
    assert len(named) == 1 and named[0].startswith("axis X has no design")
    assert main(["machine", "solve", str(p)]) == 1
    out = capsys.readouterr().out
    assert "axis X has no design meeting its own limits" in out
    assert "nominal joint combinations not counted" in out and "offers kept none" in out
    # the same machine with X's life within reach: no such note
    p.write_text(MACHINE)
    res = solve_machine(load_machine(p))
    assert res.best is not None and not [n for n in res.notes if n.startswith("axis ")]
