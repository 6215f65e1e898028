"""What a solve's answer proves: the certificate (method, how many combinations were enumerated,
bounded or pruned, the gap, what was assumed) with the statistics a search stage hands to it
(:class:`SearchStats`).  The limits that bind at the optimum are the result's
(:class:`.result.Binding`)."""

from __future__ import annotations

from dataclasses import asdict, dataclass, fields

from ..display import json_value


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
    # the limits or reach the incumbent with any guide and drive), and combinations in the blocks
    # screened (one by one, or a drive at a time where its bounds over the block rule it out:
    # search.drivebounds)
    pruned_by_block: int = 0
    screened: int | None = None
    # combinations never formed (not in ``combinations``): a (motor, coupling) pair whose coupling
    # is dominated by another or cannot carry the motor's peak torque
    pruned_by_dominance: int = 0
    # the objective and the active limits and checks of the best design that rest on estimated part
    # values (not the vendor's table): model.estimates.Resting.to_dict() each; empty when every
    # active value is a vendor's
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
