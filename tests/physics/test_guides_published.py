"""Physics formulas against published numbers (source named per test; tolerance = half a unit of the
last printed digit unless a comment explains otherwise)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from axisopt.physics import guides

# Seed Table 1 (Wang et al. [27]): k_n / k_t [N/mm] and the printed ratio column (k_t/k_n, 9
# digits).
TABLE1 = [(167, 120, 0.718562874), (156, 112, 0.717948718), (182, 131, 0.71978022)]


@pytest.mark.published
@pytest.mark.parametrize(("kn", "kt", "ratio"), TABLE1)
def test_guide_table1_rows(kn, kt, ratio):
    assert kt / kn == pytest.approx(ratio, abs=5e-10)
    # The text's 0.71 is the ratio truncated to two digits (rounded it would be 0.72): each row lies
    # in [0.71, 0.72), and the 0.71 default therefore under-predicts k_t by 1.1-1.4 %.
    assert math.floor(100 * kt / kn) / 100 == guides.TANGENTIAL_NORMAL_RATIO
    assert guides.guide_tangential_stiffness(kn * 1e3) == pytest.approx(kt * 1e3, rel=0.015)


# Seed Table 9 (after [16]), ball linear guideway 35 mm: friction [N] at block load 0/10/20/30 kN
# and v = 5000 and 40000 mm/min.  F0 + mu N + c_v v fitted (least squares, range midpoints) to 0-20
# kN lands in every printed range there.  The table grows faster than linearly above 20 kN: at 30 kN
# the linear model under-predicts by ~25 N; that limitation is pinned, not hidden.  Fitted mu is in
# the 0.001-0.005 band.
TABLE9_BALL35 = {
    5000: [(15, 20), (30, 35), (50, 55), (95, 100)],
    40000: [(30, 45), (40, 55), (60, 75), (100, 115)],
}


@pytest.mark.published
def test_guide_friction_table9_ball35():
    rows, y = [], []
    for v_mm_min, ranges in TABLE9_BALL35.items():
        for load_kn, (lo, hi) in zip((0, 10, 20), ranges[:3], strict=True):
            rows.append((1.0, load_kn * 1e3, v_mm_min / 60e3))
            y.append((lo + hi) / 2)
    f0, mu, cv = np.linalg.lstsq(np.array(rows), np.array(y), rcond=None)[0]
    assert 0.001 < mu < 0.005 and f0 > 0 and cv > 0
    for v_mm_min, ranges in TABLE9_BALL35.items():
        for load_kn, (lo, hi) in zip((0, 10, 20, 30), ranges, strict=True):
            f = guides.guide_friction_force(f0, mu, cv, load_kn * 1e3, v_mm_min / 60e3)
            if load_kn < 30:
                assert lo <= f <= hi
            else:
                assert lo - 35 < f < lo
    mirrored = guides.guide_friction_force(f0, mu, cv, -1e4, -0.5)
    assert mirrored == guides.guide_friction_force(f0, mu, cv, 1e4, 0.5)
