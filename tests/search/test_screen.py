"""The faster screening paths against plain references: the drive stage evaluated structured over
(survivor, drive pair) against the model evaluated per (combination, drive) row on the flat layout,
the screening over cache-sized sub-blocks against one block, and mathx.power's products against
numpy's power; random catalogs, fixed seeds."""

import numpy as np
import pytest
from test_bounds import _problem

from axisopt import mathx as mx
from axisopt import model
from axisopt.model.accuracy import BUDGET_OUTPUTS
from axisopt.search import screen as core
from axisopt.search.bounds import screen_ok
from axisopt.search.parts import build_space
from axisopt.search.screen import convex_margin_bound
from axisopt.search.task.constraints import build_constraints
from axisopt.search.task.objective import objective_spec
from axisopt.search.task.space import DRIVE_KEYS


def _reference_drives(space, mounting, constraints, phases, nn, bb, gg):
    """Each (survivor, drive) row on its own: params_flat and drive_response per expanded row
    (float64)."""
    D = space.n_drives
    cons = [c for c in constraints if c.key in DRIVE_KEYS]
    ne, be = np.repeat(nn, D), np.repeat(bb, D)
    ge = (gg[:, None] * D + np.arange(D)[None]).ravel()
    p = space.params_flat(mounting, ne, be, ge)
    lo, hi = space.preload_lo[ne][:, None], space.preload_hi[ne][:, None]
    ok = np.ones(len(ne), dtype=bool)
    with np.errstate(all="ignore"):
        out_lo, out_hi = model.drive_response(p, lo), model.drive_response(p, hi)
        for c in cons:
            if c.convex:
                ub = np.asarray(convex_margin_bound(c, out_lo, out_hi, phases))
                ok &= (ub >= c.limit * (1.0 - core.SCREEN_RTOL)).reshape(len(ne))
            else:
                ok &= screen_ok(c, out_lo).reshape(len(ne))
    return ne[ok], be[ok], ge[ok], np.repeat(np.arange(len(nn)), D)[ok]


@pytest.mark.parametrize("seed", [1, 3, 5])
def test_structured_drive_stage_equals_rows(seed, monkeypatch):
    p = _problem(seed)
    sp, cons = build_space(p), build_constraints(p)
    assert sp.m_arr is not None and sp.n_drives > 1
    rng = np.random.default_rng(seed)
    _, N, B, G = sp.shape
    K = 300
    nn, bb = rng.integers(0, N, K), rng.integers(0, B, K)
    gg = rng.integers(0, G // sp.n_drives, K)
    monkeypatch.setattr(core, "DRIVE_CHUNK", 7 * sp.n_drives)  # several chunks
    for mounting in sp.mountings:
        phases = sp.problem.axis_for(mounting).phases
        n, b, g, bnd = core._screen_drives(
            sp, mounting, cons, phases, nn, bb, gg, np.arange(K, dtype=float)
        )
        rn, rb, rg, rk = _reference_drives(sp, mounting, cons, phases, nn, bb, gg)
        assert 0 < len(rn) < K * sp.n_drives, "the drive limits keep some pairs and drop others"
        np.testing.assert_array_equal(n, rn)
        np.testing.assert_array_equal(b, rb)
        np.testing.assert_array_equal(g, rg)
        np.testing.assert_array_equal(bnd, rk)  # each pair keeps its mechanical survivor's bound


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_sub_blocks_keep_the_survivors(seed, monkeypatch):
    p = _problem(seed)
    sp, cons = build_space(p), build_constraints(p)
    spec = objective_spec(p.objective.mode, p)
    idx, bound, _ = core.screen(sp, cons, spec)
    assert len(idx)
    _, _, B, G = sp.shape
    monkeypatch.setattr(core, "CACHE_BLOCK", B * G // sp.n_drives)  # one nut per evaluation
    idx1, bound1, _ = core.screen(sp, cons, spec)
    np.testing.assert_array_equal(idx1, idx)
    np.testing.assert_array_equal(bound1, bound)
    # and on a nut index array with a premask, as the block search calls it
    nuts = np.array([0, 2, 3])
    premask = np.random.default_rng(seed).random((3, B)) < 0.7
    i1, b1 = core.screen_nuts(sp, 0, nuts, cons, spec, premask=premask)
    monkeypatch.setattr(core, "CACHE_BLOCK", 10**9)
    i2, b2 = core.screen_nuts(sp, 0, nuts, cons, spec, premask=premask)
    np.testing.assert_array_equal(i1, i2)
    np.testing.assert_array_equal(b1, b2)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_power_products_match_numpy(dtype):
    x = np.random.default_rng(0).uniform(1e-3, 1e3, 10_000).astype(dtype)
    eps = np.finfo(dtype).eps
    for e in (2, 3, 1.5, 2.5):
        np.testing.assert_allclose(mx.power(x, e), x**e, rtol=4 * eps)
        assert mx.power(x, e).dtype == dtype
    assert mx.power(2.0, 3) == 8.0


def test_chain_outputs_are_what_chain_false_leaves_out():
    p = _problem(1)
    sp = build_space(p)
    m = sp.mountings[0]
    ps = sp.params_structured(m, slice(0, 3), dtype=np.float32)
    lo = sp.preload_lo[:3].reshape(-1, 1, 1, 1).astype(np.float32)
    x = sp.positions(m)[-1:]
    full = model.axis_response(ps, x, m, lo, sp.request)
    part = model.axis_response(ps, x, m, lo, sp.request.but(chain=False))
    # the positioning budget (model.accuracy) is in the chain block, and only where a limit reads it
    budget = set() if sp.request.budget else set(BUDGET_OUTPUTS)
    assert set(full) - set(part) == model.CHAIN_OUTPUTS - budget
    with_budget = model.axis_response(ps, x, m, lo, sp.request.but(budget=True))
    assert set(with_budget) - set(part) == model.CHAIN_OUTPUTS
    assert all(np.array_equal(full[k], part[k]) for k in part if k != "duty_torques")
