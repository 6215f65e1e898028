"""The joint machine search against every combination of every axis (small catalogs), and the sequential sizing."""

import pytest
from machinegen import random_machine

from axisopt.machine import load_machine, solve_machine

SEEDS = range(100)


@pytest.mark.parametrize("seed", SEEDS)
def test_default_equals_every_combination_of_every_axis(seed, tmp_path):
    path = tmp_path / "machine.yaml"
    path.write_text(random_machine(seed))
    m = load_machine(path)
    a = solve_machine(m)
    b = solve_machine(m, "exhaustive")
    assert a.status == b.status
    if b.best is None:
        return
    va, vb = a.best.value(m.objective), b.best.value(m.objective)
    assert va == pytest.approx(vb, rel=1e-9)
    assert a.best.feasible and b.best.feasible
    # never worse than the sequential sizing where that one meets every limit
    if a.sequential is not None and a.sequential.feasible:
        assert a.gain >= -1e-9 * max(1.0, abs(va))
