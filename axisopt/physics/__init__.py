"""Pure physics formulas of a feed axis, all SI, evaluable on floats, numpy arrays and CasADi
symbols.

Modules: screw, nut, bearings, guides, dynamics, damping, friction, thermal, checks, carriage,
gantry.  See each function's docstring for the equation, units and source (seed paper eq. numbers;
vendor catalogs).
"""

from axisopt.physics import (
    bearings,
    carriage,
    checks,
    damping,
    dynamics,
    friction,
    gantry,
    guides,
    nut,
    screw,
    thermal,
)
from axisopt.physics.screw import MOUNTINGS, parallel_stiffness, series_stiffness

MODULES = (
    screw,
    nut,
    bearings,
    guides,
    dynamics,
    damping,
    friction,
    thermal,
    checks,
    carriage,
    gantry,
)

__all__ = [
    "MODULES",
    "MOUNTINGS",
    "bearings",
    "carriage",
    "checks",
    "damping",
    "dynamics",
    "friction",
    "gantry",
    "guides",
    "nut",
    "parallel_stiffness",
    "screw",
    "series_stiffness",
    "thermal",
]
