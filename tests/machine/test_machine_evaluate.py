"""axisopt machine evaluate: a machine of chosen parts.  Pinned to the joint optimum's parts it
gives the joint optimum's figures (one model serves solve and evaluate); a machine limit it misses
is shown, exit 1; an axis left with a choice is a one-line error, exit 2."""

import json
import re

import pytest
from machinegen import random_machine

from axisopt.cli import main
from axisopt.machine import load_machine, solve_machine
from axisopt.machine.evaluate import evaluate_machine

SLOTS = ("screw", "nut", "bearing", "guide")


def _pinned(text: str, md) -> str:
    """The machine text with each axis's catalog.require naming the parts of ``md``."""
    parts = {a.name: a.candidate.parts() for a in md.axes}
    out, axis = [], None
    for line in text.splitlines():
        m = re.match(r"^  (\w+):$", line)
        if m:
            axis = m.group(1)
        if line.strip().startswith("require:"):
            p = parts[axis]
            line = "        require: {" + ", ".join(f"{s}: [{p[s]}]" for s in SLOTS) + "}"
        elif line.startswith("                  bearing:"):
            continue
        out.append(line)
    return "\n".join(out) + "\n"


@pytest.fixture(scope="module")
def machine(tmp_path_factory):
    d = tmp_path_factory.mktemp("me")
    text = random_machine(4)
    p = d / "m.yaml"
    p.write_text(text)
    res = solve_machine(load_machine(p))
    pinned = d / "pinned.yaml"
    pinned.write_text(_pinned(text, res.best))
    return d, p, pinned, res


def test_the_optimum_pinned_evaluates_to_the_optimum(machine):
    _d, _p, pinned, res = machine
    ev = evaluate_machine(load_machine(pinned))
    md, best = ev.design, res.best
    assert md is not None and md.feasible
    assert md.k_tool == pytest.approx(best.k_tool, rel=1e-9)
    assert md.f_lowest == pytest.approx(best.f_lowest, rel=1e-9)
    assert md.cost == pytest.approx(best.cost, rel=1e-12)
    assert [a.candidate.parts() for a in md.axes] == [a.candidate.parts() for a in best.axes]


def test_cli_shows_a_missed_machine_limit_and_refuses_an_open_choice(machine, tmp_path, capsys):
    d, p, pinned, res = machine
    out = tmp_path / "e.json"
    assert (
        main(
            [
                "machine",
                "evaluate",
                str(pinned),
                "--json",
                str(out),
                "--report",
                str(tmp_path / "e.html"),
            ]
        )
        == 0
    )
    assert json.loads(out.read_text())["design"]["cost_eur"] == pytest.approx(res.best.cost)
    assert "Compliance at the tool, each link" in (tmp_path / "e.html").read_text()
    strict = tmp_path / "strict.yaml"
    k = min(res.best.k_tool) * 1e-6
    strict.write_text(
        pinned.read_text().replace(
            "min_tool_stiffness: ", f"min_tool_stiffness: {2 * k:.0f} N/um #"
        )
    )
    capsys.readouterr()
    assert main(["machine", "evaluate", str(strict)]) == 1
    assert "misses min_tool_stiffness" in capsys.readouterr().out
    assert main(["machine", "evaluate", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "catalog combinations" in err and "catalog.require" in err


def _with_preload(text: str, axis: str, value: str) -> str:
    """The machine text with ``nut_preload: value`` in axis ``axis``'s node."""
    head = f"  {axis}:\n    carried_by:"
    assert head in text
    return text.replace(head, f"  {axis}:\n    nut_preload: {value}\n    carried_by:", 1)


def test_the_machine_file_sets_each_nut_preload(machine, tmp_path):
    """An axis's nut_preload is the preload its nut is evaluated at: the optimum's own preload gives
    the optimum's figures; the nut's least preload gives that axis the axis model's stiffness at
    that preload (evaluated on the axis's own Design), and a machine stiffer than it in no
    direction."""
    from dataclasses import replace

    from axisopt.model import evaluate

    _d, _p, pinned, res = machine
    text = pinned.read_text()
    best = {a.name: a for a in res.best.axes}
    name = next(n for n, a in best.items() if a.candidate.design.nut["preload_min"] > 0)
    top = best[name].candidate.nut_preload
    p = tmp_path / "top.yaml"
    p.write_text(_with_preload(text, name, f"{top!r} N"))
    md = evaluate_machine(load_machine(p)).design
    assert md.k_tool == pytest.approx(res.best.k_tool, rel=1e-9)
    low = float(best[name].candidate.design.nut["preload_min"])
    assert low < top * 0.9
    p = tmp_path / "low.yaml"
    p.write_text(_with_preload(text, name, f"{low!r} N"))
    ev = evaluate_machine(load_machine(p))
    if ev.design is None:  # the axis misses one of its own limits at the least preload: named
        assert [n for n, _ in ev.failed] == [name]
        return
    a = next(x for x in ev.design.axes if x.name == name)
    assert a.candidate.nut_preload == pytest.approx(low)
    axial = a.roles.index("axial")
    design = replace(best[name].candidate.design, nut_preload=low)
    k_axis = float(min(evaluate(design, use_casadi=False)["k_total"]))
    tw = load_machine(p).by_name[name].problem.axis.twin_drive
    if tw is not None:
        k_axis /= tw.force_share**2 + (1 - tw.force_share) ** 2
    assert a.k_axis[axial] == pytest.approx(k_axis, rel=1e-9)
    assert a.k_axis[axial] < best[name].k_axis[axial]
    assert all(k <= kb * (1 + 1e-12) for k, kb in zip(ev.design.k_tool, res.best.k_tool))


def test_a_nut_preload_outside_the_nut_or_in_a_solve_is_one_line_exit_2(machine, tmp_path, capsys):
    _d, p, pinned, res = machine
    name = res.best.axes[0].name
    hi = float(res.best.axes[0].candidate.design.nut["preload_max"])
    bad = tmp_path / "bad.yaml"
    bad.write_text(_with_preload(pinned.read_text(), name, f"{2 * hi:.0f} N"))
    capsys.readouterr()
    assert main(["machine", "evaluate", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert f"axes.{name}.nut_preload" in err and "outside nut" in err and str(bad) in err
    unit = tmp_path / "unit.yaml"
    unit.write_text(_with_preload(pinned.read_text(), name, "3000"))
    assert main(["machine", "evaluate", str(unit)]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    solve = tmp_path / "solve.yaml"
    solve.write_text(_with_preload(p.read_text(), name, "1000 N"))
    assert main(["machine", "solve", str(solve)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "machine evaluate" in err and "nut_preload" in err
