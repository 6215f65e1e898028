"""The twin-drive gantry model (axisopt.physics.gantry) against closed-form answers.

No vendor publishes a worked twin-drive example; the lumped model follows the structure of Teo et
al., Mechatronics 17 (2007) and Garcia-Herreros et al., Control Eng. Practice 21 (2013)
(translation + yaw, the drives' axial stiffnesses at +/-L/2).  Its closed-form limits: the load at
the centre on equal drives gives two independent halves (each side a single-DOF axis with half the
mass, and the racking mode sqrt(k_theta / J)); one drive alone leaves a free rigid body on one
spring (a zero mode and omega^2 = k (1/m + d^2/J), the mass reduced to the spring's point); the
general 2x2 eigenvalues against numpy's eigenvalues of M^-1 K.
"""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import gantry as pg
from axisopt.physics.dynamics import axial_natural_frequency

M_B, J_B, M_C, L = 900.0, 363.0, 400.0, 2.2


def test_load_at_centre_is_two_independent_halves():
    k = 2.0e8
    f1, f2 = pg.gantry_frequencies(M_B, J_B, M_C, 0.0, k, k, L)
    half = axial_natural_frequency(k, 0.5 * (M_B + M_C))  # one side, half the mass
    racking = math.sqrt(pg.yaw_stiffness(k, k, L) / J_B) / (2.0 * math.pi)
    assert sorted((float(f1), float(f2))) == pytest.approx(sorted((half, racking)), rel=1e-12)
    # and the shares: half each
    assert pg.side_mass_share(M_B, M_C, 0.0, L) == pytest.approx((0.5 * (M_B + M_C),) * 2)
    assert pg.side_force_share(6e3, 0.0, L) == pytest.approx((3e3, 3e3))


def test_yaw_stiffness_closed_form():
    # k_theta = (k1 + k2) (L/2)^2 + k_g
    assert pg.yaw_stiffness(1e8, 3e8, 2.0, 5e6) == pytest.approx(4e8 * 1.0 + 5e6)


def test_one_drive_alone_is_a_free_rigid_body_on_one_spring():
    # rigid-body limit: k2 = 0, no guides: one zero mode; the other omega^2 = k1 (1/m + d^2/J) with
    # the carriage at the centre (d = L/2 from the centre of mass)
    k1 = 1.5e8
    w1, w2 = pg.gantry_eigenvalues(M_B, J_B, M_C, 0.0, k1, 0.0, L)
    assert float(w1) == pytest.approx(0.0, abs=1e-6)
    assert float(w2) == pytest.approx(k1 * (1.0 / (M_B + M_C) + (0.5 * L) ** 2 / J_B), rel=1e-12)


def test_stiff_drives_rigid_limit():
    # both drives very stiff: both frequencies grow as sqrt(k) (no finite rigid-body mode is left)
    lo = np.array(pg.gantry_frequencies(M_B, J_B, M_C, 0.7, 1e8, 1e8, L))
    hi = np.array(pg.gantry_frequencies(M_B, J_B, M_C, 0.7, 1e12, 1e12, L))
    assert hi / lo == pytest.approx([100.0, 100.0], rel=1e-9)


@pytest.mark.parametrize("y", [-0.9, -0.3, 0.0, 0.5, 0.9])
@pytest.mark.parametrize("k2", [1.2e8, 2e8, 3.1e8])
def test_eigenvalues_match_generalized_eigensolver(y, k2):
    m11, m12, m22, k11, k12, k22 = pg.gantry_matrices(M_B, J_B, M_C, y, 2e8, k2, L, 4e7)
    mass, stiff = np.array([[m11, m12], [m12, m22]]), np.array([[k11, k12], [k12, k22]])
    ref = np.sort(np.linalg.eigvals(np.linalg.solve(mass, stiff)).real)
    got = pg.gantry_eigenvalues(M_B, J_B, M_C, y, 2e8, k2, L, 4e7)
    assert [float(g) for g in got] == pytest.approx(list(ref), rel=1e-10)


@pytest.mark.parametrize("y", np.linspace(-1.1, 1.1, 7))
def test_shares_sum_to_the_total_at_every_position(y):
    f1, f2 = pg.side_force_share(6e3, y, L)
    m1, m2 = pg.side_mass_share(M_B, M_C, y, L)
    assert f1 + f2 == pytest.approx(6e3)
    assert m1 + m2 == pytest.approx(M_B + M_C)
    # the moment about the centre: the two reactions balance the load at y
    assert (f2 - f1) * 0.5 * L == pytest.approx(6e3 * y)


def test_governing_share_at_the_stroke_end():
    s = 1.8
    r = pg.side_shares(s, L)
    assert r == pytest.approx(pg.side_force_share(1.0, -0.5 * s, L)[0])
    assert pg.side_shares(0.0, L) == 0.5 and pg.side_shares(L, L) == 1.0


def test_float_numpy_casadi_agree():
    args = (M_B, J_B, M_C, 0.6, 1.7e8, 2.3e8, L, 3e7)
    ref = [float(v) for v in pg.gantry_frequencies(*args)]
    arr = pg.gantry_frequencies(*(np.array([a, a]) for a in args))
    np.testing.assert_allclose(np.asarray(arr), [[r, r] for r in ref], rtol=1e-12)
    syms = [ca.SX.sym(f"a{i}") for i in range(len(args))]
    f = ca.Function("f", syms, list(pg.gantry_frequencies(*syms)))
    np.testing.assert_allclose([float(v) for v in f(*args)], ref, rtol=1e-12)
    assert pg.bridge_yaw_inertia_estimate(900.0, 2.2) == pytest.approx(900.0 * 2.2**2 / 12.0)
