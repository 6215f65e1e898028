"""Interval arithmetic on numpy arrays, so that a model formula written for floats and arrays bounds
its output over a set of inputs (the searches' block bounds).

An :class:`Interval` holds elementwise lower and upper ends.  The arithmetic operators, and the
numpy functions the model's math dispatch (:mod:`axisopt.mathx`) calls on arrays -- ``abs``,
``maximum``, ``minimum``, ``sqrt``, ``where`` -- give an interval that contains every value the
formula takes when each interval input takes any value in its range, independently (the dependency
problem of interval arithmetic makes the result wider than the true range, never narrower, with one
exception kept exact: ``x * x`` of the same interval is a square).  Any other numpy function on an
interval raises ``TypeError``, so a formula that uses one fails loudly instead of giving a bound
that is not one.
"""

from __future__ import annotations

import numpy as np

__all__ = ["Interval", "ends"]


def _lohi(v):
    if isinstance(v, Interval):
        return v.lo, v.hi
    return v, v


def _finite_ends(lo, hi):
    """0 * inf (an unbounded end times zero) is 0 at every point of the range: nan is not a
    bound."""
    if np.isnan(lo).any() or np.isnan(hi).any():
        lo = np.nan_to_num(lo, nan=0.0, posinf=np.inf, neginf=-np.inf)
        hi = np.nan_to_num(hi, nan=0.0, posinf=np.inf, neginf=-np.inf)
    return lo, hi


def _mul(a_lo, a_hi, b_lo, b_hi):
    with np.errstate(invalid="ignore"):
        c = (a_lo * b_lo, a_lo * b_hi, a_hi * b_lo, a_hi * b_hi)
        lo = np.minimum(np.minimum(c[0], c[1]), np.minimum(c[2], c[3]))
        hi = np.maximum(np.maximum(c[0], c[1]), np.maximum(c[2], c[3]))
    return _finite_ends(lo, hi)


def _scale(a_lo, a_hi, k):
    """[a_lo, a_hi] times an exact value ``k`` (two products instead of four)."""
    with np.errstate(invalid="ignore"):
        x, y = a_lo * k, a_hi * k
        return _finite_ends(np.minimum(x, y), np.maximum(x, y))


class Interval:
    """Elementwise closed intervals ``[lo, hi]`` (numpy arrays or floats, broadcastable)."""

    __slots__ = ("lo", "hi")
    __array_priority__ = 100

    def __init__(self, lo, hi=None):
        self.lo = np.asarray(lo, dtype=float)
        self.hi = self.lo if hi is None else np.asarray(hi, dtype=float)

    def __repr__(self) -> str:
        return f"Interval({self.lo!r}, {self.hi!r})"

    # arithmetic ----------------------------------------------------------------------------------
    def __add__(self, other):
        o_lo, o_hi = _lohi(other)
        return Interval(self.lo + o_lo, self.hi + o_hi)

    __radd__ = __add__

    def __neg__(self):
        return Interval(-self.hi, -self.lo)

    def __pos__(self):
        return self

    def __sub__(self, other):
        o_lo, o_hi = _lohi(other)
        return Interval(self.lo - o_hi, self.hi - o_lo)

    def __rsub__(self, other):
        o_lo, o_hi = _lohi(other)
        return Interval(o_lo - self.hi, o_hi - self.lo)

    def __mul__(self, other):
        if other is self:
            return self._square()
        if not isinstance(other, Interval):
            return Interval(*_scale(self.lo, self.hi, np.asarray(other, dtype=float)))
        return Interval(*_mul(self.lo, self.hi, other.lo, other.hi))

    def __rmul__(self, other):
        return self * other

    def _square(self):
        lo2, hi2 = self.lo * self.lo, self.hi * self.hi
        straddles = (self.lo <= 0) & (self.hi >= 0)
        return Interval(np.where(straddles, 0.0, np.minimum(lo2, hi2)), np.maximum(lo2, hi2))

    def _reciprocal(self):
        """1/x; the whole line when the interval holds 0 (a division by a range through zero bounds
        nothing)."""
        away = (self.lo > 0) | (self.hi < 0)
        with np.errstate(divide="ignore", invalid="ignore"):
            lo = np.where(away, 1.0 / self.hi, -np.inf)
            hi = np.where(away, 1.0 / self.lo, np.inf)
        return Interval(lo, hi)

    def __truediv__(self, other):
        if isinstance(other, Interval):
            return self * other._reciprocal()
        with np.errstate(divide="ignore", invalid="ignore"):
            return self * (1.0 / np.asarray(other, dtype=float))

    def __rtruediv__(self, other):
        return Interval(*_lohi(other)) * self._reciprocal()

    def __pow__(self, p):
        if p == 2:
            return self._square()
        if p == 1:
            return self
        raise TypeError(f"Interval ** {p!r} is not supported")

    def __bool__(self):
        raise TypeError("an Interval has no truth value (a Python 'if' on a model value)")

    # numpy protocol -------------------------------------------------------------------------------
    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        if method != "__call__" or kwargs:
            return NotImplemented
        if ufunc is np.add:
            return Interval(*_lohi(inputs[0])) + inputs[1]
        if ufunc is np.subtract:
            return Interval(*_lohi(inputs[0])) - inputs[1]
        if ufunc is np.multiply:
            a, b = inputs
            return a * b if isinstance(a, Interval) else b.__rmul__(a)
        if ufunc is np.true_divide:
            return Interval(*_lohi(inputs[0])) / inputs[1]
        if ufunc is np.negative:
            return -inputs[0]
        if ufunc is np.absolute:
            x = inputs[0]
            straddles = (x.lo <= 0) & (x.hi >= 0)
            lo = np.where(straddles, 0.0, np.minimum(np.abs(x.lo), np.abs(x.hi)))
            return Interval(lo, np.maximum(np.abs(x.lo), np.abs(x.hi)))
        if ufunc in (np.maximum, np.minimum):
            (a_lo, a_hi), (b_lo, b_hi) = _lohi(inputs[0]), _lohi(inputs[1])
            return Interval(ufunc(a_lo, b_lo), ufunc(a_hi, b_hi))
        if ufunc is np.sqrt:
            x = inputs[0]
            return Interval(np.sqrt(np.maximum(x.lo, 0.0)), np.sqrt(np.maximum(x.hi, 0.0)))
        raise TypeError(f"numpy.{ufunc.__name__} is not supported on an Interval")

    def __array_function__(self, func, types, args, kwargs):
        if func is np.where and len(args) == 3 and not kwargs:
            cond, a, b = args
            if isinstance(cond, Interval):
                raise TypeError("numpy.where on an Interval condition")
            (a_lo, a_hi), (b_lo, b_hi) = _lohi(a), _lohi(b)
            return Interval(np.where(cond, a_lo, b_lo), np.where(cond, a_hi, b_hi))
        raise TypeError(f"numpy.{func.__name__} is not supported on an Interval")


def ends(out: dict) -> tuple[dict, dict]:
    """(lower ends, upper ends) of a dict of model outputs: an Interval's ends, any other value as
    it is (lists and tuples of values element by element)."""

    def lo(v):
        if isinstance(v, (list, tuple)):
            return type(v)(lo(x) for x in v)
        return v.lo if isinstance(v, Interval) else v

    def hi(v):
        if isinstance(v, (list, tuple)):
            return type(v)(hi(x) for x in v)
        return v.hi if isinstance(v, Interval) else v

    return {k: lo(v) for k, v in out.items()}, {k: hi(v) for k, v in out.items()}
