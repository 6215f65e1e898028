"""The limits of a problem as the search checks them: :class:`Constraint` (one per limit and
vendor-check margin), built from the problem by :func:`build_constraints`.

Everything a constraint knows comes from the model's tables: the output it reads and its sense from
:data:`axisopt.model.limits.LIMIT_TABLE` (a margin from ``CHECK_TABLE``), how that output moves with
the nut preload from ``OUTPUT_PRELOAD`` (:class:`Preload`), whether it is a profile over the stroke
from :data:`axisopt.model.PROFILE_OUTPUTS`.  From the direction and the sense follow the preload end
that favours the limit (:attr:`Constraint.favourable`) and the form every solver is given
(:meth:`Constraint.scaled`, the one scaling used by IPOPT, Bonmin and SCIP).

Preload structure (from the model; default == exhaustive in tests/search checks it): the minimum
stiffness and frequency, the drag torque and the nut lift-off margin are nondecreasing in the nut
preload, the nut life is nonincreasing, the motor-torque margins are met on an interval of preloads,
every other output is independent of it.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

import numpy as np

from ... import mathx, model
from ...model.limits import CHECK_RECORDS, CONVEX, LIMITS, check_name, margin_output
from ...model.outputs import REGEN_OUTPUTS
from ...problem import Problem
from .objective import min_last

# outputs given per position: a limit reads their minimum
PROFILE = frozenset(model.PROFILE_OUTPUTS)


class Preload(enum.IntEnum):
    """How a model output moves with the nut preload (``axisopt.model.limits.OUTPUT_PRELOAD``)."""

    INDEPENDENT = 0
    RISES = 1  # nondecreasing
    FALLS = -1  # nonincreasing
    CONVEX = CONVEX  # convex in the preload: a ``>=`` limit on it is met on an interval


class End(enum.Enum):
    """The allowed preload end where a limit is easiest to meet (where screening tests it)."""

    LOW = "low"  # upper-type limits (drag, life) and the preload-independent ones
    HIGH = "high"  # lower-type limits (lift-off, minimum stiffness and frequency)
    INTERVAL = "interval"  # convex: met on an interval, at neither end necessarily


# a part's value at its limit within this relative amount meets it: a nut's 0.05 mm play is
# 5.000000000000001e-05 m and a 50 um limit 4.9999999999999996e-05 m once converted to SI, and the
# part at the limit was refused
EQ_RTOL = 1e-9


@dataclass(frozen=True)
class Constraint:
    """``value(out) sense limit``; ``direction`` is how the value moves with the nut preload."""

    name: str  # limit key or 'margin_<check>'
    key: str  # model output
    sense: str  # '<=' or '>='
    limit: float  # SI
    # a Preload: 0 independent, +1 nondecreasing, -1 nonincreasing, CONVEX (met on an interval)
    direction: int
    label: str
    unit: str
    factor: float  # SI per display unit
    # derived from the fields above (set in __post_init__), read in the search's inner loops the
    # output is a profile over the stroke
    profile: bool = field(init=False, repr=False, compare=False)
    # satisfied on an interval of preloads
    convex: bool = field(init=False, repr=False, compare=False)
    # satisfied below a preload threshold
    upper_type: bool = field(init=False, repr=False, compare=False)
    # satisfied above a preload threshold
    lower_type: bool = field(init=False, repr=False, compare=False)
    # the preload end where it is easiest to meet
    favourable: End = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        d = Preload(self.direction)
        convex = d is Preload.CONVEX
        up = not convex and ((self.sense == "<=" and d > 0) or (self.sense == ">=" and d < 0))
        low = not convex and ((self.sense == ">=" and d > 0) or (self.sense == "<=" and d < 0))
        end = End.INTERVAL if convex else End.HIGH if low else End.LOW
        for k, v in (
            ("profile", self.key in PROFILE),
            ("convex", convex),
            ("upper_type", up),
            ("lower_type", low),
            ("favourable", end),
        ):
            object.__setattr__(self, k, v)

    def value(self, out, axis=-1):
        v = out[self.key]
        return min_last(v) if self.profile else v

    def ok(self, v):
        """Whether ``v`` meets the limit; a value that does not depend on the preload (a part's
        play, a price) meets it within :data:`EQ_RTOL` (the preload searches find exact boundaries
        themselves)."""
        slack = EQ_RTOL * abs(self.limit) if self.direction == 0 else 0.0
        return v <= self.limit + slack if self.sense == "<=" else v >= self.limit - slack

    def violation(self, v):
        """Relative miss (0 when met, as :meth:`ok`)."""
        if self.sense == "<=":
            if self.limit <= 0:  # e.g. max_backlash 0: the miss in display units
                return np.maximum(v / self.factor, 0.0)
            m = v / self.limit - 1.0
        else:
            m = 1.0 - v / self.limit
        return np.where(m > (EQ_RTOL if self.direction == 0 else 0.0), m, 0.0)

    def scaled(self, v, limit=None):
        """The constraint as a solver sees it, ``scaled(v) >= 0`` for ``>=`` and ``<= 0`` for
        ``<=``: the logarithm of the ratio for a life or a margin (ratios over decades), else the
        ratio minus one, and for a limit of 0 (``max_backlash: 0``) the value in display units.
        ``limit``: the limit as a solver parameter (default: :attr:`limit`).  ``v`` numpy or
        CasADi."""
        lim = self.limit if limit is None else limit
        if self.key == "life" or check_name(self.key) is not None:
            return mathx.log(mathx.fmax(v, 1e-300) / lim)
        if limit is None and self.limit <= 0:
            return v / self.factor
        return v / lim - 1.0


def reads_regen(constraints) -> bool:
    """Whether a limit reads the regenerated energy or power (the drive block skips that sum
    otherwise)."""
    return any(c.key in REGEN_OUTPUTS for c in constraints)


def as_vector(v, K):
    """A scalar, (K,) or (K, 1) array as a fresh (K,) array."""
    a = np.asarray(v, dtype=float)
    return np.full(K, a.item()) if a.size == 1 else a.reshape(K).copy()


def ok_all(cons, out, K):
    """(K,) bool: every constraint of ``cons`` met by the model outputs ``out`` of K
    combinations."""
    ok = np.ones(K, dtype=bool)
    for c in cons:
        ok &= as_vector(c.ok(c.value(out)), K).astype(bool)
    return ok


# Checks the search's preload range holds by construction (build_space), at a margin up to 1: not
# constraints.
RANGE_CHECKS = frozenset({"nut_preload"})


def build_constraints(problem: Problem) -> tuple[Constraint, ...]:
    out = []
    for key, value in problem.limits:
        lim = LIMITS[key]
        out.append(
            Constraint(
                key,
                lim.output,
                lim.sense,
                value,
                lim.preload,
                key.replace("_", " "),
                lim.unit,
                lim.factor,
            )
        )
    for check, m in problem.margins:
        if check in RANGE_CHECKS and m <= 1.0:
            continue  # the search's preload range holds it (build_space)
        if m > 0:
            k = margin_output(check)
            out.append(
                Constraint(
                    k, k, ">=", m, CHECK_RECORDS[check].preload, model.CHECK_LABELS[check], "", 1.0
                )
            )
    return tuple(out)


def limit_constraint(key: str, value: float, name: str, label: str) -> Constraint:
    """The problem limit ``key`` (``LIMIT_TABLE``) at ``value`` [SI] under another name and label
    (the lexicographic objective's floor on its primary)."""
    lim = LIMITS[key]
    return Constraint(name, lim.output, lim.sense, value, lim.preload, label, lim.unit, lim.factor)
