"""What one axis offers the machine at a carried load: its feasible designs, each at its best nut
preload, with what the machine reads of it (cost, part masses, the stiffness of its link in x, y and
z).

A design's nut preload is the upper end of its feasible preload interval (the axis search's exact
1-D solve): the stiffnesses only grow with the preload and cost and mass do not depend on it, so no
machine objective or limit gains from a lower one.  The designs are then reduced to the exact Pareto
set of what the machine reads (lower cost, lighter moving and stationary parts, stiffer in every
direction): a dominated design is never better for the machine, whatever the other axes are.

Where the axis cannot lose by carrying more (:func:`monotone_in_load`), the designs feasible at the
lightest load are a superset of those feasible at any heavier one, and the heavier loads are solved
on that set only; elsewhere every load is screened in full.  ``exhaustive`` solves every combination
at every load (the ground truth the tests compare with).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field, replace

import numpy as np

from ..search.candidates import make_candidate
from ..search.drivespace import MOTOR_MASS_BASE, MOTOR_MASS_PER_NM
from ..search.exhaustive import exhaustive_search
from ..search.pareto import nondominated, screen_feasible_blocks
from ..search.parts import build_space
from ..search.preload import exact_solve
from ..search.task.constraints import build_constraints
from ..search.task.objective import objective_spec
from .spec import DIRECTIONS, MachineAxis, at_carried_load

SPEC = objective_spec("stiffness")  # the exact solves' objective: the highest feasible preload


def arrangements(ax: MachineAxis) -> tuple:
    """((label, Axis), ...): the axis's own, or its search.counterbalance / twin-drive choices."""
    p = ax.problem
    return p.arrangements if p.arrangements else (("", p.axis),)


def counterweight(axis) -> float:
    """The counterweight (with its chain) a counterbalanced axis hangs on its carrier [kg]."""
    cb = axis.counterbalance
    return cb.mass + cb.chain_mass if cb is not None and cb.kind == "counterweight" else 0.0


def monotone_in_load(ax: MachineAxis) -> bool:
    """Whether the axis never gains from carrying more mass (all its limits worsen with the moving
    mass).  Not so for a vertical axis with a counterbalance: a heavier head may bring the weight
    nearer the counterweight's pull and lower the net load on the screw and motor."""
    return not any(
        a.orientation == "vertical"
        and a.counterbalance is not None
        and a.counterbalance.kind != "none"
        for _, a in arrangements(ax)
    )


@dataclass
class AxisDesigns:
    """The designs an axis offers at one carried load, the rows of each array one design (SI)."""

    axis: MachineAxis
    load: float  # carried mass [kg]
    problems: list  # per arrangement: (label, Problem, Space)
    arr: np.ndarray  # arrangement number
    idx: np.ndarray  # combination number in its space
    preload: np.ndarray  # [N]
    cost: np.ndarray  # [EUR]
    parts: np.ndarray  # every part's mass, the drive's too [kg]
    moving_parts: np.ndarray  # nut(s) and guide blocks [kg]
    counterweight: np.ndarray  # hung on the carrier [kg]
    k: np.ndarray  # (K, 3) the axis link's stiffness in x, y, z, without the frame [N/m]
    combinations: int = 0  # catalog combinations of the space(s)
    feasible: int = 0  # before the Pareto reduction
    _cands: dict = field(default_factory=dict, repr=False)

    def __len__(self) -> int:
        return len(self.idx)

    @property
    def stationary(self) -> np.ndarray:
        """What stays on the carrier: screw, bearings, rails, motor ... and the counterweight
        [kg]."""
        return self.parts - self.moving_parts + self.counterweight

    def candidate(self, j: int):
        """The axis search's Candidate of design ``j`` (with its Design)."""
        if j not in self._cands:
            label, _problem, space = self.problems[int(self.arr[j])]
            c = make_candidate(space, int(self.idx[j]), float(self.preload[j]), SPEC, rank=1)
            if label:
                c.arrangement = label
            self._cands[j] = c
        return self._cands[j]

    def take(self, keep) -> AxisDesigns:
        keep = np.asarray(keep, dtype=np.int64)
        out = replace(
            self,
            arr=self.arr[keep],
            idx=self.idx[keep],
            preload=self.preload[keep],
            cost=self.cost[keep],
            parts=self.parts[keep],
            moving_parts=self.moving_parts[keep],
            counterweight=self.counterweight[keep],
            k=self.k[keep],
        )
        out._cands = {}
        return out


def _link_stiffness(ax: MachineAxis, axis, space, ex_rows, stiffness) -> np.ndarray:
    """(K, 3) stiffness of the axis link in x, y, z [N/m]: along the travel the drive chain's least
    over the stroke (a twin drive: both sides' chains under a rigid bridge at the governing
    position, k / (r^2 + (1 - r)^2)), across it the guide blocks' normal and tangential rigidity, in
    parallel."""
    _m, _n, _b, g = space.unravel(ex_rows)
    blocks = axis.guide_blocks
    k_ax = stiffness * 1e6
    if axis.twin_drive is not None:
        r = axis.twin_drive.force_share
        k_ax = k_ax / (r * r + (1.0 - r) ** 2)
    k_n = blocks * space.g_arr["normal_rigidity"][g]
    k_l = blocks * space.g_arr["tangential_rigidity"][g]
    by = {"axial": k_ax, "normal": k_n, "lateral": k_l}
    return np.column_stack([by[ax.link_role(d)] for d in DIRECTIONS])


def _masses(table) -> np.ndarray:
    """The ``mass`` column of a part table [kg] (NaN where a row or the catalog gives none)."""
    if table is None or not len(table):
        return np.zeros(0)
    return table.number("mass") if "mass" in table else np.full(len(table), np.nan)


def drive_mass(space, g) -> np.ndarray:
    """The mass [kg] of the drive (motor, coupling, reduction) of guide-and-drive numbers ``g``: it
    stays on the carrier.  A motor without a catalog mass weighs the rack drives' estimate, 2 kg +
    0.7 kg per N m rated; a coupling or reduction without one, nothing (docs/assumptions.md); no
    drive search: 0 (the axis's own values)."""
    g = np.asarray(g, dtype=np.int64)
    if space.m_arr is None:
        return np.zeros(len(g))
    m = _masses(space.motors)
    guess = MOTOR_MASS_BASE + MOTOR_MASS_PER_NM * space.motors.number("rated_torque")
    m = np.where(np.isfinite(m), m, guess)
    cm = np.nan_to_num(_masses(space.couplings))
    rm = np.nan_to_num(_masses(space.reductions))
    per = np.array(
        [
            m[mi] + (cm[ci] if ci is not None else 0.0) + (rm[ri] if ri is not None else 0.0)
            for mi, ci, ri in space.drives
        ]
    )
    return per[g % len(space.drives)]


def axis_designs(
    ax: MachineAxis,
    load: float,
    at: tuple = (0.0, 0.0),
    *,
    exhaustive: bool = False,
    superset: dict | None = None,
    preload: float | None = None,
) -> AxisDesigns:
    """The axis's feasible designs at ``load`` kg carried at ``at`` = (height, offset) on its
    carriage (the machine file's ``carried_at`` of the axis above).  ``superset``: per arrangement
    the combinations to solve (those feasible at a lighter load, where :func:`monotone_in_load`).
    ``preload`` [N]: every nut at this preload only (machine evaluate's ``nut_preload``; a design is
    feasible only if it meets every limit there)."""
    rows = {k: [] for k in ("arr", "idx", "preload", "cost", "parts", "moving", "cw", "k")}
    problems, combos = [], 0
    for ai, (label, arr_axis) in enumerate(arrangements(ax)):
        axis = at_carried_load(arr_axis, load, *at)
        problem = replace(ax.problem, axis=axis, arrangements=())
        space = build_space(problem)
        if preload is not None:  # the nuts' preload range shrunk to the one preload (on a copy)
            space = copy.copy(space)
            space.preload_lo = np.full_like(space.preload_lo, preload, dtype=float)
            space.preload_hi = space.preload_lo.copy()
        cons = build_constraints(problem)
        combos += space.size
        problems.append((label, problem, space))
        if exhaustive:
            ex, _ = exhaustive_search(space, cons, SPEC)
        elif superset is not None and ai in superset and superset[ai][0] == space.shape:
            ex = exact_solve(space, superset[ai][1], cons, SPEC)
        else:
            idx, _, _, _ = screen_feasible_blocks(space, cons, SPEC)
            ex = exact_solve(space, idx, cons, SPEC)
        ok = np.nonzero(ex.feasible)[0]
        idx = ex.idx[ok]
        _m, n, _b, g = space.unravel(idx)
        twin = axis.twin_drive is not None
        moving = (1.0 + twin) * space.n_arr["mass"][n] + axis.guide_blocks * space.g_arr[
            "block_mass"
        ][g]
        rows["arr"].append(np.full(len(ok), ai))
        rows["idx"].append(idx)
        rows["preload"].append(ex.preload[ok])
        rows["cost"].append(ex.goals["cost"][ok])
        # in the model's total mass
        carried = axis.moving_mass + (axis.twin_drive.cross_mass if twin else 0.0)
        # the axis's parts and its drive(s), which stay on the carrier
        drives = (1.0 + twin) * drive_mass(space, g)
        rows["parts"].append(ex.goals["total_mass"][ok] - carried + drives)
        rows["moving"].append(moving)
        rows["cw"].append(np.full(len(ok), counterweight(axis)))
        rows["k"].append(_link_stiffness(ax, axis, space, idx, ex.goals["stiffness"][ok]))
    cat = {k: np.concatenate(v) for k, v in rows.items()}
    return AxisDesigns(
        ax,
        load,
        problems,
        cat["arr"],
        cat["idx"],
        cat["preload"],
        cat["cost"],
        cat["parts"],
        cat["moving"],
        cat["cw"],
        cat["k"].reshape(-1, 3),
        combinations=combos,
        feasible=len(cat["idx"]),
    )


def pareto_designs(d: AxisDesigns) -> AxisDesigns:
    """The exact Pareto set of ``d`` in what the machine reads: cost, moving parts, what stays on
    the carrier (parts and counterweight), the link's stiffness in x, y and z (every point kept,
    equal ones too)."""
    if not len(d):
        return d
    P = np.column_stack([-d.cost, -d.moving_parts, -d.stationary, d.k])
    return d.take(nondominated(P))


def feasible_sets(d: AxisDesigns) -> dict:
    """Per arrangement (space shape, combination numbers) of ``d``'s designs: the superset a heavier
    load is solved on."""
    return {ai: (space.shape, d.idx[d.arr == ai]) for ai, (_l, _p, space) in enumerate(d.problems)}
