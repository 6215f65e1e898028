"""Damping relations (seed eq. 36-39) and component damping data (Tables 5-7)."""

from __future__ import annotations

from types import MappingProxyType

from axisopt import mathx as mx
from axisopt.physics.screw import choose

__all__ = [
    "DAMPING_RATIO_TABLE5",
    "BEARING_DAMPING_TABLE6",
    "GUIDE_DAMPING_TABLE7",
    "critical_damping",
    "damping_ratio",
    "damping_coefficient",
    "damping_ratio_from_log_decrement_eq39",
    "damping_ratio_from_log_decrement_exact",
    "LOG_DECREMENT_METHODS",
    "damping_ratio_from_log_decrement",
    "damping_ratio_from_loss_factor",
    "damping_ratio_from_decay_rate",
    "modal_damping_ratio",
    "rolling_joint_damping",
    "chain_damper_share",
]

# Seed Table 5 (after [16]): damping ratio ranges [-], as printed ("0.02-0.0" and "Red" are garbled
# in the source).
DAMPING_RATIO_TABLE5 = MappingProxyType(
    {
        "steel": (0.001, 0.002),
        "cast iron": (0.002, 0.004),
        "polymer concrete": (0.02, None),
        "welded structure": (0.004, 0.08),
        "red (as printed)": (0.04, 0.08),
    }
)
# Seed Table 6 (after [20]): bearing damping [N*s/m] by bore [mm].
BEARING_DAMPING_TABLE6 = MappingProxyType(
    {
        55: (2000.0, 9000.0),
        90: (5500.0, 12000.0),
        120: (50000.0, 550000.0),
        160: (200000.0, 1000000.0),
    }
)
# Seed Table 7 (after [9]): linear guide damping [N*s/m] by type and rail size [mm].
GUIDE_DAMPING_TABLE7 = MappingProxyType(
    {
        ("ball", 35): (4000.0, 10000.0),
        ("roller", 35): (3500.0, 14500.0),
        ("ball", 45): (4000.0, 14000.0),
        ("roller", 45): (6500.0, 10500.0),
    }
)


def critical_damping(mass, stiffness):
    r"""Critical damping coefficient, d_c = 2 sqrt(m k) = 2 m omega_0        (seed eq. 38)

    mass : m [kg];  stiffness : k [N/m].  Returns d_c [N*s/m].
    """
    return 2.0 * mx.sqrt(mass * stiffness)


def damping_ratio(damping, mass, stiffness):
    r"""Damping ratio, zeta = d / (2 sqrt(m k))                               (seed eq. 39)

    damping : d [N*s/m];  mass : m [kg];  stiffness : k [N/m].  Returns zeta [-].
    """
    return damping / critical_damping(mass, stiffness)


def damping_coefficient(ratio, mass, stiffness):
    r"""Viscous damping coefficient from a damping ratio, d = 2 zeta sqrt(m k)   (seed eq. 38-39)

    ratio : zeta [-];  mass [kg];  stiffness [N/m].  Returns d [N*s/m].
    """
    return ratio * critical_damping(mass, stiffness)


def damping_ratio_from_log_decrement_eq39(log_decrement):
    r"""zeta = Lambda / (2 pi)      (seed eq. 39; small-damping form, error < 1 % for zeta < 0.14)

    log_decrement : Lambda = ln(x_i / x_{i+1}) [-].  Returns zeta [-].
    """
    return log_decrement / (2.0 * mx.pi)


def damping_ratio_from_log_decrement_exact(log_decrement):
    r"""zeta = Lambda / sqrt(4 pi^2 + Lambda^2)       (exact for a viscous SDOF, any zeta < 1)

    log_decrement : Lambda [-].  Returns zeta [-].
    """
    return log_decrement / mx.sqrt(4.0 * mx.pi**2 + log_decrement**2)


LOG_DECREMENT_METHODS = MappingProxyType(
    {
        "eq39": damping_ratio_from_log_decrement_eq39,
        "exact": damping_ratio_from_log_decrement_exact,
    }
)


def damping_ratio_from_log_decrement(log_decrement, method="eq39"):
    """Damping ratio from the logarithmic decrement; method "eq39" (seed) or "exact".  Returns
    [-]."""
    return choose(LOG_DECREMENT_METHODS, method, "method")(log_decrement)


def damping_ratio_from_loss_factor(loss_factor):
    r"""zeta = eta / 2           (seed eq. 39; at resonance)

    loss_factor : eta [-].  Returns zeta [-].
    """
    return 0.5 * loss_factor


def damping_ratio_from_decay_rate(decay_rate, angular_frequency):
    r"""zeta = delta / omega     (seed eq. 39; delta = d/(2m) decay constant)

    decay_rate : delta [1/s];  angular_frequency : omega_0 [rad/s].  Returns zeta [-].
    """
    return decay_rate / angular_frequency


def modal_damping_ratio(mass, stiffness, *dampers, structural_ratio=0.0):
    r"""Damping ratio of a lumped mode from discrete component dampers acting on the modal
    coordinate.

    .. math:: \zeta = \zeta_s + \sum_i d_i / (2\sqrt{m k})              (seed eq. 39 summed; Tables 5-7)

    mass : modal mass m [kg];  stiffness : modal stiffness k [N/m]
    dampers : d_i [N*s/m], e.g. guide blocks (Table 7) and bearings (Table 6), already referred to
        the mode
    structural_ratio : zeta_s, material damping (Table 5) [-].  Returns zeta [-].
    """  # noqa: E501
    total = 0.0
    for d in dampers:
        total = total + d
    return structural_ratio + total / critical_damping(mass, stiffness)


def rolling_joint_damping(bore):
    r"""Axial damping of a rolling-element joint (support bearing set, ball nut) from seed Table 6.

    Table 6 lists spindle bearings by bore (55, 90, 120, 160 mm).  The midpoint of the row for the
    nearest listed bore at or above ``bore`` is used; bores below 55 mm take the 55 mm row
    (2000-9000 N*s/m, midpoint 5500), the smallest listed, and bores above 160 mm the 160 mm row.
    Feed-axis support bearings (15-60 mm) and nuts therefore get 5500 N*s/m: an order-of-magnitude
    figure.

    bore : d [m] (float, array or symbol).  Returns d [N*s/m].
    """
    mm = bore * 1e3
    rows = sorted(BEARING_DAMPING_TABLE6)
    lo, hi = BEARING_DAMPING_TABLE6[rows[-1]]
    out = 0.5 * (lo + hi) + 0.0 * mm
    for b in reversed(rows[:-1]):
        lo, hi = BEARING_DAMPING_TABLE6[b]
        out = mx.if_else(mm <= b, 0.5 * (lo + hi), out)
    return out


def chain_damper_share(damping, chain_stiffness, component_stiffness):
    r"""A damper across one spring of a series chain, referred to the chain's end coordinate.

    .. math:: d_{eff} = d\,(k/k_i)^2

    The component deforms by (k/k_i) of the chain's end displacement, so it dissipates (k/k_i)^2 of
    what the same damper would at the end (strain-energy share).  damping : d
    [N*s/m];  chain_stiffness : k [N/m]
    component_stiffness : k_i [N/m].  Returns d_eff [N*s/m].
    """
    return damping * (chain_stiffness / component_stiffness) ** 2
