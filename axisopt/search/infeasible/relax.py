"""What to relax when no design meets every limit: the user's relaxable limits ranked by the
smallest relative change that makes a design feasible, with that design.

Read from the explanation's closest designs (:class:`.answer.Infeasibility`, their relative misses
at the preload that minimises the total miss): a design becomes feasible when each limit it misses
is relaxed by its miss.  A design that breaks a compatibility rule (the bearing bore does not fit
the screw end, the screw is shorter than the axis needs:
:attr:`axisopt.model.limits.Check.relaxable` False) cannot be freed by any
limit: it is proposed only when every closest design breaks one (the one that breaks fewest), and
then with the rules it breaks.  The proposal is the closest design that needs the fewest limits
relaxed, then the smallest total change; its relaxations are listed smallest change first.  The
designs considered are the closest ones by the sum of misses, so a design that one limit alone would
free but that misses by more in total may be left out (the amounts are then upper bounds of what is
needed).

A relative miss m of a limit ``value >= L`` is met by L (1 - m), of ``value <= L`` by L (1 + m); a
margin (a vendor check, available / needed >= margin) relaxed below 1 ignores the vendor's own rule,
which the relaxation says (change the axis instead: speed, stroke, loads).  The user's own limits
are listed first, the vendor margins last, and no margin is proposed below :data:`MARGIN_FLOOR`
(0.95): a design that needs one lower breaks a rule no relaxation frees, as a compatibility rule.  A
margin is never proposed at 0 or below (a miss of 100 % or more: the check disabled, not relaxed):
such a miss counts as a rule no limit frees, like a compatibility rule.  Where the available value
is 0 because the catalog row gives none (a motor without a brake torque on an axis that needs a
holding brake: :data:`MISSING`), :func:`missing_values` says which rows lack it and what to do
instead.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from ...model.limits import CHECK_RECORDS, LIMITS, check_name
from .answer import Relaxation

# the explanation's miss key for a bearing that does not fit the screw end
FIT = "bearing bore fits screw"


@dataclass(frozen=True)
class Missing:
    """A check whose available value is a catalog cell that a row may leave empty (the model then
    takes 0)."""

    check: str  # the check (model.limits.CHECK_RECORDS)
    slot: str  # the design's part slot (Design attribute)
    table: str  # the catalog table (catalogs/<table>.csv)
    column: str  # its column header, with the unit
    what: str  # what the cell is
    instead: str  # the other way out


# model.params: a motor row without brake_torque holds with 0 N.m (the brake check then fails on a
# vertical axis)
MISSING = MappingProxyType(
    {
        m.check: m
        for m in (
            Missing(
                "brake_holding",
                "motor",
                "motors",
                "brake_torque [N.m]",
                "brake torque",
                "pick a motor with a holding brake",
            ),
        )
    }
)


def _unfreed(constraint, miss: float) -> bool:
    """A margin that only 0 or less would free (a miss of 100 % or more): never proposed."""
    return (
        check_name(constraint.name) is not None and constraint.sense == ">=" and miss >= 1.0 - 1e-12
    )


# the lowest vendor margin ever proposed: 5 % below the vendor's rule (a rule relaxed further is a
# different part, speed or load, which the design changes of search.advice propose first)
MARGIN_FLOOR = 0.95


def _beyond_floor(constraint, miss: float) -> bool:
    """A vendor margin that only a value below :data:`MARGIN_FLOOR` would free: never proposed (the
    design breaks a vendor's rule no relaxation frees, as a compatibility rule)."""
    if not (constraint.name.startswith("margin_") and constraint.sense == ">="):
        return False
    return constraint.limit / constraint.factor * (1.0 - miss) < MARGIN_FLOOR - 1e-12


def relaxable(constraint) -> bool:
    """A problem limit, or the margin of a check that is not a compatibility rule."""
    if check_name(constraint.name) is not None:
        rec = CHECK_RECORDS.get(check_name(constraint.name))
        return rec is not None and rec.relaxable
    return constraint.name in LIMITS


def problem_key(constraint) -> str:
    """Where the limit sits in the problem file: ``limits.max_cost``,
    ``limits.margins.critical_speed``."""
    if check_name(constraint.name) is not None:
        return f"limits.margins.{check_name(constraint.name)}"
    return f"limits.{constraint.name}"


def rank_relaxations(constraints, infeasibility) -> tuple[list, list, list]:
    """(relaxations, left_out, blocked_by): the relaxations that make one closest design feasible
    (smallest change first, see the module docstring); the closest designs left out for a
    compatibility rule they break, ``[(rank, [rules])]``; and, when every closest design breaks one,
    the rules the proposed design breaks (no relaxation frees it: its relaxations say what it needs
    besides)."""
    by_label = {c.label: c for c in constraints}
    options, left_out = [], []
    for cand in infeasibility.closest:
        fixed = [
            k
            for k, m in cand.misses.items()
            if k not in by_label
            or not relaxable(by_label[k])
            or _unfreed(by_label[k], float(m))
            or _beyond_floor(by_label[k], float(m))
        ]
        need = [(by_label[k], float(m)) for k, m in cand.misses.items() if m > 0 and k not in fixed]
        options.append(
            (len(fixed), len(need), sum(m for _, m in need), cand.rank, cand, need, fixed)
        )
    if not options:
        return [], [], []
    blocked, _, _, rank, cand, need, fixed = min(options, key=lambda o: o[:4])
    left_out = [(o[3], o[6]) for o in options if o[6] and not blocked]
    out = []
    # the user's own limits first, the vendor margins last (labelled, never below MARGIN_FLOOR);
    # each smallest first
    for c, m in sorted(need, key=lambda cm: (cm[0].name.startswith("margin_"), cm[1], cm[0].name)):
        lim = c.limit / c.factor
        to = lim * (1.0 - m) if c.sense == ">=" else (lim * (1.0 + m) if c.limit > 0 else m)
        margin = check_name(c.name) is not None
        out.append(
            Relaxation(
                problem_key(c),
                c.label,
                c.unit,
                lim,
                to,
                m,
                rank,
                cand,
                together=len(need) > 1,
                below_vendor_rule=margin and to < 1.0,
            )
        )
    return out, left_out, fixed if blocked else []


def _rows_named(need: Missing, series: dict, space) -> tuple:
    """(the rows that give no ``need.what``, by series: every searched row of a series when
    ``space`` shows none of them gives it, else the part ids; whether more than one)."""
    col = need.column.split(" ")[0]
    table = getattr(space, f"{need.slot}s", None) if space is not None else None
    named, many = [], len(series) > 1
    for name, ids in sorted(series.items()):
        of = table.isin("series", (name,)) if table is not None and len(table) else None
        if of is not None and of.any() and not np.isfinite(table.number(col)[of]).any():
            named.append(f"the {need.slot} rows of series {name}")
            many = True
        else:
            named.append(f"{need.slot} {', '.join(sorted(ids))} ({name})")
            many = many or len(ids) > 1
    return " and ".join(named), many


def missing_values(constraints, infeasibility, space=None) -> list:
    """The checks the closest designs fail by 100 % or more (their available value is 0: no margin
    above 0 frees them), one sentence per check: where the value is a catalog cell the rows leave
    empty (:data:`MISSING`), which rows (``space``: the search space, to say when every searched row
    of a series lacks it) and the two ways out; otherwise which design reaches 0.  [] when no
    closest design fails one so."""
    by_label = {c.label: c for c in constraints}
    rows: dict = {}
    other: dict = {}
    for cand in infeasibility.closest:
        for label, m in cand.misses.items():
            c = by_label.get(label)
            if c is None or not _unfreed(c, float(m)):
                continue
            need = MISSING.get(check_name(c.name))
            row = (
                getattr(cand.design, need.slot, None)
                if need is not None and cand.design is not None
                else None
            )
            if row is not None and not math.isfinite(float(row[need.column.split(" ")[0]])):
                rows.setdefault(need, {}).setdefault(str(row["series"]), set()).add(str(row["id"]))
            else:
                other.setdefault(c.label, cand.rank)
    out = []
    for need, series in rows.items():
        named, many = _rows_named(need, series, space)
        out.append(
            f"{named} give{'' if many else 's'} no {need.what} (catalogs/{need.table}.csv "
            f"{need.column}): the {CHECK_RECORDS[need.check].short} check cannot pass at any "
            f"margin above 0; give it, or {need.instead}"
        )
    out += [
        f"{label} is 0 on design #{rank}: no margin above 0 frees it"
        for label, rank in other.items()
    ]
    return out


__all__ = [
    "rank_relaxations",
    "relaxable",
    "problem_key",
    "missing_values",
    "MISSING",
    "MARGIN_FLOOR",
]
