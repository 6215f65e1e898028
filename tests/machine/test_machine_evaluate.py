"""axisopt machine evaluate: a machine of chosen parts.  Pinned to the joint optimum's parts it gives the joint
optimum's figures (one model serves solve and evaluate); a machine limit it misses is shown, exit 1; an axis
left with a choice is a one-line error, exit 2."""

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
