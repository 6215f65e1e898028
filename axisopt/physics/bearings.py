"""Support bearings: radial/axial stiffness relations and methods, friction torque (seed 3.3, eq.
40)."""

from __future__ import annotations

import math
from types import MappingProxyType

from axisopt import mathx as mx
from axisopt.physics.screw import choose

__all__ = [
    "C_TYPE_TABLE2",
    "CATALOG_RADIAL_AXIAL_RATIO",
    "FRICTION_COEFFICIENTS_TABLE8",
    "radial_from_axial_eq27",
    "radial_from_axial_catalog",
    "RADIAL_FROM_AXIAL_METHODS",
    "radial_from_axial",
    "radial_stiffness_eq20",
    "radial_stiffness_palmgren",
    "radial_stiffness_kramer",
    "RADIAL_STIFFNESS_METHODS",
    "bearing_radial_stiffness",
    "bearing_friction_torque",
    "SUPPORT_TORQUE_ENVELOPE",
    "support_starting_torque_envelope",
    "NSK_PERMISSIBLE_SHARE",
    "STATIC_SAFETY_MACHINE_TOOL",
    "STATIC_SAFETY_IBC",
    "row_static_rating",
    "support_static_margin",
    "HOUSING_UNIT_RATIO",
    "housing_stiffness_default",
]

# Seed Table 2, c_type of eq. 20 by angular-contact series (C: 15 deg, AC: 25 deg).  The extracted
# table is partly garbled; the 719C/719AC pair is read as 4.83/5.83 (one cell is blank in the source
# text).
C_TYPE_TABLE2 = MappingProxyType(
    {"719C": 4.83, "719AC": 5.83, "70C": 5.43, "70AC": 6.03, "72C": 5.38, "72AC": 6.03}
)

# Seed sec. 3.3.2 (bearing catalog [12]): c_r / c_a by contact angle in whole degrees.
CATALOG_RADIAL_AXIAL_RATIO = MappingProxyType({15: 6.0, 20: 3.5, 25: 2.0})

# Seed Table 8 (after [23], DIN ISO 15312): (f0_min, f0_max, f1_min, f1_max) for eq. 40.
FRICTION_COEFFICIENTS_TABLE8 = MappingProxyType(
    {
        "deep groove ball": (1.7, 2.3, 0.00010, 0.00020),
        "self-aligning ball": (2.4, 4.0, 0.00008, 0.00008),
        "angular contact ball": (2.0, 7.0, 0.00025, 0.00035),
        "four point": (2.0, 3.0, 0.00037, 0.00037),
        "cylindrical roller with cage": (2.0, 4.0, 0.00020, 0.00040),
        "cylindrical roller full complement": (5.0, 12.0, 0.00055, 0.00055),
        "needle roller": (5.0, 10.0, 0.00050, 0.00050),
        "self-aligning roller": (4.5, 6.5, 0.00017, 0.00036),
        "tapered roller": (3.0, 4.5, 0.00040, 0.00040),
        "axial cylindrical roller": (3.0, 4.0, 0.00150, 0.00150),
        "axial self-aligning roller": (2.5, 3.3, 0.00023, 0.00033),
    }
)


def radial_from_axial_eq27(axial_stiffness, contact_angle):
    r"""Radial stiffness of an angular contact bearing from its axial stiffness ("design
    experience").

    .. math:: k_r = (k_a / 2) \cot^2\alpha                              (seed eq. 27)

    axial_stiffness : k_a [N/m];  contact_angle : alpha [rad].  Returns k_r [N/m].
    Gives 6.96 / 3.77 / 2.30 k_a at 15 / 20 / 25 deg, about 15 % above the catalog ratios 6 / 3.5
    / 2.
    """
    return 0.5 * axial_stiffness / mx.tan(contact_angle) ** 2


def radial_from_axial_catalog(axial_stiffness, contact_angle):
    r"""Catalog radial/axial ratio for bearing pairs in O or X arrangement.

    .. math:: c_r = 6 c_a (15^\circ),\ 3.5 c_a (20^\circ),\ 2 c_a (25^\circ)

    Source: seed sec. 3.3.2 (bearing catalog [12]).

    axial_stiffness : c_a [N/m];  contact_angle : alpha [rad], a plain number equal to 15, 20 or 25
        deg.
    Returns c_r [N/m].  Other angles raise ValueError.
    """
    deg = round(math.degrees(float(contact_angle)), 6)
    key = int(round(deg))
    if abs(deg - key) > 1e-6 or key not in CATALOG_RADIAL_AXIAL_RATIO:
        raise ValueError(f"catalog radial/axial ratio known only for 15, 20, 25 deg, not {deg} deg")
    return CATALOG_RADIAL_AXIAL_RATIO[key] * axial_stiffness


RADIAL_FROM_AXIAL_METHODS = MappingProxyType(
    {"eq27": radial_from_axial_eq27, "catalog": radial_from_axial_catalog}
)


def radial_from_axial(axial_stiffness, contact_angle, method="catalog"):
    """Radial stiffness from axial stiffness; method in RADIAL_FROM_AXIAL_METHODS ("eq27",
    "catalog").

    axial_stiffness [N/m], contact_angle [rad].  Returns [N/m].
    """
    return choose(RADIAL_FROM_AXIAL_METHODS, method, "method")(axial_stiffness, contact_angle)


def radial_stiffness_eq20(bore, outer_diameter, radial_load, c_type):
    r"""Radial stiffness of an angular contact ball bearing, empirical form of seed eq. 20 (after
    [1]).

    .. math:: k_r = c_{type} (D + d)^{2/3} (D - d)^{-1/4} F_r^{1/3}

    evaluated with D, d in [mm], F_r in [N] and read as k_r in [N/um] (units as printed in the
    seed).
    bore : d [m];  outer_diameter : D [m];  radial_load : F_r [N];  c_type : Table 2 value [-]
    (C_TYPE_TABLE2).  Returns k_r [N/m].  Valid for preloaded spindle-type bearings 70xx/719xx/72xx.
    """
    d_mm, dd_mm = bore * 1e3, outer_diameter * 1e3
    return (
        1e6 * c_type * (dd_mm + d_mm) ** (2.0 / 3.0) / (dd_mm - d_mm) ** 0.25 * mx.cbrt(radial_load)
    )


def radial_stiffness_palmgren(radial_load, ball_diameter, n_balls, contact_angle, n_rows=1.0):
    r"""Radial stiffness after Palmgren (seed eq. 21-23).

    .. math:: \delta_r = \frac{0.436}{\cos\alpha} (Q^2 / D_w)^{1/3}\ [\mu m],\ Q [N],\ D_w [mm]   (eq. 23)
    .. math:: Q = 5 F_r / (i Z \cos\alpha)\ \text{(Stribeck)},
    .. math:: k_r = dF_r/d\delta_r = \tfrac32 F_r/\delta_r

    (p = 2/3 for ball bearings, eq. 21-22.)
    radial_load : F_r [N];  ball_diameter : D_w [m];  n_balls : Z per row [-];  contact_angle :
        alpha [rad]
    n_rows : i [-].  Returns k_r [N/m].  Valid for rigid rings, zero clearance, ball bearings.
    """  # noqa: E501
    ca = mx.cos(contact_angle)
    q = 5.0 * radial_load / (n_rows * n_balls * ca)
    delta_um = 0.436 / ca * mx.cbrt(q**2 / (ball_diameter * 1e3))
    return 1.5 * radial_load / (delta_um * 1e-6)


def radial_stiffness_kramer(radial_load, ball_diameter, n_balls):
    r"""Radial stiffness after Kraemer (seed eq. 25-26).

    .. math:: x_r = 1.2\times10^{-7} d_b^{-1/3} Z^{-2/3} F^{2/3},\quad k_r = n F_r / x_r,\ n = 3/2

    evaluated in SI (d_b [m], F [N], x_r [m]); this matches Palmgren within ~10 % for typical
    geometry.
    radial_load : F_r [N];  ball_diameter : d_b [m];  n_balls : Z [-].  Returns k_r [N/m].
    """
    x_r = (
        1.2e-7
        * ball_diameter ** (-1.0 / 3.0)
        * n_balls ** (-2.0 / 3.0)
        * radial_load ** (2.0 / 3.0)
    )
    return 1.5 * radial_load / x_r


RADIAL_STIFFNESS_METHODS = MappingProxyType(
    {
        "eq20": radial_stiffness_eq20,
        "palmgren": radial_stiffness_palmgren,
        "kramer": radial_stiffness_kramer,
    }
)


def bearing_radial_stiffness(method, **kwargs):
    """Radial bearing stiffness by a named method ("eq20", "palmgren", "kramer"); kwargs are that
    function's arguments (SI).  Returns [N/m]."""
    return choose(RADIAL_STIFFNESS_METHODS, method, "method")(**kwargs)


def bearing_friction_torque(f0, f1, viscosity, speed, mean_diameter, load):
    r"""Rolling bearing friction torque, load-independent plus load-dependent part.

    .. math:: M = 10^{-7} f_0 (\nu n)^{2/3} d_m^3 + f_1 P_1 d_m\ [N mm],\ \nu n \ge 2000      (seed eq. 40)
    .. math:: M = 160\cdot10^{-7} f_0 d_m^3 + f_1 P_1 d_m\ [N mm],\ \nu n < 2000

    (low-speed branch: SKF / Schaeffler)

    with nu [mm^2/s], n [1/min], d_m [mm].  Inputs and output here are SI:
    f0, f1        : coefficients [-] (FRICTION_COEFFICIENTS_TABLE8)
    viscosity     : nu, kinematic viscosity at operating temperature [m^2/s]
    speed         : omega [rad/s] (sign ignored)
    mean_diameter : d_m = (d + D)/2 [m]
    load          : P_1, equivalent load [N]
    Returns M [N*m].  Source: seed eq. 40, Table 8, DIN ISO 15312.
    """  # noqa: E501
    nu_n = viscosity * 1e6 * mx.fabs(speed) * 60.0 / (2.0 * mx.pi)
    dm = mean_diameter * 1e3
    m0 = mx.if_else(
        nu_n >= 2000.0,
        1e-7 * f0 * mx.fmax(nu_n, 2000.0) ** (2.0 / 3.0) * dm**3,
        160e-7 * f0 * dm**3,
    )
    return 1e-3 * (m0 + f1 * load * dm)


# Upper envelope of the vendors' starting torque of preloaded support-bearing sets per unit preload
# and mean diameter, T_start / (F_pr d_m), over every shipped catalog row that lists both (HIWIN WBK
# H-BS Table 8.12, NSK TAC B NSK-SP p. 168, Schaeffler ZKLN M_RL H-BS Tables 8.38/8.40;
# catalogs/SOURCES.md "Estimated support drag").  Largest observed: INA ZKLN1034, 0.06 N.m / (735 N
# x 22 mm) = 3.71e-3; rounded up. tests/catalog/test_loading.py checks that no vendor row lies above
# it.
SUPPORT_TORQUE_ENVELOPE = 3.72e-3


def support_starting_torque_envelope(preload, mean_diameter, coefficient=SUPPORT_TORQUE_ENVELOPE):
    r"""Conservative starting torque of a preloaded support-bearing set whose vendor lists none.

    .. math:: M = c_{max} F_{pr} d_m,\quad c_{max} = \max_{\text{vendor rows}} M_{vendor} / (F_{pr} d_m)

    The vendors' starting torques scale with preload times pitch radius (NSK TAC B, HIWIN WBK, ZKLN;
    ratio spread x2.6 over bores 10-60 mm); the estimate takes the upper envelope, so a part without
    a vendor value is never credited with less drag than the worst comparable vendor part (seed eq.
    40 reads 4-9x below the vendor values and is not used for the drag).
    preload : F_pr of the set [N];  mean_diameter : d_m = (d + D)/2 [m];  coefficient : c_max [-].
    Returns M [N*m].
    """  # noqa: E501
    return coefficient * preload * mean_diameter


# Static safety of support-bearing sets.  The vendors rate the sets' static capacity three ways: NSK
# TAC B (and HIWIN WBK, which carry them) print a "limiting axial load" whose permissible share is
# 0.7 (NSK super-precision bearings, p. 111 footnote 2: "the permissible axial load equals 0.7 x the
# limiting axial load"); THK prints the support unit's "permissible load", which "indicates the
# static permissible load" (General Catalog A-806 note), i.e. safety 1 on it; a true basic static
# rating C0a takes S0 = C0a / P0a >= 4 for machine tools (Bosch Rexroth R310RU 3301 p. 125, its
# LGF/LGN support bearings; IBC TI-I-5010.2 eq. 2.6 asks S0a > 2.5 for its BS bearings in general
# use).
NSK_PERMISSIBLE_SHARE = 0.7
STATIC_SAFETY_MACHINE_TOOL = 4.0
STATIC_SAFETY_IBC = 2.5


def row_static_rating(set_rating, rows_loaded, rows_rated):
    r"""Static (or limiting) axial rating of the rows of a bearing set that carry one load
    direction, from the set's printed rating (vendors print the direction with the most rows).

    .. math:: C_{0,i} = C_{0,set}\, i / i_{set}

    set_rating : C0_set [N], printed for ``rows_rated`` rows loaded together;  rows_loaded : i [-].
    Returns C0_i [N].  Sources: IBC TI-I-5010.2 eq. 2.5 (Cao_set = i Cao_single); NSK
    super-precision bearings Table 1.2 (multi-row sets: C0 x 2, 3, 4 for 2, 3, 4 rows; TAC B
    limiting axial load 40.5 / 81.5 / 122 kN for 25TAC62B, 1 / 2 / 3 rows); NACHI TAB note 3 (x 2 or
    3).  The static rating grows with the row count, unlike the dynamic one (i^0.7,
    :func:`axisopt.physics.life.row_group_rating`).
    """
    return set_rating * rows_loaded / rows_rated


def support_static_margin(rating_strong, rating_weak, push, back, safety):
    r"""Static safety margin of a support-bearing set: the least of the two load directions' ratings
    over the safety times the largest axial load in that direction.

    .. math:: m = \min\left(\frac{C_{0,s}}{S_0 F_{push}},\ \frac{C_{0,w}}{S_0 F_{back}}\right)

    rating_strong, rating_weak : C0 of the rows carrying the static set load's direction and of the
        others [N] (:func:`row_static_rating`; the set is mounted with its stronger rows facing the
        static load)
    push : the largest axial load the strong rows take, max axial force + static set load
        (pretension, thermal force) [N];  back : the largest the other rows take [N] (> 0)
    safety : S0, the least static safety the rating's vendor asks [-].  Returns m (>= 1 passes).
    Sources: IBC TI-I-5010.2 eq. 2.6 (S0a = C0a / P0a); Rexroth R310RU 3301 eq. 25 (S0 = C0 / F0);
    NSK p. 111 (permissible axial load = 0.7 x limiting axial load).
    """
    return mx.fmin(rating_strong / (safety * push), rating_weak / (safety * back))


# Axial stiffness of a precision support-bearing unit (housing, locknut) against its bare
# bearing set: IBC TI-I-5010.2 prints both for the same sets and preloads, bare duplex sets p. 9 and
# flange/pillow-block units
# p. 22 (sec. 4.6); the units read 0.963-0.992 x the bare sets.  The least ratio, the heavy series
# BS 35 at light preload (3200 N: bare 1090 N/um, unit BSBU 35 DB 128 1050 N/um), is the default:
# the housing is then 26.3 x the set.  An estimate for other vendors' housings; the joint to the
# machine bed is not included.
HOUSING_UNIT_RATIO = 1050.0 / 1090.0


def housing_stiffness_default(set_stiffness, unit_ratio=HOUSING_UNIT_RATIO):
    r"""Axial stiffness of a support-bearing housing whose design gives none, from the published
    ratio of a bearing unit's stiffness to its bare bearing set's.

    .. math:: k_H = k_B\, r / (1 - r),\qquad 1/k_{unit} = 1/k_B + 1/k_H = 1 / (r k_B)

    set_stiffness : k_B, the bearing set's axial stiffness [N/m];  unit_ratio : r = k_unit / k_B [-]
        (:data:`HOUSING_UNIT_RATIO`, IBC TI-I-5010.2 p. 9 and p. 22).  Returns k_H [N/m].
        An estimate: the ratio is IBC's for its own units, without the bolted joint to the bed.
    """
    return set_stiffness * unit_ratio / (1.0 - unit_ratio)
