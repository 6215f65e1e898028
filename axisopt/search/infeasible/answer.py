"""The answer to an infeasible problem as plain data (JSON-ready through ``to_dict``): the limits no
combination meets and the closest designs (:class:`Infeasibility`), what to relax for each
(:class:`Relaxation`) and a verified change of the axis or a part (:class:`DesignChange`).  The
modules beside it compute them."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

from ...display import fmt, frame, json_value, one_line


@dataclass(frozen=True)
class DesignChange:
    """An input changed (search.advice) after which the catalogs hold a design: ``key``
    (``axis.max_speed``), its unit, the value and the proposed one in that unit, and what it means
    where the key does not say it (``note``: 'admits a gearbox or belt ...'); or a list of the
    ``catalog:`` section edited (search.widen): ``edit`` 'add' (``values`` added to the list at
    ``key``) or 'remove' (taken out of it), ``value`` and ``to`` NaN."""

    key: str  # the input, e.g. 'axis.max_speed', 'catalog.mountings'
    unit: str  # its display unit (m/min, kg, ...; '' for a list)
    value: float  # the input now, in ``unit``
    to: float  # the proposed value, in ``unit``
    note: str = ""  # what the change means where the key does not say it
    edit: str = ""  # a list of the catalog section: 'add' or 'remove' ('' : a value changed)
    values: tuple = ()  # what the edit adds or removes

    def to_dict(self) -> dict:
        d = {
            "key": self.key,
            "unit": self.unit,
            "value": json_value(self.value),
            "to": json_value(self.to),
            "note": self.note,
        }
        return d | ({"edit": self.edit, "values": list(self.values)} if self.edit else {})


@dataclass
class Relaxation:
    """A limit to relax so that a design becomes feasible
    (:func:`axisopt.search.infeasible.relax.rank_relaxations`)."""

    # where it sits in the problem file, e.g. 'limits.max_cost', 'limits.margins.critical_speed'
    key: str
    label: str
    unit: str  # display unit ('' for a margin)
    value: float  # the limit now (display units)
    # the value the design reaches: the limit relaxed to it makes the design meet it
    relaxed_to: float
    change: float  # relative change of the limit (0.25: 25 %)
    design_rank: int  # the closest design (Infeasibility.closest rank) it frees
    design: object = field(default=None, repr=False, compare=False)  # that Candidate
    together: bool = False  # the design needs other limits relaxed too (the other Relaxations)
    # a check's margin relaxed below 1: the vendor's own rule would not hold
    below_vendor_rule: bool = False

    def to_dict(self) -> dict:
        d = asdict(self)
        d.pop("design")
        d["parts"] = self.design.parts() if self.design is not None else None
        d["mounting"] = self.design.mounting if self.design is not None else None
        return {k: json_value(v) for k, v in d.items()}


@dataclass(repr=False)
class Infeasibility:
    """Why no combination meets the limits."""

    # [(limit name, best achievable value, limit value, unit)] met by no combination
    unmeetable: list
    closest: list  # list[Candidate] with .misses filled
    # what to relax: list[Relaxation], smallest change first, all for one design (search.relax); the
    # closest designs left out because they break a compatibility rule: [(rank, [rules])]; and when
    # every closest design breaks one, the rules the proposed design breaks (relaxing the limits is
    # then not enough)
    relax: list = field(default_factory=list)
    not_relaxable: list = field(default_factory=list)
    relax_blocked_by: list = field(default_factory=list)
    # axis or catalog changes verified to make the problem feasible (search.advice), offered before
    # any relaxation
    design_changes: list = field(default_factory=list)
    # checks the closest designs fail because a catalog row gives no value
    # (search.relax.missing_values): what to give or choose instead, one sentence per check (never a
    # margin relaxed to 0)
    missing: list = field(default_factory=list)
    # the explanation stopped before every block was scored (at the time limit, or after
    # explain.MAX_OPENED combinations where a limit no combination meets makes every design miss, or
    # after explain.MAX_WORK model evaluations): the closest designs are those found by then, the
    # unmeetable limits' best values those reached by then (the least cost exact); ``cut_by``
    # says which: 'time', 'opened' or 'work' ('' : not cut)
    cut: bool = False
    cut_by: str = ""

    def to_dict(self) -> dict:
        return {
            "unmeetable": [
                {
                    "limit": n,
                    "best_achievable": json_value(b),
                    "limit_value": json_value(v),
                    "unit": u,
                }
                for n, b, v, u in self.unmeetable
            ],
            "closest": [c.to_dict() for c in self.closest],
            "relax": [r.to_dict() for r in self.relax],
            "not_relaxable": [{"rank": r, "breaks": list(k)} for r, k in self.not_relaxable],
            "relax_blocked_by": list(self.relax_blocked_by),
            "design_changes": [d.to_dict() for d in self.design_changes],
        } | ({"missing": list(self.missing)} if self.missing else {})

    def to_frame(self):
        """pandas DataFrame of the closest designs, with ``miss <limit> [%]`` per missed limit."""
        return frame([c.row() for c in self.closest])

    def deciding(self, most: int = 3) -> str:
        """The misses that decide, one clause: the limits no combination meets (with the best any
        reaches), else what the closest design misses and by how much (at most ``most`` named); what
        an infeasible answer and a study's reason lead with, before any note."""
        if self.unmeetable:
            shown = [
                f"{n} (limit {fmt(v, u)}, best any reaches {fmt(b, u)})"
                for n, b, v, u in self.unmeetable
            ]
            return (
                "no combination meets "
                + ", ".join(shown[:most])
                + (f" and {len(shown) - most} more" if len(shown) > most else "")
            )
        c = self.closest[0] if self.closest else None
        if c is None or not c.misses:
            return "no combination meets every limit"
        miss = [f"{k} by {fmt(100 * v)} %" for k, v in c.misses.items()]
        return (
            "the closest design misses "
            + ", ".join(miss[:most])
            + (f" and {len(miss) - most} more" if len(miss) > most else "")
        )

    def __repr__(self) -> str:
        unmet = {n: f"limit {fmt(v, u)}, best {fmt(b, u)}" for n, b, v, u in self.unmeetable}
        return one_line(
            "Infeasibility",
            f"{len(self.unmeetable)} limits no combination meets"
            if unmet
            else "every limit met by some combination, not all together",
            unmet,
        )
