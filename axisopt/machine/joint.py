"""The joint search over every axis's designs, proven; the sequential sizing beside it.

Per chain on the frame, from the top axis down: the top axis's designs at no carried load, reduced
to the exact Pareto set of what the machine reads (:mod:`.offers`), are its *offers*.  The axis
below is solved at each distinct mass an offer hangs on it, and each of its designs joins each offer
of that mass: the new offers of the sub-tree (cost, the mass it hangs on its own carrier, what of it
stays on the carrier, the compliance it adds at the tool, the chain's masses and springs where a
frequency is read).  An offer is dropped when

- a machine limit is already missed: the costs, masses and compliances only grow further down, and
  the lowest frequency of the whole chain is at most that of the sub-chain on a rigid base (a
  constraint raises the eigenvalues, Rayleigh), or
- another offer is at least as good in everything the rest of the machine reads (the exact Pareto
  set).  That is exact where the axis below never gains from more carried mass
  (:func:`.offers.monotone_in_load`), where the compliances add in series and the chain's
  frequencies fall with mass and rise with stiffness.  Below a counterbalanced vertical axis it
  is not: there offers of different carried mass are never compared, and that axis is screened in
  full at every mass (the proven enumeration).

``method='exhaustive'`` drops nothing and solves every combination of every axis at every load: the
ground truth.  The result's ``sequential`` is the designer's way: the top axis alone at its best for
the machine objective, its mass carried down, and so on.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ..search.pareto import nondominated
from ..search.result import INFEASIBLE, OPTIMAL
from .chain import lowest_frequency
from .model import MachineDesign, evaluate_choice, link_with_frame
from .offers import axis_designs, feasible_sets, monotone_in_load, pareto_designs
from .spec import Machine

METHODS = ("default", "exhaustive")


@dataclass
class MachineResult:
    """A machine solve: the joint optimum, the sequential sizing beside it, and how the search
    went."""

    machine: Machine
    method: str
    status: str  # 'optimal' | 'infeasible'
    best: MachineDesign | None
    sequential: MachineDesign | None
    nominal_combinations: float  # product of every axis's catalog combinations
    axis_solves: int  # axis searches (one per axis and carried load)
    offers: dict  # axis name -> offers kept after it
    time: float  # [s]
    notes: list = field(default_factory=list)

    @property
    def gain(self) -> float | None:
        """The joint optimum's objective over the sequential one (None: either missing or
        infeasible)."""
        if self.best is None or self.sequential is None or not self.sequential.feasible:
            return None
        return self.best.value(self.machine.objective) - self.sequential.value(
            self.machine.objective
        )


def _reads_frequency(machine: Machine) -> bool:
    return machine.min_frequency > 0 or machine.objective == "frequency"


class _Designs:
    """Every axis's designs per carried load, solved once (the lightest load first where
    monotone)."""

    def __init__(self, exhaustive: bool):
        self.exhaustive = exhaustive
        self.cache: dict = {}
        self.superset: dict = {}
        self.solves = 0
        self.combinations: dict = {}
        self.loads: dict = {}  # axis name -> {carried load [kg]: feasible designs}

    def get(self, ax, load: float, at: tuple):
        key = (ax.name, round(load, 9))
        if key not in self.cache:
            sup = None
            # the feasible set of the heaviest lighter load
            if not self.exhaustive and monotone_in_load(ax):
                lighter = [x for x in self.superset.get(ax.name, []) if x[0] <= load]
                sup = max(lighter, key=lambda x: x[0])[1] if lighter else None
            d = axis_designs(ax, load, at, exhaustive=self.exhaustive, superset=sup)
            self.solves += 1
            self.combinations[ax.name] = max(self.combinations.get(ax.name, 0), d.combinations)
            self.loads.setdefault(ax.name, {})[load] = d.feasible
            if not self.exhaustive:
                self.superset.setdefault(ax.name, []).append((load, feasible_sets(d)))
            self.cache[key] = d if self.exhaustive else pareto_designs(d)
        return self.cache[key]


def _join(ax, own: float, O: dict, sel, D) -> dict:
    """The offers ``sel`` of ``O`` (the axes above) each joined with each design of ``D`` (the axis
    below)."""
    oi, dj = (a.ravel() for a in np.meshgrid(sel, np.arange(len(D)), indexing="ij"))
    klink = link_with_frame(ax, D.k[dj])
    lumped = own + D.moving_parts[dj] + O["stat"][oi]
    return {
        "oi": oi,
        "dj": dj,
        "cost": O["cost"][oi] + D.cost[dj],
        "M": own + D.parts[dj] + D.counterweight[dj] + O["M"][oi],
        "stat": D.stationary[dj],
        "c": O["c"][oi] + 1.0 / klink,
        "mm": O["mm"][oi] + lumped,
        "m": np.column_stack([lumped, O["m"][oi]]),
        "k": np.concatenate([klink[:, None, :], O["k"][oi]], axis=1),
    }


def _within_limits(machine: Machine, J: dict, cmax) -> tuple:
    """The joined offers ``J`` of part of a chain that do not yet miss a machine limit (costs,
    masses and compliances only grow further down; the frequency of the sub-chain on a rigid base
    bounds the whole's), and that sub-chain frequency at the rows kept (None where the machine does
    not read the frequency).  The frequency is solved only for the rows the other limits keep."""
    ok = (J["cost"] <= machine.max_cost * (1 + 1e-9)) & (
        J["mm"] <= machine.max_moving_mass * (1 + 1e-9)
    )
    ok &= (J["c"] <= cmax * (1 + 1e-9)).all(1)
    if not _reads_frequency(machine):
        return ok, None
    rows = np.nonzero(ok)[0]
    f = _sub_frequency(J["m"][rows], J["k"][rows])
    if machine.min_frequency > 0:
        met = f >= machine.min_frequency * (1 - 1e-9)
        ok[rows[~met]] = False
        f = f[met]
    return ok, f


def _sub_frequency(m, k) -> np.ndarray:
    """The lowest natural frequency over x, y and z of chains ``m`` (K, n) on springs ``k`` (K, n,
    3)."""
    if not len(m):
        return np.zeros(0)
    # the three directions as one batch (3, K, n): one call of the closed form, not three
    return lowest_frequency(np.asarray(m, dtype=float), np.moveaxis(k, 2, 0)).min(axis=0)


def _best_below(machine: Machine, chain: list, designs: _Designs, i: int) -> dict | None:
    """What the axes under ``chain[i]`` offer at best, each in every criterion on its own: its
    designs at the lightest load it could carry (the own moving masses above it, no parts: a
    superset of its designs at any real load, each at least as stiff), the least cost, compliance
    per direction and moving mass.  None: an axis below is not monotone in its load (no such
    bound)."""
    out = {"cost": 0.0, "c": np.zeros(3), "mm": 0.0}
    for j in range(i):
        ax = chain[j]
        if not monotone_in_load(ax):
            return None
        load = sum(_own(a) for a in chain[j + 1 :])
        at = chain[j + 1].carried_at
        D = designs.get(ax, load, at)
        if not len(D):
            return {"cost": np.inf, "c": np.full(3, np.inf), "mm": np.inf}
        out["cost"] += D.cost.min()
        out["c"] += (1.0 / link_with_frame(ax, D.k)).min(0)
        out["mm"] += _own(ax) + D.moving_parts.min()
    return out


def _own(ax) -> float:
    a = ax.problem.axis
    return a.moving_mass + (a.twin_drive.cross_mass if a.twin_drive is not None else 0.0)


def _optimistic(machine: Machine, J: dict, ok, rest: dict | None, other: dict, f_ok=None) -> float:
    """An upper bound of the machine objective (larger is better) of the joined offers ``J`` (rows
    ``ok``) completed by the axes below at their best (``rest``) and the other chain's offers
    ``other``: each criterion at its best on its own (cost, compliance per direction, moving mass),
    the frequency that of the sub-chain on a rigid base (``f_ok``: already solved at the rows
    ``ok``).  +inf: no bound."""
    if rest is None:
        return np.inf
    J = {k: v[ok] for k, v in J.items()}
    cost = J["cost"] + rest["cost"] + other["cost"].min()
    c = J["c"] + rest["c"] + other["c"].min(0)
    mm = J["mm"] + rest["mm"] + other["mm"].min()
    if not _reads_frequency(machine):
        f = np.full(len(cost), np.inf)
    else:
        f = f_ok if f_ok is not None else _sub_frequency(J["m"], J["k"])
    f = np.minimum(f, other["f"].max())
    kmin = np.asarray(machine.min_tool_stiffness, dtype=float)
    good = (cost <= machine.max_cost * (1 + 1e-9)) & (mm <= machine.max_moving_mass * (1 + 1e-9))
    good &= ((1.0 / c) >= kmin * (1 - 1e-9)).all(-1)
    if machine.min_frequency > 0:
        good &= f >= machine.min_frequency * (1 - 1e-9)
    obj = _objective(machine, cost, c, f, mm)
    return float(obj[good].max()) if good.any() else -np.inf


class _Incumbent:
    """The best machine objective found so far (larger is better).  With a machine and its designs
    it starts at the sequential sizing's value where that meets every limit, computed when
    first read: by then the upper axes' lightest loads are solved, so the sequential sizing's
    heavier loads are solved on their feasible supersets."""

    def __init__(self, machine: Machine | None = None, designs: _Designs | None = None):
        self.machine, self.designs = machine, designs
        self.sequential = None
        self.seeded = False
        self._value = -np.inf

    @property
    def value(self) -> float:
        if not self.seeded and self.machine is not None:
            self.seeded = True
            seq = self.sequential = sequential(self.machine, self.designs)
            if seq is not None and seq.feasible:
                v = seq.value(self.machine.objective)
                obj = self.machine.objective
                self._value = max(self._value, -v if obj in ("cost", "moving_mass") else v)
        return self._value

    @value.setter
    def value(self, v: float) -> None:
        self._value = v


def _tol(v: float) -> float:
    return 1e-9 * max(abs(v), 1.0)


def _completion(machine: Machine, J: dict, other: dict) -> np.ndarray:
    """The best machine objective (larger is better) each joined offer ``J`` of a whole chain
    reaches with the other chain's offers ``other`` within the machine limits (-inf: none)."""
    f = (
        _sub_frequency(J["m"], J["k"])
        if _reads_frequency(machine)
        else np.full(len(J["cost"]), np.inf)
    )
    kmin = np.asarray(machine.min_tool_stiffness, dtype=float)
    out = np.full(len(J["cost"]), -np.inf)
    for s in range(0, len(J["cost"]), 2048):
        r = slice(s, s + 2048)
        cost = J["cost"][r, None] + other["cost"][None, :]
        c = J["c"][r, None, :] + other["c"][None, :, :]
        mm = J["mm"][r, None] + other["mm"][None, :]
        ff = np.minimum(f[r, None], other["f"][None, :])
        ok = (cost <= machine.max_cost * (1 + 1e-9)) & (mm <= machine.max_moving_mass * (1 + 1e-9))
        ok &= ((1.0 / c) >= kmin * (1 - 1e-9)).all(-1)
        if machine.min_frequency > 0:
            ok &= ff >= machine.min_frequency * (1 - 1e-9)
        obj = np.where(ok, _objective(machine, cost, c, ff, mm), -np.inf)
        out[r] = obj.max(axis=1, initial=-np.inf)
    return out


def _branch_offers(
    machine: Machine,
    chain: list,
    designs: _Designs,
    prune: bool,
    kept: dict,
    other: dict | None = None,
    incumbent: _Incumbent | None = None,
    below=None,
) -> dict:
    """The offers of one chain on the frame (arrays, one row per offer).  ``other``: the other
    chain's offers (or the empty chain) when this is the last chain: its loads are then bounded
    against ``incumbent`` (an :class:`_Incumbent`, the best machine objective found, larger is
    better); ``below(i)``: the best each axis under chain[i] can offer (:func:`_best_below`), for
    the bound of the loads of the axes above the frame's."""
    freq = _reads_frequency(machine)
    kmin = np.asarray(machine.min_tool_stiffness, dtype=float)
    cmax = np.where(kmin > 0, 1.0 / np.where(kmin > 0, kmin, 1.0), np.inf)
    O = {
        "cost": np.zeros(1),
        "M": np.zeros(1),
        "stat": np.zeros(1),
        "c": np.zeros((1, 3)),
        "mm": np.zeros(1),
        "m": np.zeros((1, 0)),
        "k": np.zeros((1, 0, 3)),
        "refs": [()],
    }
    for i in range(len(chain) - 1, -1, -1):
        ax = chain[i]
        at = chain[i + 1].carried_at if i + 1 < len(chain) else (0.0, 0.0)
        own = ax.problem.axis.moving_mass + (
            ax.problem.axis.twin_drive.cross_mass if ax.problem.axis.twin_drive is not None else 0.0
        )
        parts = {k: [] for k in ("cost", "M", "stat", "c", "mm", "m", "k")}
        refs = []
        loads = np.unique(O["M"])
        if len(loads) > 1 and monotone_in_load(ax) and not designs.exhaustive:
            # the lightest first: its feasible set bounds the others
            designs.get(ax, float(loads[0]), at)
        bound = prune and i == 0 and other is not None and monotone_in_load(ax)
        for L in loads:  # ascending
            sel = np.nonzero(O["M"] == L)[0]
            if prune and monotone_in_load(ax) and len(sel) and not bound:
                # the same with the machine limits only: no design at the lightest load meets them
                # with these offers -> none at this load does; and with the incumbent, each axis
                # below at its best
                J = _join(ax, own, O, sel, designs.get(ax, float(loads[0]), at))
                ok, f_ok = _within_limits(machine, J, cmax)
                if not ok.any():
                    continue
                if (
                    below is not None
                    and np.isfinite(incumbent.value)
                    and _optimistic(machine, J, ok, below(i), other, f_ok)
                    < incumbent.value - _tol(incumbent.value)
                ):
                    continue
            if bound and len(sel) and np.isfinite(incumbent.value):
                # what this load's offers could reach with the axis's designs at the lightest load
                # (a superset, each at least as stiff): none beats the incumbent -> the load is
                # never solved
                J = _join(ax, own, O, sel, designs.get(ax, float(loads[0]), at))
                if _completion(machine, J, other).max(initial=-np.inf) < incumbent.value - _tol(
                    incumbent.value
                ):
                    continue
            D = designs.get(ax, float(L), at)
            if not len(D) and monotone_in_load(ax) and not designs.exhaustive:
                break  # nothing fits this load: nothing fits a heavier one
            if not len(D) or not len(sel):
                continue
            J = _join(ax, own, O, sel, D)
            if bound:
                incumbent.value = max(
                    incumbent.value, _completion(machine, J, other).max(initial=-np.inf)
                )
            for k in parts:
                parts[k].append(J[k])
            refs.extend((D, int(j)) + O["refs"][o] for o, j in zip(J["oi"], J["dj"]))
        if not refs:
            return {
                "cost": np.zeros(0),
                "c": np.zeros((0, 3)),
                "mm": np.zeros(0),
                "f": np.zeros(0),
                "refs": [],
            }
        N = {k: np.concatenate(v) for k, v in parts.items()}
        N["refs"] = refs
        keep = np.ones(len(refs), bool)
        if prune:  # limits already missed (everything further down only adds)
            keep &= N["cost"] <= machine.max_cost * (1 + 1e-9)
            keep &= N["mm"] <= machine.max_moving_mass * (1 + 1e-9)
            keep &= (N["c"] <= cmax * (1 + 1e-9)).all(1)
        f_sub = None
        if freq:
            f_sub = _sub_frequency(N["m"], N["k"])
            if prune and machine.min_frequency > 0:
                keep &= f_sub >= machine.min_frequency * (1 - 1e-9)
        N = _take(N, np.nonzero(keep)[0])
        if f_sub is not None:
            f_sub = f_sub[keep]
        if prune and len(N["refs"]):
            N = _take(
                N,
                _pareto(N, f_sub, freq, i == 0, monotone_in_load(chain[i - 1]) if i > 0 else True),
            )
        kept[ax.name] = len(N["refs"])
        O = N
    O["f"] = _sub_frequency(O["m"], O["k"]) if len(O["refs"]) else np.zeros(0)
    return O


def _take(N: dict, keep) -> dict:
    out = {k: v[keep] for k, v in N.items() if k != "refs"}
    out["refs"] = [N["refs"][int(i)] for i in keep]
    return out


def _pareto(N: dict, f_sub, freq: bool, root: bool, monotone: bool) -> np.ndarray:
    """The offers no other beats in what the rest of the machine reads (see the module
    docstring)."""
    cols = [-N["cost"], -N["c"], -N["mm"]]
    if root:
        if freq:
            cols.append(f_sub)
    else:
        cols += [-N["stat"]]
        if freq:
            cols += [-N["m"], N["k"].reshape(len(N["cost"]), -1)]
        if monotone:
            cols.append(-N["M"])
    P = np.column_stack([np.asarray(c).reshape(len(N["cost"]), -1) for c in cols])
    if root or monotone:
        return nondominated(P)
    out = []  # below a counterbalanced axis: only offers of the same carried mass are compared
    for L in np.unique(N["M"]):
        sel = np.nonzero(N["M"] == L)[0]
        out.append(sel[nondominated(P[sel])])
    return np.sort(np.concatenate(out))


def _objective(machine: Machine, cost, c, f, mm) -> np.ndarray:
    """The machine objective, larger is better."""
    return {"cost": -cost, "tool_stiffness": (1.0 / c).min(-1), "frequency": f, "moving_mass": -mm}[
        machine.objective
    ]


def refuse_preloads(machine: Machine) -> None:
    """A machine solve chooses every nut's preload: an axis's ``nut_preload`` (machine evaluate's)
    is an InputError naming it."""
    for ax in machine.axes:
        if ax.nut_preload is not None:
            raise InputError(
                f"nut_preload pins axis {ax.name}'s preload for `axisopt machine evaluate`; a "
                "machine solve chooses every preload: remove it (or bound the search with the axis "
                "problem's continuous.nut_preload {min, max})",
                source=machine.source,
                where=f"axes.{ax.name}.nut_preload",
            )


def solve_machine(machine: Machine, method: str = "default") -> MachineResult:
    """The machine's joint optimum over every axis's catalog combinations (``default``: proven
    through the exact Pareto sets; ``exhaustive``: every combination of every axis) and the
    sequential sizing beside it."""
    if method not in METHODS:
        raise ValueError(f"unknown method '{method}'; use one of {', '.join(METHODS)}")
    refuse_preloads(machine)
    t0 = time.perf_counter()
    exhaustive = method == "exhaustive"
    designs = _Designs(exhaustive)
    kept: dict = {}
    branches = machine.branches()
    # the shorter chains first; the longest last, bounded by the best machine the others complete
    order = sorted(range(len(branches)), key=lambda b: len(branches[b]))
    offers = [None] * len(branches)
    for b in order[:-1]:
        offers[b] = _branch_offers(machine, branches[b], designs, not exhaustive, kept)
    rest = offers[order[0]] if len(branches) > 1 else _EMPTY
    if rest is None or not len(rest["refs"]):
        rest = None
    last = order[-1]
    incumbent = _Incumbent()
    below = None
    if not exhaustive and rest is not None:
        # the designer's sizing: where it meets every limit, its value is the first incumbent
        incumbent = _Incumbent(machine, designs)
        chain = branches[last]
        cache: dict = {}

        def below(i):
            if i not in cache:
                cache[i] = _best_below(machine, chain, designs, i)
            return cache[i]

    offers[last] = _branch_offers(
        machine,
        branches[last],
        designs,
        not exhaustive,
        kept,
        other=rest,
        incumbent=incumbent,
        below=below,
    )
    best = _combine(machine, branches, offers)
    notes = [
        f"exact Pareto sets: below {ch[i - 1].name} offers of different carried mass are not "
        f"compared ({ch[i - 1].name} is counterbalanced: more carried mass may help it); every "
        "load screened in full"
        for ch in branches
        for i in range(1, len(ch))
        if not monotone_in_load(ch[i - 1])
    ]
    if best is None:
        notes += _without_designs(designs)
    for name in machine.estimated_frames:
        notes.append(
            f"the frame under {name} is the stated estimate (as stiff as the axis link: its "
            "compliance doubled); give axes.{name}.frame_stiffness when known".replace(
                "{name}", name
            )
        )
    seq = incumbent.sequential if incumbent.seeded else sequential(machine, designs)
    nominal = float(np.prod([float(designs.combinations.get(a.name, 0)) for a in machine.axes]))
    return MachineResult(
        machine,
        method,
        OPTIMAL if best is not None else INFEASIBLE,
        best,
        seq,
        nominal,
        designs.solves,
        kept,
        time.perf_counter() - t0,
        notes,
    )


def _without_designs(designs: _Designs) -> list:
    """Notes naming each axis that had no design meeting its own limits at any load it was solved
    at (an infeasible machine: that axis is the one to look at alone)."""
    return [
        f"axis {name} has no design meeting its own limits at {min(by):,.1f} kg carried (the "
        "lightest load it was solved at): solve its problem alone (`axisopt solve`) to see which "
        "limit no design meets"
        for name, by in designs.loads.items()
        if not any(by.values())
    ]


_EMPTY = {
    "cost": np.zeros(1),
    "c": np.zeros((1, 3)),
    "mm": np.zeros(1),
    "f": np.full(1, np.inf),
    "refs": [()],
}


def _combine(machine: Machine, branches: list, offers: list) -> MachineDesign | None:
    """The best combination of the chains' offers (one or two chains)."""
    if any(not len(o["refs"]) for o in offers):
        return None
    A = offers[0]
    B = offers[1] if len(offers) > 1 else _EMPTY
    ia, ib = (
        a.ravel()
        for a in np.meshgrid(np.arange(len(A["refs"])), np.arange(len(B["refs"])), indexing="ij")
    )
    cost = A["cost"][ia] + B["cost"][ib]
    c = A["c"][ia] + B["c"][ib]
    mm = A["mm"][ia] + B["mm"][ib]
    f = (
        np.minimum(A["f"][ia], B["f"][ib])
        if _reads_frequency(machine)
        else np.full(len(ia), np.inf)
    )
    kmin = np.asarray(machine.min_tool_stiffness, dtype=float)
    ok = (cost <= machine.max_cost * (1 + 1e-9)) & (mm <= machine.max_moving_mass * (1 + 1e-9))
    ok &= ((1.0 / c) >= kmin * (1 - 1e-9)).all(1)
    if machine.min_frequency > 0:
        ok &= f >= machine.min_frequency * (1 - 1e-9)
    if not ok.any():
        return None
    obj = _objective(machine, cost, c, f, mm)
    w = np.nonzero(ok)[0]
    top = obj[w].max()
    tied = w[obj[w] >= top - 1e-9 * max(abs(top), 1.0)]
    j = tied[np.lexsort((mm[tied], cost[tied]))[0]]  # ties: cheaper, then lighter
    picks = {}
    for chain, o, r in zip(branches, offers, (ia[j], ib[j])):
        for ax, (D, row) in zip(chain, _pairs(o["refs"][r])):
            picks[ax.name] = (D, row)
    return evaluate_choice(machine, picks)


def _pairs(ref: tuple) -> list:
    return [(ref[i], ref[i + 1]) for i in range(0, len(ref), 2)]


def sequential(machine: Machine, designs: _Designs) -> MachineDesign | None:
    """The designer's sizing: each chain's top axis first, alone, at its best for the machine
    objective (cost: the cheapest; tool stiffness or frequency: the stiffest link along its travel;
    moving mass: the lightest), its mass carried to the axis below, and so on; the machine limits
    are checked only at the end."""
    picks = {}
    for chain in machine.branches():
        load = 0.0
        for i in range(len(chain) - 1, -1, -1):
            ax = chain[i]
            at = chain[i + 1].carried_at if i + 1 < len(chain) else (0.0, 0.0)
            D = designs.get(ax, load, at)
            if not len(D):
                return None
            di = "xyz".index(ax.direction)
            score = {"cost": -D.cost, "moving_mass": -D.parts}.get(machine.objective, D.k[:, di])
            top = score.max()
            tied = np.nonzero(score >= top - 1e-9 * max(abs(top), 1.0))[0]
            j = int(tied[np.lexsort((D.parts[tied], D.cost[tied]))[0]])
            picks[ax.name] = (D, j)
            own = ax.problem.axis.moving_mass + (
                ax.problem.axis.twin_drive.cross_mass
                if ax.problem.axis.twin_drive is not None
                else 0.0
            )
            load = load + own + float(D.parts[j] + D.counterweight[j])
    return evaluate_choice(machine, picks)
