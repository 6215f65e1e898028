"""The second half of the 100 random machines, default against every combination of every axis (a
file of its own, so that pytest-xdist runs the two halves on two workers)."""

import pytest
from machinegen import check_default_equals_exhaustive
from test_joint import SEEDS, seed_params


@pytest.mark.parametrize("seed", seed_params(SEEDS[50:]))
def test_default_equals_every_combination_of_every_axis(seed, tmp_path):
    check_default_equals_exhaustive(seed, tmp_path)
