"""The joint machine search against every combination of every axis (small catalogs), and the sequential sizing."""

import pytest
from machinegen import check_default_equals_exhaustive, random_machine

from axisopt.machine import load_machine

SEEDS = range(100)


@pytest.mark.parametrize("seed", SEEDS[:50])  # the other half in test_joint_more.py (xdist runs the two apart)
def test_default_equals_every_combination_of_every_axis(seed, tmp_path):
    check_default_equals_exhaustive(seed, tmp_path)


def test_the_random_machines_cover_counterweights_twin_drives_and_the_non_monotone_case(tmp_path):
    from axisopt.machine.offers import monotone_in_load

    seen = {"counterweight": 0, "below a counterweighted axis": 0, "twin drive": 0, "two chains": 0}
    for seed in SEEDS:
        path = tmp_path / f"m{seed}.yaml"
        path.write_text(random_machine(seed))
        m = load_machine(path)
        chains = m.branches()
        seen["counterweight"] += any(a.problem.axis.counterbalance is not None for a in m.axes)
        seen["below a counterweighted axis"] += any(not monotone_in_load(c[i - 1]) for c in chains
                                                    for i in range(1, len(c)))
        seen["twin drive"] += any(a.problem.axis.twin_drive is not None for a in m.axes)
        seen["two chains"] += len(chains) > 1
    assert min(seen.values()) >= 15, seen
