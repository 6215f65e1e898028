"""The numbers of one design that the identification model needs (SI), taken from the axis model.

:func:`plant_from_design` evaluates :func:`axisopt.model.axis_response` once and keeps what the
measurement models use: the component stiffnesses at the design preload, the screw section, span and
mounting, masses and the catalog friction terms.  Tests and benchmarks may also build a
:class:`Plant` directly.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

import numpy as np

from ..physics.screw import E_STEEL
from .effects.orders import ball_pass_order

G = 9.80665


@dataclass(frozen=True)
class Plant:
    """Design quantities for the measurement models.  SI throughout."""

    mounting: str  # 'fixed-free' | 'fixed-supported' | 'fixed-fixed'
    span: float  # bearing to bearing L [m]
    start_offset: float  # fixed bearing to nut at position 0 [m]
    stroke: float  # [m]
    root_diameter: float  # d_r [m]
    k_bearing: float  # axial rigidity of one support-bearing set with its housing [N/m]
    k_nut: float  # nut stiffness at the design preload, no external load [N/m]
    preload: float  # nut preload Fa0 [N]
    moving_mass: float  # table + nut + blocks [kg]
    screw_mass: float  # [kg]
    coulomb: float  # catalog no-load friction of the axis at the table [N]
    mu: float  # guide friction coefficient [-]
    viscous: float  # guide viscous friction, all blocks [N s/m]
    weight_on_guides: float  # normal load from gravity on the guides [N]
    guide_blocks: int = 4
    guide_normal_stiffness: float = 0.0  # per block [N/m]
    lead: float = 0.01  # [m]
    efficiency: float = 0.9  # screw efficiency for torque <-> force
    youngs_modulus: float = E_STEEL
    # position-independent compliance besides bearings and nut: bracket, coupling [m/N]
    c_series: float = 0.0
    torsion: bool = False  # screw torsion through the lead in the chain (as the axis model)
    reduction: float = 1.0  # motor turns per screw turn (a belt or gear between motor and screw)
    # balls passing a point of the nut per screw turn (effects.orders.ball_pass_order; 0: unknown)
    ball_order: float = 0.0
    belt_teeth: int = 0  # teeth of a belt stage's motor pulley (0: no belt or not known)
    name: str = "design"
    # the position loop's structure the design states (axis.controller: 'pd' | 'p_pi_cascade');
    # None: fitted from the record
    controller: str | None = None

    @property
    def area(self) -> float:
        return math.pi * self.root_diameter**2 / 4.0

    @property
    def k_far(self) -> float:
        """Declared axial stiffness at the far end: the far bearing set for fixed-fixed, else 0."""
        return self.k_bearing if self.mounting == "fixed-fixed" else 0.0

    def nut_x(self, position):
        """Fixed bearing to nut [m] for table positions along the stroke [m]."""
        return self.start_offset + np.asarray(position, dtype=float)

    def m_eff(self, x):
        """Modal mass of the axial mode [kg] (as axisopt.model: Rayleigh share of the screw)."""
        if self.mounting == "fixed-fixed":
            return self.moving_mass + self.screw_mass / 3.0 + 0.0 * x
        return self.moving_mass + self.screw_mass * (1.0 - 2.0 * x / (3.0 * self.span))

    def with_(self, **kw) -> Plant:
        return replace(self, **kw)


def _known(value) -> float:
    """A catalog value, 0 when the row leaves it empty."""
    return float(value) if value is not None and math.isfinite(float(value)) else 0.0


def belt_teeth(reduction) -> int:
    """The motor pulley's teeth of a toothed-belt stage, 0 when not known: the catalog names a belt
    stage's pulleys in its id as ``<z1>x<z2>`` (ELATECH's ``...-32x48``: 32 teeth on the motor,
    48 on the screw), taken only when z2 / z1 is the row's ratio."""
    if reduction is None or str(reduction.get("kind", "")) != "belt":
        return 0
    m = re.search(r"(\d+)x(\d+)$", str(reduction.get("id", "")))
    if m is None:
        return 0
    z1, z2 = int(m.group(1)), int(m.group(2))
    ratio = _known(reduction.get("ratio"))
    return z1 if z1 > 0 and ratio > 0 and abs(z2 / z1 - ratio) <= 0.01 * ratio else 0


def plant_from_design(design) -> Plant:
    """Plant of a :class:`axisopt.design.Design` from the design's own axis model (same chain
    components)."""
    from ..model import SCREW_EFFICIENCY, axis_response, design_params
    from ..model.loads import bearing_set_stiffness

    p = design_params(design)
    ax = design.axis
    out = axis_response(p, np.array([ax.start_offset]), ax.mounting, design.preload)
    blocks = int(ax.guide_blocks)
    nut_drag_force = float(out["drag_nut"]) * 2.0 * math.pi * SCREW_EFFICIENCY / p["lead"]
    weight = 0.0 if ax.orientation == "vertical" else float(out["moving_mass"]) * G
    return Plant(
        mounting=ax.mounting,
        span=ax.span,
        start_offset=ax.start_offset,
        stroke=ax.stroke,
        root_diameter=float(p["root_diameter"]),
        k_bearing=float(bearing_set_stiffness(p)),
        k_nut=float(out["k_nut_unloaded"]),
        preload=float(design.preload),
        moving_mass=float(out["moving_mass"]),
        screw_mass=float(out["screw_mass"]),
        coulomb=blocks * float(p["guide_friction_force"]) + nut_drag_force,
        mu=float(p["guide_friction_coefficient"]),
        viscous=blocks * float(p["guide_friction_viscous"]),
        weight_on_guides=weight,
        guide_blocks=blocks,
        guide_normal_stiffness=float(p["guide_normal_stiffness"]),
        lead=float(p["lead"]),
        efficiency=SCREW_EFFICIENCY,
        c_series=float(out["c_bracket"]) + 1.0 / float(out["k_coupling"]),
        torsion=True,
        reduction=float(p["reduction_ratio"]),
        ball_order=ball_pass_order(
            float(design.screw.get("nominal_diameter", 0.0)),
            _known(design.screw.get("ball_diameter")),
            _known(design.nut.get("contact_angle")),
        ),
        belt_teeth=belt_teeth(design.reduction),
        name=design.name,
        controller=ax.controller,
    )
