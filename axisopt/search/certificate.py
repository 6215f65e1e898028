"""What a solve's answer proves and what binds it: the certificate (method, how many combinations were
enumerated, bounded or pruned, the gap, what was assumed) with the statistics a search stage hands to it
(:class:`SearchStats`), and the limits that bind at the optimum (:class:`Binding`, :class:`Bindings`)."""

from __future__ import annotations

from dataclasses import asdict, dataclass, fields

from ..display import fmt, frame, html_table, json_value, one_line


@dataclass
class SearchStats:
    """What a search stage counted (the certificate's search fields; :meth:`Certificate.of`)."""

    combinations: int  # in the search space
    feasible: int | None  # passed screening (exhaustive: exactly feasible); None: not counted
    pruned_by_bound: int  # feasible combinations never solved because their bound cannot win
    exact_evaluations: int  # combinations whose continuous problem was solved
    gap: float  # relative optimality gap; 0 when proven
    proven: bool
    screening_time: float = 0.0  # [s]
    screening_rate: float = 0.0  # combinations / s
    pruned_by_block: int = 0  # default method: combinations never screened (their block cannot win)
    screened: int | None = None  # default method: combinations in the blocks screened
    pruned_by_dominance: int = 0  # combinations never formed (dominated drive pairs)
    # default method: stopped at the time limit (the gap says how far from proven)
    timed_out: bool = False


@dataclass
class Certificate:
    """How the answer was obtained and how sure it is."""

    combinations: int  # in the search space (mountings x nuts x bearings x guides)
    # combinations that pass the preload-independent limits and the preload-dependent ones at their
    # most favourable preload (exhaustive: exactly feasible); None: not counted (Bonmin)
    feasible: int | None
    pruned_by_bound: int  # feasible combinations never solved because their bound cannot win
    # combinations whose continuous problem was solved (vectorized 1-D solve)
    exact_evaluations: int
    nlps_solved: int  # IPOPT solves
    nlp_failures: int
    gap: float  # relative optimality gap; 0 when proven
    proven: bool
    screening_time: float = 0.0  # [s]
    screening_rate: float = 0.0  # combinations / s
    notes: tuple = ()
    # default method: combinations never screened (their (mounting, nut, bearing) block cannot meet
    # the limits
    # or reach the incumbent with any guide and drive), and combinations in the blocks screened (one
    # by one, or a
    # drive at a time where its bounds over the block rule it out: search.drivebounds)
    pruned_by_block: int = 0
    screened: int | None = None
    # combinations never formed (not in ``combinations``): a (motor, coupling) pair whose coupling
    # is dominated
    # by another or cannot carry the motor's peak torque
    pruned_by_dominance: int = 0
    # the objective and the active limits and checks of the best design that rest on estimated part
    # values (not
    # the vendor's table): model.estimates.Resting.to_dict() each; empty when every active value is
    # a vendor's
    estimated: tuple = ()

    @classmethod
    def of(cls, stats: SearchStats, nlps: int = 0, fails: int = 0, notes=()) -> Certificate:
        """The certificate of a search's statistics, its NLP solves and failures and its notes."""
        notes = tuple(notes) + (
            ("the search stopped at the time limit (--time-limit)",) if stats.timed_out else ()
        )
        return cls(
            nlps_solved=nlps,
            nlp_failures=fails,
            notes=notes,
            **{
                f.name: getattr(stats, f.name) for f in fields(SearchStats) if f.name != "timed_out"
            },
        )

    def to_dict(self) -> dict:
        return {k: json_value(v) for k, v in asdict(self).items()}


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
        """One table row, the units in the column names (``objective_unit``: the objective's unit)."""
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
    """``SolveResult.binding``: a list of :class:`Binding` that also gives a table (``to_frame()``, units in the
    column names, the objective gain in the objective's unit) and an HTML table in Jupyter."""

    def __init__(self, items=(), objective_unit: str = ""):
        super().__init__(items)
        self.objective_unit = objective_unit

    def to_frame(self):
        """pandas DataFrame, one row per limit: its name and ``unit`` (the limits differ in unit), the limit, the
        best design's value and the relaxed limit in that unit, the objective gain in the objective's unit."""
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
