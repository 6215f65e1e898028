"""Screw checks: critical speed, buckling, L10 life, DN value (vendor catalog forms in SI)."""

from __future__ import annotations

import math
from types import MappingProxyType

from axisopt import mathx as mx
from axisopt.physics.screw import E_STEEL, RHO_STEEL, choose

__all__ = [
    "CRITICAL_SPEED_LAMBDA1",
    "BUCKLING_ETA1",
    "critical_speed",
    "buckling_load",
    "life_revolutions",
    "life_time",
    "dn_value",
    "critical_speed_hiwin",
    "THK_LOAD_FACTOR_TABLE",
    "load_factor_default",
]

# THK catalog A15-32 eq. 7: lambda_1 by mounting.  lambda_2 = 3.4 / 9.7 / 15.1 / 21.9 includes the
# 0.8 factor.
CRITICAL_SPEED_LAMBDA1 = MappingProxyType(
    {
        "fixed-free": 1.875,
        "supported-supported": 3.142,
        "fixed-supported": 3.927,
        "fixed-fixed": 4.730,
    }
)
# THK catalog A15-30 eq. 5: eta_1 by mounting (eta_2 = 1.3 / 10 / 20 incl. 0.5); supported-supported
# eta_1 = 1 (eta_2 = 5).
BUCKLING_ETA1 = MappingProxyType(
    {"fixed-free": 0.25, "supported-supported": 1.0, "fixed-supported": 2.0, "fixed-fixed": 4.0}
)


# THK General Catalog A-704 Table 19 "Load Factor (fW)" (the same as Table 3, A-12, for LM guides):
# rows by vibration/impact and speed, (top of the speed range [m/s], fW range).  HIWIN H-BS p. 25
# gives fp 1.1-1.2 without impact, 1.3-1.8 in normal operation, 2-3 with high impact and vibration.
THK_LOAD_FACTOR_TABLE = (
    (0.25, (1.0, 1.2)),  # faint vibration, very low speed, V <= 0.25 m/s
    (1.0, (1.2, 1.5)),  # weak, slow, 0.25 < V <= 1 m/s
    (2.0, (1.5, 2.0)),  # medium, 1 < V <= 2 m/s
    (float("inf"), (2.0, 3.5)),  # strong, high speed, V > 2 m/s
)


def load_factor_default(speed):
    r"""Load factor f_W of the life calculations for an axis whose design gives none: the upper end
    of the row of THK's Table 19 that the axis's top speed falls in.

    .. math:: f_W = 1.2\ (V \le 0.25),\ 1.5\ (\le 1),\ 2.0\ (\le 2),\ 3.5\ (> 2\ \mathrm{m/s})

    speed : V, the top table speed [m/s] (a float: the row is a choice, not a formula).  Returns f_W
        [-].
    Source: THK General Catalog A-704 Table 19; THK's worked examples take the upper end of the row:
    f_W = 1.5 at V_max = 1 m/s (A-729, high-speed transfer) and at 0.3 m/s (A-742, vertical
    conveyance).
    """
    for top, (_, upper) in THK_LOAD_FACTOR_TABLE:
        if speed <= top:
            return upper
    return THK_LOAD_FACTOR_TABLE[-1][1][1]


def critical_speed(
    root_diameter, span, mounting, safety_factor=0.8, youngs_modulus=E_STEEL, density=RHO_STEEL
):
    r"""Permissible speed from the first bending (whirling) frequency of the screw shaft.

    .. math:: \omega = s\, \frac{\lambda_1^2}{\ell_b^2} \sqrt{\frac{E I}{\rho A}}

    with I = pi d_r^4/64, A = pi d_r^2/4.

    root_diameter : d_r [m];  span : l_b, between mounting surfaces [m];  mounting : one of
        MOUNTINGS
    safety_factor : s = 0.8 (THK, Schneeberger, HSK: 80 % of critical)
    youngs_modulus [Pa];  density [kg/m^3]
    Returns omega [rad/s].  Source: THK catalog A15-32 eq. 7
    (N1 = lambda_2 d_r / l_b^2 * 1e7 [1/min], d, l [mm]).
    """
    lam = choose(CRITICAL_SPEED_LAMBDA1, mounting, "mounting")
    return (
        safety_factor
        * lam**2
        / span**2
        * mx.sqrt(youngs_modulus * root_diameter**2 / (16.0 * density))
    )


# HIWIN Ballscrews H-BS F 3.27/3.28: n_k,max = 0.8 x 2.71e8 f_n d_k / l_s^2 [rpm; mm], f_n by
# mounting (HIWIN prints these three)
HIWIN_CRITICAL_SPEED_FN = MappingProxyType(
    {"fixed-fixed": 1.0, "fixed-supported": 0.692, "fixed-free": 0.147}
)


def critical_speed_hiwin(root_diameter, span, mounting, safety_factor=0.8):
    r"""Permissible speed from the shaft's dangerous speed as HIWIN states it for its screws.

    .. math:: n = s \cdot 2.71\times 10^8 f_n\, d_k / l_s^2\ [\mathrm{rpm};\ \mathrm{mm}]

    root_diameter : d_k [m];  span : l_s [m];  mounting : f_n 1.0 fixed-fixed, 0.692
    fixed-supported, 0.147 fixed-free (a mounting HIWIN does not print, supported-supported: THK's
    :func:`critical_speed`);  safety_factor : s = 0.8.  Returns omega [rad/s].  Source: HIWIN
    Ballscrews H-BS F 3.27/3.28 (fixed-free 6.3 % below THK's lambda_2 3.4, the others within 1 %).
    """
    if mounting not in HIWIN_CRITICAL_SPEED_FN:
        return critical_speed(root_diameter, span, mounting, safety_factor)
    fn = HIWIN_CRITICAL_SPEED_FN[mounting]
    # d [mm] / l^2 [mm^2] = 1e-3 d / l^2 [m]
    rpm = safety_factor * 2.71e8 * fn * 1e-3 * root_diameter / span**2
    return rpm * 2.0 * math.pi / 60.0


def buckling_load(root_diameter, length, mounting, safety_factor=0.5, youngs_modulus=E_STEEL):
    r"""Permissible compressive axial load from Euler buckling.

    .. math:: P_1 = s\, \eta_1 \pi^2 E I / \ell_a^2,\ I = \pi d_r^4 / 64

    root_diameter : d_r [m];  length : l_a, load point to mounting [m];  mounting : one of MOUNTINGS
    safety_factor : s = 0.5 (THK);  youngs_modulus [Pa].  Returns P_1 [N].
    Source: THK catalog A15-30 eq. 5 (P_1 = eta_2 d_r^4 / l_a^2 * 1e4 [N], mm); MiSUMi uses eta_2 =
    10 for fixed-supported.  Check also the yield limit P_2 = 116 d_r^2 separately.
    """
    eta = choose(BUCKLING_ETA1, mounting, "mounting")
    return safety_factor * eta * mx.pi**3 * youngs_modulus * root_diameter**4 / (64.0 * length**2)


def life_revolutions(dynamic_load_rating, load, load_factor=1.0):
    r"""Nominal (L10) life in revolutions.

    .. math:: L = (C_a / (f_w F_a))^3 \cdot 10^6

    dynamic_load_rating : C_a [N];  load : F_a, mean axial load [N] (> 0);  load_factor : f_w [-]
    Returns L [rev].  Source: THK / MiSUMi / ISO 3408-5.
    """
    return mx.power(dynamic_load_rating / (load_factor * load), 3) * 1e6


def life_time(dynamic_load_rating, load, speed, load_factor=1.0):
    r"""Nominal (L10) life in seconds at a constant mean speed.

    .. math:: L_t = L / n = 2\pi L / \omega           (L_h = L / (60 N) in hours, N in 1/min)

    dynamic_load_rating : C_a [N];  load : F_a [N];  speed : omega, mean speed [rad/s] (> 0)
    load_factor : f_w [-].  Returns L_t [s] (divide by 3600 for hours).
    """
    return life_revolutions(dynamic_load_rating, load, load_factor) * 2.0 * mx.pi / speed


def guide_life_distance(
    dynamic_load_rating, load, load_factor=1.0, roller=0.0, rating_distance=None
):
    r"""Nominal (L10) travel life of a linear guide block.

    .. math:: L = (C / (f_w P))^{3} \cdot L_C            (ball blocks)
    .. math:: L = (C / (f_w P))^{10/3} \cdot L_C         (roller blocks)

    dynamic_load_rating : C per block [N], on the rating basis L_C its vendor defines it for
    load : P, equivalent load per block [N];  load_factor : f_w [-]
    roller : 0 for ball blocks, 1 for roller blocks (a number, so it may be symbolic or an array)
    rating_distance : L_C, the travel C is defined for [m]: 50 km for ball blocks of every vendor in
        the catalogs; for roller blocks 100 km at THK and HIWIN, 50 km at IKO.  None: THK's
        convention (50 km ball, 100 km roller).
    Returns L [m].  Sources: THK LM Guide selection ("calculating the nominal life": L = (C/P_C)^3 x
    50 km for balls, (C/P_C)^(10/3) x 100 km for rollers); HIWIN G99TE20 sec. 2-1 (C for 50 km of
    operation for a ball type guideway, 100 km for a roller type; f_w divides C); IKO CAT-1578E p.
    I-20, life calculation example L = 50 (C/P)^(10/3) km for the roller type MXG45.
    """
    exponent = 3.0 + roller / 3.0
    basis = 50e3 * (1.0 + roller) if rating_distance is None else rating_distance
    return (dynamic_load_rating / (load_factor * load)) ** exponent * basis


def dn_value(diameter, speed):
    r"""DN value, diameter times screw speed, in SI.

    .. math:: DN = d\,|\omega|

    diameter : d, ball centre (or nominal) diameter [m];  speed : omega [rad/s].
    Returns DN [m rad/s].  Vendors quote D [mm] x N [1/min]: 1 mm*rpm = 1.0472e-4 m rad/s; catalog
    limits (70 000-210 000 mm*rpm) are converted to SI when the catalog is loaded.
    Source: THK catalog eq. 8-17, vendor-formulas.md sec. 2.2.
    """
    return diameter * mx.fabs(speed)
