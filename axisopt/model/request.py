"""What a caller asks the axis model to compute: a :class:`Request` names the sub-assemblies
:func:`axisopt.model.axis_response` (and :func:`axisopt.model.drive_response`) evaluate.

The model's inputs are the axis's data and its parts (the parameter dict ``p``); which outputs to
compute is the caller's question, asked here and not in ``p``.  ``evaluate``, ``diagnose`` and the
CasADi Function ask for everything (:data:`FULL`); the searches ask only for what their limits and
objectives read (:data:`SCREEN`, and :data:`MECHANICS` where each drive is screened apart), each
stage narrowing it with :meth:`Request.but` (e.g. no stiffness chain where only the limits at the
lowest preload are checked).  A request leaves out work; it never changes the value of an output it
computes.
"""

from __future__ import annotations

from dataclasses import dataclass, replace


@dataclass(frozen=True)
class Request:
    """Which sub-assemblies of the axis model to evaluate (``True``: computed, with its outputs).

    chain  : the stiffness chain, the rocking and the axial modes (:data:`~.outputs.CHAIN_OUTPUTS`)
    budget : with the chain, the positioning-error budget (:mod:`.accuracy`; its extra chain points
             cost the screening time: a search none of whose limits reads it leaves it out)
    drive  : the drive block: motor torques, inertia ratio, drive margins (:func:`.drive.drive`)
    regen  : with the drive block, the regenerated energy and power
    extras : the drive-train frequencies and the damping (no limit or objective reads them; with
             them the chain is computed too)
    """

    chain: bool = True
    budget: bool = True
    drive: bool = True
    regen: bool = True
    extras: bool = True

    def but(self, **changes) -> Request:
        """This request with the named fields changed (``SCREEN.but(chain=False)``)."""
        return replace(self, **changes)


FULL = Request()  # every output (evaluate, diagnose, the CasADi Function)
SCREEN = Request(extras=False)  # every output a limit or an objective can read (the searches)
MECHANICS = SCREEN.but(drive=False)  # the searches' outputs but the drive block's (screened apart)
