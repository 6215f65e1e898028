"""The CasADi model of one mounting translated node by node to a SCIP model (through pyscipopt).

The symbolic :func:`axisopt.model.axis_response` is built in CasADi on the one-hot mixtures of the
part parameters (:mod:`axisopt.search.minlp.formulation`) and its expression graph is translated
to SCIP:

* a node that depends on the parts of one slot only (a nut, bearing or guide-and-drive property,
  however nonlinear) is exact as ``sum_i z_i v_i`` with ``v_i`` its value for part i, computed
  numerically;
* every other node becomes the SCIP expression of its operation (+ - * /, powers, sqrt, exp, log,
  abs); ``fmin``/``fmax`` are ``(a + b -/+ |a - b|)/2``; a comparison is a binary tied to the sign
  of its difference by two indicator constraints, ``if_else`` is a product with that binary;
* a node used more than once, or a large expression, becomes a scaled auxiliary variable
  (``v = s * y``, ``y`` of order one) so that SCIP sees a DAG, not an exploding tree, at sane
  magnitudes;
* the double nut's shift (:func:`axisopt.physics.nut.double_nut_shift`, unrolled Newton steps whose
  relaxation is useless to a global solver) becomes a variable s with its defining equation
  ``(1+s)^{3/2} - (1-s)_+^{3/2} = f`` (monotone: tight bounds).
"""

from __future__ import annotations

import contextlib
import threading

import casadi as ca
import numpy as np

from ... import model
from .formulation import SLOTS, one_hot_params, one_hot_symbols

MAX_TERMS = 40  # a larger SCIP expression becomes an auxiliary variable


_BUILD_LOCK = threading.Lock()  # the shift is swapped in a module: one build at a time


@contextlib.contextmanager
def implicit_shift(record: list):
    """While building the model: :func:`axisopt.physics.nut.double_nut_shift` (12 unrolled Newton
    steps, whose relaxation is useless to a global solver) returns a fresh symbol s and records its
    force ratio f, so that SCIP gets the defining equation (1+s)^{3/2} - (1-s)_+^{3/2} = f instead
    (monotone: tight bounds)."""
    from ...physics import nut as pn

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


def casadi_model(space, mounting, constraints, objective):
    """(f, shift): f(z_nut, z_bearing, z_guide, P, s) -> [objective term profiles..., constraint
    values..., force ratios of the nut shifts s]; ``shift`` is the model's own shift function
    (numeric)."""
    z = one_hot_symbols(space)
    pre = ca.SX.sym("P")
    p = one_hot_params(space, mounting, z)
    record = []
    with implicit_shift(record) as shift:
        out = model.axis_response(
            p, ca.DM(space.positions(mounting)), mounting, pre, space.request.but(extras=True)
        )
    outs = [ca.SX(out[key]) for key, _w in objective.terms] + [
        ca.SX(out[c.key]) for c in constraints
    ]
    s = ca.vertcat(*[ca.vec(sym) for sym, _f in record]) if record else ca.SX(0, 1)
    ratios = ca.vertcat(*[ca.vec(f) for _s, f in record]) if record else ca.SX(0, 1)
    if ca.depends_on(ratios, s) if record else False:
        raise NotImplementedError("a nut shift depends on another one")
    return ca.Function("axis", [z["nut"], z["bearing"], z["guide"], pre, s], outs + [ratios]), shift


_UNARY = {
    ca.OP_NEG: np.negative,
    ca.OP_SQRT: np.sqrt,
    ca.OP_SQ: np.square,
    ca.OP_EXP: np.exp,
    ca.OP_LOG: np.log,
    ca.OP_INV: lambda a: 1.0 / a,
    ca.OP_FABS: np.abs,
    ca.OP_NOT: lambda a: (a == 0).astype(float),
    ca.OP_ASSIGN: lambda a: a,
    ca.OP_TWICE: lambda a: 2.0 * a,
}
_BINARY = {
    ca.OP_ADD: np.add,
    ca.OP_SUB: np.subtract,
    ca.OP_MUL: np.multiply,
    ca.OP_DIV: np.divide,
    ca.OP_POW: np.power,
    ca.OP_CONSTPOW: np.power,
    ca.OP_FMIN: np.minimum,
    ca.OP_FMAX: np.maximum,
    ca.OP_LT: lambda a, b: (a < b).astype(float),
    ca.OP_LE: lambda a, b: (a <= b).astype(float),
    ca.OP_EQ: lambda a, b: (a == b).astype(float),
    ca.OP_NE: lambda a, b: (a != b).astype(float),
    ca.OP_AND: lambda a, b: ((a != 0) & (b != 0)).astype(float),
    ca.OP_OR: lambda a, b: ((a != 0) | (b != 0)).astype(float),
    ca.OP_IF_ELSE_ZERO: lambda c, a: np.where(c != 0, a, 0.0),
}


class Graph:
    """The expression graph of a CasADi SX Function as nodes (op, args), with each node's dependency
    mask (bit i for input i: nut 1, bearing 2, guide-and-drive 4, preload 8, nut shifts 16), its use
    count and its numeric value on a batch of points."""

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


class Translator:
    """The SCIP expression of each graph node (memoized), on the model ``m`` with the part binaries
    ``z`` (slot -> variables), the preload variable and the nut-shift variables; ``columns``: slot
    -> the batch columns where that slot runs over its parts (the numeric values of a folded
    node)."""

    def __init__(self, ps, m, graph: Graph, z: dict, pre, shifts: list, columns: dict):
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
        slot = SLOTS[int(dep).bit_length() - 1]
        return slot, self.g.value[node][self.columns[slot]]

    def folded(self, node) -> bool:
        return self.g.dep[node] in (0, 1, 2, 4)

    def scale(self, node) -> float:
        v = np.abs(self.g.value[node])
        v = v[np.isfinite(v)]
        s = float(np.max(v)) if len(v) else 1.0
        return 2.0 ** round(np.log2(s)) if s > 0 else 1.0

    def aux(self, node, expr, lb=None, ub=None, s=None, name=""):
        """A scaled auxiliary variable equal to ``expr``: returns ``s * y`` (``s`` by default the
        node's largest magnitude on the sample points, a power of 2)."""
        s = self.scale(node) if s is None else s
        name = name or f"v{node}"
        y = self.m.addVar(
            name, lb=None if lb is None else lb / s, ub=None if ub is None else ub / s
        )
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
                raise ValueError(
                    f"node {node} (operation {g.op[node]}) is not finite for some parts"
                )
            if slot is None or np.ptp(vals) == 0:
                e = float(vals[0])
            # a 0/1 flag: exact and linear in the binaries
            elif np.array_equal(vals, vals.astype(bool)):
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
        """A binary d with d = 1 => a <= b and d = 0 => a >= b (equality may go either way: the
        model's branches agree there or the tie has measure zero)."""
        d = self.m.addVar(f"d{node}", vtype="B")
        s = max(self.scale(n) for n in self.g.args[node])
        diff = self.aux(node, a - b, s=s, name=f"diff{node}")
        self.m.addConsIndicator(diff <= 0, binvar=d, name=f"le{node}")
        self.m.addConsIndicator(-diff <= 0, binvar=d, activeone=False, name=f"ge{node}")
        self.n_binary += 1
        return d


__all__ = ["casadi_model", "implicit_shift", "Graph", "Translator", "MAX_TERMS"]
