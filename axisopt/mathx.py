"""Small math dispatch so one formula evaluates on floats, numpy arrays and CasADi symbols.

Every physics function uses these instead of ``np.`` or ``ca.`` directly, and never a
Python ``if`` on a value that may be symbolic.  CasADi types (SX, MX, DM) go to CasADi;
everything else goes to numpy.  A float in gives a numpy float (or a 0-d value) out.
"""

from __future__ import annotations

import math

import casadi as ca
import numpy as np

pi = math.pi

_CASADI_TYPES = (ca.SX, ca.MX, ca.DM)


def is_symbolic(*values) -> bool:
    """True when any argument is a CasADi SX/MX/DM object."""
    # a loop, not any(generator): called on every elementary operation of the model
    for v in values:
        if isinstance(v, _CASADI_TYPES):
            return True
    return False


def _pick(*values):
    return ca if is_symbolic(*values) else np


def sqrt(x):
    return _pick(x).sqrt(x)


def exp(x):
    return _pick(x).exp(x)


def log(x):
    return _pick(x).log(x)


def tanh(x):
    return _pick(x).tanh(x)


def sin(x):
    return _pick(x).sin(x)


def cos(x):
    return _pick(x).cos(x)


def tan(x):
    return _pick(x).tan(x)


def atan(x):
    return _pick(x).arctan(x) if not is_symbolic(x) else ca.atan(x)


def fabs(x):
    return ca.fabs(x) if isinstance(x, _CASADI_TYPES) else np.abs(x)


def sign(x):
    return ca.sign(x) if is_symbolic(x) else np.sign(x)


def fmin(a, b):
    return (
        ca.fmin(a, b)
        if isinstance(a, _CASADI_TYPES) or isinstance(b, _CASADI_TYPES)
        else np.minimum(a, b)
    )


def fmax(a, b):
    return (
        ca.fmax(a, b)
        if isinstance(a, _CASADI_TYPES) or isinstance(b, _CASADI_TYPES)
        else np.maximum(a, b)
    )


def power(x, p):
    """x**p; for non-integer p the base must be non-negative.  On numpy arrays the exponents 2, 3
    and 1.5 are products (and a square root): a general ``**`` per element is 10-30 times slower
    there, and the screening of the catalogs evaluates these on every combination."""
    if isinstance(x, np.ndarray) and x.ndim:
        if p == 2:
            return x * x
        if p == 3:
            return x * x * x
        if p == 1.5:
            return x * np.sqrt(x)
    return x**p


def cbrt(x):
    """Cube root of a non-negative value."""
    return x ** (1.0 / 3.0)


def if_else(cond, a, b):
    """Elementwise ``a if cond else b`` that also works on symbols."""
    if is_symbolic(cond, a, b):
        return ca.if_else(cond, a, b)
    return np.where(cond, a, b)


def hinge(x):
    """max(0, x)."""
    return fmax(x, 0.0)


def smooth_abs(x, eps):
    """sqrt(x^2 + eps^2): a differentiable |x| for solvers."""
    return sqrt(x * x + eps * eps)
