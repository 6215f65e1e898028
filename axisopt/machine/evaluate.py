"""A machine whose parts are chosen: every axis's problem names one part per slot (``catalog.require``), and the
machine model gives the stiffness at the tool with every link, the lumped chain's frequencies and the machine
limits it misses (no search: the designer's own choice checked).

Each axis is taken from its carrier's top down, as the machine is built: the top axis at no carried load, each
axis below at the mass of everything it carries, each nut at the top of its feasible preload interval (as the
joint search takes it).  An axis whose parts miss its own limits at the mass it carries has no design: the
result names it (evaluate that axis alone with ``axisopt solve`` to see why).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from ..errors import InputError
from ..search.parts import build_space
from .model import MachineDesign, evaluate_choice
from .offers import arrangements, axis_designs
from .spec import Machine


@dataclass
class MachineEvaluation:
    machine: Machine
    design: MachineDesign | None  # None: an axis's parts miss its own limits
    failed: list = field(
        default_factory=list
    )  # (axis name, carried mass [kg]) of the axes with no design


def check_pinned(machine: Machine) -> None:
    """Every axis must have one catalog combination (one part per slot): InputError naming the axis otherwise."""
    for ax in machine.axes:
        arr = arrangements(ax)
        if len(arr) > 1:
            raise InputError(
                f"axis {ax.name} leaves {len(arr)} arrangements open ({', '.join(lb for lb, _ in arr)}): "
                "choose one in its axis section",
                source=machine.source,
                where=f"axes.{ax.name}.problem.search",
            )
        n = build_space(replace(ax.problem, axis=arr[0][1], arrangements=())).size
        if n != 1:
            raise InputError(
                f"axis {ax.name} has {n:,} catalog combinations: name one part per slot in "
                "its catalog.require (screw, nut, bearing, guide, motor, coupling, reduction), or "
                "size the machine with `axisopt machine solve`",
                source=machine.source,
                where=f"axes.{ax.name}.problem.catalog",
            )


def evaluate_machine(machine: Machine) -> MachineEvaluation:
    """The machine model of the machine's pinned parts (:func:`check_pinned` first)."""
    check_pinned(machine)
    picks, failed = {}, []
    for chain in machine.branches():
        load = 0.0
        for i in range(len(chain) - 1, -1, -1):
            ax = chain[i]
            at = chain[i + 1].carried_at if i + 1 < len(chain) else (0.0, 0.0)
            D = axis_designs(ax, load, at)
            if not len(D):
                failed.append((ax.name, load))
                break
            j = 0
            picks[ax.name] = (D, j)
            a = ax.problem.axis
            own = a.moving_mass + (a.twin_drive.cross_mass if a.twin_drive is not None else 0.0)
            load = load + own + float(D.parts[j] + D.counterweight[j])
    if failed:
        return MachineEvaluation(machine, None, failed)
    return MachineEvaluation(machine, evaluate_choice(machine, picks))


__all__ = ["MachineEvaluation", "evaluate_machine", "check_pinned"]
