"""Timing-belt stages (physics.belt) against the vendors' published numbers, belt geometry computed
independently, and the support-bearing set and belt formulas on floats, numpy arrays and CasADi SX
alike."""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import bearingsets, belt


@pytest.mark.published
def test_synchroflex_at10_worked_example():
    """ContiTech SYNCHROFLEX pp. 42-43: AT10, z = 25, a = 625 mm, M = 300 N m: F_U = 2e3 M / d0 =
    7539 N, L = 2 a + z t = 1500 mm, and with z_e = 12 and Mspec 11.70 Ncm/cm the width 8.54 cm
    carries the 300 N m."""
    d0 = belt.pitch_diameter(10e-3, 25)
    assert 2.0 * 300.0 / d0 == pytest.approx(7539, abs=1.0)
    assert belt.belt_length(d0, d0, 0.625) == pytest.approx(1.500, abs=1e-9)
    # Mspec per tooth and cm of width is FUspec times the pitch radius per tooth: FUspec = Mspec 2
    # pi / t
    fu_spec = 11.70e-2 * 2.0 * math.pi / 10e-3 * 100.0  # [N/m of width]
    torque = belt.tooth_shear_pull(fu_spec, 12, 8.54e-2) * 0.5 * d0
    assert torque == pytest.approx(300.0, rel=0.002)


@pytest.mark.published
def test_synchroflex_mspec_from_fuspec_at10():
    """SYNCHROFLEX AT10 GEN III p. 55: FUspec 91.88 N/cm and Mspec 14.63 Ncm/cm at n = 0 (and 61.88
    / 9.85 at 1000 min^-1) are one tooth's pull times the pitch radius per tooth, p / 2 pi."""
    for fu, m in ((91.88, 14.63), (61.88, 9.85)):
        one_tooth = (
            belt.tooth_shear_pull(fu * 100.0, 1.0, 0.01) * 0.5 * belt.pitch_diameter(10e-3, 1)
        )
        assert one_tooth * 100.0 == pytest.approx(m, rel=0.002)  # N m -> N cm, per cm of width


@pytest.mark.published
def test_elatech_permissible_pull_htd5m():
    """ELATECH HTD5M (cat. p. 36): FUspez 19.23 N/cm at 3000 min^-1, at most 12 teeth counted: 50 mm
    wide, a pulley with 15 teeth in mesh carries 19.23 x 12 x 5 = 1153.8 N; the cords (F_Tzul 5060
    N) with F_TV = F_U allow 5060 / 1.5 (tight span F_TV + F_U / 2)."""
    ze = belt.teeth_in_mesh(32.0, 0.05, 0.05, 0.2)  # equal pulleys: half the teeth, 16 -> 12
    assert ze == pytest.approx(12.0)
    assert belt.effective_pull(1923.0, ze, 0.05, 5060.0) == pytest.approx(1153.8, rel=1e-9)
    assert belt.tension_pull(5060.0) == pytest.approx(5060.0 / 1.5)


def test_belt_geometry_independent():
    """Geometry written out independently: the wrap of a 1.5:1 stage and its span by the tangent
    construction."""
    d1, d2, c = 0.05093, 0.07639, 0.1294
    alpha = math.asin((d2 - d1) / (2 * c))
    assert belt.wrap_angle(d1, d2, c) == pytest.approx(math.pi - 2 * alpha, rel=1e-12)
    assert belt.span_length(d1, d2, c) == pytest.approx(c * math.cos(alpha), rel=1e-12)
    # both spans on the output pulley: 2 (C/l) r^2
    k = belt.stage_torsional_stiffness(1.265e6, 0.129, d2)
    assert k == pytest.approx(2 * 1.265e6 / 0.129 * (d2 / 2) ** 2, rel=1e-12)
    # a solid steel disc: m r^2 / 2
    m = math.pi * 0.05**2 / 4 * 0.02 * 7850
    assert belt.pulley_inertia(0.05, 0.02, 7850.0) == pytest.approx(m * 0.025**2 / 2, rel=1e-12)


BACKEND_CASES = [
    (bearingsets.set_preload_ratio, (3.0, 1.0)),
    (bearingsets.set_lift_off, (1.0e4, 3.0, 1.0)),
    (bearingsets.set_rigidity_ratio, (2.0, 1.0)),
    (bearingsets.set_pressed_load, (1.0e4, 2.0e4, 3.0, 1.0)),
    (bearingsets.set_pressed_load, (1.0e4, 7.0e4, 3.0, 1.0)),
    (bearingsets.set_halves, (1.0e4, -1.2e4, 3.0, 1.0)),
    (bearingsets.set_halves, (1.0e4, 2.0e4, 3.0, 1.0)),
    (bearingsets.hertz_set_halves, (1.0e4, 2.0e4, 3.0, 1.0)),
    (bearingsets.hertz_set_halves, (1.0e4, -1.2e4, 3.0, 1.0)),
    (bearingsets.hertz_set_halves, (1.0e4, 7.0e4, 3.0, 1.0)),
    (bearingsets.nsk_pair_halves, (1.0e4, 2.0e4)),
    (bearingsets.nsk_pair_halves, (1.0e4, -1.2e4)),
    (bearingsets.nsk_pair_halves, (1.0e4, 4.0e4)),
    (belt.pitch_diameter, (5e-3, 32.0)),
    (belt.belt_length, (0.05, 0.076, 0.13)),
    (belt.span_length, (0.05, 0.076, 0.13)),
    (belt.wrap_angle, (0.05, 0.076, 0.13)),
    (belt.teeth_in_mesh, (20.0, 0.05, 0.076, 0.13)),
    (belt.span_stiffness, (1.265e6, 0.13)),
    (belt.stage_torsional_stiffness, (1.265e6, 0.13, 0.076)),
    (belt.tooth_shear_pull, (1985.0, 12.0, 0.05)),
    (belt.tension_pull, (5060.0, 1.0)),
    (belt.effective_pull, (1985.0, 12.0, 0.05, 5060.0, 1.0)),
    (belt.pulley_inertia, (0.076, 0.06, 7850.0, 0.02)),
    (belt.stage_input_inertia, (3e-4, 1.4e-3, 0.02, 0.05, 1.5)),
]


def _outs(v):
    return list(v) if isinstance(v, tuple) else [v]


@pytest.mark.parametrize(
    ("func", "args"), BACKEND_CASES, ids=[f.__name__ for f, _ in BACKEND_CASES]
)
def test_float_numpy_casadi_agree(func, args):
    scale = (0.9, 1.0, 1.1)
    refs = [[float(o) for o in _outs(func(*(a * s for a in args)))] for s in scale]
    arr = _outs(func(*(np.array([a * s for s in scale]) for a in args)))
    for j, out in enumerate(arr):
        np.testing.assert_allclose(np.asarray(out, dtype=float), [r[j] for r in refs], rtol=1e-12)
    syms = [ca.SX.sym(f"a{i}") for i in range(len(args))]
    f = ca.Function("f", syms, [ca.SX(o) for o in _outs(func(*syms))])
    for s, ref in zip(scale, refs):
        got = f(*(a * s for a in args))
        got = [float(g) for g in (got if isinstance(got, tuple) else (got,))]
        np.testing.assert_allclose(got, ref, rtol=1e-9)


def test_every_public_function_is_covered():
    covered = {f.__name__ for f, _ in BACKEND_CASES}
    public = {n for m in (belt, bearingsets) for n in m.__all__ if callable(getattr(m, n))}
    assert public == covered
