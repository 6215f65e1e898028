"""The machine model of one choice of designs: the stiffness at the tool through every axis and the
frame, the lumped chain's natural frequencies, Dunkerley's bound, and what limits each (floats and
numpy only).

The structural loop from the tool to the workpiece runs through every axis (both chains on the
frame): the compliance at the tool in a direction is the sum of every link's compliance in it
(springs in series), a link being the axis's drive chain along its travel (the least over the
stroke) or its guide blocks across it, in series with the frame under it.  The chain of each branch
is :mod:`.chain`'s, one mass per axis.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .chain import chain_modes, dunkerley_frequency, strain_shares
from .spec import DIRECTIONS, Machine, MachineAxis


def link_with_frame(ax: MachineAxis, k) -> np.ndarray:
    """The axis link in series with the frame under it [N/m] (..., 3): the frame's given stiffness,
    or the stated estimate, a frame as stiff as the link (the link's compliance doubled)."""
    k = np.asarray(k, dtype=float)
    if ax.frame_stiffness is None:
        return 0.5 * k
    kf = np.asarray(ax.frame_stiffness, dtype=float)
    return 1.0 / (1.0 / k + 1.0 / kf)


@dataclass
class AxisChoice:
    """One axis of a machine design (SI)."""

    name: str
    candidate: object  # axisopt.search.result.Candidate (parts, preload, design)
    carried: float  # mass it carries [kg]
    lumped: float  # its mass in the chain [kg]
    k_axis: tuple  # its link in x, y, z without the frame [N/m]
    k_frame: tuple  # the frame under it in x, y, z [N/m] (the estimate where none is given)
    k_link: tuple  # the two in series [N/m]
    roles: tuple  # 'axial' | 'normal' | 'lateral' per direction
    cost: float  # [EUR]
    parts_mass: float  # its parts and drive (motor, coupling, reduction) [kg]
    counterweight: float = 0.0  # [kg]
    frame_estimated: bool = False


@dataclass
class MachineDesign:
    """A choice of designs for every axis and the machine's values (SI)."""

    axes: list  # AxisChoice, carriers first
    k_tool: tuple  # stiffness at the tool in x, y, z [N/m]
    frequencies: dict  # (branch index, direction) -> ascending natural frequencies [Hz]
    f_lowest: float  # [Hz]
    f_dunkerley: float  # Dunkerley's lower bound of f_lowest [Hz]
    # (direction, axis name, link role): the mode and the spring with most of its strain energy
    lowest_at: tuple
    cost: float  # [EUR]
    moving_mass: float  # every lumped mass [kg]
    misses: list = field(default_factory=list)  # machine limits missed: (key, value, limit) in SI
    tool_point: dict = field(default_factory=dict)  # axis name -> nut position on its stroke [m]
    k_axial_at_point: dict = field(default_factory=dict)  # axis name -> its drive chain there [N/m]
    k_tool_at_point: tuple = ()  # the stiffness at the tool at the tool point, x, y, z [N/m]
    branches: list = field(default_factory=list)  # axis names per chain, the one on the frame first

    @property
    def feasible(self) -> bool:
        return not self.misses

    def value(self, objective: str) -> float:
        return {
            "cost": self.cost,
            "tool_stiffness": min(self.k_tool),
            "frequency": self.f_lowest,
            "moving_mass": self.moving_mass,
        }[objective]

    def weakest(self, d: int) -> tuple:
        """(axis name, role) of the largest compliance at the tool in direction ``d`` (0, 1, 2), and
        'frame' where the frame under an axis is the larger part of its link."""
        best, who = -1.0, ("", "")
        for a in self.axes:
            for part, k in (("frame", a.k_frame[d]), (a.roles[d], a.k_axis[d])):
                if 1.0 / k > best:
                    best, who = 1.0 / k, (a.name, part)
        return who


def evaluate_choice(machine: Machine, picks: dict) -> MachineDesign:
    """The machine design of ``picks``: axis name -> (AxisDesigns, row) (every axis of
    ``machine``)."""
    by = machine.by_name
    choices = {}
    for a in machine.axes:
        d, j = picks[a.name]
        choices[a.name] = (a, d, j)
    out_axes, comp = [], np.zeros(3)
    freqs, f_low, f_dunk, low_at, moving = {}, np.inf, np.inf, ("", "", ""), 0.0
    branches = machine.branches()
    for bi, chain in enumerate(branches):
        masses, links = [], []
        for i, a in enumerate(chain):
            _a, d, j = choices[a.name]
            carried = 0.0
            stat_above = 0.0
            if i + 1 < len(chain):
                up = chain[i + 1]
                _u, du, ju = choices[up.name]
                carried = d.load
                stat_above = float(du.stationary[ju])
            m = a.problem.axis.moving_mass + float(d.moving_parts[j]) + stat_above
            if a.problem.axis.twin_drive is not None:
                m += a.problem.axis.twin_drive.cross_mass
            k_axis = d.k[j]
            k_link = link_with_frame(a, k_axis)
            kf = np.asarray(a.frame_stiffness) if a.frame_stiffness is not None else k_axis
            masses.append(m)
            links.append(k_link)
            comp += 1.0 / k_link
            moving += m
            out_axes.append(
                AxisChoice(
                    a.name,
                    d.candidate(j),
                    carried,
                    m,
                    tuple(k_axis),
                    tuple(kf),
                    tuple(k_link),
                    tuple(a.link_role(x) for x in DIRECTIONS),
                    float(d.cost[j]),
                    float(d.parts[j]),
                    float(d.counterweight[j]),
                    a.frame_stiffness is None,
                )
            )
        M = np.asarray(masses)
        for di, dname in enumerate(DIRECTIONS):
            K = np.asarray([k[di] for k in links])
            f, _phi = chain_modes(M, K)
            freqs[(bi, dname)] = tuple(float(x) for x in f)
            if f[0] < f_low:
                share = strain_shares(M, K)
                f_low = float(f[0])
                who = chain[int(np.argmax(share))]
                low_at = (dname, who.name, who.link_role(dname))
            f_dunk = min(f_dunk, float(dunkerley_frequency(M, K)))
    k_tool = tuple(float(x) for x in 1.0 / comp)
    cost = sum(a.cost for a in out_axes)
    md = MachineDesign(
        sorted(out_axes, key=lambda c: [a.name for a in machine.axes].index(c.name)),
        k_tool,
        freqs,
        f_low,
        f_dunk,
        low_at,
        cost,
        moving,
        branches=[[a.name for a in ch] for ch in branches],
    )
    for di, dname in enumerate(DIRECTIONS):
        if machine.min_tool_stiffness[di] > 0 and k_tool[di] < machine.min_tool_stiffness[di] * (
            1 - 1e-9
        ):
            md.misses.append(
                (f"min_tool_stiffness.{dname}", k_tool[di], machine.min_tool_stiffness[di])
            )
    if machine.min_frequency > 0 and f_low < machine.min_frequency * (1 - 1e-9):
        md.misses.append(("min_frequency", f_low, machine.min_frequency))
    if cost > machine.max_cost * (1 + 1e-9):
        md.misses.append(("max_cost", cost, machine.max_cost))
    if moving > machine.max_moving_mass * (1 + 1e-9):
        md.misses.append(("max_moving_mass", moving, machine.max_moving_mass))
    del by
    _at_tool_point(machine, md)
    return md


def _at_tool_point(machine: Machine, md: MachineDesign) -> None:
    """The stiffness chain at the tool point (each axis's nut at ``machine.tool_point``, mid-stroke
    where not given): each drive chain's stiffness there from its design's evaluation, the guides
    and frame as before."""
    from ..model import evaluate

    pts = dict(machine.tool_point)
    comp = np.zeros(3)
    for a in md.axes:
        ax = machine.by_name[a.name]
        s = pts.get(a.name, 0.5 * ax.problem.axis.stroke)
        # on numpy (the same model): a CasADi Function per mounting would be built for this one
        # evaluation
        ev = evaluate(a.candidate.design, use_casadi=False)
        x0 = a.candidate.design.axis.start_offset
        k_side = float(np.interp(x0 + s, ev.x, np.asarray(ev["k_total"], dtype=float)))
        tw = ax.problem.axis.twin_drive
        k_ax = (
            k_side / (tw.force_share**2 + (1 - tw.force_share) ** 2) if tw is not None else k_side
        )
        md.tool_point[a.name] = s
        md.k_axial_at_point[a.name] = k_ax
        k = [k_ax if a.roles[i] == "axial" else a.k_axis[i] for i in range(3)]
        comp += 1.0 / link_with_frame(ax, np.asarray(k))
    md.k_tool_at_point = tuple(float(v) for v in 1.0 / comp)
