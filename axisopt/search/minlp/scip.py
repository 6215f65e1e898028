"""Reference method: the whole problem as one global MINLP for SCIP (through pyscipopt, optional
extra ``axisopt[scip]``).

The formulation is :mod:`axisopt.search.minlp.formulation`'s, as for Bonmin: one-hot binaries choose
the nut (which fixes the screw), the bearing arrangement and the guide-and-drive entry; the nut
preload P is continuous within the chosen nut's range (``sum lo_i z_i <= P <= sum hi_i z_i``,
linear); the objective is an epigraph variable below the objective at every grid position; every
limit is a constraint scaled by :func:`axisopt.search.minlp.scaling.scaled_limit`.  Each allowed
mounting is one MINLP, solved in turn within the overall time limit.

The algebra is not written twice: the CasADi model is translated node by node to SCIP
(:mod:`axisopt.search.minlp.translate`).  A limit on a node that depends on one slot only removes
the parts that miss it before SCIP starts (decided by the model itself); the carriage's limits,
which depend on the nut and the guide alone, cut off the failing pairs linearly.

SCIP's spatial branch-and-bound proves the optimum up to its tolerances (feasibility 1e-6, gap
:data:`GAP`).  The chosen combination and preload are then re-evaluated with the project's own model
and re-checked; the numbers printed are the model's.  A proven answer is cross-checked against the
default method's best design (:func:`_contradiction`).
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from ...errors import InputError
from ...model.limits import margin_output
from ...units import N_PER_UM
from ..bestfirst import bound_order_search
from ..candidates import make_candidate
from ..certificate import Certificate
from ..result import INFEASIBLE, OPTIMAL, SOLVER_FAILED, STATUSES, TIME_LIMIT, SolveResult
from ..task.objective import STIFFNESS_OUTPUTS
from ..task.space import respond
from .formulation import SLOTS, recover
from .scaling import reciprocal_times, scaled_limit
from .statuses import PROVED, UNEXPECTED, scip_outcome
from .streams import c_stderr_to_file
from .translate import Graph, Translator, casadi_model

GAP = 1e-5  # SCIP's relative gap limit (limits/gap)
SAMPLES = 64  # random integer points (fixed seed) that set the scale of each auxiliary variable
# Dual reductions (fixing a variable because the objective prefers one side) cut the optimum off the
# teaching problem (110.09 -> "optimal" 102.95 N/um; SCIP 10, the epigraph-with-comparisons model);
# off, it is right.
SCIP_PARAMS = {"misc/allowstrongdualreds": False, "misc/allowweakdualreds": False}
# SCIP's presolving can cut a feasible point off: with the vendor rules (lift-off by load case, nut
# life per phase) it stopped the teaching optimum's preload at 1007 N (70.38 N/um "optimal"; the
# model's 1146.8 N gives 71.66 N/um, and that point, every part and the preload fixed, is feasible
# in the same SCIP model).  A proof the cross-check contradicts is solved again once with presolving
# off (which finds 71.66); presolving stays on by default, since infeasibility proofs need it (the
# random infeasible catalog: 2.8 s CPU with it, over 8 s without)
RETRY_PARAMS = {"presolving/maxrounds": 0}
# a design better than SCIP's proven optimum by more than this contradicts the proof
CROSS_CHECK_REL = 1e-4
BRANCH_PRIORITY = (3, 2, 1)  # nut, bearing, guide-and-drive binaries
INSTALL = "pip install 'axisopt[scip]'"
# a preload that misses a limit on exact re-evaluation: moved by these fractions of its range, down
# then up (SCIP's feasibility tolerance, either way)
MOVES = tuple(
    step * rel for rel in (1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3) for step in (-1.0, 1.0)
)

PAIR_CHUNK = 20000  # (nut, guide) pairs per model evaluation of the carriage's limits
_PAIR_KEYS = tuple(margin_output(c) for c in ("guide_static", "guide_life", "nut_static"))
_CONTINUOUS = 8 | 16  # dependency bits of the preload and the nut shifts (translate.Graph)


def _pyscipopt():
    try:
        import pyscipopt
    except ImportError:
        raise InputError(
            f"--method scip needs pyscipopt, which is not installed: {INSTALL}"
        ) from None
    return pyscipopt


# --------------------------------------------------------------------------- one mounting
def _mounting_model(ps, space, mounting, constraints, objective, seed=0):
    """The SCIP model of one mounting.  Returns (model, z, P, info) or (None, None, None, reason)
    when no part survives the one-slot limits."""
    _, N, B, G = space.shape
    f, shift = casadi_model(space, mounting, constraints, objective)
    graph = Graph(f)
    lo_n, hi_n = np.asarray(space.preload_lo, float), np.asarray(space.preload_hi, float)
    # points: each slot over its parts (others at part 0, preload mid-range), then random integer
    # points
    cols, blocks, start = {}, [], 0
    for s, n in zip(SLOTS, (N, B, G)):
        eye = [np.zeros((k, n)) for k in (N, B, G)]
        for j in range(3):
            if SLOTS[j] == s:
                eye[j] = np.eye(n)
            else:
                eye[j][0, :] = 1.0
        blocks.append((eye, 0.5 * (lo_n[0] + hi_n[0]) if s != "nut" else 0.5 * (lo_n + hi_n)))
        cols[s] = slice(start, start + n)
        start += n
    rng = np.random.default_rng(seed)
    pick = [rng.integers(0, k, SAMPLES) for k in (N, B, G)]
    rand = [np.eye(k)[:, pk] for k, pk in zip((N, B, G), pick)]
    w = rng.uniform(0, 1, SAMPLES)
    pr = lo_n[pick[0]] + w * (hi_n[pick[0]] - lo_n[pick[0]])
    zs = [np.concatenate([b[0][j] for b in blocks] + [rand[j]], axis=1) for j in range(3)]
    pre_row = np.concatenate([np.broadcast_to(b[1], (b[0][0].shape[1],)) for b in blocks] + [pr])[
        None, :
    ]
    n_s = f.size1_in(4)
    flat = np.concatenate(zs + [pre_row, np.zeros((n_s, pre_row.shape[1]))], axis=0)
    # the force ratios do not depend on the shifts: solve those, then evaluate again
    graph.evaluate(flat)
    if n_s:
        with np.errstate(all="ignore"):
            flat[-n_s:] = shift(np.maximum(graph.output_values(f.n_out() - 1), 0.0))
        graph.evaluate(flat)

    m = ps.Model(f"axisopt_{mounting}")
    m.hideOutput()
    z = {s: [m.addVar(f"z_{s}{i}", vtype="B") for i in range(n)] for s, n in zip(SLOTS, (N, B, G))}
    # the nut first: it fixes the screw and the preload range
    for prio, s in zip(BRANCH_PRIORITY, SLOTS):
        for v in z[s]:
            m.chgVarBranchPriority(v, prio)
    P = m.addVar("P", lb=float(lo_n.min()), ub=float(hi_n.max()))
    shifts = [m.addVar(f"s{k}", lb=0.0) for k in range(n_s)]
    tr = Translator(ps, m, graph, z, P, shifts, cols)
    for k, node in enumerate(graph.outputs[-1]):  # the nut shifts by their defining equation
        sk = shifts[k]
        m.addCons(
            (1.0 + sk) ** 1.5 - (0.5 * (1.0 - sk + abs(1.0 - sk))) ** 1.5 - tr.expr(node) == 0,
            name=f"shift{k}",
        )
    nt = len(objective.terms)
    # limits on one slot: remove the parts that miss them (a constant limit that fails: nothing is
    # feasible)
    allowed = {s: np.ones(n, dtype=bool) for s, n in zip(SLOTS, (N, B, G))}
    general = []
    pair_limits = []
    # limits on the parts alone, not on the preload (e.g. the support bearings' life)
    parts_limits = set()
    # their values from the model itself (numpy, flat layout, as the exhaustive search evaluates
    # them): a part exactly at a limit must pass or fail as it does there, not as the translation's
    # rounding has it
    K = N + B + G
    pick_n, pick_b, pick_g = (np.argmax(zj[:, :K], axis=0) for zj in zs)
    exact = respond(
        space.params_flat(mounting, pick_n, pick_b, pick_g),
        space.positions(mounting),
        mounting,
        pre_row[0, :K][:, None],
        space.request,
    )
    for ci, c in enumerate(constraints):
        nodes = graph.outputs[nt + ci]
        a = np.asarray(exact[c.key], dtype=float)
        v_exact = np.broadcast_to(
            a.reshape(K, -1) if a.ndim and a.shape[0] == K else a.reshape(1, -1), (K, len(nodes))
        )
        for j, node in enumerate(nodes):
            if tr.folded(node):
                slot, vals = tr.part_values(node)
                if slot is not None:
                    vals = v_exact[cols[slot], j]
                ok = np.asarray(c.ok(vals), dtype=bool)
                if slot is None:
                    if not ok.all():
                        return None, None, None, f"{c.label} fails for every combination"
                else:
                    allowed[slot] &= ok
            # the carriage: the nut's mass and the guide
            elif c.key in _PAIR_KEYS and tr.g.dep[node] == 5:
                pair_limits.append((ci, c, j))
            elif not tr.g.dep[node] & _CONTINUOUS and all(
                not tr.g.dep[nd] & _CONTINUOUS for nd in nodes
            ):
                parts_limits.add(ci)  # the parts alone (no preload): enumerated below
            else:
                general.append((c, node))
    # the carriage's limits depend on the nut (its mass) and the guide alone: evaluated on every
    # pair with the model (as the exhaustive search does) and failing pairs cut off linearly, one
    # cut per nut
    forbidden = (
        _failing_pairs(space, mounting, pair_limits, N, G)
        if pair_limits
        else np.zeros((N, G), bool)
    )
    for s in SLOTS:
        if not allowed[s].any():
            return None, None, None, f"no {s} meets the limits that depend on the {s} alone"
        for i in np.nonzero(~allowed[s])[0]:
            m.chgVarUb(z[s][i], 0.0)
        m.addCons(ps.quicksum(z[s]) == 1, name=f"one_{s}")
    m.addCons(P >= ps.quicksum(float(v) * zi for v, zi in zip(lo_n, z["nut"])), name="preload_lo")
    m.addCons(P <= ps.quicksum(float(v) * zi for v, zi in zip(hi_n, z["nut"])), name="preload_hi")
    for n_i, b_i in zip(*np.nonzero(~space.fits)):
        m.addCons(z["nut"][n_i] + z["bearing"][b_i] <= 1)
    # a limit on the parts alone (no preload, no nut shift) is decided by the model on every allowed
    # combination, as the exhaustive search decides it, and the failing (nut, bearing, guides) cut
    # off linearly: its relaxation (the support bearings' life: cubic means, Weibull sums, a min
    # over two mountings) would otherwise carry SCIP's whole tree
    for n_i, b_i, bad_gs in (
        _failing_combinations(
            space, mounting, [constraints[ci] for ci in sorted(parts_limits)], allowed
        )
        if parts_limits
        else ()
    ):
        m.addCons(
            z["nut"][n_i] + z["bearing"][b_i] + ps.quicksum(z["guide"][g_i] for g_i in bad_gs) <= 2,
            name=f"parts_nut{n_i}_bearing{b_i}",
        )
    for n_i in np.nonzero(forbidden.any(axis=1) & allowed["nut"])[0]:
        bad_g = [z["guide"][g_i] for g_i in np.nonzero(forbidden[n_i] & allowed["guide"])[0]]
        if bad_g:  # one guide is chosen: this equals the pair cuts z_n + z_g <= 1
            m.addCons(z["nut"][n_i] + ps.quicksum(bad_g) <= 1, name=f"pair_nut{n_i}")
    t = [m.addVar(f"t{k}", lb=None) for k in range(nt)]
    for k, (key, _w) in enumerate(objective.terms):
        unit = N_PER_UM if key in STIFFNESS_OUTPUTS else 1.0
        for j, node in enumerate(graph.outputs[k]):
            m.addCons(t[k] - (1.0 / unit) * tr.expr(node) <= 0, name=f"epi{k}_{j}")
    for c, node in general:
        lhs, rhs = scaled_limit(c, tr.expr(node), log=False, divide=reciprocal_times)
        m.addCons(lhs >= rhs if c.sense == ">=" else lhs <= rhs, name=c.name)
    m.setObjective(
        ps.quicksum(wt * t[k] for k, (_key, wt) in enumerate(objective.terms)), "maximize"
    )
    info = {
        "aux": tr.n_aux,
        "binaries": tr.n_binary,
        "parts": {s: int(allowed[s].sum()) for s in SLOTS},
    }
    return m, z, P, info


def _failing_pairs(space, mounting, pair_limits, N, G) -> np.ndarray:
    """(N, G) mask of the (nut, guide-and-drive) pairs that miss a carriage limit (bearing 0 and the
    nut's lowest preload stand in: these limits do not depend on them)."""
    n_idx = np.repeat(np.arange(N), G)
    g_idx = np.tile(np.arange(G), N)
    x = space.positions(mounting)[-1:]
    bad = np.zeros(N * G, dtype=bool)
    for lo in range(0, N * G, PAIR_CHUNK):
        sl = slice(lo, min(N * G, lo + PAIR_CHUNK))
        k = sl.stop - sl.start
        out = respond(
            space.params_flat(mounting, n_idx[sl], np.zeros(k, dtype=int), g_idx[sl]),
            x,
            mounting,
            np.asarray(space.preload_lo, float)[n_idx[sl]][:, None],
            space.request.but(chain=False),
        )
        for _ci, c, _j in pair_limits:
            v = np.broadcast_to(np.asarray(out[c.key], dtype=float).reshape(-1), (k,))
            bad[sl] |= ~np.asarray(c.ok(v), dtype=bool)
    return bad.reshape(N, G)


def _failing_combinations(space, mounting, limits, allowed):
    """(nut, bearing, [guides]) for every allowed nut and bearing that fit, with the allowed
    guide-and-drive entries whose combination misses one of ``limits`` (limits that do not depend on
    the preload: the nut's lowest preload stands in)."""
    n_ok = np.nonzero(allowed["nut"])[0]
    b_ok = np.nonzero(allowed["bearing"])[0]
    g_ok = np.nonzero(allowed["guide"])[0]
    pairs = [(n_i, b_i) for n_i in n_ok for b_i in b_ok if space.fits[n_i, b_i]]
    if not pairs or len(g_ok) == 0:
        return []
    G = len(g_ok)
    n_idx = np.repeat(np.array([q[0] for q in pairs]), G)
    b_idx = np.repeat(np.array([q[1] for q in pairs]), G)
    g_idx = np.tile(g_ok, len(pairs))
    x = space.positions(mounting)
    bad = np.zeros(len(n_idx), dtype=bool)
    for lo in range(0, len(n_idx), PAIR_CHUNK):
        sl = slice(lo, min(len(n_idx), lo + PAIR_CHUNK))
        k = sl.stop - sl.start
        out = respond(
            space.params_flat(mounting, n_idx[sl], b_idx[sl], g_idx[sl]),
            x,
            mounting,
            np.asarray(space.preload_lo, float)[n_idx[sl]][:, None],
            space.request,
        )
        for c in limits:
            v = np.asarray(c.value(out), dtype=float)
            v = (
                v.reshape(k, -1)
                if v.ndim and v.shape[0] == k
                else np.broadcast_to(v.reshape(1, -1), (k, v.size))
            )
            bad[sl] |= ~np.asarray(c.ok(v), dtype=bool).all(axis=1)
    bad = bad.reshape(len(pairs), G)
    return [
        (int(n_i), int(b_i), [int(g) for g in g_ok[bad[r]]])
        for r, (n_i, b_i) in enumerate(pairs)
        if bad[r].any()
    ]


def _recover(space, mi, z, P, m, constraints):
    """The combination and preload of SCIP's best point, the preload nudged into the exact
    model's limits: (combination, preload or None, note)."""
    sol = m.getBestSol()
    zs = {s: [m.getSolVal(sol, v) for v in z[s]] for s in SLOTS}
    got = recover(
        space,
        mi,
        zs,
        lambda lo, hi: float(np.clip(m.getSolVal(sol, P), lo, hi)),
        constraints,
        MOVES,
    )
    if got.preload is None:
        return (
            got.combination,
            None,
            (
                f"SCIP's point violates a limit on exact re-evaluation (combination "
                f"{got.combination}, preload {got.proposed:.1f} N)"
            ),
        )
    if got.preload != got.proposed:
        return (
            got.combination,
            got.preload,
            f"preload moved by {got.preload - got.proposed:+.3g} N into the limits",
        )
    return got.combination, got.preload, ""


def _contradiction(space, constraints, objective, best) -> str:
    """SCIP's proof against a design the project's own search finds (re-evaluated by the model): ''
    when none contradicts it, else why it is wrong.

    SCIP's LP relaxation of this model can be numerically wrong: on ``highspeed_problem.yaml``
    (stage 2, fixed-supported) it declares infeasible even the single combination whose parts and
    preload are all fixed at the default method's optimum, a point that SCIP's own ``checkSol``
    accepts (it stops at "unresolved numerical troubles in LP ... using pseudo solution instead" and
    cuts the node off).  Such a proof is never passed on: a design that meets every limit and beats
    SCIP's answer turns its status into a failure."""
    ex, _info = bound_order_search(space, constraints, objective, top=1)
    fin = np.isfinite(ex.objective)
    if not fin.any():
        return ""
    j = int(np.argmax(np.where(fin, ex.objective, -np.inf)))
    j_ref = float(ex.objective[j])
    if best is not None and j_ref <= best.objective + CROSS_CHECK_REL * max(
        abs(best.objective), 1e-12
    ):
        return ""
    ref = make_candidate(space, int(ex.idx[j]), float(ex.preload[j]), objective)
    claim = "no design meets the limits" if best is None else f"the optimum is {best.objective:.6g}"
    return (
        f"SCIP proved that {claim}, but {ref.mounting} {ref.nut} + {ref.bearing} + {ref.guide} at "
        f"preload {ref.nut_preload:.1f} N meets every limit on the model with objective "
        f"{j_ref:.6g}: SCIP's proof is wrong on this problem (numerical trouble in its LP "
        "relaxation); no proven answer"
    )


def solve_scip(
    problem,
    space,
    constraints,
    objective,
    *,
    time_limit: float = 100.0,
    top: int = 1,
    t0: float | None = None,
    retry: bool = True,
) -> SolveResult:
    """Solve each mounting's MINLP with SCIP and return the best design (re-evaluated).  A proof the
    default method's best design contradicts is solved again with :data:`RETRY_PARAMS` (``retry``),
    within the same time limit."""
    ps = _pyscipopt()
    t0 = time.perf_counter() if t0 is None else t0
    _, N, B, G = space.shape
    best = None
    statuses, notes = [], []
    gaps, nodes, solves = [], 0, 0
    stopped = False

    def out_of_time(mounting) -> bool:
        """Less than 0.1 s of the limit left: the mounting is not run (recorded)."""
        nonlocal stopped
        if time_limit - (time.perf_counter() - t0) > 0.1:
            return False
        statuses.append(f"{mounting}: not run (time limit)")
        stopped = True
        return True

    for mi, mounting in enumerate(space.mountings):
        if N == 0 or B == 0 or G == 0:
            statuses.append(f"{mounting}: infeasible (empty search space)")
            continue
        if out_of_time(mounting):
            continue
        try:
            m, z, P, info = _mounting_model(ps, space, mounting, constraints, objective)
        except (NotImplementedError, ValueError) as exc:
            statuses.append(f"{mounting}: ERROR building the SCIP model ({exc})")
            continue
        if m is None:
            statuses.append(f"{mounting}: infeasible ({info})")
            continue
        if out_of_time(mounting):
            continue
        m.setParam("limits/time", float(time_limit - (time.perf_counter() - t0)))
        m.setParam("limits/gap", GAP)
        m.setParam("randomization/randomseedshift", 0)
        for key, value in (SCIP_PARAMS if retry else SCIP_PARAMS | RETRY_PARAMS).items():
            m.setParam(key, value)
        with c_stderr_to_file() as lines:
            m.optimize()
        if lines:
            notes.append(
                f"{mounting}: {len(lines)} distinct SCIP/SoPlex messages kept off the terminal, "
                f"e.g. '{lines[0]}'"
            )
        solves += 1
        st = m.getStatus()
        nodes += int(m.getNNodes())
        statuses.append(f"{mounting}: {st}")
        outcome = scip_outcome(st)
        if outcome != PROVED:
            stopped = True
        if outcome == UNEXPECTED:
            notes.append(f"{mounting}: SCIP status {st}")
        if m.getNSols() == 0:
            continue
        gaps.append(float(m.getGap()))
        combo, pre, note = _recover(space, mi, z, P, m, constraints)
        if note:
            notes.append(f"{mounting}: {note}")
        if pre is None:
            stopped = True
            continue
        cand = make_candidate(space, combo, pre, objective, rank=1)
        if best is None or cand.objective > best.objective:
            best = cand
    failed = any("ERROR" in s for s in statuses)
    if failed:
        status = SOLVER_FAILED
    elif stopped:
        status = TIME_LIMIT
    elif best is None:
        status = INFEASIBLE
    else:
        status = OPTIMAL
    if STATUSES[status].proven:
        wrong = _contradiction(space, constraints, objective, best)
        if wrong and retry and time_limit - (time.perf_counter() - t0) > 0.1:
            again = solve_scip(
                problem,
                space,
                constraints,
                objective,
                time_limit=time_limit,
                top=top,
                t0=t0,
                retry=False,
            )
            first = (
                "; ".join(statuses) + f"; {wrong}; solved again with presolving off "
                f"({', '.join(f'{k} {v}' for k, v in RETRY_PARAMS.items())})"
            )
            cert = replace(again.certificate, notes=again.certificate.notes + (first,))
            return replace(again, certificate=cert)
        if wrong:
            status = SOLVER_FAILED
            notes.append(wrong)
            statuses.append("proof contradicted by a feasible design")
        else:
            notes.append("proof cross-checked against the default method's best design: consistent")
    gap = max(gaps) if gaps else (0.0 if STATUSES[status].proven else float("nan"))
    cert = Certificate(
        combinations=space.size,
        feasible=None,
        pruned_by_bound=0,
        exact_evaluations=0,
        nlps_solved=solves,
        nlp_failures=int(failed),
        gap=gap,
        proven=STATUSES[status].proven,
        notes=tuple(
            [
                f"SCIP spatial branch-and-bound (global up to its tolerances: feasibility "
                f"1e-6, gap {GAP:g}); {nodes} nodes"
            ]
            + notes
        ),
    )
    msg = "; ".join(statuses + notes)
    return SolveResult(
        status,
        "scip",
        problem.name,
        objective.label,
        objective.unit,
        best,
        [],
        cert,
        time.perf_counter() - t0,
        message=msg if status != OPTIMAL else "",
        solver_status="; ".join(statuses),
    )


__all__ = ["solve_scip", "GAP"]
