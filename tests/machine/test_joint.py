"""The joint machine search against every combination of every axis (small catalogs), and never
worse than the sequential sizing on the shipped machines."""

import pytest
from machinegen import check_default_equals_exhaustive, random_machine

from axisopt.machine import load_machine, solve_machine
from axisopt.machine.templates import SHIPPED, TEMPLATES

SEEDS = range(100)
# About 2.6 s of CPU a seed (0.4 to 5 s): the default run solves the first 25 (17 with a
# counterweight, 8 with the non-monotone carrier, 8 with a twin drive, 5 with two chains), the other
# 75 are marked slow (`python -m pytest -m slow`, .ci/run's second step): every seed still runs in
# CI.
FAST_SEEDS = 25


def seed_params(seeds):
    """``seeds`` as parameters, those from FAST_SEEDS on marked slow."""
    return [s if s < FAST_SEEDS else pytest.param(s, marks=pytest.mark.slow) for s in seeds]


# the other half in test_joint_more.py (xdist runs the two apart)
@pytest.mark.parametrize("seed", seed_params(SEEDS[:50]))
def test_default_equals_every_combination_of_every_axis(seed, tmp_path):
    check_default_equals_exhaustive(seed, tmp_path)


def test_the_random_machines_cover_counterweights_twin_drives_and_the_non_monotone_case(tmp_path):
    """The 100 random machines hold each case the issue names, with and without a counterweight
    and a twin drive (and both, and neither), and every machine objective."""
    from axisopt.machine.offers import monotone_in_load

    seen = dict.fromkeys(
        (
            "counterweight",
            "no counterweight",
            "below a counterweighted axis",
            "twin drive",
            "no twin drive",
            "counterweight and twin drive",
            "neither",
            "two chains",
        ),
        0,
    )
    objectives = set()
    for seed in SEEDS:
        path = tmp_path / f"m{seed}.yaml"
        path.write_text(random_machine(seed))
        m = load_machine(path)
        chains = m.branches()
        cw = any(a.problem.axis.counterbalance is not None for a in m.axes)
        twin = any(a.problem.axis.twin_drive is not None for a in m.axes)
        seen["counterweight"] += cw
        seen["no counterweight"] += not cw
        seen["below a counterweighted axis"] += any(
            not monotone_in_load(c[i - 1]) for c in chains for i in range(1, len(c))
        )
        seen["twin drive"] += twin
        seen["no twin drive"] += not twin
        seen["counterweight and twin drive"] += cw and twin
        seen["neither"] += not cw and not twin
        seen["two chains"] += len(chains) > 1
        objectives.add(m.objective)
    assert min(seen.values()) >= 15, seen
    assert objectives == {"cost", "tool_stiffness", "frequency", "moving_mass"}


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
