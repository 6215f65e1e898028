"""No-load drag torque at the motor at rapid speed: nut, support bearings, guide blocks."""

from __future__ import annotations

import math

from ..physics import friction as pf
from ..physics import nut as pn
from .loads import unit

# Efficiency of the ball screw used to refer guide friction to the motor (vendor typical 0.9).
SCREW_EFFICIENCY = 0.9


def drag_torque(p, preload, loads) -> dict:
    """Drag torque [N*m] by source.  Nut: the preload drag rule (THK/HIWIN, eq. in physics.nut) at
    the nut's preload (a single nut's preload is its catalog value, 0 without oversize
    balls).  Bearings: the starting torque the support unit's vendor lists, else the upper envelope
    of the vendors' values (an estimate, ``model.params.axis_params``; results name it where it
    binds).  Guides: block friction at rapid speed through the screw efficiency.  A driven
    rotating nut: its unit's bearing (its vendor's starting torque, else the same envelope, an
    estimate) instead of the end sets, which do not turn."""
    omega = 2.0 * math.pi * p["max_speed"] / p["lead"]
    t_nut = pn.nut_preload_drag_torque(preload, p["lead"], p["nominal_diameter"])
    # a driven rotating nut: the end bearings stand still, the unit's built-in bearing turns
    # (model.checks)
    t_brg = (1.0 - unit(p, "nut_rotating")) * p["bearing_sets"] * p["bearing_torque"] + unit(
        p, "nut_rotating"
    ) * unit(p, "unit_bearing_torque")
    t_guides = pf.axial_force_torque(loads["guide_friction"], p["lead"], SCREW_EFFICIENCY)
    return {
        "drag_torque": t_nut + t_brg + t_guides,
        "drag_nut": t_nut,
        "drag_bearings": t_brg,
        "drag_guides": t_guides,
        "screw_speed": omega,
    }
