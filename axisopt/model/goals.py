"""The goals a problem may optimise (:data:`OBJECTIVE_TABLE`: one :class:`Goal` per objective, its
sense, unit, the result field that carries it and its printed column) and the vocabularies derived
from it: the objective modes, the weighted and Pareto keys.  The problem reader, the search's
objective functions, the results and the printed tables all read this one table."""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

from .limits import LIMITS
from .outputs import PROFILE as PROFILE_OUTPUTS


@dataclass(frozen=True)
class Objective:
    """What to maximise.  Performance values are the minima over the stroke (model position
    grid)."""

    mode: str = "stiffness"
    weights: tuple = (("stiffness", 1.0), ("frequency", 1.0))  # weighted
    scale: tuple = (("stiffness", 100e6), ("frequency", 100.0))  # weighted, SI
    order: tuple = ("stiffness", "frequency")  # lexicographic
    tolerance: float = 0.0  # lexicographic, relative
    pareto: tuple = ()  # pareto keys

    @property
    def label(self) -> str:
        if self.mode == "weighted":
            return " + ".join(
                f"{w:g}*{k}/{_fmt_si(k, s)}" for (k, w), (_, s) in zip(self.weights, self.scale)
            )
        if self.mode == "lexicographic":
            return (
                " then ".join(
                    f"max min {k}" if GOALS[k].sense == "max" else f"least {k}" for k in self.order
                )
                + f" (tolerance {self.tolerance:g})"
            )
        if self.mode == "pareto":
            return "Pareto front of " + ", ".join(self.pareto)
        g = GOALS[self.mode]
        return f"maximise minimum {g.what}" if g.sense == "max" else f"minimise {g.what}"


def _fmt_si(key, value):
    g = GOALS[key]
    return f"{value / g.factor:g} {g.unit}"


@dataclass(frozen=True)
class Column:
    """A goal's column in the printed candidate and Pareto tables (``report.solve``):
    ``format(value, f">{width}{spec}")`` under ``header``, in every table (``always``) or only in a
    front's that has the goal as a key."""

    header: str  # e.g. 'k N/um'
    width: int
    spec: str  # format spec after the width, e.g. '.1f', ',.0f'
    always: bool = True


# a goal's roles: a scalar objective mode of its own, combinable in a weighted or lexicographic
# objective, allowed in a Pareto front, carried by every search result (under :attr:`Goal.field`)
ROLE_MODE, ROLE_PERFORMANCE, ROLE_PARETO, ROLE_RESULT = "mode", "performance", "pareto", "result"


@dataclass(frozen=True)
class Goal:
    """One objective a problem may name: maximised or minimised, the minimum over the stroke of a
    profile.

    key         : its name in the problem file (``objective: {mode: key}``, ``pareto: [...]``)
    limit       : the limit on the same model output (``model.limits.LIMIT_TABLE``): the output, its
                  display unit and factor, and the sense (a ``>=`` limit: maximised) come from there
    what        : what it is, for the mode's label (``maximise minimum <what>``) and the search's
                  label (``minimum <what>`` or ``least <what>``); '' for a goal that is no mode
    roles       : of ``ROLE_MODE``, ``ROLE_PERFORMANCE``, ``ROLE_PARETO``, ``ROLE_RESULT``
    column      : its column in the printed candidate and Pareto tables (None: not printed there)
    """

    key: str
    limit: str
    what: str = ""
    roles: tuple = ()
    column: Column | None = None

    @property
    def field(self) -> str:
        """The name of its value on a search result ('' if none: the value is only the objective):
        the exact solves (:class:`axisopt.search.result.Exact`) and every design
        (:class:`axisopt.search.result.Candidate`) carry it in display units (a profile's minimum
        over the stroke over the display factor), named after its limit: ``min_stiffness``, or
        without ``max_`` (``cost``)."""
        if ROLE_RESULT not in self.roles:
            return ""
        return self.limit if self.limit.startswith("min_") else self.limit.removeprefix("max_")

    @property
    def mode(self) -> bool:
        """A scalar objective mode of its own."""
        return ROLE_MODE in self.roles

    @property
    def performance(self) -> bool:
        """Combinable in a weighted or lexicographic objective."""
        return ROLE_PERFORMANCE in self.roles

    @property
    def pareto(self) -> bool:
        """Allowed in a Pareto front."""
        return ROLE_PARETO in self.roles

    @property
    def label(self) -> str:
        """The search's objective label of a scalar mode ('' without ``what``)."""
        if not self.what:
            return ""
        return f"{'minimum' if self.sense == 'max' else 'least'} {self.what}"

    @property
    def output(self) -> str:
        return LIMITS[self.limit].output

    @property
    def unit(self) -> str:
        return LIMITS[self.limit].unit

    @property
    def factor(self) -> float:
        """SI per display unit."""
        return LIMITS[self.limit].factor

    def value(self, outputs: dict) -> float:
        """The goal's value in its display unit from a design's model outputs (SI, a profile's
        minimum over the
        stroke: ``Candidate.outputs``); NaN where the output was not evaluated."""
        return outputs.get(self.output, math.nan) / self.factor

    @property
    def sense(self) -> str:
        """'max' or 'min'."""
        return "max" if LIMITS[self.limit].sense == ">=" else "min"

    @property
    def profile(self) -> bool:
        """Its output is a profile over the stroke (the goal's value is the profile's minimum)."""
        return self.output in PROFILE_OUTPUTS


_ALL = (ROLE_MODE, ROLE_PERFORMANCE, ROLE_PARETO, ROLE_RESULT)
_FRONT = (ROLE_PARETO, ROLE_RESULT)  # a Pareto key only (no mode of its own)
_ERROR_COLUMN = Column("error um", 10, ".1f", always=False)  # only in a front that has it as a key
# Every objective, declared once: the problem reader's modes and Pareto keys, the labels, the
# search's objective functions (axisopt.search.task.objective), the values the exact solves and the
# designs carry (axisopt.search.result.Exact and Candidate, under ``field``), the Pareto front's
# senses, units and values and the printed tables' columns derive from it.  A new objective: one
# Goal here plus the physics of its output (and its limit in LIMIT_TABLE).  The positioning budget's
# worst-case total (model.accuracy) is minimised: it falls with the nut preload, so a combination's
# front point stays its highest feasible preload; the search chooses the grade.
# fmt: off
OBJECTIVE_TABLE = (
    Goal("stiffness", "min_stiffness", "axial stiffness", _ALL, Column("k N/um", 9, ".1f")),
    Goal("frequency", "min_frequency", "first natural frequency", _ALL, Column("f Hz", 8, ".1f")),
    Goal("tool_stiffness", "min_tool_stiffness", "stiffness at the tool", (ROLE_MODE,)),
    Goal("kv", "min_kv", "achievable position-loop gain Kv", (ROLE_MODE,)),
    Goal("cost", "max_cost", "cost", _ALL, Column("cost EUR", 10, ",.0f")),
    Goal("total_mass", "max_total_mass", "", _FRONT, Column("mass kg", 9, ".1f")),
    Goal("moving_mass", "max_moving_mass", "moving mass", _ALL),
    Goal("positioning_error", "max_positioning_error", "", _FRONT, _ERROR_COLUMN),
)
# fmt: on


GOALS = MappingProxyType({g.key: g for g in OBJECTIVE_TABLE})


# the goals whose values a search result carries
RESULT_GOALS = tuple(g for g in OBJECTIVE_TABLE if g.field)


PARETO_ALIASES = MappingProxyType({"mass": "total_mass"})


COMBINED_MODES = ("weighted", "lexicographic", "pareto")  # modes built from the goals


PERFORMANCE = tuple(g.key for g in OBJECTIVE_TABLE if g.performance)


# the goals a weighted sum adds (each maximised; a least cost or mass is a mode or a lexicographic
# stage)
WEIGHTED = tuple(g.key for g in OBJECTIVE_TABLE if g.performance and g.sense == "max")


OBJECTIVE_MODES = (
    PERFORMANCE
    + COMBINED_MODES
    + tuple(g.key for g in OBJECTIVE_TABLE if g.mode and not g.performance)
)


PARETO_KEYS = tuple(g.key for g in OBJECTIVE_TABLE if g.pareto) + tuple(PARETO_ALIASES)
