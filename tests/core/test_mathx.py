"""One formula on floats, numpy arrays and CasADi symbols (axisopt.mathx): each operation agrees
with the math module on floats, elementwise on arrays, and through a CasADi function of a symbol."""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest

from axisopt import mathx as mx

UNARY = [
    (mx.sqrt, math.sqrt, 2.5),
    (mx.exp, math.exp, 0.7),
    (mx.log, math.log, 3.2),
    (mx.tanh, math.tanh, -0.4),
    (mx.sin, math.sin, 1.1),
    (mx.cos, math.cos, 1.1),
    (mx.tan, math.tan, 0.3),
    (mx.atan, math.atan, 2.0),
    (mx.fabs, abs, -1.5),
    (mx.sign, lambda x: math.copysign(1.0, x), -1.5),
    (mx.hinge, lambda x: max(0.0, x), -0.2),
    (mx.hinge, lambda x: max(0.0, x), 0.2),
    (mx.cbrt, lambda x: 3.0 if x == 27.0 else math.nan, 27.0),
    (lambda x: mx.smooth_abs(x, 0.3), lambda x: math.hypot(x, 0.3), -0.4),
]


def _sym(f, x):
    s = ca.SX.sym("s")
    out = f(s)
    assert isinstance(out, ca.SX)
    return float(ca.Function("f", [s], [out])(x))


@pytest.mark.parametrize("f, ref, x", UNARY)
def test_unary_on_every_backend(f, ref, x):
    assert float(f(x)) == pytest.approx(ref(x), rel=1e-12)
    np.testing.assert_allclose(f(np.array([x, x])), [ref(x)] * 2, rtol=1e-12)
    assert _sym(f, x) == pytest.approx(ref(x), rel=1e-12)


@pytest.mark.parametrize("p", [2, 3, 1.5, 0.5])
def test_power_shortcuts_equal_the_power(p):
    x = np.array([0.3, 1.7, 4.0])
    np.testing.assert_allclose(mx.power(x, p), [v**p for v in x], rtol=1e-14)
    assert _sym(lambda s: mx.power(s, p), 1.7) == pytest.approx(1.7**p, rel=1e-12)


def test_min_max_if_else():
    a, b = np.array([1.0, 5.0]), np.array([3.0, 2.0])
    np.testing.assert_array_equal(mx.fmin(a, b), [1.0, 2.0])
    np.testing.assert_array_equal(mx.fmax(a, b), [3.0, 5.0])
    np.testing.assert_array_equal(mx.if_else(a > b, a, b), [3.0, 5.0])
    assert _sym(lambda s: mx.fmin(s, 2.0), 5.0) == 2.0
    assert _sym(lambda s: mx.fmax(2.0, s), 5.0) == 5.0
    assert _sym(lambda s: mx.if_else(s > 1.0, s, -s), 0.5) == -0.5
    assert _sym(lambda s: mx.if_else(s > 1.0, s, -s), 1.5) == 1.5


def test_is_symbolic():
    assert mx.is_symbolic(1.0, ca.DM(2.0)) and mx.is_symbolic(ca.MX.sym("m"))
    assert not mx.is_symbolic(1.0, np.ones(2))
