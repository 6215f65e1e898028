"""The feed-axis model: physics assembled for an axis and its chosen parts.

One set of pure functions, one per sub-assembly (:mod:`.loads`, :mod:`.chain`, :mod:`.modes`,
:mod:`.drag`, :mod:`.cost`, :mod:`.checks`), put together by :func:`axis_response`.  ``evaluate``,
the search (screening on numpy, exact solves, IPOPT on the CasADi Function) and ``diagnose`` (its
plant) all call it, each asking for the sub-assemblies it needs (:class:`Request`, :mod:`.request`).
"""

from .checks import CHECK_LABELS, CHECKS, DRIVE_CHECKS, passes
from .drag import SCREW_EFFICIENCY
from .function import (
    COMPONENTS,
    PROFILE_OUTPUTS,
    SCALAR_OUTPUTS,
    AxisModel,
    Evaluation,
    design_params,
    evaluate,
    model_for,
)
from .modes import STEEL_DAMPING
from .outputs import CHAIN_OUTPUTS, OUTPUT_TABLE, OUTPUTS
from .paramnames import PARAM_NAMES
from .params import axis_params, nut_length, one_design, positions
from .request import FULL, MECHANICS, SCREEN, Request
from .response import axis_response, chain_response, drive_inputs, drive_response

__all__ = [
    "CHAIN_OUTPUTS",
    "OUTPUT_TABLE",
    "OUTPUTS",
    "CHECKS",
    "CHECK_LABELS",
    "DRIVE_CHECKS",
    "COMPONENTS",
    "passes",
    "PARAM_NAMES",
    "PROFILE_OUTPUTS",
    "SCALAR_OUTPUTS",
    "SCREW_EFFICIENCY",
    "STEEL_DAMPING",
    "AxisModel",
    "Evaluation",
    "axis_params",
    "nut_length",
    "axis_response",
    "design_params",
    "drive_inputs",
    "chain_response",
    "drive_response",
    "evaluate",
    "model_for",
    "one_design",
    "positions",
    "FULL",
    "MECHANICS",
    "SCREEN",
    "Request",
]
