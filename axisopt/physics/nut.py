"""Ball nut: catalog and Hertz stiffness, preload lift-off, double-nut load curve, drag torque."""

from __future__ import annotations

from axisopt import mathx as mx
from axisopt.physics.screw import E_STEEL

__all__ = [
    "POISSON_STEEL",
    "nut_stiffness_catalog",
    "hertz_point_deflection",
    "nut_axial_deflection_hertz",
    "nut_stiffness_hertz",
    "lift_off_force",
    "double_nut_stiffness_under_load",
    "nut_preload_drag_torque",
    "preloaded_pair_load",
    "double_nut_shift",
    "PRELOAD_CEILING",
    "preload_ceiling",
    "MOUNTING_SHARE",
    "bracket_stiffness_default",
    "NUT_LENGTH_FACTORS",
    "nut_length_estimate",
]

POISSON_STEEL = 0.3
NEWTON_STEPS = 12  # fixed, so the double-nut solve is one symbolic expression (converged to ~1e-15)


def nut_stiffness_catalog(k_catalog, preload, dynamic_load_rating, reference_preload=None):
    r"""Nut stiffness at the actual preload from the catalog value at 10 % C.

    .. math:: k_n = 0.8\, k \,(P / (0.1 C))^{1/3}                     (seed eq. 9; THK/HIWIN)

    k_catalog           : k, catalog rigidity at preload 0.1 C [N/m]
    preload             : P, preload (or 0.3 C for a nut without preload) [N]
    dynamic_load_rating : C [N]
    reference_preload   : the preload k is quoted at when a catalog uses another basis than 0.1 C
                          (e.g. 0.3 C axial load for single nuts) [N]; default 0.1 C
    Returns k_n [N/m].  The 0.8 covers nut body and flange compliance.  Valid for 0 < P <= 0.1 C.
    """
    ref = 0.1 * dynamic_load_rating if reference_preload is None else reference_preload
    return 0.8 * k_catalog * mx.cbrt(preload / ref)


def hertz_point_deflection(load, radius_x, radius_y, youngs_modulus=E_STEEL, poisson=POISSON_STEEL):
    r"""Mutual approach of two bodies in elliptical Hertz point contact (one ball-groove contact).

    .. math:: \delta = \mathcal{F}\,[ (9/(2\mathcal{E} R)) (Q/(\pi \kappa E'))^2 ]^{1/3}

    with 1/R = 1/R_x + 1/R_y, E' = E/(1-\nu^2) (both bodies steel) and the Hamrock-Brewe (1983)
    approximations kappa = 1.0339 (R_y/R_x)^0.636, E_k = 1.0003 + 0.5968 R_x/R_y, F_k = 1.5277 +
    0.6023 ln(R_y/R_x).  This supplies the Hertz coefficient K_i/(pi a_i) of seed eq. 12 (same power
    law delta ~ Q^(2/3) (sum rho)^(1/3)).  Hamrock and Brewe give the fits for 1 <= kappa <= 10
    (ball-groove contacts); in the circular limit R_y = R_x the approach is 5.4 % low.

    load           : Q, normal load on the ball [N]
    radius_x       : R_x, effective radius in the rolling direction [m] (1/R_x = sum of curvatures)
    radius_y       : R_y >= R_x, effective radius across the groove [m]
    youngs_modulus : E [Pa];  poisson : nu [-]
    Returns delta [m].  Valid for elastic contact, R_y >= R_x.
    """
    ratio = radius_y / radius_x
    kappa = 1.0339 * ratio**0.636
    ell_e = 1.0003 + 0.5968 / ratio
    ell_f = 1.5277 + 0.6023 * mx.log(ratio)
    r_eq = 1.0 / (1.0 / radius_x + 1.0 / radius_y)
    e_prime = youngs_modulus / (1.0 - poisson**2)
    return ell_f * mx.cbrt(9.0 / (2.0 * ell_e * r_eq) * (load / (mx.pi * kappa * e_prime)) ** 2)


def nut_axial_deflection_hertz(
    axial_load,
    n_balls,
    ball_diameter,
    pitch_diameter,
    contact_angle,
    lead_angle,
    conformity_nut=0.55,
    conformity_screw=0.55,
    youngs_modulus=E_STEEL,
    poisson=POISSON_STEEL,
):
    r"""Axial deflection of nut against screw from the per-ball Hertz deformations.

    .. math:: P = F_a / (z \sin\beta \cos\phi)                                  (seed eq. 17)
    .. math:: \sum\rho_{1,2} = 4/d_b - 1/(f d_b) \mp 2\cos\beta\cos\phi/(d \pm d_b\cos\beta)  (eq. 13-14)
    .. math:: \delta_N = (\delta_1 + \delta_2) / (\sin\beta \cos\phi)            (seed eq. 15)

    delta_1 (ball-nut, concave both ways) and delta_2 (ball-screw) from hertz_point_deflection.

    axial_load      : F_a [N];  n_balls : z, loaded balls [-];  ball_diameter : d_b [m]
    pitch_diameter  : d, ball centre diameter [m];  contact_angle : beta [rad];  lead_angle : phi
                      [rad]
    conformity_*    : f, groove radius / ball diameter [-] (0.52-0.56 typical)
    Returns delta_N [m].  Ideal load sharing, rigid nut body.
    """  # noqa: E501
    sb, cp, cb = mx.sin(contact_angle), mx.cos(lead_angle), mx.cos(contact_angle)
    ball_load = axial_load / (n_balls * sb * cp)
    e_nut = 2.0 * cb * cp / (pitch_diameter + ball_diameter * cb)
    e_screw = 2.0 * cb * cp / (pitch_diameter - ball_diameter * cb)
    rx_nut, rx_screw = 1.0 / (2.0 / ball_diameter - e_nut), 1.0 / (2.0 / ball_diameter + e_screw)
    ry_nut = 1.0 / (2.0 / ball_diameter - 1.0 / (conformity_nut * ball_diameter))
    ry_screw = 1.0 / (2.0 / ball_diameter - 1.0 / (conformity_screw * ball_diameter))
    d1 = hertz_point_deflection(ball_load, rx_nut, ry_nut, youngs_modulus, poisson)
    d2 = hertz_point_deflection(ball_load, rx_screw, ry_screw, youngs_modulus, poisson)
    return (d1 + d2) / (sb * cp)


def nut_stiffness_hertz(
    axial_load,
    n_balls,
    ball_diameter,
    pitch_diameter,
    contact_angle,
    lead_angle,
    conformity_nut=0.55,
    conformity_screw=0.55,
    youngs_modulus=E_STEEL,
    poisson=POISSON_STEEL,
):
    r"""Tangent axial stiffness of one loaded ball row set (one nut half) from Hertz contact.

    .. math:: k_N = dF_a/d\delta_N = \tfrac{3}{2} F_a / \delta_N

    Source: seed eq. 12-18 (eq. 16 prints the secant F_a/delta_N, 2/3 of this).

    Arguments as nut_axial_deflection_hertz (axial_load = preload F_p of this half [N]).  Returns
    k_N [N/m]; proportional to F_p^(1/3) z^(2/3) as seed eq. 18.  A preloaded double nut at zero
    external load has twice this value (see double_nut_stiffness_under_load).
    """
    delta = nut_axial_deflection_hertz(
        axial_load,
        n_balls,
        ball_diameter,
        pitch_diameter,
        contact_angle,
        lead_angle,
        conformity_nut,
        conformity_screw,
        youngs_modulus,
        poisson,
    )
    return 1.5 * axial_load / delta


# The largest preload of a preloaded ball nut as a fraction of its dynamic load rating Ca: THK Ball
# Screw General Catalog, "Preload" (A-687): "an excessive preload adversely affects the service life
# and heat generation. The maximum preload should be set at 10% of the basic dynamic load rating
# (Ca)"; HIWIN H-BS sec. 3.6.2 (10 % for double nuts); Steinmeyer, "Nut rigidity": 10 % for 2-point
# contact, about 8 % for 4-point contact nuts.
PRELOAD_CEILING = 0.10


def preload_ceiling(dynamic_load_rating, fraction=PRELOAD_CEILING):
    r"""The largest preload a vendor allows a preloaded ball nut, :math:`P_{max} = 0.1\, C_a` (THK
    A-687, HIWIN H-BS 3.6.2).  dynamic_load_rating : Ca [N].  Returns [N].  No vendor found states a
    ceiling by speed or DN; the preload's heat enters through the heat balance (model.heat)
    instead."""
    return fraction * dynamic_load_rating


def lift_off_force(preload):
    r"""External axial load at which the opposing half of a preloaded double nut unloads completely.

    .. math:: F_{lift} = 2^{3/2} F_{a0} \approx 2.83 F_{a0}

    preload : F_a0 [N].  Returns [N].  Source: Steinmeyer "2.83 x preload"; ISO 3408-5 (per
        mechanixcalc).
    Valid for Hertz point contact (delta ~ F^(2/3)) in both halves.
    """
    return 2.0**1.5 * preload


def preloaded_pair_load(preload, axial_load):
    r"""Load on the loaded half of a preloaded pair (double nut, bearing set, guide ball rows).

    .. math:: F_1 = F_{pr}\,(1 + F/(2^{3/2} F_{pr}))^{3/2}\ \text{for}\ F < 2^{3/2}F_{pr},\ F_1 = F\ \text{above}

    preload : F_pr [N] (> 0);  axial_load : F, external load [N] (>= 0).  Returns F_1 [N].
    Source: Steinmeyer technical pages ("expressions and definitions"), ISO 3408-5 (per
    mechanixcalc).
    """  # noqa: E501
    lift = 2.0**1.5 * mx.fmax(preload, 1e-9)
    f1 = mx.fmax(preload, 1e-9) * mx.power(1.0 + mx.fmin(axial_load, lift) / lift, 1.5)
    return mx.if_else(axial_load < lift, f1, axial_load)


def double_nut_shift(force_ratio):
    r"""Common contact shift s = u / delta_0 of a preloaded double nut under external load, with
    lift-off.

    .. math:: (1+s)^{3/2} - (1-s)_+^{3/2} = f

    solved by a fixed number of Newton steps (symbolic-safe; (1-s) is floored at 1e-24 rather than 0
    so the derivatives stay finite after lift-off).  force_ratio : f = |F| / F_a0 [-] (>= 0).
    Returns s [-] (s = f/3 for small f; s >= 1 after lift-off at f = 2^(3/2)).  Source: Hertz delta
    ~ F^(2/3) in each half.
    """
    f = force_ratio
    s = mx.if_else(f >= 2.0**1.5, f ** (2.0 / 3.0) - 1.0, f / 3.0)
    for _ in range(NEWTON_STEPS):
        lo = mx.fmax(1.0 - s, 1e-24)
        g = (1.0 + s) ** 1.5 - lo**1.5 - f
        dg = 1.5 * (mx.sqrt(1.0 + s) + mx.sqrt(lo))
        s = s - g / dg
    return s


def double_nut_stiffness_under_load(k0, preload, axial_load):
    r"""Stiffness of a preloaded double nut (or 4-point nut) under external axial load, with
    lift-off.

    Each half: delta_i = c F_i^(2/3).  The external load F moves both contacts by a common u: F_1 =
    ((delta_0 + u)/c)^{3/2}, F_2 = ((delta_0 - u)_+/c)^{3/2}, F_1 - F_2 = F.  With s = u/delta_0 and
    f = |F|/F_a0:

    .. math:: (1+s)^{3/2} - (1-s)_+^{3/2} = f,\qquad k/k_0 = \tfrac12[(1+s)^{1/2} + (1-s)_+^{1/2}]

    solved by :func:`double_nut_shift`.  k/k0 = 0.707 at lift-off (f = 2.83) and f^(1/3)/2 beyond
    it.  Source: Hertz point contact (delta ~ F^(2/3)); the power law of the seed paper, eq. 12-18.

    k0         : stiffness at zero external load [N/m]
    preload    : F_a0 [N] (> 0)
    axial_load : F, external axial load [N] (sign ignored)
    Returns k [N/m].
    """
    s = double_nut_shift(mx.fabs(axial_load) / preload)
    return k0 * 0.5 * (mx.sqrt(1.0 + s) + mx.sqrt(mx.fmax(1.0 - s, 1e-24)))


def nut_preload_drag_torque(preload, lead, nominal_diameter, coefficient=0.05):
    r"""Preload drag torque of a ball nut.

    .. math:: T_p = K\, F_{a0} P_h / (2\pi),\quad K = 0.05 / \sqrt{\tan\beta},\ \tan\beta = P_h / (\pi d)

    preload : F_a0 [N];  lead : P_h [m];  nominal_diameter : d [m];  coefficient : 0.05 [-]
    Returns T_p [N*m].  Source: THK / HIWIN / NSK catalog form (vendor-formulas.md sec. 2.6).  ISO
    3408-3 allows +-50 % scatter; Zhou et al. 2016 report large deviations from measurement.
    """  # noqa: E501
    tan_beta = lead / (mx.pi * nominal_diameter)
    return coefficient / mx.sqrt(tan_beta) * preload * lead / (2.0 * mx.pi)


# THK General Catalog A-709 and the nut tables' note: the nut rigidity "does not include the
# rigidity of the components related to mounting the ball screw nut. Therefore, it is normally
# appropriate to regard roughly 80% of the value in the table as the actual value" (the 0.8 of
# :func:`nut_stiffness_catalog`).  For the nut bracket itself (THK's K_H, A-708: "set the rigidity
# as high as possible") no vendor or textbook number was found; the default takes THK's allowance
# once more: the bracket costs the nut another 20 %, i.e. it is 0.8 / 0.2 = 4 x the nut's rigidity.
# An estimate.
MOUNTING_SHARE = 0.8


def bracket_stiffness_default(nut_stiffness, share=MOUNTING_SHARE):
    r"""Axial stiffness of a nut bracket whose design gives none (an estimate from THK's mounting
    allowance).

    .. math:: k_{br} = k_N\, s / (1 - s),\qquad 1 / (1/k_N + 1/k_{br}) = s\, k_N

    nut_stiffness : k_N, the nut's rigidity as the model takes it at the catalog's reference preload
        (0.8 x the table value, :func:`nut_stiffness_catalog`) [N/m];  share : s [-]
        (:data:`MOUNTING_SHARE`).
    Returns k_br [N/m].  Source of s: THK General Catalog A-709 (nut rigidity x 0.8 for the
    nut-mounting components); applying it to the bracket is our estimate (no published bracket
    stiffness).
    """
    return nut_stiffness * share / (1.0 - share)


# The nut body's length over (lead + nominal diameter), the largest of the vendor rows of
# catalogs/nuts.csv (212 rows read from H-BS Tables 6.4-7.1, T-GC B-652-B-721 and BR-BS pp. 37/45):
# single nuts 2.71 (THK BNF4016-5), double nuts 5.05 (THK BNFN1605-5); rounded up.  No vendor
# publishes a length rule; an upper envelope never makes the travelled thread shorter than the
# catalog's nuts of the same lead and diameter make it.
NUT_LENGTH_FACTORS = (2.75, 5.1)  # (single, double) [-]


def nut_length_estimate(lead, nominal_diameter, double):
    """The length of a ball nut whose vendor lists none [m]: the upper envelope ``f (P + d)`` of the
    catalog's vendor rows (:data:`NUT_LENGTH_FACTORS`; f = 2.75 for a single nut, 5.1 for a double
    nut, ``double`` 0 or 1).  What the lead band reads: the nut travels stroke + its length of
    thread (ISO 3408-3's useful travel; THK A-677).  Floats, arrays and CasADi symbols alike."""
    single, pair = NUT_LENGTH_FACTORS
    return (single + (pair - single) * double) * (lead + nominal_diameter)
