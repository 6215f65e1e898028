"""The whole machine: a tree of feed axes (bed, column, carriages, bridge) sized together.

A machine file names each axis's problem (the ``axis:``, ``limits:``, ``catalog:`` sections of a
problem file, with ``axis.moving_mass`` the axis's own moving structure), what carries it (the frame
or another axis), its direction and the normal of its guides, and the frame's stiffness under it.
Every part an upper axis chooses adds to the mass the axis below carries (:mod:`.offers`); the
machine model (:mod:`.model`) gives the stiffness at the tool in x, y and z through every axis and
the lowest natural frequencies of the lumped chain (:mod:`.chain`); the joint search (:mod:`.joint`)
proves the machine's optimum over every axis's catalog combinations, and the sequential sizing a
designer does by hand (top axis first) is computed beside it.

This package is a layer above the axis: it uses :mod:`axisopt.search` and :mod:`axisopt.model`,
which know nothing of it.
"""

from .joint import solve_machine
from .spec import Machine, MachineAxis, load_machine

__all__ = ["Machine", "MachineAxis", "load_machine", "solve_machine"]
