"""The machine's lumped chain against published closed forms, and Dunkerley's bound."""

import numpy as np
import pytest

from axisopt.machine.chain import chain_modes, dunkerley_frequency, lowest_frequency, strain_shares


# Two equal masses on two equal springs (frame - k - m - k - m): omega^2 = (3 -/+ sqrt 5)/2 k/m, the
# classic two-degree-of-freedom example (S. S. Rao, Mechanical Vibrations, ch. 5; W. T. Thomson,
# Theory of Vibration with Applications, ch. 5): 0.618 and 1.618 sqrt(k/m).
@pytest.mark.published
def test_two_dof_equal_chain_matches_closed_form():
    m, k = 400.0, 100e6
    f, _ = chain_modes([m, m], [k, k])
    w = np.sqrt(np.array([(3 - np.sqrt(5)) / 2, (3 + np.sqrt(5)) / 2]) * k / m)
    assert f == pytest.approx(w / (2 * np.pi), rel=1e-12)
    assert np.sqrt(k / m) * 0.618 / (2 * np.pi) == pytest.approx(f[0], rel=1e-3)


# A uniform fixed-free chain of n equal masses and springs: omega_r = 2 sqrt(k/m) sin((2r - 1) pi /
# (2 (2n + 1))), r = 1..n (e.g. L. Meirovitch, Fundamentals of Vibrations, the lumped string / rod;
# Rao, ch. 6).
@pytest.mark.published
@pytest.mark.parametrize("n", [2, 3, 5])
def test_uniform_chain_matches_closed_form(n):
    m, k = 250.0, 80e6
    f, _ = chain_modes(np.full(n, m), np.full(n, k))
    r = np.arange(1, n + 1)
    w = 2 * np.sqrt(k / m) * np.sin((2 * r - 1) * np.pi / (2 * (2 * n + 1)))
    assert f == pytest.approx(w / (2 * np.pi), rel=1e-12)


# Two unequal masses: the 2x2 characteristic equation m1 m2 w^4 - (m1 (k2) + m2 (k1 + k2)) w^2 + k1
# k2 = 0, solved here by the quadratic formula (written apart from the code's eigenvalue solve).
def test_two_dof_unequal_chain_matches_characteristic_equation():
    m1, m2, k1, k2 = 900.0, 300.0, 250e6, 120e6
    a, b, c = m1 * m2, -(m1 * k2 + m2 * (k1 + k2)), k1 * k2
    w2 = np.sort(
        [(-b - np.sqrt(b * b - 4 * a * c)) / (2 * a), (-b + np.sqrt(b * b - 4 * a * c)) / (2 * a)]
    )
    f, _ = chain_modes([m1, m2], [k1, k2])
    assert f == pytest.approx(np.sqrt(w2) / (2 * np.pi), rel=1e-12)


def test_dunkerley_bounds_the_lowest_frequency_from_below_vectorised():
    rng = np.random.default_rng(7)
    m = rng.uniform(50, 2000, (200, 3))
    k = rng.uniform(20e6, 2e9, (200, 3))
    f1 = lowest_frequency(m, k)
    fd = dunkerley_frequency(m, k)
    assert (fd <= f1 * (1 + 1e-12)).all()
    assert (fd > 0.5 * f1).all()  # a close bound for these chains, not a vacuous one
    assert f1 == pytest.approx(
        np.array([chain_modes(mi, ki)[0][0] for mi, ki in zip(m, k)]), rel=1e-12
    )


def test_softest_spring_carries_most_strain_energy():
    share = strain_shares([500.0, 300.0], [1e9, 50e6])
    assert share.sum() == pytest.approx(1.0)
    assert np.argmax(share) == 1


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_lowest_frequency_closed_form_equals_the_eigenvalue_solve(n):
    """Chains of up to three masses take the 3x3 closed form (Smith 1961), longer ones LAPACK: the
    same."""
    rng = np.random.default_rng(n)
    m = rng.uniform(20, 5000, (500, n))
    k = rng.uniform(1e6, 1e10, (500, n))
    k[:50] = k[:50, :1]  # equal springs and masses too
    m[:50] = m[:50, :1]
    ref = np.array([chain_modes(mi, ki)[0][0] for mi, ki in zip(m, k)])
    assert lowest_frequency(m, k) == pytest.approx(ref, rel=1e-11)
