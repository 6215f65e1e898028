"""The one-hot formulation shared by Bonmin and SCIP: the slot tables, the part parameters as
binary-weighted catalog columns (exact at integer points) and the recovery of a design from a
solver's point."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import casadi as ca
import numpy as np
import pytest

from axisopt.problem import load_problem
from axisopt.search.minlp import formulation
from axisopt.search.minlp.formulation import (
    SLOTS,
    integral,
    one_hot_params,
    one_hot_symbols,
    recover,
    slot_params,
)
from axisopt.search.parts import build_space

TEACHING = Path(__file__).resolve().parents[3] / "problems" / "teaching_problem.yaml"


@pytest.fixture(scope="module")
def space():
    return build_space(load_problem(TEACHING))


def test_slot_tables_have_one_value_per_part(space):
    _, N, B, G = space.shape
    sizes = {"nut": N, "bearing": B, "guide": G}
    table = slot_params(space, space.mountings[0])
    assert "duty" not in table and {s for s, _v in table.values()} <= set(sizes) | {"axis"}
    for slot, vals in table.values():
        if slot == "axis":
            assert isinstance(vals, float)
        else:
            assert vals.shape == (sizes[slot],)


def test_one_hot_mixture_is_the_chosen_parts_at_an_integer_point(space):
    mounting = space.mountings[0]
    _, N, B, G = space.shape
    z = one_hot_symbols(space)
    zcol = ca.vertcat(*(z[s] for s in SLOTS))
    exact = one_hot_params(space, mounting, z)
    floored = one_hot_params(space, mounting, z, floor=1e-6)
    assert exact["duty"] == space.problem.axis_for(mounting).phases
    table = slot_params(space, mounting)
    pick = {"nut": N - 1, "bearing": B // 2, "guide": G // 3}
    point = np.concatenate([np.eye(n)[pick[s]] for s, n in zip(SLOTS, (N, B, G))])
    for name, (slot, vals) in table.items():
        if slot == "axis":
            assert exact[name] == vals
            continue
        at = float(ca.Function("p", [zcol], [exact[name]])(point))
        assert at == vals[pick[slot]]
        floor = float(ca.Function("p", [zcol], [floored[name]])(point))
        assert floor == pytest.approx(
            vals[pick[slot]] + 1e-6 * np.mean(vals), rel=1e-12, abs=1e-300
        )


def test_integral_point_needs_a_one_in_every_slot():
    z = {
        "nut": np.array([0.0, 1.0]),
        "bearing": np.array([1.0 - 1e-8]),
        "guide": np.array([0.0, 1.0, 0.0]),
    }
    assert integral(z)
    assert not integral({**z, "guide": np.array([0.5, 0.5, 0.0])})


def test_recover_moves_the_preload_into_the_limits(monkeypatch):
    """The largest binary per slot is the part; a preload that misses a limit is moved by the first
    move that meets it (clipped to the nut's range), else None."""
    space = SimpleNamespace(
        shape=(2, 2, 1, 3), preload_lo=np.array([100.0, 200.0]), preload_hi=np.array([300.0, 400.0])
    )
    monkeypatch.setattr(formulation, "feasible_at", lambda sp, combo, pre, cons: pre <= 350.0)
    z = {"nut": [0.0, 1.0], "bearing": [1.0], "guide": [0.0, 0.0, 1.0]}
    combo = int(np.ravel_multi_index((1, 1, 0, 2), space.shape))
    got = recover(space, 1, z, lambda lo, hi: lo + 0.5 * (hi - lo), ())
    assert (got.combination, got.proposed, got.preload) == (combo, 300.0, 300.0)
    got = recover(space, 1, z, lambda lo, hi: hi, (), moves=(1.0, -1e-3, -0.3, -0.4))
    assert (got.combination, got.proposed, got.preload) == (combo, 400.0, pytest.approx(340.0))
    assert recover(space, 1, z, lambda lo, hi: hi, (), moves=(-1e-6,)).preload is None
