"""Levels of a factor logged with jitter (identify.levels): readings meant at one level become that
level's mean, distinct levels stay apart; the cases are built here with known levels and jitter."""

from __future__ import annotations

import numpy as np
import pytest

from axisopt.identify.levels import cluster_levels


def test_jittered_speeds_become_their_level_means():
    rng = np.random.default_rng(7)
    levels = np.array([0.01, 0.1, 0.5])  # m/s, a decade apart and more
    meant = np.repeat(levels, 6)
    logged = meant * (1 + rng.uniform(-0.005, 0.005, meant.size))  # a speed held to +-0.5 %
    perm = rng.permutation(meant.size)
    got = cluster_levels(logged[perm], "velocity")
    for lv in levels:
        group = np.isclose(meant[perm], lv)
        assert np.all(got[group] == got[group][0])  # one value per level
        assert got[group][0] == pytest.approx(np.mean(logged[perm][group]), rel=1e-14)  # its mean
    assert len(np.unique(got)) == 3


def test_positions_join_within_a_millimetre_on_a_long_stroke():
    # 0, 400 and 800 mm each logged +-1 mm apart: 0.4 % of the 800 mm range joins them
    pos = np.array([0.0, 0.001, 0.4, 0.401, 0.399, 0.8, 0.799])
    got = cluster_levels(pos, "position")
    np.testing.assert_allclose(
        got, [0.0005, 0.0005, 0.4, 0.4, 0.4, 0.7995, 0.7995], rtol=0, atol=1e-15
    )


def test_velocity_levels_are_relative_only():
    # 1 mm/s and 2 mm/s are twice apart, a different level, though within 0.4 % of a 1 m/s range
    v = np.array([0.001, 0.002, 1.0])
    np.testing.assert_array_equal(cluster_levels(v, "velocity"), v)
    assert (
        len(np.unique(cluster_levels(v, "load"))) == 2
    )  # a non-velocity factor joins them by the range


def test_exact_repeats_and_short_input_stay():
    np.testing.assert_array_equal(cluster_levels([5.0, 5.0, 9.0]), [5.0, 5.0, 9.0])
    np.testing.assert_array_equal(cluster_levels([3.0]), [3.0])
