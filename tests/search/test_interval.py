"""Interval arithmetic (search/interval.py) and the explanation's drive bounds built on it.

The arithmetic is checked the way it is defined: for random intervals and random points inside them,
every operation's result holds the operation applied to the points (numpy on plain floats is the
reference).  The drive bounds are checked against the drive model evaluated on every combination of
a random catalog, at each preload end, limit by limit."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from axisopt import mathx as mx
from axisopt.physics import drive as pdr
from axisopt.search import drivebounds
from axisopt.search.infeasible import optimism as E
from axisopt.search.interval import Interval, ends
from axisopt.search.parts import build_space
from axisopt.search.task.constraints import build_constraints
from axisopt.search.task.space import DRIVE_KEYS, respond_drive

finite = st.floats(-1e3, 1e3, allow_nan=False)


def _iv(a, b):
    return Interval(min(a, b), max(a, b))


def _points(iv, u):
    return iv.lo + u * (iv.hi - iv.lo)


OPS = {
    "add": lambda a, b: a + b,
    "sub": lambda a, b: a - b,
    "rsub": lambda a, b: 3.0 - a,
    "mul": lambda a, b: a * b,
    "square": lambda a, b: a * a,
    "scale": lambda a, b: -2.5 * a,
    "div": lambda a, b: a / b,
    "rdiv": lambda a, b: 7.0 / b,
    "neg": lambda a, b: -a,
    "abs": lambda a, b: mx.fabs(a),
    "max": lambda a, b: mx.fmax(a, b),
    "min": lambda a, b: mx.fmin(a, b),
    "sqrt": lambda a, b: mx.sqrt(mx.fabs(a)),
    "where": lambda a, b: mx.if_else(np.array(True), a, b),
    "rms": lambda a, b: pdr.linear_rms_torque([(a, b), (b, a)], [0.3, 0.7]),
}


@settings(max_examples=200, deadline=None)
@given(
    st.sampled_from(sorted(OPS)), finite, finite, finite, finite, st.floats(0, 1), st.floats(0, 1)
)
def test_every_operation_holds_the_points(op, a0, a1, b0, b1, u, w):
    a, b = _iv(a0, a1), _iv(b0, b1)
    # through or next to zero: moved off it
    if op in ("div", "rdiv") and (b.lo <= 1e-3 and b.hi >= -1e-3):
        b = Interval(abs(b.lo) + 0.1, abs(b.hi) + 0.2)
    res = OPS[op](a, b)
    x, y = _points(a, u), _points(b, w)
    v = OPS[op](x, y)
    tol = 1e-9 * (1 + abs(float(v)))
    assert float(res.lo) - tol <= float(v) <= float(res.hi) + tol, (op, a, b, x, y, v, res)


def test_division_by_a_range_through_zero_bounds_nothing():
    r = Interval(1.0, 2.0) / Interval(-1.0, 1.0)
    assert r.lo == -np.inf and r.hi == np.inf


def test_unsupported_function_fails_loudly():
    with pytest.raises(TypeError):
        np.exp(Interval(0.0, 1.0))
    with pytest.raises(TypeError):
        bool(Interval(0.0, 1.0) > 0)


@pytest.mark.parametrize("seed,groups", [(1, 8), (3, 8), (5, 8), (1, 2), (3, 1)])
def test_drive_bounds_hold_every_combination(seed, groups, monkeypatch):
    """Per (nut, bearing) block, each drive limit's interval bound is at least as good as the value
    of every guide and drive pair in it at the favourable preload end (weak motors: the drive limits
    are active); with the bearings taken one by one (8 groups of these 5 bearings) and together (2
    groups, 1 group)."""
    from test_explain import _case

    monkeypatch.setattr(drivebounds, "DRIVE_BEARING_GROUPS", groups)
    p = _case(seed, "drive")
    sp, cons = build_space(p), build_constraints(p)
    drive = [c for c in cons if not E.is_bounded(c)]
    assert drive
    _, N, B, G = sp.shape
    for mounting in sp.mountings:
        bound = E.drive_optimism(sp, mounting, slice(0, N), drive)
        pd = sp.params_structured(mounting, slice(0, N))
        lo = sp.preload_lo.reshape(-1, 1, 1, 1)
        hi = sp.preload_hi.reshape(-1, 1, 1, 1)
        d_lo, d_hi = respond_drive(pd, lo), respond_drive(pd, hi)
        for c in drive:
            v = E.favourable_bound(c, d_lo, d_hi, (N, B, G))
            b = bound[c.name][:, :, None]
            tol = 1e-9 * np.maximum(np.abs(v), 1.0)
            held = v <= b + tol if c.sense == ">=" else v >= b - tol
            assert held.all(), (c.name, np.argwhere(~held)[:3])


def test_drive_block_in_intervals_holds_every_mass_and_drag():
    """The drive block (model/drive.py) on interval moving mass and drag torque holds its value at
    every point of the box, with a braking six times harder than the acceleration: there a carriage
    with less friction needs more peak torque (the motor brakes what friction does not), so the
    guide of least friction is not the optimistic one and the bound must take the whole range; and
    on a vertical axis."""
    from pathlib import Path

    from axisopt.design import load_design
    from axisopt.model import design_params
    from axisopt.model.drive import drive
    from axisopt.physics.motion import Phase, Phases

    d = load_design(Path(__file__).resolve().parents[2] / "problems" / "vmc_x_design.yaml")
    p = dict(design_params(d))
    p["gravity_axial"] = 0.0
    p["duty"] = Phases(
        (
            Phase(0.1, 2.0, 2.0, 1.0, 500.0, 0.2),
            Phase(0.4, 0.0, 0.0, 1.0, 500.0, 0.4),
            Phase(0.05, -12.0, -12.0, 1.0, 0.0, 0.4),
            Phase(0.3, 0.0, 0.0, 0.0, 0.0, 0.0),
        )
    )
    m_lo, m_hi, t_lo, t_hi = 200.0, 450.0, 0.2, 3.0
    rng = np.random.default_rng(4)
    corners = [(m_lo, t_lo), (m_lo, t_hi), (m_hi, t_lo), (m_hi, t_hi)]
    points = corners + [tuple(x) for x in rng.uniform([m_lo, t_lo], [m_hi, t_hi], (200, 2))]
    for vertical in (0.0, 1.0):
        p["gravity_axial"] = vertical
        box_lo, box_hi = ends(drive(p, Interval(m_lo, m_hi), Interval(t_lo, t_hi)))
        peak = []
        for m, t in points:
            out = drive(p, m, t)
            peak.append(float(out["margin_motor_peak_torque"]))
            for k, v in out.items():
                if k.startswith("margin_") or k in (
                    "rms_torque",
                    "peak_torque",
                    "inertia_ratio",
                    "load_inertia",
                ):
                    lo, hi = float(box_lo[k]), float(box_hi[k])
                    assert lo * (1 - 1e-12) - 1e-12 <= float(v) <= hi * (1 + 1e-12) + 1e-12, (
                        k,
                        m,
                        t,
                        v,
                        lo,
                        hi,
                    )
        # the premise: the best peak-torque margin is not at the corner of least mass and drag
        if not vertical:
            assert max(peak) > peak[0] * 1.001


@pytest.mark.parametrize("seed,groups", [(1, 8), (3, 2), (5, 1)])
def test_drive_hull_holds_every_guide_drive_and_preload(seed, groups, monkeypatch):
    """drivebounds.drive_hull: per (nut, bearing group, drive), each drive limit's bound is at least
    as good as its value with every guide at every allowed preload (the two ends and three points
    between them), so the screening may leave out a drive that fails it and the explanation a drive
    it shows cannot score low."""
    from test_explain import _case

    monkeypatch.setattr(drivebounds, "DRIVE_BEARING_GROUPS", groups)
    p = _case(seed, "drive")
    sp, cons = build_space(p), build_constraints(p)
    drive = [c for c in cons if c.key in DRIVE_KEYS and c.key != "cost"]
    assert drive
    _, N, B, G = sp.shape
    D = sp.n_drives
    for mounting in sp.mountings:
        hull, group = drivebounds.drive_hull(sp, mounting, np.arange(N), drive)
        assert set(hull) == {c.name for c in drive}
        pd = sp.params_structured(mounting, slice(0, N))
        for t in (0.0, 0.2, 0.5, 0.9, 1.0):
            pre = (sp.preload_lo + t * (sp.preload_hi - sp.preload_lo)).reshape(-1, 1, 1, 1)
            out = respond_drive(pd, pre)
            for c in drive:
                v = np.broadcast_to(np.asarray(c.value(out), dtype=float), (N, B, G, 1))[..., 0]
                v = v.reshape(N, B, G // D, D)
                b = hull[c.name][:, group][:, :, None, :]
                tol = 1e-9 * np.maximum(np.abs(v), 1.0)
                held = v <= b + tol if c.sense == ">=" else v >= b - tol
                assert held.all(), (c.name, t, np.argwhere(~held)[:3])
