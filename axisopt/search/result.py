"""Result dataclasses of a sizing search (plain data; JSON-ready through ``to_dict``)."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field


@dataclass
class Candidate:
    """One design: parts, continuous values and its evaluation summary (display units)."""

    rank: int
    combination: int  # combination number in the search space
    mounting: str
    screw: str
    nut: str
    bearing: str
    guide: str
    nut_preload: float  # [N]
    objective: float  # in SolveResult.objective_unit
    min_stiffness: float  # [N/um], minimum over the model position grid
    min_frequency: float  # [Hz]
    cost: float  # [EUR]
    moving_mass: float  # [kg]
    total_mass: float  # [kg]
    drag_torque: float  # [N*m]
    life_h: float  # nut L10 life [h]
    design: object = field(default=None, repr=False, compare=False)  # axisopt.design.Design
    misses: dict = field(default_factory=dict)  # infeasible problems: limit -> relative miss
    motor: str = ""  # servo motor id ('' without drive search)
    coupling: str = ""
    # the model outputs a problem may limit (model.limits.LIMITS), SI; profile outputs as their minimum over
    # the stroke.  Not in the JSON (the display fields above carry the same values in vendor units).
    outputs: dict = field(default_factory=dict, repr=False, compare=False)

    def parts(self) -> dict:
        out = {"screw": self.screw, "nut": self.nut, "bearing": self.bearing, "guide": self.guide}
        if self.motor:
            out["motor"] = self.motor
        if self.coupling:
            out["coupling"] = self.coupling
        return out

    def to_dict(self) -> dict:
        d = asdict(self)
        d.pop("design")
        d.pop("outputs")
        return {k: _clean(v) for k, v in d.items()}


@dataclass
class Certificate:
    """How the answer was obtained and how sure it is."""

    combinations: int  # in the search space (mountings x nuts x bearings x guides)
    feasible: int | None  # combinations that pass the preload-independent limits and the preload-dependent
    #                ones at their most favourable preload (exhaustive: exactly feasible); None: not counted (Bonmin)
    pruned_by_bound: int  # feasible combinations never solved because their bound cannot win
    exact_evaluations: int  # combinations whose continuous problem was solved (vectorized 1-D solve)
    nlps_solved: int  # IPOPT solves
    nlp_failures: int
    gap: float  # relative optimality gap; 0 when proven
    proven: bool
    screening_time: float = 0.0  # [s]
    screening_rate: float = 0.0  # combinations / s
    notes: tuple = ()
    # default method: combinations never screened (their (mounting, nut, bearing) block cannot meet the limits
    # or reach the incumbent with any guide and drive), and combinations screened one by one
    pruned_by_block: int = 0
    screened: int | None = None
    # combinations never formed (not in ``combinations``): a (motor, coupling) pair whose coupling is dominated
    # by another or cannot carry the motor's peak torque
    pruned_by_dominance: int = 0
    # the objective and the active limits and checks of the best design that rest on estimated part values (not
    # the vendor's table): model.estimates.Resting.to_dict() each; empty when every active value is a vendor's
    estimated: tuple = ()

    def to_dict(self) -> dict:
        return {k: _clean(v) for k, v in asdict(self).items()}


@dataclass
class Binding:
    """A limit at the optimum and what relaxing it would buy."""

    limit: str
    unit: str
    value: float  # limit value (display units)
    at_optimum: float  # the design's value (display units)
    relaxed_to: float | None = None
    objective_gain: float | None = None  # objective change when relaxed
    binding: bool = False

    def to_dict(self) -> dict:
        return {k: _clean(v) for k, v in asdict(self).items()}


@dataclass
class ParetoFront:
    keys: tuple  # objective keys, e.g. ('stiffness', 'cost')
    senses: tuple  # 'max' | 'min' per key
    units: tuple
    points: list  # list[Candidate], sorted by the first key
    feasible: int = 0
    # objective values (columns in ``keys`` order, display units) of up to 4000 feasible designs drawn at
    # random with a fixed seed, for plotting the front against what it dominates; not in the JSON
    cloud: object = None

    def to_dict(self) -> dict:
        return {"keys": list(self.keys), "senses": list(self.senses), "units": list(self.units),
                "feasible": self.feasible, "points": [p.to_dict() for p in self.points]}


@dataclass
class Infeasibility:
    """Why no combination meets the limits."""

    unmeetable: list  # [(limit name, best achievable value, limit value, unit)] met by no combination
    closest: list  # list[Candidate] with .misses filled

    def to_dict(self) -> dict:
        return {"unmeetable": [{"limit": n, "best_achievable": _clean(b), "limit_value": _clean(v), "unit": u}
                               for n, b, v, u in self.unmeetable],
                "closest": [c.to_dict() for c in self.closest]}


@dataclass
class SolveResult:
    """The answer of :func:`axisopt.search.solve`.

    status: 'optimal' (proven), 'infeasible', 'time_limit' (stopped; gap > 0 or unknown),
    'solver_failed' (an NLP/MINLP failed; see message), 'feasible' (Bonmin: found, not proven).
    """

    status: str
    method: str
    problem: str
    objective_label: str
    objective_unit: str
    best: Candidate | None
    runners_up: list
    certificate: Certificate
    time: float  # wall clock [s]
    message: str = ""
    binding: list = field(default_factory=list)
    infeasibility: Infeasibility | None = None
    pareto: ParetoFront | None = None
    solver_status: str = ""  # raw status of the underlying solver (Bonmin / IPOPT)

    @property
    def objective(self) -> float:
        return self.best.objective if self.best else float("nan")

    def to_dict(self) -> dict:
        return {
            "status": self.status, "method": self.method, "problem": self.problem,
            "objective": {"label": self.objective_label, "unit": self.objective_unit,
                          "value": _clean(self.objective)},
            "best": self.best.to_dict() if self.best else None,
            "runners_up": [c.to_dict() for c in self.runners_up],
            "certificate": self.certificate.to_dict(),
            "time_s": self.time, "message": self.message, "solver_status": self.solver_status,
            "binding": [b.to_dict() for b in self.binding],
            "infeasibility": self.infeasibility.to_dict() if self.infeasibility else None,
            "pareto": self.pareto.to_dict() if self.pareto else None,
        }


def _clean(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, (list, tuple)):
        return [_clean(x) for x in v]
    if isinstance(v, dict):
        return {k: _clean(x) for k, x in v.items()}
    return v
