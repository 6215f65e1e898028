"""Reference method: the whole problem as one global MINLP for SCIP (through pyscipopt, optional extra
``axisopt[scip]``).

The formulation is Bonmin's (:mod:`axisopt.search.bonmin`): one-hot binaries choose the nut (which fixes the
screw), the bearing arrangement and the guide-and-drive entry; the nut preload P is continuous within the
chosen nut's range (``sum lo_i z_i <= P <= sum hi_i z_i``, linear); the objective is an epigraph variable
below the objective at every grid position; every limit is a constraint.  Each allowed mounting is one
MINLP, solved in turn within the overall time limit.

The algebra is not written twice: the symbolic :func:`axisopt.model.axis_response` is built in CasADi on the
one-hot mixtures of the part parameters and its expression graph is translated node by node to SCIP:

* a node that depends on the parts of one slot only (a nut, bearing or guide-and-drive property, however
  nonlinear) is exact as ``sum_i z_i v_i`` with ``v_i`` its value for part i, computed numerically;
  a limit on such a node removes the parts that miss it before SCIP starts (decided by the model itself);
* every other node becomes the SCIP expression of its operation (+ - * /, powers, sqrt, exp, log, abs);
  ``fmin``/``fmax`` are ``(a + b -/+ |a - b|)/2``; a comparison is a binary tied to the sign of its
  difference by two indicator constraints, ``if_else`` is a product with that binary;
* a node used more than once, or a large expression, becomes a scaled auxiliary variable
  (``v = s * y``, ``y`` of order one) so that SCIP sees a DAG, not an exploding tree, at sane magnitudes.

SCIP's spatial branch-and-bound proves the optimum up to its tolerances (feasibility 1e-6, gap
:data:`GAP`).  The chosen combination and preload are then re-evaluated with the project's own model and
re-checked; the numbers printed are the model's.
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
import threading
import time

import casadi as ca
import numpy as np

from .. import model
from ..errors import InputError
from ..units import N_PER_UM
from .bestfirst import bound_order_search
from .bonmin import _slot_params
from .candidates import make_candidate
from .objective import STIFFNESS_OUTPUTS
from .polish import feasible_at as _feasible_at
from .result import Certificate, SolveResult
from .space import respond

GAP = 1e-5  # SCIP's relative gap limit (limits/gap)
MAX_TERMS = 40  # a larger SCIP expression becomes an auxiliary variable
SAMPLES = 64  # random integer points (fixed seed) that set the scale of each auxiliary variable
# Dual reductions (fixing a variable because the objective prefers one side) cut the optimum off the teaching
# problem (110.09 -> "optimal" 102.95 N/um; SCIP 10, the epigraph-with-comparisons model); off, it is right.
SCIP_PARAMS = {"misc/allowstrongdualreds": False, "misc/allowweakdualreds": False}
CROSS_CHECK_REL = 1e-4  # a design better than SCIP's proven optimum by more than this contradicts the proof
BRANCH_PRIORITY = (3, 2, 1)  # nut, bearing, guide-and-drive binaries
INSTALL = "pip install 'axisopt[scip]'"

_SLOTS = ("nut", "bearing", "guide")
PAIR_CHUNK = 20000  # (nut, guide) pairs per model evaluation of the carriage's limits
_PAIR_KEYS = ("margin_guide_static", "margin_guide_life", "margin_nut_static")
_P = 8  # dependency bit of the preload (slots: 1, 2, 4; nut shifts: 16)


def _pyscipopt():
    try:
        import pyscipopt
    except ImportError:
        raise InputError(f"--method scip needs pyscipopt, which is not installed: {INSTALL}") from None
    return pyscipopt


# --------------------------------------------------------------------------- the CasADi model of one mounting
_BUILD_LOCK = threading.Lock()


@contextlib.contextmanager
def _implicit_shift(record: list):
    """While building the model: :func:`axisopt.physics.nut.double_nut_shift` (12 unrolled Newton steps, whose
    relaxation is useless to a global solver) returns a fresh symbol s and records its force ratio f, so that
    SCIP gets the defining equation (1+s)^{3/2} - (1-s)_+^{3/2} = f instead (monotone: tight bounds)."""
    from ..physics import nut as pn

    def shift(force_ratio):
        sym = ca.SX.sym(f"s{len(record)}", ca.SX(force_ratio).shape)
        record.append((sym, ca.SX(force_ratio)))
        return sym

    with _BUILD_LOCK:
        real = pn.double_nut_shift
        pn.double_nut_shift = shift
        try:
            yield real
        finally:
            pn.double_nut_shift = real


def _casadi_model(space, mounting, constraints, objective):
    """(f, shift): f(z_nut, z_bearing, z_guide, P, s) -> [objective term profiles..., constraint values...,
    force ratios of the nut shifts s]; ``shift`` is the model's own shift function (numeric)."""
    _, N, B, G = space.shape
    z = {"nut": ca.SX.sym("z_nut", N), "bearing": ca.SX.sym("z_bearing", B), "guide": ca.SX.sym("z_guide", G)}
    pre = ca.SX.sym("P")
    p = {}
    for name, (slot, vals) in _slot_params(space, mounting).items():
        p[name] = vals if slot == "axis" else ca.dot(ca.DM(vals), z[slot])
    p["duty"] = space.problem.axis_for(mounting).phases
    record = []
    with _implicit_shift(record) as shift:
        out = model.axis_response(p, ca.DM(space.positions(mounting)), mounting, pre)
    outs = [ca.SX(out[key]) for key, _w in objective.terms] + [ca.SX(out[c.key]) for c in constraints]
    s = ca.vertcat(*[ca.vec(sym) for sym, _f in record]) if record else ca.SX(0, 1)
    ratios = ca.vertcat(*[ca.vec(f) for _s, f in record]) if record else ca.SX(0, 1)
    if ca.depends_on(ratios, s) if record else False:
        raise NotImplementedError("a nut shift depends on another one")
    return ca.Function("axis", [z["nut"], z["bearing"], z["guide"], pre, s], outs + [ratios]), shift


_UNARY = {ca.OP_NEG: np.negative, ca.OP_SQRT: np.sqrt, ca.OP_SQ: np.square, ca.OP_EXP: np.exp, ca.OP_LOG: np.log,
          ca.OP_INV: lambda a: 1.0 / a, ca.OP_FABS: np.abs, ca.OP_NOT: lambda a: (a == 0).astype(float),
          ca.OP_ASSIGN: lambda a: a, ca.OP_TWICE: lambda a: 2.0 * a}
_BINARY = {ca.OP_ADD: np.add, ca.OP_SUB: np.subtract, ca.OP_MUL: np.multiply, ca.OP_DIV: np.divide,
           ca.OP_POW: np.power, ca.OP_CONSTPOW: np.power, ca.OP_FMIN: np.minimum, ca.OP_FMAX: np.maximum,
           ca.OP_LT: lambda a, b: (a < b).astype(float), ca.OP_LE: lambda a, b: (a <= b).astype(float),
           ca.OP_EQ: lambda a, b: (a == b).astype(float), ca.OP_NE: lambda a, b: (a != b).astype(float),
           ca.OP_AND: lambda a, b: ((a != 0) & (b != 0)).astype(float),
           ca.OP_OR: lambda a, b: ((a != 0) | (b != 0)).astype(float),
           ca.OP_IF_ELSE_ZERO: lambda c, a: np.where(c != 0, a, 0.0)}


class _Graph:
    """The expression graph of a CasADi SX Function as nodes (op, args), with each node's dependency mask
    (bits: nut 1, bearing 2, guide 4, preload 8), its use count and its numeric value on a batch of points."""

    def __init__(self, f: ca.Function):
        self.op, self.args, self.const, self.dep = [], [], [], []
        self.outputs = [[None] * f.size1_out(i) for i in range(f.n_out())]
        self.offsets = np.cumsum([0] + [f.size1_in(i) for i in range(f.n_in())])
        work = {}
        for k in range(f.n_instructions()):
            op = f.instruction_id(k)
            if op == ca.OP_OUTPUT:
                o, nz = f.instruction_output(k)
                self.outputs[o][nz] = work[f.instruction_input(k)[0]]
                continue
            node = len(self.op)
            if op == ca.OP_INPUT:
                i, nz = f.instruction_input(k)
                args, dep, c = (), (1 << i), float(self.offsets[i] + nz)
            elif op == ca.OP_CONST:
                args, dep, c = (), 0, float(f.instruction_constant(k))
            else:
                if op not in _UNARY and op not in _BINARY:
                    raise NotImplementedError(f"CasADi operation {op} has no SCIP translation")
                args = tuple(work[w] for w in f.instruction_input(k))
                args = args[:1] if op in _UNARY else args[:2]
                dep, c = 0, 0.0
                for a in args:
                    dep |= self.dep[a]
            self.op.append(op)
            self.args.append(args)
            self.const.append(c)
            self.dep.append(dep)
            work[f.instruction_output(k)[0]] = node
        self.uses = np.zeros(len(self.op), dtype=int)
        for args in self.args:
            for a in args:
                self.uses[a] += 1
        for out in self.outputs:
            for n in out:
                self.uses[n] += 1
        self.value = []

    def evaluate(self, flat: np.ndarray) -> None:
        """Every node's value on the points ``flat`` (inputs stacked, one column per point)."""
        self.value = []
        with np.errstate(all="ignore"):
            for op, args, c in zip(self.op, self.args, self.const):
                if op == ca.OP_INPUT:
                    v = flat[int(c)]
                elif op == ca.OP_CONST:
                    v = np.full(flat.shape[1], c)
                elif op in _UNARY:
                    v = _UNARY[op](self.value[args[0]])
                else:
                    v = _BINARY[op](self.value[args[0]], self.value[args[1]])
                self.value.append(np.asarray(v, dtype=float))

    def output_values(self, o: int) -> np.ndarray:
        return np.array([self.value[n] for n in self.outputs[o]]).reshape(len(self.outputs[o]), -1)


# --------------------------------------------------------------------------- translation to SCIP
class _Translator:
    def __init__(self, ps, m, graph: _Graph, z: dict, pre, shifts: list, columns: dict):
        self.ps, self.m, self.g, self.z, self.pre, self.shifts = ps, m, graph, z, pre, shifts
        self.columns = columns  # slot -> slice of the batch where that slot runs over its parts
        self.memo = {}
        self.n_aux = 0
        self.n_binary = 0

    def part_values(self, node):
        """Values per part of a node depending on (at most) one slot: (slot or None, values)."""
        dep = self.g.dep[node]
        if dep == 0:
            return None, self.g.value[node][:1]
        slot = _SLOTS[int(dep).bit_length() - 1]
        return slot, self.g.value[node][self.columns[slot]]

    def folded(self, node) -> bool:
        return self.g.dep[node] in (0, 1, 2, 4)

    def scale(self, node) -> float:
        v = np.abs(self.g.value[node])
        v = v[np.isfinite(v)]
        s = float(np.max(v)) if len(v) else 1.0
        return 2.0 ** round(np.log2(s)) if s > 0 else 1.0

    def aux(self, node, expr, lb=None, ub=None, s=None, name=""):
        """A scaled auxiliary variable equal to ``expr``: returns ``s * y`` (``s`` by default the node's
        largest magnitude on the sample points, a power of 2)."""
        s = self.scale(node) if s is None else s
        name = name or f"v{node}"
        y = self.m.addVar(name, lb=None if lb is None else lb / s, ub=None if ub is None else ub / s)
        self.m.addCons(y - (1.0 / s) * expr == 0, name=f"def_{name}")
        self.n_aux += 1
        return s * y

    def expr(self, node):
        if node in self.memo:
            return self.memo[node]
        g = self.g
        if self.folded(node):
            slot, vals = self.part_values(node)
            if not np.all(np.isfinite(vals)):
                raise ValueError(f"node {node} (operation {g.op[node]}) is not finite for some parts")
            if slot is None or np.ptp(vals) == 0:
                e = float(vals[0])
            elif np.array_equal(vals, vals.astype(bool)):  # a 0/1 flag: exact and linear in the binaries
                e = self.ps.quicksum(self.z[slot][i] for i in np.nonzero(vals)[0])
            else:
                lin = self.ps.quicksum(float(v) * zi for v, zi in zip(vals, self.z[slot]))
                e = self.aux(node, lin, float(vals.min()), float(vals.max()))
        else:
            e = self._op(node)
            if not isinstance(e, float) and (g.uses[node] > 1 or self._large(e)):
                e = self.aux(node, e)
        self.memo[node] = e
        return e

    @staticmethod
    def _large(e) -> bool:
        terms = getattr(e, "terms", None)
        if terms is not None:  # a polynomial Expr
            return len(terms) > MAX_TERMS
        return len(str(e)) > 40 * MAX_TERMS

    def _op(self, node):
        g, ps = self.g, self.ps
        op, args = g.op[node], g.args[node]
        if op == ca.OP_INPUT:  # the preload or a nut shift (the part binaries are folded)
            pos = int(g.const[node])
            return self.pre if pos == g.offsets[3] else self.shifts[pos - int(g.offsets[4])]
        a = self.expr(args[0])
        b = self.expr(args[1]) if len(args) > 1 else None
        if op == ca.OP_ADD:
            return a + b
        if op == ca.OP_SUB:
            return a - b
        if op == ca.OP_MUL:
            return a * b
        if op == ca.OP_DIV:
            return a * (1.0 / b) if isinstance(b, float) else a / b
        if op == ca.OP_NEG:
            return -a
        if op == ca.OP_INV:
            return 1.0 / a
        if op == ca.OP_SQ:
            return a * a
        if op == ca.OP_SQRT:
            return ps.sqrt(a)
        if op == ca.OP_EXP:
            return ps.exp(a)
        if op == ca.OP_LOG:
            return ps.log(a)
        if op == ca.OP_FABS:
            return abs(a)
        if op == ca.OP_ASSIGN:
            return a
        if op == ca.OP_TWICE:
            return 2.0 * a
        if op in (ca.OP_FMIN, ca.OP_FMAX):
            sign = 1.0 if op == ca.OP_FMAX else -1.0
            return 0.5 * (a + b) + sign * 0.5 * abs(a - b)
        if op in (ca.OP_CONSTPOW, ca.OP_POW):
            if isinstance(b, float):
                return a ** (int(b) if b == int(b) else b)
            return ps.exp(b * ps.log(a))
        if op in (ca.OP_LT, ca.OP_LE):
            return self._compare(node, a, b)
        if op == ca.OP_NOT:
            return 1.0 - a
        if op == ca.OP_AND:
            return a * b
        if op == ca.OP_OR:
            return a + b - a * b
        if op == ca.OP_IF_ELSE_ZERO:
            return a * b
        raise NotImplementedError(f"CasADi operation {op} has no SCIP translation")

    def _compare(self, node, a, b):
        """A binary d with d = 1 => a <= b and d = 0 => a >= b (equality may go either way: the model's
        branches agree there or the tie has measure zero)."""
        d = self.m.addVar(f"d{node}", vtype="B")
        s = max(self.scale(n) for n in self.g.args[node])
        diff = self.aux(node, a - b, s=s, name=f"diff{node}")
        self.m.addConsIndicator(diff <= 0, binvar=d, name=f"le{node}")
        self.m.addConsIndicator(-diff <= 0, binvar=d, activeone=False, name=f"ge{node}")
        self.n_binary += 1
        return d


# --------------------------------------------------------------------------- one mounting
def _mounting_model(ps, space, mounting, constraints, objective, seed=0):
    """The SCIP model of one mounting.  Returns (model, z, P, info) or (None, None, None, reason) when no
    part survives the one-slot limits."""
    _, N, B, G = space.shape
    f, shift = _casadi_model(space, mounting, constraints, objective)
    graph = _Graph(f)
    lo_n, hi_n = np.asarray(space.preload_lo, float), np.asarray(space.preload_hi, float)
    # points: each slot over its parts (others at part 0, preload mid-range), then random integer points
    cols, blocks, start = {}, [], 0
    for s, n in zip(_SLOTS, (N, B, G)):
        eye = [np.zeros((k, n)) for k in (N, B, G)]
        for j in range(3):
            if _SLOTS[j] == s:
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
    pre_row = np.concatenate([np.broadcast_to(b[1], (b[0][0].shape[1],)) for b in blocks] + [pr])[None, :]
    n_s = f.size1_in(4)
    flat = np.concatenate(zs + [pre_row, np.zeros((n_s, pre_row.shape[1]))], axis=0)
    graph.evaluate(flat)  # the force ratios do not depend on the shifts: solve those, then evaluate again
    if n_s:
        with np.errstate(all="ignore"):
            flat[-n_s:] = shift(np.maximum(graph.output_values(f.n_out() - 1), 0.0))
        graph.evaluate(flat)

    m = ps.Model(f"axisopt_{mounting}")
    m.hideOutput()
    z = {s: [m.addVar(f"z_{s}{i}", vtype="B") for i in range(n)] for s, n in zip(_SLOTS, (N, B, G))}
    for prio, s in zip(BRANCH_PRIORITY, _SLOTS):  # the nut first: it fixes the screw and the preload range
        for v in z[s]:
            m.chgVarBranchPriority(v, prio)
    P = m.addVar("P", lb=float(lo_n.min()), ub=float(hi_n.max()))
    shifts = [m.addVar(f"s{k}", lb=0.0) for k in range(n_s)]
    tr = _Translator(ps, m, graph, z, P, shifts, cols)
    for k, node in enumerate(graph.outputs[-1]):  # the nut shifts by their defining equation
        sk = shifts[k]
        m.addCons((1.0 + sk) ** 1.5 - (0.5 * (1.0 - sk + abs(1.0 - sk))) ** 1.5 - tr.expr(node) == 0,
                  name=f"shift{k}")
    nt = len(objective.terms)
    # limits on one slot: remove the parts that miss them (a constant limit that fails: nothing is feasible)
    allowed = {s: np.ones(n, dtype=bool) for s, n in zip(_SLOTS, (N, B, G))}
    general = []
    pair_limits = []
    # their values from the model itself (numpy, flat layout, as the exhaustive search evaluates them): a part
    # exactly at a limit must pass or fail as it does there, not as the translation's rounding has it
    K = N + B + G
    pick_n, pick_b, pick_g = (np.argmax(zj[:, :K], axis=0) for zj in zs)
    exact = respond(space.params_flat(mounting, pick_n, pick_b, pick_g), space.positions(mounting), mounting,
                    pre_row[0, :K][:, None])
    for ci, c in enumerate(constraints):
        nodes = graph.outputs[nt + ci]
        a = np.asarray(exact[c.key], dtype=float)
        v_exact = np.broadcast_to(a.reshape(K, -1) if a.ndim and a.shape[0] == K else a.reshape(1, -1), (K, len(nodes)))
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
            elif c.key in _PAIR_KEYS and tr.g.dep[node] == 5:  # the carriage: the nut's mass and the guide
                pair_limits.append((ci, c, j))
            else:
                general.append((c, node))
    # the carriage's limits depend on the nut (its mass) and the guide alone: evaluated on every pair with the
    # model (as the exhaustive search does) and failing pairs cut off linearly, one cut per nut
    forbidden = _failing_pairs(space, mounting, pair_limits, N, G) if pair_limits else np.zeros((N, G), bool)
    for s in _SLOTS:
        if not allowed[s].any():
            return None, None, None, f"no {s} meets the limits that depend on the {s} alone"
        for i in np.nonzero(~allowed[s])[0]:
            m.chgVarUb(z[s][i], 0.0)
        m.addCons(ps.quicksum(z[s]) == 1, name=f"one_{s}")
    m.addCons(P >= ps.quicksum(float(v) * zi for v, zi in zip(lo_n, z["nut"])), name="preload_lo")
    m.addCons(P <= ps.quicksum(float(v) * zi for v, zi in zip(hi_n, z["nut"])), name="preload_hi")
    for n_i, b_i in zip(*np.nonzero(~space.fits)):
        m.addCons(z["nut"][n_i] + z["bearing"][b_i] <= 1)
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
        e = tr.expr(node)
        if c.limit <= 0:  # e.g. max_backlash 0: the value in display units
            lhs, rhs = (1.0 / c.factor) * e, 0.0
        else:
            lhs, rhs = (1.0 / c.limit) * e, 1.0
        m.addCons(lhs >= rhs if c.sense == ">=" else lhs <= rhs, name=c.name)
    m.setObjective(ps.quicksum(wt * t[k] for k, (_key, wt) in enumerate(objective.terms)), "maximize")
    info = {"aux": tr.n_aux, "binaries": tr.n_binary, "parts": {s: int(allowed[s].sum()) for s in _SLOTS}}
    return m, z, P, info


def _failing_pairs(space, mounting, pair_limits, N, G) -> np.ndarray:
    """(N, G) mask of the (nut, guide-and-drive) pairs that miss a carriage limit (bearing 0 and the nut's
    lowest preload stand in: these limits do not depend on them)."""
    n_idx = np.repeat(np.arange(N), G)
    g_idx = np.tile(np.arange(G), N)
    x = space.positions(mounting)[-1:]
    bad = np.zeros(N * G, dtype=bool)
    for lo in range(0, N * G, PAIR_CHUNK):
        sl = slice(lo, min(N * G, lo + PAIR_CHUNK))
        k = sl.stop - sl.start
        out = respond(space.params_flat(mounting, n_idx[sl], np.zeros(k, dtype=int), g_idx[sl]), x, mounting,
                      np.asarray(space.preload_lo, float)[n_idx[sl]][:, None], chain=False)
        for _ci, c, _j in pair_limits:
            v = np.broadcast_to(np.asarray(out[c.key], dtype=float).reshape(-1), (k,))
            bad[sl] |= ~np.asarray(c.ok(v), dtype=bool)
    return bad.reshape(N, G)


def _recover(space, mi, z, P, m, constraints):
    """The combination and preload of SCIP's best point, the preload nudged into the exact model's limits."""
    sol = m.getBestSol()
    n, b, g = (int(np.argmax([m.getSolVal(sol, v) for v in z[s]])) for s in _SLOTS)
    combo = int(np.ravel_multi_index((mi, n, b, g), space.shape))
    lo, hi = float(space.preload_lo[n]), float(space.preload_hi[n])
    pre = float(np.clip(m.getSolVal(sol, P), lo, hi))
    if _feasible_at(space, combo, pre, constraints):
        return combo, pre, ""
    for rel in (1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3):  # SCIP's feasibility tolerance, either way
        for step in (-1.0, 1.0):
            p2 = float(np.clip(pre + step * rel * max(hi - lo, 1.0), lo, hi))
            if _feasible_at(space, combo, p2, constraints):
                return combo, p2, f"preload moved by {p2 - pre:+.3g} N into the limits"
    return combo, None, (f"SCIP's point violates a limit on exact re-evaluation (combination {combo}, "
                         f"preload {pre:.1f} N)")


@contextlib.contextmanager
def _c_stderr_to_file():
    """Send what the SCIP/SoPlex C code writes to file descriptor 2 during the block (e.g. 'Cannot set
    feasibility tolerance to small value 1e-12 without GMP', hundreds of times on a long solve) to a temporary
    file instead of the user's terminal; yields a list that holds its distinct lines afterwards."""
    lines: list = []
    fd = 2  # the C library's stderr, whatever Python's sys.stderr is
    with contextlib.suppress(AttributeError, OSError, ValueError):
        sys.stderr.flush()
    try:
        tmp = tempfile.TemporaryFile()
    except OSError:  # no room for the file: leave the messages where they go
        yield lines
        return
    with tmp:  # closed on every path, also when descriptor 2 cannot be duplicated
        try:
            saved = os.dup(fd)
        except OSError:  # no descriptor 2 (a daemon): leave the messages where they go
            saved = None
        if saved is None:
            yield lines
            return
        try:
            os.dup2(tmp.fileno(), fd)
            try:
                yield lines
            finally:
                os.dup2(saved, fd)
        finally:
            os.close(saved)
        tmp.seek(0)
        text = tmp.read().decode("utf-8", "replace").splitlines()
        lines.extend(dict.fromkeys(t.strip() for t in text if t.strip()))


def _contradiction(space, constraints, objective, best) -> str:
    """SCIP's proof against a design the project's own search finds (re-evaluated by the model): '' when none
    contradicts it, else why it is wrong.

    SCIP's LP relaxation of this model can be numerically wrong: on ``highspeed_problem.yaml`` (stage 2,
    fixed-supported) it declares infeasible even the single combination whose parts and preload are all fixed
    at the default method's optimum, a point that SCIP's own ``checkSol`` accepts (it stops at "unresolved
    numerical troubles in LP ... using pseudo solution instead" and cuts the node off).  Such a proof is never
    passed on: a design that meets every limit and beats SCIP's answer turns its status into a failure."""
    ex, _info = bound_order_search(space, constraints, objective, top=1)
    fin = np.isfinite(ex.objective)
    if not fin.any():
        return ""
    j = int(np.argmax(np.where(fin, ex.objective, -np.inf)))
    j_ref = float(ex.objective[j])
    if best is not None and j_ref <= best.objective + CROSS_CHECK_REL * max(abs(best.objective), 1e-12):
        return ""
    ref = make_candidate(space, int(ex.idx[j]), float(ex.preload[j]), objective)
    claim = "no design meets the limits" if best is None else f"the optimum is {best.objective:.6g}"
    return (f"SCIP proved that {claim}, but {ref.mounting} {ref.nut} + {ref.bearing} + {ref.guide} at preload "
            f"{ref.nut_preload:.1f} N meets every limit on the model with objective {j_ref:.6g}: SCIP's proof is "
            f"wrong on this problem (numerical trouble in its LP relaxation); no proven answer")


def solve_scip(problem, space, constraints, objective, *, time_limit: float = 100.0, top: int = 1,
               t0: float | None = None) -> SolveResult:
    """Solve each mounting's MINLP with SCIP and return the best design (re-evaluated)."""
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
        for key, value in SCIP_PARAMS.items():
            m.setParam(key, value)
        with _c_stderr_to_file() as lines:
            m.optimize()
        if lines:
            notes.append(f"{mounting}: {len(lines)} distinct SCIP/SoPlex messages kept off the terminal, "
                         f"e.g. '{lines[0]}'")
        solves += 1
        st = m.getStatus()
        nodes += int(m.getNNodes())
        statuses.append(f"{mounting}: {st}")
        if st in ("timelimit", "userinterrupt", "memlimit", "nodelimit", "stallnodelimit"):
            stopped = True
        elif st not in ("optimal", "gaplimit", "infeasible"):
            stopped = True
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
        status = "solver_failed"
    elif stopped:
        status = "time_limit"
    elif best is None:
        status = "infeasible"
    else:
        status = "optimal"
    if status in ("optimal", "infeasible"):
        wrong = _contradiction(space, constraints, objective, best)
        if wrong:
            status = "solver_failed"
            notes.append(wrong)
            statuses.append("proof contradicted by a feasible design")
        else:
            notes.append("proof cross-checked against the default method's best design: consistent")
    gap = max(gaps) if gaps else (0.0 if status in ("optimal", "infeasible") else float("nan"))
    cert = Certificate(combinations=space.size, feasible=None, pruned_by_bound=0, exact_evaluations=0,
                       nlps_solved=solves, nlp_failures=int(failed), gap=gap,
                       proven=status in ("optimal", "infeasible"),
                       notes=tuple([f"SCIP spatial branch-and-bound (global up to its tolerances: feasibility "
                                    f"1e-6, gap {GAP:g}); {nodes} nodes"] + notes))
    msg = "; ".join(statuses + notes)
    return SolveResult(status, "scip", problem.name, objective.label, objective.unit, best, [], cert,
                       time.perf_counter() - t0, message=msg if status != "optimal" else "",
                       solver_status="; ".join(statuses))


__all__ = ["solve_scip", "GAP"]
