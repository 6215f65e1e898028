"""The parts list of a design, as one would order it: each part's id, vendor, quantity and what to
tell the vendor (the screw's bearing span, the nut's preload in round figures, the rails' length).
Nothing here prints.

The nut preload is ordered in round figures (:func:`order_preload`): three significant figures,
never finer than 10 N (3183.3 N -> 3180 N, 12 345 N -> 12 300 N), rounded the way that keeps every
limit and check the exact preload met (an optimum usually sits on one: a higher preload raises the
drag torque and shortens the nut life, a lower one lowers the lift-off margin and the stiffness).
The design is evaluated with the model at both round neighbours; if neither keeps them, a finer step
is tried (1 N, 0.1 N ...).

The rail length is the model's own (``stroke + table_length``,
:func:`axisopt.model.params.design_params`), rounded up to a whole 10 mm: an estimate, not the
vendor's cut length (which follows the rail's hole pitch and end distances in the vendor's catalog;
see docs/assumptions.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

# [N] the nut preload is ordered no finer than this (unless a limit needs it)
PRELOAD_MIN_STEP = 10.0
PRELOAD_DIGITS = 3  # significant figures of an ordered nut preload
# a limit the exact preload misses by less than this (relative) counts as met (it sits on it)
TOLERANCE = 1e-9


def _up(length_m: float, step_mm: float = 10.0) -> float:
    """A length [m] in mm rounded up to a whole ``step_mm``."""
    return step_mm * math.ceil(round(length_m * 1e3 / step_mm, 9))


def preload_step(preload: float) -> float:
    """The round step [N] a preload of ``preload`` [N] is ordered in: :data:`PRELOAD_DIGITS`
    significant figures, at least :data:`PRELOAD_MIN_STEP`."""
    if not (math.isfinite(preload) and preload > 0):
        return PRELOAD_MIN_STEP
    return max(PRELOAD_MIN_STEP, 10.0 ** (math.floor(math.log10(preload)) - PRELOAD_DIGITS + 1))


@dataclass(frozen=True)
class OrderedPreload:
    """A nut preload in round figures.  ``value`` and ``exact`` [N]; ``step`` [N] the rounding step
    used;
    ``nearest_breaks``: the limits or checks the nearest round value would have broken (the value
    went the other way), empty when it is the nearest."""

    value: float
    exact: float
    step: float
    nearest_breaks: tuple = ()

    @property
    def moved(self) -> bool:
        return self.value != self.exact

    @property
    def text(self) -> str:
        """The value in N as ordered (``1,140``)."""
        decimals = max(0, -math.floor(math.log10(self.step) + 1e-9))
        return f"{self.value:,.{decimals}f}"

    def note(self) -> str:
        """What the rounding did, for a comment beside the value ('' when it did not move)."""
        if not self.moved:
            return ""
        way = "down" if self.value < self.exact else "up"
        s = f"{self.exact:.6g} N rounded {way} to {self.step:g} N"
        if self.nearest_breaks:
            s += (
                f" ({self.value + (self.step if way == 'down' else -self.step):.6g} N would break "
                f"{', '.join(self.nearest_breaks)})"
            )
        return s


def _name(name: str) -> str:
    """A limit's key as the problem file writes it, a check as 'the <check> check'."""
    from ..model.limits import CHECK_RECORDS, check_name

    return f"the {CHECK_RECORDS[check_name(name)].short} check" if check_name(name) else name


def _constraints(problem):
    """What the ordered preload must keep: the problem's limits and check margins (``problem`` None:
    every vendor check at margin 1), the preload ceiling's check included."""
    from ..model import CHECK_LABELS, CHECKS
    from ..model.limits import CHECK_RECORDS, margin_output
    from ..search.task.constraints import Constraint, build_constraints

    def margin(check, m):
        name = margin_output(check)
        return Constraint(
            name, name, ">=", m, CHECK_RECORDS[check].preload, CHECK_LABELS[check], "", 1.0
        )

    if problem is None:
        return tuple(margin(c, 1.0) for c in CHECKS)
    cons = build_constraints(problem)
    m = problem.margin_map.get("nut_preload", 1.0)
    if m > 0 and not any(c.name == margin_output("nut_preload") for c in cons):
        cons += (margin("nut_preload", m),)
    return cons


def _preload_range(design, problem) -> tuple:
    """The preloads [N] the search allows the design's nut: its catalog range, within the problem's
    ``continuous.nut_preload`` for a preloaded nut (``axisopt.search.parts``)."""
    nut = design.nut
    lo, hi = float(nut.get("preload_min", 0.0)), float(nut.get("preload_max", math.inf))
    lo, hi = (0.0 if not math.isfinite(lo) else lo), (math.inf if not math.isfinite(hi) else hi)
    if problem is not None and nut.get("type") != "single":
        lo, hi = max(lo, problem.preload_min), min(hi, problem.preload_max)
    return lo, hi


def order_preload(design, problem=None) -> OrderedPreload:
    """The nut preload of ``design`` in round figures (module docstring) that keeps every limit of
    ``problem`` (None: every vendor check) the design's exact preload meets, within the nut's
    catalog preload range (and the problem's ``continuous.nut_preload``).  A design without its own
    preload (the catalog's) keeps it."""
    from ..model import evaluate

    exact = float(design.preload)
    if design.nut_preload is None or not (math.isfinite(exact) and exact > 0):
        return OrderedPreload(exact, exact, preload_step(exact))
    cons = _constraints(problem)
    lo, hi = _preload_range(design, problem)
    if not lo <= exact <= hi:
        # a design given outside the range: the rounding keeps the limits only
        lo, hi = 0.0, math.inf

    def values(p):
        return evaluate(replace(design, nut_preload=p)).values

    # what the exact preload meets (an optimum may sit on a limit within rounding)
    base = values(exact)
    keep = [
        c for c in cons if c.ok(c.value(base)) or float(c.violation(c.value(base))) <= TOLERANCE
    ]

    def broken(p) -> tuple:
        if not lo <= p <= hi or p <= 0:
            return ("the nut's preload range",)
        v = values(p)
        return tuple(_name(c.name) for c in keep if not c.ok(c.value(v)))

    step = preload_step(exact)
    while step >= 1e-3:
        near = step * round(exact / step)
        if near == exact:
            return OrderedPreload(exact, exact, step)
        missed = broken(near)
        if not missed:
            return OrderedPreload(near, exact, step)
        other = near + step if near < exact else near - step
        if not broken(other):
            return OrderedPreload(other, exact, step, missed)
        step /= 10.0
    return OrderedPreload(exact, exact, step)


def parts_list(design, problem=None) -> list[dict]:
    """One row per part to order: ``part``, ``id``, ``vendor``, ``quantity`` and ``order`` (the
    values the order needs: lengths in mm, the preload in N, rounded by :func:`order_preload`
    against ``problem``'s limits, or against the vendor checks without one)."""
    a = design.axis
    # a twin-drive gantry orders two of each
    drives = 2 if getattr(a, "twin_drive", None) is not None else 1
    rows = []

    def add(slot: str, qty: int, note: str) -> None:
        part = getattr(design, slot)
        if part is not None:
            rows.append(
                {
                    "part": slot,
                    "id": str(part["id"]),
                    "vendor": str(part.get("vendor", "")),
                    "quantity": qty,
                    "order": note,
                }
            )

    add(
        "screw",
        drives,
        f"bearing span {_up(a.span):,.0f} mm (stroke {a.stroke * 1e3:,.0f} mm); end journals "
        "machined to the support bearings",
    )
    add("nut", drives, f"preload {order_preload(design, problem).text} N")
    sets = 2 if a.mounting == "fixed-fixed" else 1
    add(
        "bearing",
        drives * sets,
        f"{a.mounting}: {sets} set{'s' if sets > 1 else ''} per screw"
        + (
            ""
            if a.mounting == "fixed-fixed"
            else " (the free or supported end's bearing is not sized here)"
        ),
    )
    if design.guide is not None:
        add("guide", a.guide_blocks, "blocks")
        rows.append(
            {
                "part": "guide rail",
                "id": str(design.guide["id"]),
                "vendor": str(design.guide.get("vendor", "")),
                "quantity": a.rails,
                "order": f"length {_up(a.stroke + a.table_length):,.0f} mm (estimate: "
                "stroke + table length; cut to the vendor's hole pitch)",
            }
        )
    add("motor", drives, "")
    add("coupling", drives, "")
    add("reduction", drives, "")
    return rows


__all__ = [
    "parts_list",
    "order_preload",
    "OrderedPreload",
    "preload_step",
    "PRELOAD_MIN_STEP",
    "PRELOAD_DIGITS",
]
