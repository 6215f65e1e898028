"""The shipped machines: templates equal the shipped files, every one solves, the joint optimum is never worse
than the sequential sizing; the tool-point stiffness chain adds compliances in series."""

import json

import pytest

from axisopt.cli import main
from axisopt.machine import load_machine, solve_machine
from axisopt.machine.templates import SHIPPED, TEMPLATES


@pytest.mark.parametrize("kind", list(TEMPLATES))
def test_template_is_the_shipped_machine(kind, tmp_path):
    out = tmp_path / "m.yaml"
    assert main(["init", "machine", "--kind", kind, "--out", str(out)]) == 0
    with open(f"problems/machines/{SHIPPED[kind]}") as f:
        assert out.read_text() == f.read()


@pytest.mark.slow
@pytest.mark.parametrize("kind", list(TEMPLATES))
def test_shipped_machine_joint_never_worse_than_sequential(kind):
    m = load_machine(f"problems/machines/{SHIPPED[kind]}")
    res = solve_machine(m)
    assert res.status == "optimal" and res.best.feasible
    seq = res.sequential
    assert seq is not None
    if seq.feasible:
        assert res.gain >= -1e-9 * max(1.0, abs(res.best.value(m.objective)))
    # the stiffness at the tool: every link's compliance (axis part and frame) in series, by hand
    for d in range(3):
        c = sum(1.0 / a.k_axis[d] + 1.0 / a.k_frame[d] for a in res.best.axes)
        assert res.best.k_tool[d] == pytest.approx(1.0 / c, rel=1e-12)
    assert res.best.f_dunkerley <= res.best.f_lowest * (1 + 1e-12)


def test_machine_json(tmp_path):
    out = tmp_path / "vmc.json"
    assert main(["machine", "solve", "problems/machines/vmc_machine.yaml", "--json", str(out)]) == 0
    d = json.loads(out.read_text())
    assert d["status"] == "optimal"
    best = d["best"]
    assert [a["name"] for a in best["axes"]] == ["Y", "X", "Z"]
    assert best["lowest_frequency_hz"] >= 60.0 and best["dunkerley_hz"] <= best["lowest_frequency_hz"]
    assert min(best["k_tool_n_per_um"].values()) >= 40.0
    assert d["sequential"]["misses"]  # the designer's sizing misses the frequency limit here
