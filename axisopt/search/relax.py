"""What to relax when no design meets every limit: the user's relaxable limits ranked by the smallest relative
change that makes a design feasible, with that design.

Read from the explanation's closest designs (:class:`.result.Infeasibility`, their relative misses at the
preload that minimises the total miss): a design becomes feasible when each limit it misses is relaxed by its
miss.  A design that breaks a compatibility rule (the bearing bore does not fit the screw end, the screw is
shorter than the axis needs: :attr:`axisopt.model.limits.Check.relaxable` False) cannot be freed by any
limit: it is proposed only when every closest design breaks one (the one that breaks fewest), and then with the
rules it breaks.  The proposal is the closest design that needs the fewest limits relaxed, then the smallest
total change; its relaxations are listed smallest change first.  The designs considered are the closest
ones by the sum of misses, so a design that one limit alone would free but that misses by more in total may
be left out (the amounts are then upper bounds of what is needed).

A relative miss m of a limit ``value >= L`` is met by L (1 - m), of ``value <= L`` by L (1 + m); a margin (a
vendor check, available / needed >= margin) relaxed below 1 ignores the vendor's own rule, which the
relaxation says (change the axis instead: speed, stroke, loads).
"""

from __future__ import annotations

from ..model.limits import CHECK_RECORDS, LIMITS
from .result import Relaxation

FIT = "bearing bore fits screw"  # the explanation's miss key for a bearing that does not fit the screw end


def relaxable(constraint) -> bool:
    """A problem limit, or the margin of a check that is not a compatibility rule."""
    if constraint.name.startswith("margin_"):
        rec = CHECK_RECORDS.get(constraint.name[len("margin_"):])
        return rec is not None and rec.relaxable
    return constraint.name in LIMITS


def problem_key(constraint) -> str:
    """Where the limit sits in the problem file: ``limits.max_cost``, ``limits.margins.critical_speed``."""
    if constraint.name.startswith("margin_"):
        return f"limits.margins.{constraint.name[len('margin_'):]}"
    return f"limits.{constraint.name}"


def rank_relaxations(constraints, infeasibility) -> tuple[list, list, list]:
    """(relaxations, left_out, blocked_by): the relaxations that make one closest design feasible (smallest
    change first, see the module docstring); the closest designs left out for a compatibility rule they
    break, ``[(rank, [rules])]``; and, when every closest design breaks one, the rules the proposed design
    breaks (no relaxation frees it: its relaxations say what it needs besides)."""
    by_label = {c.label: c for c in constraints}
    options, left_out = [], []
    for cand in infeasibility.closest:
        fixed = [k for k in cand.misses if k not in by_label or not relaxable(by_label[k])]
        need = [(by_label[k], float(m)) for k, m in cand.misses.items() if m > 0 and k not in fixed]
        options.append((len(fixed), len(need), sum(m for _, m in need), cand.rank, cand, need, fixed))
    if not options:
        return [], [], []
    blocked, _, _, rank, cand, need, fixed = min(options, key=lambda o: o[:4])
    left_out = [(o[3], o[6]) for o in options if o[6] and not blocked]
    out = []
    for c, m in sorted(need, key=lambda cm: (cm[1], cm[0].name)):
        lim = c.limit / c.factor
        to = lim * (1.0 - m) if c.sense == ">=" else (lim * (1.0 + m) if c.limit > 0 else m)
        margin = c.name.startswith("margin_")
        out.append(Relaxation(problem_key(c), c.label, c.unit, lim, to, m, rank, cand,
                              together=len(need) > 1, below_vendor_rule=margin and to < 1.0))
    return out, left_out, fixed if blocked else []


__all__ = ["rank_relaxations", "relaxable", "problem_key"]
