"""How a limit enters a gradient-based or branch-and-bound solver: scaled to order one.

A limit ``value <sense> limit`` is handed to the solver as ``g <sense> rhs``, with ``g`` of order
one at the limit, so that a solver's absolute feasibility tolerance (SCIP: 1e-6) means the same
relative slack for a cost in EUR as for a drag torque in N m:

* a life or a safety margin (key ``life`` or ``margin_*``) spans decades between designs: with
  ``log``, ``g = ln(max(value, 1e-300) / limit)``, ``rhs = 0``;
* a limit of 0 (or below: e.g. ``max_backlash 0``) has no ratio: ``g = value / factor`` (the value
  in the limit's display units), ``rhs = 0``;
* any other limit: ``g = value / limit``, ``rhs = 1``.

One rule for every solver; only the arithmetic differs (CasADi expressions divide, a pyscipopt
expression is multiplied by the reciprocal: see :func:`reciprocal_times`).
"""

from __future__ import annotations

import operator
from typing import Any, Callable

import casadi as ca

from ...model.limits import check_name

LOG_FLOOR = 1e-300  # a life or margin of 0 (or below) still has a logarithm


def log_scaled(key: str) -> bool:
    """A life or a safety margin: compared on a logarithmic scale (its ratio to the limit spans
    decades)."""
    return key == "life" or check_name(key) is not None


def reciprocal_times(value, divisor: float):
    """``(1 / divisor) * value``: a pyscipopt expression keeps a constant factor
    (``value / divisor`` would add a ``divisor ** -1`` node to a nonlinear expression)."""
    return (1.0 / divisor) * value


def scaled_limit(
    c,
    value,
    limit: Any = None,
    *,
    log: bool = True,
    divide: Callable[[Any, Any], Any] = operator.truediv,
) -> tuple[Any, float]:
    """The limit ``c`` (a :class:`axisopt.search.task.space.Constraint`) on ``value`` as
    ``(g, rhs)``: the solver's constraint is ``g >= rhs`` or ``g <= rhs`` (``c.sense``).

    ``limit``  : the divisor, by default ``c.limit``; a symbol where one solver serves every limit
                 value (the branch for a limit of 0 is still chosen by the number ``c.limit``)
    ``log``    : life and margins on a logarithmic scale (CasADi expressions only)
    ``divide`` : ``divide(value, number)``; :func:`reciprocal_times` for pyscipopt expressions
    """
    limit = c.limit if limit is None else limit
    if log and log_scaled(c.key):
        return ca.log(ca.fmax(value, LOG_FLOOR) / limit), 0.0
    if c.limit <= 0:  # e.g. max_backlash 0: the value in display units must be <= 0
        return divide(value, c.factor), 0.0
    return divide(value, limit), 1.0


__all__ = ["scaled_limit", "log_scaled", "reciprocal_times", "LOG_FLOOR"]
