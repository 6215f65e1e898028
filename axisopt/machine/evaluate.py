"""A machine whose parts are chosen: every axis's problem names one part per slot
(``catalog.require``), and the machine model gives the stiffness at the tool with every link, the
lumped chain's frequencies and the machine limits it misses (no search: the designer's own choice
checked).

Each axis is taken from its carrier's top down, as the machine is built: the top axis at no carried
load, each axis below at the mass of everything it carries, each nut at the axis's ``nut_preload``
where the machine file gives one, else at the top of its feasible preload interval (as the joint
search takes it).  An axis whose parts miss its own limits at the mass it carries has no design: the
result names it (evaluate that axis alone with ``axisopt solve`` to see why).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from ..errors import InputError
from ..physics.nut import preload_ceiling
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
    """Every axis must have one catalog combination (one part per slot): InputError naming the axis
    otherwise."""
    for ax in machine.axes:
        arr = arrangements(ax)
        if len(arr) > 1:
            raise InputError(
                f"axis {ax.name} leaves {len(arr)} arrangements open "
                f"({', '.join(lb for lb, _ in arr)}): choose one in its axis section",
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


def check_preloads(machine: Machine) -> None:
    """Each axis's ``nut_preload`` within its pinned nut's catalog range and, a preloaded nut, the
    vendors' ceiling (10 % of its Ca, THK A-687): InputError naming the axis's key otherwise."""
    for ax in machine.axes:
        pre = ax.nut_preload
        if pre is None:
            continue
        arr = arrangements(ax)[0][1]
        nut = build_space(replace(ax.problem, axis=arr, arrangements=())).nuts.row(0)
        lo, hi = float(nut["preload_min"]), float(nut["preload_max"])
        top, why = hi, "range"
        if nut["type"] != "single" and preload_ceiling(float(nut["dynamic_load_rating"])) < hi:
            top, why = preload_ceiling(float(nut["dynamic_load_rating"])), "range (10 % of its Ca)"
        if not (lo - 1e-9 <= pre <= top + 1e-9):
            raise InputError(
                f"{pre:.0f} N is outside nut '{nut['id']}' {why} {lo:.0f}..{top:.0f} N",
                source=machine.source,
                where=f"axes.{ax.name}.nut_preload",
            )


def evaluate_machine(machine: Machine) -> MachineEvaluation:
    """The machine model of the machine's pinned parts (:func:`check_pinned` first), each nut at the
    axis's ``nut_preload`` where given (:func:`check_preloads`), else at the top of its feasible
    interval."""
    check_pinned(machine)
    check_preloads(machine)
    picks, failed = {}, []
    for chain in machine.branches():
        load = 0.0
        for i in range(len(chain) - 1, -1, -1):
            ax = chain[i]
            at = chain[i + 1].carried_at if i + 1 < len(chain) else (0.0, 0.0)
            D = axis_designs(ax, load, at, preload=ax.nut_preload)
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


__all__ = ["MachineEvaluation", "evaluate_machine", "check_pinned", "check_preloads"]
