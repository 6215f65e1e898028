"""build_space reuses the filtered part tables of an earlier problem on the same catalog object with
the same restrictions (a study's cases), while each problem keeps its own axis and parameter cache;
a change of restrictions or preload range builds anew.  Reference: the uncached build."""

from pathlib import Path

import numpy as np
import pytest

from axisopt.problem import load_problem
from axisopt.search import parts as S

ROOT = Path(__file__).resolve().parents[2]


def _eq(x, y):
    # a column may hold NaN (no vendor value)
    return np.array_equal(x, y, equal_nan=x.dtype.kind == "f")


def _same(a, b):
    assert a.shape == b.shape and a.drives == b.drives
    assert np.array_equal(a.preload_lo, b.preload_lo) and np.array_equal(a.preload_hi, b.preload_hi)
    for d1, d2 in ((a.s_arr, b.s_arr), (a.n_arr, b.n_arr), (a.b_arr, b.b_arr), (a.g_arr, b.g_arr)):
        assert d1.keys() == d2.keys() and all(_eq(d1[k], d2[k]) for k in d1)


def test_cases_share_tables_not_axes():
    p = load_problem(ROOT / "problems" / "vmc_x_problem.yaml")
    q = p.with_limit("max_cost", 5000.0)
    from dataclasses import replace

    q = replace(q, axis=replace(q.axis, stroke=0.6))
    a, b = S.build_space(p), S.build_space(q)
    assert a.problem is p and b.problem is q and a._cache is not b._cache
    assert b.n_arr is a.n_arr  # shared, read-only
    _same(b, S._build_space(q))
    assert b.positions(b.mountings[0])[-1] != a.positions(a.mountings[0])[-1]  # each its own axis


def test_other_restrictions_build_anew():
    p = load_problem(ROOT / "problems" / "vmc_x_problem.yaml")
    from dataclasses import replace

    q = replace(p, preload_max=0.5 * float(S.build_space(p).preload_hi.max()))
    a, b = S.build_space(p), S.build_space(q)
    assert b.n_arr is not a.n_arr or not np.array_equal(a.preload_hi, b.preload_hi)
    _same(b, S._build_space(q))
    assert b.preload_hi.max() <= q.preload_max


def test_what_prunes_drives_builds_anew(tmp_path):
    """The drive pruning reads the cycle's top speed, the speed margins and the lost-motion limit
    (parts._add_drives): a case differing in one of them must not take a space pruned for another
    (issue 39: a laser case's space, built without reductions under max_backlash 0, was reused for a
    lathe case that admits 10 um)."""
    src = ROOT / "problems" / "lathe_z_problem.yaml"
    p = load_problem(src)  # admits 10 um: gearboxes are formed
    tight = p.with_limit("max_backlash", 1e-9)  # no gearbox's backlash fits
    assert "max_speed: 40 m/min" in src.read_text(encoding="utf-8")
    fast_file = tmp_path / "fast.yaml"  # 60 m/min: fewer (motor, gearbox) pairs fast enough
    fast_file.write_text(
        src.read_text(encoding="utf-8").replace("max_speed: 40 m/min", "max_speed: 60 m/min"),
        encoding="utf-8",
    )
    fast = load_problem(fast_file)
    assert fast.catalog is p.catalog
    a = S.build_space(p)
    for q in (tight, fast):
        b = S.build_space(q)
        assert len(b.drives) < len(a.drives)
        _same(b, S._build_space(q))
    assert any(ri is not None for _, _, ri in a.drives)
    # every reduction with backlash is left out (the zero-gap belt stages of issue 54 have none:
    # they stay)
    backlash = p.catalog.rows("reductions").number("backlash")
    assert S.build_space(tight).reductions_by_backlash == int(np.count_nonzero(backlash > 0))


def test_relaxing_a_backlash_limit_that_left_reductions_out_builds_anew(monkeypatch, tmp_path):
    """The sensitivity of max_backlash re-solves on the relaxed problem's own space when the limit
    left reductions out (a relaxed limit may admit them; the space prunes on it), and on the same
    space when it left none out."""
    from axisopt.search import sensitivity, solve

    # the teaching problem with reductions admitted (the shipped file leaves them out since
    # issue 54)
    f = tmp_path / "teaching.yaml"
    f.write_text(
        (ROOT / "problems" / "teaching_problem.yaml")
        .read_text(encoding="utf-8")
        .replace("  reductions: no\n", ""),
        encoding="utf-8",
    )
    # a limit just under the least lost motion it leaves out: relaxed by 10 % it admits that
    # reduction, so the relaxed problem is searched on its own space (a limit whose relaxation
    # admits nothing new is not re-solved: test_sensitivity.py)
    least = S.build_space(load_problem(f).with_limit("max_backlash", 1e-6)).backlash_left_least
    assert np.isfinite(least)
    p = load_problem(f).with_limit("max_backlash", least / 1.05)
    built = []
    real = S.build_space
    monkeypatch.setattr(
        S, "build_space", lambda q: built.append(q.limit_map.get("max_backlash")) or real(q)
    )
    res = solve(p, sensitivities=False)
    space = real(p)
    # the 8-arcmin NPT rows left out at 1 um
    assert res.best is not None and space.reductions_by_backlash > 0
    built.clear()
    sensitivity.limit_sensitivities(p, res, space=space)
    # the relaxed max_backlash built its own space
    assert pytest.approx(1.1 * least / 1.05) in built
