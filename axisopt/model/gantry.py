"""Twin-drive gantry sub-assembly: two synchronised screw drives, the same parts on both sides,
under one bridge with a cross carriage on it (:mod:`axisopt.physics.gantry`).

The single-drive model stays the model of one side: the parameters of a twin-drive axis
(:func:`gantry_params`) scale what one drive carries to the governing side at its worst cross
position, and the outputs add the pair's cost and mass and the gantry's yaw (racking) modes.  Per
side, with the cross carriage at the end of its stroke nearest that side
(:func:`axisopt.physics.gantry.side_shares`, r = 1/2 + s / 2L):

* the process force: ``axial_load``, ``mean_axial_load`` and the duty cycle's phase forces times r
  (``force_share``; the guides' load cases take the whole force back: :mod:`.carriage`);
* the moving mass: m_side = m/2 + m_c s / 2L (:func:`side_moving_mass`: the bridge's half and the
  cross carriage's share r; m the whole moving mass: bridge, cross carriage, both nuts and the
  blocks), with the guide friction in the same share; the guides themselves carry the whole gantry
  (:mod:`.carriage`);
* the modes: each side's axial mode with m_side, and the 2-DOF gantry (translation + yaw) with both
  drives' chains k_total at +/-L/2 and the guides' yaw stiffness (:func:`gantry_modes`); its lower
  frequency enters the frequency minimum ``f1`` in place of the guides-only yaw mode of a
  single-drive table;
* cost and mass: a second screw, nut, bearing sets, motor, coupling and reduction
  (:func:`pair_cost`).

A single-drive axis has ``twin`` = 0 and neutral values: every expression then reduces to the
single-drive model exactly (x * 1.0, x + 0.0, min(f, 1e30)), with no branch on a value that may be
symbolic.
"""

from __future__ import annotations

import numpy as np

from .. import mathx as mx
from ..physics import gantry as pg

# the frequency a mode left out of the minimum takes (min(f, NO_MODE) = f)
NO_MODE = 1e30
# parameters of a single-drive axis: no second drive, no cross carriage, neutral geometry
SINGLE = {
    "twin": 0.0,
    "force_share": 1.0,
    "cross_mass": 0.0,
    "cross_stroke": 0.0,
    "twin_span": 1.0,
    "bridge_yaw_inertia": 1.0,
}
TWIN_PARAMS = tuple(SINGLE)


def tp(p, name):
    """A twin-drive parameter of ``p``, or its single-drive value when ``p`` has none (a bare
    parameter dict)."""
    return p[name] if name in p else SINGLE[name]


def single_drive(p) -> bool:
    """True when ``p`` is certainly one drive: ``twin`` a number (not a CasADi symbol) that is 0
    everywhere.  The gantry's modes are then left out of the expressions (no 2-DOF eigenvalues on
    millions of screened combinations, no 1e30 terms in a MINLP's relaxation); a symbolic ``twin``
    keeps them."""
    t = tp(p, "twin")
    return not mx.is_symbolic(t) and not np.any(np.asarray(t) != 0.0)


def gantry_params(axis) -> dict:
    """The twin-drive parameters of an :class:`axisopt.design.Axis` (SI floats; :data:`SINGLE`
    without ``axis.twin_drive``).  The bridge's yaw inertia, when the YAML gives none, from its
    parts (:func:`axisopt.physics.gantry.bridge_yaw_inertia`: a beam over the span and the uprights
    at the drives, ``twin_drive.upright_mass``, else the ESTIMATE of half the bridge's mass,
    ``UPRIGHT_SHARE``)."""
    tw = getattr(axis, "twin_drive", None)
    if tw is None:
        return dict(SINGLE)
    inertia = tw.bridge_yaw_inertia
    # from the bridge's parts: its uprights as given, else the estimate pg.UPRIGHT_SHARE
    if inertia is None:
        uprights = (
            pg.UPRIGHT_SHARE * axis.moving_mass if tw.upright_mass is None else tw.upright_mass
        )
        inertia = pg.bridge_yaw_inertia(axis.moving_mass, tw.span, uprights)
    return {
        "twin": 1.0,
        "force_share": tw.force_share,
        "cross_mass": tw.cross_mass,
        "cross_stroke": tw.cross_stroke,
        "twin_span": tw.span,
        "bridge_yaw_inertia": float(inertia),
    }


def side_moving_mass(p, moving):
    r"""The governing side's moving mass [kg] from the whole moving mass ``moving`` [kg]
    (:func:`axisopt.physics.gantry.side_mass_share` at y = -s/2):

    .. math:: m_{side} = m\,(1 - t/2) + m_c\,(r - 1 + t/2)

    t = ``twin`` (0 or 1), r = ``force_share`` = 1/2 + s/2L: m/2 + m_c s/2L for a twin drive, m for
    one drive.
    """
    t = tp(p, "twin")
    return moving * (1.0 - 0.5 * t) + tp(p, "cross_mass") * (tp(p, "force_share") - 1.0 + 0.5 * t)


def gantry_modes(p, k_total, moving, moving_side, m_eff, k_guides) -> dict:
    """The gantry's two modes [Hz] (:func:`axisopt.physics.gantry.gantry_frequencies`) with both
    drives' chains ``k_total`` [N/m] (per position) at +/-L/2, the guides' yaw stiffness
    ``k_guides`` [N m/rad] (:func:`axisopt.model.carriage.rocking`), the bridge (the whole moving
    mass ``moving`` [kg] less the cross carriage) and the screws' Rayleigh shares
    (``m_eff - moving_side`` per drive, at +/-L/2: mass and yaw inertia).  The cross carriage at the
    centre, a quarter and the end of its half stroke: ``f_gantry`` the lowest frequency over them
    (per position), ``f_racking`` the higher mode with the carriage at the end.  A
    single-drive axis: both :data:`NO_MODE`."""
    t = tp(p, "twin")
    span, m_c = tp(p, "twin_span"), tp(p, "cross_mass")
    m_r = m_eff - moving_side  # one screw's Rayleigh share at its nut
    m_b = moving - m_c + 2.0 * m_r
    j_b = tp(p, "bridge_yaw_inertia") + 2.0 * m_r * (0.25 * span * span)
    lows = []
    for frac in (0.0, 0.25, 0.5):
        y = frac * tp(p, "cross_stroke")
        lo, hi = pg.gantry_frequencies(m_b, j_b, m_c, y, k_total, k_total, span, k_guides)
        lows.append(lo)
    f_low = lows[0]
    for f in lows[1:]:
        f_low = mx.fmin(f_low, f)
    k_rack = pg.yaw_stiffness(k_total, k_total, span, k_guides)
    if not mx.is_symbolic(t):  # a twin drive (one drive never comes here as numbers: model.modes)
        return {"f_gantry": f_low, "f_racking": hi, "k_racking": k_rack}
    off = (1.0 - t) * NO_MODE
    return {"f_gantry": f_low + off, "f_racking": hi + off, "k_racking": k_rack + off}


def pair_cost(p):
    """The second drive's parts [EUR]: screw, nut, bearing sets, motor, coupling and reduction
    (``twin`` x)."""
    screw = (p["screw_price_per_length"] * p["span"] + p["screw_price_fixed"]) * p[
        "grade_price_factor"
    ]
    return tp(p, "twin") * (
        screw
        + p["nut_price"]
        + p["bearing_sets"] * p["bearing_price"]
        + p["motor_price"]
        + p["coupling_price"]
        + p["reduction_price"]
    )
