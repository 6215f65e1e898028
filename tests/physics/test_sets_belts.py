"""Support-bearing sets (physics.bearingsets) and timing-belt stages (physics.belt) against the vendors' published
numbers, and on floats, numpy arrays and CasADi SX alike."""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import bearingsets, belt

# IBC TI-I-5010.2/E Table 2.2: the unloading point Fae > X Fv of each arrangement (bearings loaded against the
# opposite ones; Fv the bearings' preload as a DB pair) and the single bearing's preload in a set against one
IBC_X = [(1, 1, 2.83), (2, 1, 5.66), (1, 2, 2.83), (3, 1, 8.49), (4, 1, 11.30), (2, 2, 5.66), (3, 2, 8.49),
         (2, 3, 5.66)]
IBC_SINGLE = [(2, 1.36), (3, 1.57), (4, 1.71)]


@pytest.mark.published
@pytest.mark.parametrize(("n_load", "n_other", "x"), IBC_X)
def test_lift_off_factor_ibc_table_2_2(n_load, n_other, x):
    """IBC Table 2.2: lift-off X Fv; the set's own preload is set_preload_ratio x Fv."""
    fv = 1000.0
    pre = bearingsets.set_preload_ratio(n_load, n_other) * fv
    assert bearingsets.set_lift_off(pre, n_load, n_other) / fv == pytest.approx(x, abs=0.015)


@pytest.mark.published
@pytest.mark.parametrize(("n", "ratio"), IBC_SINGLE)
def test_single_bearing_preload_ibc_table_2_2(n, ratio):
    """IBC Table 2.2, the single bearing of n against 1 ('B = 1.36 / 1.57 / 1.71 Fv - ...' at Fae = 0)."""
    assert bearingsets.set_preload_ratio(n, 1) == pytest.approx(ratio, abs=0.006)


# NSK super-precision bearings p. 168, TAC B C10 (Fpre [N], Ka [N/um]): duplex, triplex (DFD), quadruplex (DFF)
NSK_168 = {"60TAC120B": ((6650, 1810), (9100, 2650), (13200, 3550)),
           "40TAC90B": ((5000, 1320), (6750, 1960), (10300, 2650)),
           "30TAC62B": ((3350, 1030), (4500, 1520), (6650, 2010))}


@pytest.mark.published
@pytest.mark.parametrize("bearing", sorted(NSK_168))
def test_triplex_quadruplex_from_duplex_nsk_p168(bearing):
    """NSK p. 168: the triplex (2 against 1) and quadruplex (2 against 2) preload and rigidity from the duplex's
    by the Hertz set rule, within 4 % (NSK rounds and grinds to preload classes)."""
    (p2, k2), (p3, k3), (p4, k4) = NSK_168[bearing]
    assert p2 * bearingsets.set_preload_ratio(2, 1) == pytest.approx(p3, rel=0.04)
    assert p2 * bearingsets.set_preload_ratio(2, 2) == pytest.approx(p4, rel=0.04)
    assert k2 * bearingsets.set_rigidity_ratio(2, 1) == pytest.approx(k3, rel=0.04)
    assert k2 * bearingsets.set_rigidity_ratio(2, 2) == pytest.approx(k4, rel=0.04)


@pytest.mark.published
def test_db_pair_lift_off_skf():
    """SKF 'Lifting force': Ka1 = 2.83 F0 for a back-to-back pair."""
    assert bearingsets.set_lift_off(1.0, 1, 1) == pytest.approx(2.83, abs=0.005)


@pytest.mark.published
def test_synchroflex_at10_worked_example():
    """ContiTech SYNCHROFLEX pp. 42-43: AT10, z = 25, a = 625 mm, M = 300 N m: F_U = 2e3 M / d0 = 7539 N,
    L = 2 a + z t = 1500 mm, and with z_e = 12 and Mspec 11.70 Ncm/cm the width 8.54 cm carries the 300 N m."""
    d0 = belt.pitch_diameter(10e-3, 25)
    assert 2.0 * 300.0 / d0 == pytest.approx(7539, abs=1.0)
    assert belt.belt_length(d0, d0, 0.625) == pytest.approx(1.500, abs=1e-9)
    # Mspec per tooth and cm of width is FUspec times the pitch radius per tooth: FUspec = Mspec 2 pi / t
    fu_spec = 11.70e-2 * 2.0 * math.pi / 10e-3 * 100.0  # [N/m of width]
    torque = belt.tooth_shear_pull(fu_spec, 12, 8.54e-2) * 0.5 * d0
    assert torque == pytest.approx(300.0, rel=0.002)


@pytest.mark.published
def test_synchroflex_mspec_from_fuspec_at10():
    """SYNCHROFLEX AT10 GEN III p. 55: FUspec 91.88 N/cm and Mspec 14.63 Ncm/cm at n = 0 (and 61.88 / 9.85 at
    1000 min^-1) are one tooth's pull times the pitch radius per tooth, p / 2 pi."""
    for fu, m in ((91.88, 14.63), (61.88, 9.85)):
        one_tooth = belt.tooth_shear_pull(fu * 100.0, 1.0, 0.01) * 0.5 * belt.pitch_diameter(10e-3, 1)
        assert one_tooth * 100.0 == pytest.approx(m, rel=0.002)  # N m -> N cm, per cm of width


@pytest.mark.published
def test_elatech_permissible_pull_htd5m():
    """ELATECH HTD5M (cat. p. 36): FUspez 19.23 N/cm at 3000 min^-1, at most 12 teeth counted: 50 mm wide, a
    pulley with 15 teeth in mesh carries 19.23 x 12 x 5 = 1153.8 N; the cords (F_Tzul 5060 N) with F_TV = F_U
    allow 5060 / 1.5 (tight span F_TV + F_U / 2)."""
    ze = belt.teeth_in_mesh(32.0, 0.05, 0.05, 0.2)  # equal pulleys: half the teeth, 16 -> 12
    assert ze == pytest.approx(12.0)
    assert belt.effective_pull(1923.0, ze, 0.05, 5060.0) == pytest.approx(1153.8, rel=1e-9)
    assert belt.tension_pull(5060.0) == pytest.approx(5060.0 / 1.5)


def test_belt_geometry_independent():
    """Geometry written out independently: the wrap of a 1.5:1 stage and its span by the tangent construction."""
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


@pytest.mark.parametrize(("func", "args"), BACKEND_CASES, ids=[f.__name__ for f, _ in BACKEND_CASES])
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


def test_set_split_bounds_hertz():
    """The linear split (IBC's form) against Hertz's exact split of a 3-against-1 set, solved here by bisection
    from delta ~ (Q/n)^(2/3): never below it, at most 8 % above, equal at no load and at lift-off."""
    p0 = 1.0e4
    lift = bearingsets.set_lift_off(p0, 3, 1)
    for frac in np.linspace(0.0, 1.0, 11):
        f = frac * lift
        da, db = (p0 / 3) ** (2 / 3), p0 ** (2 / 3)
        lo, hi = 0.0, db  # the single unloads at u = db
        for _ in range(200):
            u = 0.5 * (lo + hi)
            qa, qb = 3 * (da + u) ** 1.5, max(db - u, 0.0) ** 1.5
            lo, hi = (u, hi) if qa - qb < f else (lo, u)
        exact = 3 * (da + 0.5 * (lo + hi)) ** 1.5
        got = float(bearingsets.set_pressed_load(p0, f, 3, 1))
        assert exact * (1 - 1e-9) <= got <= 1.08 * exact, (frac, got, exact)
    plus, minus = bearingsets.set_halves(p0, 2.0e4, 3, 1)
    assert float(plus) - float(minus) == pytest.approx(2.0e4)


def test_every_public_function_is_covered():
    covered = {f.__name__ for f, _ in BACKEND_CASES}
    public = {n for m in (belt, bearingsets) for n in m.__all__ if callable(getattr(m, n))}
    assert public == covered
