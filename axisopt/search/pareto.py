"""Exact Pareto front over two or more of the Pareto goals (``axisopt.model.goals.OBJECTIVE_TABLE``:
minimum stiffness, minimum frequency, cost, masses, positioning error).

The performance measures improve with the nut preload (stiffness and frequency grow, the positioning
error falls) and cost and mass do not depend on it, so each combination contributes one point: its
best preload (the upper end of its feasible preload interval).  Every screened combination is solved
exactly (vectorized), then :func:`nondominated` keeps the exact non-dominated set (a point is
dropped only if another is at least as good in every objective and strictly better in one; equal
points are all kept).
"""

from __future__ import annotations

import time

import numpy as np

from ..model.goals import GOALS
from .bounds import block_bounds
from .candidates import make_candidate
from .certificate import Certificate, SearchStats
from .exhaustive import exhaustive_search
from .parts import build_space
from .preload import concat_exact, exact_solve
from .result import INFEASIBLE, OPTIMAL, TIME_LIMIT, ParetoFront, SolveResult
from .screen import screen_nuts
from .task.constraints import build_constraints
from .task.objective import objective_spec

# per Pareto key (axisopt.model.goals.OBJECTIVE_TABLE): maximised or minimised, display unit, the
# name of its value on a Candidate or Exact (``Candidate.goal(key)`` and ``Exact.goals[key]`` read
# it by key)
SENSE = {k: g.sense for k, g in GOALS.items() if g.pareto}
UNIT = {k: g.unit for k, g in GOALS.items() if g.pareto}
FIELD = {k: g.field for k, g in GOALS.items() if g.pareto}


CLOUD = 4000  # feasible designs drawn for the plot of the front


def nondominated(points: np.ndarray, block: int = 2048) -> np.ndarray:
    """Indices of the non-dominated rows of ``points`` (n x d), every column maximised.

    Rows are processed in decreasing lexicographic order, so a row can only be dominated by an
    earlier row or an equal-first-column one; each block is checked against the front found so far
    and against itself (vectorized comparisons, no per-point Python loop).
    """
    P = np.asarray(points, dtype=float)
    n, d = P.shape
    if n == 0:
        return np.zeros(0, np.int64)
    order = np.lexsort(tuple(-P[:, j] for j in range(d - 1, -1, -1)))
    Q = P[order]
    front_rows = np.zeros((0, d))
    front_idx = []
    for s in range(0, n, block):
        Bk = Q[s : s + block]
        dom = np.zeros(len(Bk), bool)
        for f0 in range(0, len(front_rows), 1024):
            F = front_rows[f0 : f0 + 1024]
            ge = np.ones((len(F), len(Bk)), bool)
            gt = np.zeros((len(F), len(Bk)), bool)
            for j in range(d):
                ge &= F[:, None, j] >= Bk[None, :, j]
                gt |= F[:, None, j] > Bk[None, :, j]
            dom |= (ge & gt).any(0)
        cand = np.nonzero(~dom)[0]
        C = Bk[cand]
        ge = np.ones((len(C), len(C)), bool)
        gt = np.zeros((len(C), len(C)), bool)
        for j in range(d):
            ge &= C[:, None, j] >= C[None, :, j]
            gt |= C[:, None, j] > C[None, :, j]
        keep = cand[~(ge & gt).any(0)]
        front_rows = np.concatenate([front_rows, Bk[keep]])
        front_idx.extend((order[s + keep]).tolist())
    return np.asarray(sorted(front_idx), dtype=np.int64)


def screen_feasible_blocks(space, constraints, spec, deadline: float | None = None):
    """Screen only the (mounting, nut, bearing) blocks that some guide and drive could make feasible
    (:func:`.bounds.block_bounds`; every front point is feasible, so no bound on the objectives is
    used).  ``deadline`` (a time.perf_counter() value): stop there with the blocks screened so far.
    Returns (survivors' combination numbers, seconds, combinations screened, whether the deadline
    cut it)."""
    t0 = time.perf_counter()
    GD = space.shape[3]
    idx = []
    screened = 0
    step = space.nuts_per_block
    cut = False
    for mi, (ok, _bound) in enumerate(block_bounds(space, constraints, spec)):
        nuts = np.nonzero(ok.any(axis=1))[0]
        for s in range(0, len(nuts), step):
            if deadline is not None and time.perf_counter() > deadline:
                cut = True
                break
            nn = nuts[s : s + step]
            screened += int(ok[nn].sum()) * GD
            i, _ = screen_nuts(space, mi, nn, constraints, spec, premask=ok[nn])
            idx.append(i)
        if cut:
            break
    out = np.concatenate(idx) if idx else np.zeros(0, np.int64)
    return out, time.perf_counter() - t0, screened, cut


def _solve_screened(space, constraints, spec, deadline: float):
    """The default method's front search: the feasible blocks screened, their survivors solved
    exactly, both stopped at ``deadline``.  Returns (Exact, SearchStats)."""
    idx, t_screen, screened, cut = screen_feasible_blocks(space, constraints, spec, deadline)
    parts, done = [], 0
    for s in range(0, len(idx), 200000):
        if time.perf_counter() > deadline:
            cut = True
            break
        parts.append(exact_solve(space, idx[s : s + 200000], constraints, spec))
        done = min(len(idx), s + 200000)
    ex = concat_exact(parts) if parts else exact_solve(space, [], constraints, spec)
    info = SearchStats(
        combinations=space.size,
        feasible=int(done),
        pruned_by_bound=0,
        exact_evaluations=int(done),
        gap=float("nan") if cut else 0.0,
        proven=not cut,
        screening_time=t_screen,
        screening_rate=space.size / max(t_screen, 1e-9),
        screened=screened,
        pruned_by_block=0 if cut else space.size - screened,
        timed_out=cut,
    )
    return ex, info


def solve_pareto(
    problem,
    method: str = "default",
    t0: float | None = None,
    max_points: int = 200,
    time_limit: float = 100.0,
) -> SolveResult:
    """The exact front of ``problem.objective.pareto`` (module docstring).  ``time_limit`` [s] from
    ``t0`` bounds the whole search: a front cut by it is the front of the combinations solved so far
    (status 'time_limit', not proven), and no infeasibility is claimed when none was found in
    time."""
    t0 = time.perf_counter() if t0 is None else t0
    deadline = t0 + time_limit
    keys = problem.objective.pareto
    space = build_space(problem)
    constraints = build_constraints(problem)
    spec = objective_spec("stiffness")
    if method == "exhaustive":
        ex, info = exhaustive_search(space, constraints, spec, deadline=deadline)
    else:
        ex, info = _solve_screened(space, constraints, spec, deadline)
    info.pruned_by_dominance = space.pruned_by_dominance
    ok = np.nonzero(ex.feasible)[0]
    cols = []
    for k in keys:
        v = ex.goals[k][ok]
        cols.append(v if SENSE[k] == "max" else -v)
    P = np.column_stack(cols) if len(ok) else np.zeros((0, len(keys)))
    front = ok[nondominated(P)] if len(ok) else np.zeros(0, np.int64)
    # sort by the first objective (best first)
    first = ex.goals[keys[0]][front]
    front = front[np.argsort(-first if SENSE[keys[0]] == "max" else first, kind="stable")]
    notes = []
    if len(front) > max_points:
        notes.append(
            f"front has {len(front)} points; the first {max_points} are evaluated in full, all are "
            "in the JSON point count"
        )
    pts = [
        make_candidate(space, int(ex.idx[j]), float(ex.preload[j]), spec, rank=r + 1)
        for r, j in enumerate(front[:max_points])
    ]
    info.feasible = int(len(ok))
    cert = Certificate.of(info, 0, 0, notes + [f"front size {len(front)}"])
    sample = ok if len(ok) <= CLOUD else np.random.default_rng(0).choice(ok, CLOUD, replace=False)
    cloud = np.column_stack([ex.goals[k][sample] for k in keys]) if len(ok) else None
    pf = ParetoFront(
        tuple(keys),
        tuple(SENSE[k] for k in keys),
        tuple(UNIT[k] for k in keys),
        pts,
        feasible=int(len(ok)),
        cloud=cloud,
    )
    if info.timed_out:
        status = TIME_LIMIT
    else:
        status = OPTIMAL if len(front) else INFEASIBLE
    res = SolveResult(
        status,
        method,
        problem.name,
        problem.objective.label,
        "-",
        pts[0] if pts else None,
        [],
        cert,
        time.perf_counter() - t0,
        pareto=pf,
    )
    if info.timed_out:
        res.message = (
            f"the time limit ({time_limit:g} s) stopped the search after "
            f"{info.exact_evaluations:,} of {space.size:,} combinations: "
            + (
                f"the front of those ({len(front)} points), not proven"
                if len(front)
                else "no feasible design among them; raise --time-limit"
            )
        )
    elif not len(front):
        from .infeasible.explain import explain_infeasible
        from .infeasible.relax import missing_values, rank_relaxations

        exhaustive = method == "exhaustive"
        res.infeasibility = explain_infeasible(
            space, constraints, spec, every_combination=exhaustive
        )
        inf = res.infeasibility
        inf.relax, inf.not_relaxable, inf.relax_blocked_by = rank_relaxations(constraints, inf)
        inf.missing = missing_values(constraints, inf, space)
        res.message = "no catalog combination meets every limit"
        if inf.cut:
            from .infeasible.explain import cut_note

            res.message += "; " + cut_note(inf)
    return res
