"""Result dataclasses of a sizing search (plain data; JSON-ready through ``to_dict``), the statuses
a solve may end in (:data:`STATUS_TABLE`) and the statistics a search stage hands to the certificate
(:class:`SearchStats`)."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field, fields
from types import MappingProxyType

import numpy as np

from ..display import fmt, fmt_objective, frame, html_fields, html_table, json_value, one_line
from ..model.goals import GOALS, RESULT_GOALS
from .certificate import Certificate
from .infeasible.answer import Infeasibility
from .reported import REPORTED


@dataclass
class Binding:
    """A limit at the optimum and what relaxing it would buy."""

    limit: str  # the problem's limit key, e.g. 'min_frequency'
    unit: str  # the limit's display unit (N/um, Hz, EUR, ...)
    value: float  # limit value, in ``unit``
    at_optimum: float  # the best design's value, in ``unit``
    relaxed_to: float | None = None  # the limit relaxed by 10 %, in ``unit``
    # objective change when relaxed, in SolveResult.objective_unit
    objective_gain: float | None = None
    binding: bool = False  # relaxing it improves the objective

    def to_dict(self) -> dict:
        return {k: json_value(v) for k, v in asdict(self).items()}

    def row(self, objective_unit: str = "") -> dict:
        """One table row, the units in the column names (``objective_unit``: the objective's
        unit)."""
        u = f" [{self.unit}]" if self.unit else ""
        gain = (
            f"objective gain [{objective_unit}]"
            if objective_unit not in ("", "-")
            else "objective gain"
        )
        return {
            "limit": self.limit,
            f"value{u}": self.value,
            f"at optimum{u}": self.at_optimum,
            f"relaxed to{u}": self.relaxed_to,
            gain: self.objective_gain,
            "binding": self.binding,
        }

    def to_frame(self):
        """pandas DataFrame of this limit: one row as :meth:`row` (units in the column names)."""
        return frame([self.row()])

    def __repr__(self) -> str:
        u = self.unit if self.unit not in ("", "-") else ""
        gain = (
            ""
            if self.objective_gain is None
            else f"relaxed to {fmt(self.relaxed_to, u)} the objective changes by "
            + (f"{self.objective_gain:+.4g}" if self.binding else "+0")
        )  # a residue within tolerance is none
        return one_line(
            "Binding",
            f"{self.limit} {fmt(self.value, u)}",
            {
                "at optimum": fmt(self.at_optimum, u),
                "": "binding" if self.binding else "not binding",
                "gain": gain,
            },
        )


class Bindings(list):
    """``SolveResult.binding``: a list of :class:`Binding` that also gives a table (``to_frame()``,
    units in the column names, the objective gain in the objective's unit) and an HTML table in
    Jupyter."""

    def __init__(self, items=(), objective_unit: str = ""):
        super().__init__(items)
        self.objective_unit = objective_unit

    def to_frame(self):
        """pandas DataFrame, one row per limit: its name and ``unit`` (the limits differ in unit),
        the limit, the best design's value and the relaxed limit in that unit, the objective gain in
        the objective's unit."""
        cols = ("limit", "unit", "value", "at optimum", "relaxed to", self._gain(), "binding")
        return frame(
            [
                dict(
                    zip(
                        cols,
                        (
                            b.limit,
                            b.unit,
                            b.value,
                            b.at_optimum,
                            b.relaxed_to,
                            b.objective_gain,
                            b.binding,
                        ),
                    )
                )
                for b in self
            ],
            cols,
        )

    def _gain(self) -> str:
        return (
            f"objective gain [{self.objective_unit}]"
            if self.objective_unit not in ("", "-")
            else "objective gain"
        )

    def __repr__(self) -> str:
        binding = [b.limit for b in self if b.binding]
        return one_line(
            "Bindings", f"{len(self)} limits", {"binding": ", ".join(binding) or "none"}
        )

    def _repr_html_(self) -> str:
        rows = [
            {
                "limit": b.limit,
                "unit": b.unit,
                "value": b.value,
                "at optimum": b.at_optimum,
                "relaxed to": b.relaxed_to,
                self._gain(): b.objective_gain,
                "binding": b.binding,
            }
            for b in self
        ]
        return html_table(rows, repr(self))


@dataclass(frozen=True)
class Status:
    """A status a solve may end in (``SolveResult.status``)."""

    name: str
    meaning: str
    found: bool  # a design is returned
    proven: bool  # the design is the proven optimum (or, for 'infeasible', no design exists)


STATUS_TABLE = (
    Status("optimal", "proven optimum over the catalog (gap 0)", True, True),
    Status(
        "feasible",
        "a design found, not proven optimal (Bonmin, or SCIP's point without proof)",
        True,
        False,
    ),
    Status("time_limit", "stopped before the proof; gap > 0 or unknown", True, False),
    Status("solver_failed", "an NLP or MINLP solve failed; see the message", True, False),
    Status("infeasible", "no catalog combination meets every limit", False, True),
)
STATUSES = MappingProxyType({st.name: st for st in STATUS_TABLE})
OPTIMAL, FEASIBLE, TIME_LIMIT, SOLVER_FAILED, INFEASIBLE = (st.name for st in STATUS_TABLE)


@dataclass
class Exact:
    """The exact per-combination optimum of the continuous problem, over K combinations
    (:func:`.preload.exact_solve`, :func:`.exhaustive.grid_solve`).

    ``goals`` holds, per goal of :data:`axisopt.model.goals.RESULT_GOALS` (its key), the (K,) values
    at the chosen preload in the goal's display unit (NaN where not evaluated: no limit or front
    reads the output); each is also the attribute named by the goal's ``field``
    (``ex.min_stiffness``, ``ex.cost``, ...)."""

    idx: np.ndarray  # combination numbers
    feasible: np.ndarray
    preload: np.ndarray  # [N]
    objective: np.ndarray  # display units, -inf where infeasible
    goals: dict  # goal key -> (K,) display values


def _exact_goal(g):
    def values(self) -> np.ndarray:
        return self.goals[g.key]

    values.__doc__ = f"The goal {g.key!r} [{g.unit}] of each combination (``goals[{g.key!r}]``)."
    return property(values)


for _g in RESULT_GOALS:
    setattr(Exact, _g.field, _exact_goal(_g))


@dataclass
class NLPResult:
    """IPOPT's answer for one combination (:func:`.polish.solve_preload`)."""

    success: bool
    status: str
    preload: float  # [N]
    objective: float  # display units


# Candidate fields as table columns, the display unit in the name (Candidate's fields are in these
# units).
CANDIDATE_COLUMNS = (("nut_preload", "nut_preload [N]"),) + tuple(
    (r.field, r.column) for r in REPORTED
)


def _reported_fields(cls):
    """The :data:`REPORTED` values as fields of ``cls`` right after its ``objective`` (before
    ``dataclass``)."""
    ann = {}
    for k, t in cls.__dict__["__annotations__"].items():
        ann[k] = t
        if k == "objective":
            ann.update({r.field: "float" for r in REPORTED})
    cls.__annotations__ = ann
    # the API reference's meanings
    cls.FIELD_NOTES = MappingProxyType({r.field: r.doc for r in REPORTED})
    return cls


@dataclass
@_reported_fields
class Candidate:
    """One design: parts, continuous values and its evaluation summary (display units): after
    ``objective`` one float field per :data:`REPORTED` value (``min_stiffness``, ``min_frequency``,
    ``cost``, ...)."""

    rank: int  # 1: the best
    combination: int  # combination number in the search space
    mounting: str  # 'fixed-free' | 'fixed-supported' | 'fixed-fixed'
    screw: str  # catalog part ids
    nut: str
    bearing: str
    guide: str
    nut_preload: float  # [N]
    objective: float  # in SolveResult.objective_unit
    design: object = field(default=None, repr=False, compare=False)  # axisopt.design.Design
    misses: dict = field(default_factory=dict)  # infeasible problems: limit -> relative miss
    motor: str = ""  # servo motor id ('' without drive search)
    coupling: str = ""
    reduction: str = ""  # reduction id ('' : none, the axis's reduction values)
    # lead accuracy grade the search chose or the problem fixed ('' : the screw's cheapest)
    screw_grade: str = ""
    # the model outputs a problem may limit (model.limits.LIMITS), SI; profile outputs as their
    # minimum over the stroke.  Not in the JSON (the display fields above carry the same values in
    # vendor units).
    outputs: dict = field(default_factory=dict, repr=False, compare=False)
    # a problem with search.counterbalance / search.twin_drive options, Pareto objective: the
    # arrangement this design is of ('' otherwise; not in the JSON then)
    arrangement: str = ""

    def goal(self, key: str) -> float:
        """The value of the goal ``key`` (:data:`axisopt.model.goals.OBJECTIVE_TABLE`) in its
        display unit: its field where the Candidate has one (in the JSON), else from the model's
        outputs (NaN where not evaluated)."""
        g = GOALS[key]
        if g.field in CANDIDATE_FIELDS:
            return getattr(self, g.field)
        return g.value(self.outputs)

    def parts(self) -> dict:
        out = {"screw": self.screw, "nut": self.nut, "bearing": self.bearing, "guide": self.guide}
        if self.motor:
            out["motor"] = self.motor
        if self.coupling:
            out["coupling"] = self.coupling
        if self.reduction:
            out["reduction"] = self.reduction
        return out

    def to_dict(self) -> dict:
        d = asdict(self)
        d.pop("design")
        d.pop("outputs")
        if not d["arrangement"]:
            d.pop("arrangement")
        return {k: json_value(v) for k, v in d.items()}

    def row(self, objective_unit: str | None = None) -> dict:
        """One table row: rank, mounting, parts, the objective (when ``objective_unit`` is given)
        and the values in display units, each unit in its column name; an infeasible problem's
        closest designs add ``miss <limit> [%]`` per missed limit."""
        r = {"rank": self.rank, "mounting": self.mounting} | (
            {"arrangement": self.arrangement} if self.arrangement else {}
        )
        r["screw"] = self.screw
        if self.screw_grade:
            r["grade"] = self.screw_grade
        r.update({"nut": self.nut, "bearing": self.bearing, "guide": self.guide})
        if self.motor:
            r["motor"] = self.motor
        if self.coupling:
            r["coupling"] = self.coupling
        if self.reduction:
            r["reduction"] = self.reduction
        if objective_unit is not None:
            r[
                f"objective [{objective_unit}]" if objective_unit not in ("", "-") else "objective"
            ] = self.objective
        r.update({col: getattr(self, f) for f, col in CANDIDATE_COLUMNS})
        r.update({f"miss {k} [%]": 100.0 * v for k, v in self.misses.items()})
        return r

    def to_frame(self):
        """pandas DataFrame of this design: one row as :meth:`row` (units in the column names)."""
        return frame([self.row()])

    def __repr__(self) -> str:
        misses = ", ".join(f"{k} by {fmt(100 * v)} %" for k, v in self.misses.items())
        shown = {"objective": fmt_objective(self.objective), "preload": fmt(self.nut_preload, "N")}
        shown.update({r.label: fmt(getattr(self, r.field), r.unit) for r in REPORTED if r.label})
        return one_line(
            "Candidate",
            f"rank {self.rank}, {self.mounting} {' / '.join(self.parts().values())}",
            shown | {"misses": misses},
        )

    def _repr_html_(self) -> str:
        return html_table([self.row()], repr(self))


CANDIDATE_FIELDS = frozenset(f.name for f in fields(Candidate))


def _candidate_goal(g):
    def value(self) -> float:
        return self.goal(g.key)

    value.__doc__ = (
        f"The goal {g.key!r} [{g.unit}] (model output {g.output}; NaN where not evaluated)."
    )
    return property(value)


# a goal whose value is not a Candidate field (not in the JSON) reads the outputs under its field
# name
for _g in RESULT_GOALS:
    if _g.field not in CANDIDATE_FIELDS:
        setattr(Candidate, _g.field, _candidate_goal(_g))


@dataclass(repr=False)
class ParetoFront:
    """The non-dominated designs of a multi-objective problem (``objective.mode: pareto``): a
    sequence of :class:`Candidate`, each objective's key, sense and unit."""

    keys: tuple  # objective keys, e.g. ('stiffness', 'cost')
    senses: tuple  # 'max' | 'min' per key
    units: tuple  # display unit per key (N/um, EUR, ...)
    points: list  # list[Candidate], sorted by the first key
    feasible: int = 0  # feasible designs the front was drawn from
    # objective values (columns in ``keys`` order, display units) of up to 4000 feasible designs
    # drawn at random with a fixed seed, for plotting the front against what it dominates; not in
    # the JSON
    cloud: object = None

    def to_dict(self) -> dict:
        """The front as JSON: each point's fields and its ``objectives`` (the value of each key, in
        ``keys`` order and display units: a goal without a field of its own, the positioning error,
        is there too)."""
        return {
            "keys": list(self.keys),
            "senses": list(self.senses),
            "units": list(self.units),
            "feasible": self.feasible,
            "points": [
                p.to_dict() | {"objectives": [json_value(p.goal(k)) for k in self.keys]}
                for p in self.points
            ],
        }

    def __len__(self) -> int:
        return len(self.points)

    def __iter__(self):
        return iter(self.points)

    def __getitem__(self, i):
        return self.points[i]

    def to_frame(self):
        """pandas DataFrame, one row per non-dominated design in front order (units in the column
        names)."""
        return frame([p.row() for p in self.points])

    def __repr__(self) -> str:
        objectives = ", ".join(
            f"{s} {k}" + (f" [{u}]" if u else "")
            for k, s, u in zip(self.keys, self.senses, self.units)
        )
        return one_line(
            "ParetoFront",
            f"{len(self.points)} non-dominated of {self.feasible:,} feasible designs",
            {"objectives": objectives},
        )

    def _repr_html_(self) -> str:
        return html_table([p.row() for p in self.points], repr(self))


@dataclass(repr=False)
class SolveResult:
    """The answer of :func:`axisopt.search.solve`.

    status: one of :data:`STATUS_TABLE` ('optimal', 'feasible', 'time_limit', 'solver_failed',
    'infeasible').
    """

    status: str
    method: str  # 'default' | 'exhaustive' | 'bonmin' | 'scip'
    problem: str  # the problem's name
    objective_label: str  # e.g. 'minimum axial stiffness'
    objective_unit: str  # the objective's display unit (N/um, Hz, EUR ...; '-' for none)
    best: Candidate | None  # the best design (None: infeasible or failed)
    runners_up: list  # list[Candidate], next best designs in rank order
    certificate: Certificate
    time: float  # wall clock [s]
    message: str = ""
    # Bindings: each limit at the optimum, relaxed by 10 %
    binding: list = field(default_factory=list)
    infeasibility: Infeasibility | None = None
    pareto: ParetoFront | None = None
    solver_status: str = ""  # raw status of the underlying solver (Bonmin / IPOPT)
    # a problem with search.counterbalance / search.twin_drive options: the winning arrangement's
    # label and how many arrangements were solved (0: the problem has none; not in the JSON then)
    arrangement: str = ""
    arrangements: int = 0
    # what the search left out of the design and why, a sentence each (the drive with 'drive: no');
    # not in the JSON when empty
    left_out: tuple = ()
    # a stiffness or frequency optimum: a design within the tolerance of it that costs markedly less
    # (sensitivity.cheaper_near: value, cost, best_cost, tolerance, parts), else None
    cheaper: dict | None = None

    def __setattr__(self, name, value):
        # a list of Binding, assigned here or later: a Bindings (to_frame, units)
        if name == "binding":
            value = Bindings(value, getattr(self, "objective_unit", ""))
        object.__setattr__(self, name, value)

    @property
    def objective(self) -> float:
        """The best design's objective [objective_unit] (NaN without one)."""
        return self.best.objective if self.best else float("nan")

    def to_dict(self) -> dict:
        return (
            {
                "status": self.status,
                "method": self.method,
                "problem": self.problem,
                "objective": {
                    "label": self.objective_label,
                    "unit": self.objective_unit,
                    "value": json_value(self.objective),
                },
                "best": self.best.to_dict() if self.best else None,
                "runners_up": [c.to_dict() for c in self.runners_up],
                "certificate": self.certificate.to_dict(),
                "time_s": self.time,
                "message": self.message,
                "solver_status": self.solver_status,
                "binding": [b.to_dict() for b in self.binding],
                "infeasibility": self.infeasibility.to_dict() if self.infeasibility else None,
                "pareto": self.pareto.to_dict() if self.pareto else None,
            }
            | (
                {"arrangement": {"chosen": self.arrangement, "of": self.arrangements}}
                if self.arrangements
                else {}
            )
            | ({"left_out": list(self.left_out)} if self.left_out else {})
            | ({"cheaper": json_value(self.cheaper)} if self.cheaper else {})
        )

    def designs(self) -> list:
        """The designs shown: the Pareto front's points, else best and runners-up, else (infeasible)
        the closest designs."""
        if self.pareto is not None:
            return list(self.pareto.points)
        if self.best is not None:
            return [self.best] + list(self.runners_up)
        return list(self.infeasibility.closest) if self.infeasibility is not None else []

    def to_frame(self):
        """pandas DataFrame, one row per design of :meth:`designs` (units in the column names:
        ``objective [N/um]``, ``min_stiffness [N/um]``, ``cost [EUR]`` ...; the closest designs of
        an infeasible problem with ``miss <limit> [%]``)."""
        unit = None if self.pareto is not None or self.best is None else self.objective_unit
        return frame([c.row(unit) for c in self.designs()])

    def __repr__(self) -> str:
        fields = {}
        head = f"{self.status}, {self.problem!r}"
        if self.pareto is not None:
            fields["Pareto front"] = (
                f"{len(self.pareto)} designs of {self.pareto.feasible:,} feasible"
            )
        elif self.best is not None:
            b = self.best
            unit = self.objective_unit if self.objective_unit != "-" else ""
            fields[self.objective_label] = fmt_objective(b.objective, unit)
            fields["best"] = (
                f"{b.mounting} {' / '.join(b.parts().values())}, preload {fmt(b.nut_preload, 'N')}"
            )
            fields["min stiffness"] = fmt(b.min_stiffness, "N/um")
            fields["1st frequency"] = fmt(b.min_frequency, "Hz")
            fields["cost"] = fmt(b.cost, "EUR")
            fields["designs"] = 1 + len(self.runners_up)
        elif self.infeasibility is not None:
            fields["unmeetable"] = (
                ", ".join(n for n, *_ in self.infeasibility.unmeetable) or "none alone"
            )
            rel = self.infeasibility.relax
            if rel:
                shown = [
                    f"{r.key} {'+' if r.relaxed_to > r.value else '-'}{fmt(100 * r.change)} %"
                    for r in rel
                ]
                fields["relax"] = ", ".join(shown[:3]) + (
                    f" and {len(shown) - 3} more" if len(shown) > 3 else ""
                )
            c = self.infeasibility.closest[0] if self.infeasibility.closest else None
            if c is not None:
                miss = [f"{k} by {fmt(100 * v)} %" for k, v in c.misses.items()]
                fields["closest design misses"] = ", ".join(miss[:3]) + (
                    f" and {len(miss) - 3} more" if len(miss) > 3 else ""
                )
        if self.message and self.status != OPTIMAL:
            fields["note"] = self.message
        fields["proven"] = bool(self.certificate.proven)
        fields["time"] = f"{self.time:.2f} s"
        return one_line("SolveResult", head, fields)

    def _repr_html_(self) -> str:
        head = repr(self)
        return html_fields(
            {
                "status": self.status,
                "problem": self.problem,
                "objective": self.objective_label,
                "method": self.method,
                "proven": self.certificate.proven,
                "time [s]": round(self.time, 2),
            },
            "SolveResult",
        ) + html_table(
            [c.row(None if self.best is None else self.objective_unit) for c in self.designs()],
            head,
        )
