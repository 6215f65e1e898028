"""The machine templates (machine.templates): each equals its shipped machine file; the shipped VMC
machine solves to its JSON."""

import json

import pytest

from axisopt.cli import main
from axisopt.machine.templates import SHIPPED, TEMPLATES


@pytest.mark.parametrize("kind", list(TEMPLATES))
def test_template_is_the_shipped_machine(kind, tmp_path):
    out = tmp_path / "m.yaml"
    assert main(["init", "machine", "--kind", kind, "--out", str(out)]) == 0
    with open(f"problems/machines/{SHIPPED[kind]}") as f:
        assert out.read_text() == f.read()


def test_machine_json(tmp_path):
    out = tmp_path / "vmc.json"
    assert main(["machine", "solve", "problems/machines/vmc_machine.yaml", "--json", str(out)]) == 0
    d = json.loads(out.read_text())
    assert d["status"] == "optimal"
    best = d["best"]
    assert [a["name"] for a in best["axes"]] == ["Y", "X", "Z"]
    assert (
        best["lowest_frequency_hz"] >= 60.0 and best["dunkerley_hz"] <= best["lowest_frequency_hz"]
    )
    assert min(best["k_tool_n_per_um"].values()) >= 40.0
    assert d["sequential"]["misses"]  # the designer's sizing misses the frequency limit here
