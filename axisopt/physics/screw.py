"""Screw shaft: stiffness combination, axial and torsional stiffness, inertia, mass (seed sec.
3.1)."""

from __future__ import annotations

from types import MappingProxyType

from axisopt import mathx as mx

__all__ = [
    "E_STEEL",
    "G_STEEL",
    "RHO_STEEL",
    "MOUNTINGS",
    "CATALOG_STIFFNESS_FACTOR",
    "choose",
    "series_stiffness",
    "parallel_stiffness",
    "screw_stiffness",
    "screw_stiffness_catalog",
    "screw_axial_rigidity",
    "two_path_stiffness",
    "screw_bearing_stiffness",
    "screw_torsional_stiffness",
    "torsion_axial_stiffness",
    "screw_rotary_inertia",
    "screw_mass",
    "lead_angle",
    "SAG_FACTORS",
    "screw_sag",
]

E_STEEL = 206e9  # [Pa] THK catalog A15-30 (2.06e5 N/mm^2)
G_STEEL = 79.3e9  # [Pa]
RHO_STEEL = 7850.0  # [kg/m^3] THK catalog A15-32 (7.85e-6 kg/mm^3)

# x (L - x) of a fixed-fixed screw at its smallest [m^2]: the nut at a bearing (end margin 0)
MIN_SEGMENT_PRODUCT = 1e-12

MOUNTINGS = ("fixed-free", "fixed-supported", "fixed-fixed", "supported-supported")

# k = c * E * A / L, catalog forms of seed eq. 7-8 (c = 4: fixed-fixed, nut at mid-span; c = 1: one
# fixed end carries the load over L).  Supported ends carry no axial load, so fixed-supported
# behaves as fixed-free.  Supported-supported has no fixed bearing; by convention one support takes
# the thrust, c = 1.
CATALOG_STIFFNESS_FACTOR = MappingProxyType(
    {"fixed-free": 1.0, "fixed-supported": 1.0, "fixed-fixed": 4.0, "supported-supported": 1.0}
)


def choose(mapping, key, what):
    """Look a discrete selector up in a read-only mapping; a wrong key raises ValueError naming
    choices."""
    if not isinstance(key, str) or key not in mapping:
        allowed = ", ".join(repr(k) for k in mapping)
        raise ValueError(f"unknown {what} {key!r}; allowed: {allowed}")
    return mapping[key]


def series_stiffness(*ks):
    r"""Springs in series.

    .. math:: 1/k_e = \sum_i 1/k_i                                    (seed eq. 1, 2)

    ks : stiffnesses k_i [N/m] (or any one consistent unit), at least one.
    Returns k_e [same unit].  Valid for k_i > 0.
    """
    if not ks:
        raise ValueError("series_stiffness needs at least one stiffness")
    compliance = 0.0
    for k in ks:
        compliance = compliance + 1.0 / k
    return 1.0 / compliance


def parallel_stiffness(*ks):
    r"""Springs in parallel, e.g. the two bearings of a pair.

    .. math:: k_{Be} = \sum_i k_i                                     (seed eq. 2, k_Be = k_B1 + k_B2)

    ks : stiffnesses k_i [N/m], at least one.  Returns [N/m].
    """  # noqa: E501
    if not ks:
        raise ValueError("parallel_stiffness needs at least one stiffness")
    total = 0.0
    for k in ks:
        total = total + k
    return total


def screw_stiffness(root_diameter, x, span, mounting, youngs_modulus=E_STEEL):
    r"""Axial stiffness of the screw shaft seen by the nut at position x.

    .. math:: k_s = E A / x                     (one fixed end; seed eq. 3, 5, 10)
    .. math:: k_s = E A\, L / (x (L - x))       (fixed-fixed)

    (fixed-fixed: both segments in parallel, minimum 4EA/L at x = L/2)

    with A = pi d_r^2 / 4.

    root_diameter  : d_r, thread root (minor) diameter [m]
    x              : distance fixed bearing -> nut [m], 0 < x (< span for fixed-fixed)
    span           : L, distance between the bearings [m] (used by fixed-fixed only)
    mounting       : one of MOUNTINGS (plain string)
    youngs_modulus : E [Pa]
    Returns k_s [N/m].  Source: seed eq. 3-5, 10; THK "axial rigidity of the feed screw system".
    Valid for a slender elastic bar (bearing and nut compliance excluded).  Fixed-fixed with the nut
    at a bearing (x = L, an end margin of 0) is rigid: the product x (L - x) is held at 1e-12 m^2 or
    more, a finite stiffness far above any chain's (1/k then adds nothing in series) on floats and
    CasADi alike.
    """
    choose(CATALOG_STIFFNESS_FACTOR, mounting, "mounting")
    ea = youngs_modulus * mx.pi * root_diameter**2 / 4.0
    if mounting == "fixed-fixed":
        return ea * span / mx.fmax(x * (span - x), MIN_SEGMENT_PRODUCT)
    return ea / x


def screw_axial_rigidity(root_diameter, youngs_modulus=E_STEEL):
    r"""Section rigidity of the screw shaft, EA = E pi d_r^2 / 4  [N] (root diameter d_r [m], E [Pa])."""  # noqa: E501
    return youngs_modulus * mx.pi * root_diameter**2 / 4.0


def two_path_stiffness(k_near, k_far, axial_rigidity, x, span):
    r"""Axial stiffness at the nut of a screw held at both ends: two load paths in parallel.

    .. math:: k = \Big[\frac{1}{k_1} + \frac{x}{EA}\Big]^{-1} + \Big[\frac{1}{k_2} + \frac{L-x}{EA}\Big]^{-1}

    The nut force splits between the near path (bearing set k_1, screw segment x) and the far path
    (bearing set k_2, segment L - x).  ``k_far = 0`` gives the one-fixed-end chain 1/(1/k_1 + x/EA).
    With rigid bearings it is THK's fixed-fixed screw rigidity A E L / (a b) (vendor-formulas.md
    2.5).

    k_near, k_far  : k_1, k_2, axial stiffness of the bearing set (with its housing) at each end
                     [N/m]
    axial_rigidity : EA [N] (screw_axial_rigidity)
    x              : fixed (near) bearing to nut [m];  span : L, bearing to bearing [m]
    Returns k [N/m].  Source: statics of two springs in parallel (seed eq. 1-2 applied per path).
    """  # noqa: E501
    near = 1.0 / (1.0 / k_near + x / axial_rigidity)
    far = k_far / (1.0 + k_far * (span - x) / axial_rigidity)
    return near + far


def screw_bearing_stiffness(
    root_diameter, x, span, mounting, k_bearing_set, youngs_modulus=E_STEEL
):
    r"""Screw shaft and support bearings together, as the nut sees them, by mounting.

    fixed-fixed: :func:`two_path_stiffness` with a bearing set of stiffness ``k_bearing_set`` at
    each end; otherwise the fixed set in series with the segment x (a supported or free end carries
    no axial load).

    root_diameter : d_r [m];  x : fixed bearing to nut [m];  span : L [m];  mounting : one of
        MOUNTINGS
    k_bearing_set : one bearing set with its housing [N/m].  Returns [N/m].
    """
    choose(CATALOG_STIFFNESS_FACTOR, mounting, "mounting")
    ea = screw_axial_rigidity(root_diameter, youngs_modulus)
    k_far = k_bearing_set if mounting == "fixed-fixed" else 0.0 * k_bearing_set
    return two_path_stiffness(k_bearing_set, k_far, ea, x, span)


def screw_stiffness_catalog(root_diameter, length, mounting, youngs_modulus=E_STEEL):
    r"""Catalog form of the screw shaft stiffness, seed eq. 7-8.

    .. math:: k_s = c\, E \pi d_r^2 / (4 L_1),  c = 4 (fixed-fixed, nut at mid-span), 1 (fixed-free)

    With E = 2.06e5 N/mm^2, d_r in mm, L_1 in cm and k_s in N/um this is 64.7 d_r^2/L_1 (eq. 7) and
    16.2 d_r^2/L_1 (eq. 8 prints 16.8, likely a typo: vendor-formulas.md sec. 2.5).

    root_diameter : d_r [m];  length : L_1, bearing span [m];  mounting : one of MOUNTINGS
    youngs_modulus: E [Pa].  Returns k_s [N/m].  Worst-case (minimum) value over the stroke.
    """
    c = choose(CATALOG_STIFFNESS_FACTOR, mounting, "mounting")
    return c * youngs_modulus * mx.pi * root_diameter**2 / (4.0 * length)


def screw_torsional_stiffness(root_diameter, length, shear_modulus=G_STEEL):
    r"""Torsional stiffness of a solid shaft.

    .. math:: k_\theta = G \pi d_r^4 / (32 l)

    root_diameter : d_r [m];  length : l, motor coupling -> nut [m];  shear_modulus : G [Pa]
    Returns k_theta [N*m/rad].  Source: elementary torsion (Saint-Venant, round bar).
    """
    return shear_modulus * mx.pi * root_diameter**4 / (32.0 * length)


def torsion_axial_stiffness(torsional_stiffness, lead):
    r"""Axial stiffness at the nut of a torsional compliance in the drive, seen through the lead.

    .. math:: k_{ax} = k_\theta (2\pi / P_h)^2

    An axial force F at the nut needs the torque T = F P_h / (2 pi) at the screw; the twist
    T/k_theta moves the nut by (P_h / 2 pi) T / k_theta.  torsional_stiffness : k_theta [N*m/rad]
    (screw shaft from the coupling to the nut, or the coupling);  lead : P_h [m].  Returns k_ax
    [N/m].
    Source: THK/HIWIN feed-system rigidity (screw torsion term); rigid-body kinematics of the screw
    pair.
    Valid with the motor held by its position loop (at standstill).
    """
    return torsional_stiffness * (2.0 * mx.pi / lead) ** 2


def screw_rotary_inertia(diameter, length, density=RHO_STEEL):
    r"""Rotary inertia of a solid screw shaft about its axis.

    .. math:: J = \pi \rho d^4 L / 32                 (THK selection page /0014, "J_screw")

    diameter : d [m] (nominal for a conservative value);  length : L [m];  density : rho [kg/m^3]
    Returns J [kg*m^2].
    """
    return mx.pi * density * diameter**4 * length / 32.0


def screw_mass(diameter, length, density=RHO_STEEL):
    r"""Mass of a solid shaft, m = rho pi d^2 L / 4.

    diameter : d [m];  length : L [m];  density : rho [kg/m^3].  Returns [kg].
    """
    return density * mx.pi * diameter**2 * length / 4.0


def lead_angle(lead, nominal_diameter):
    r"""Lead (helix) angle, tan(beta) = P_h / (pi d).

    lead : P_h [m];  nominal_diameter : d, ball centre diameter [m].  Returns beta [rad].
    """
    return mx.atan(lead / (mx.pi * nominal_diameter))


# k of the largest deflection q L^4 / (k E I) of a uniform beam under its own weight, by
# end conditions: AISC Steel Construction Manual, Table 3-23 "Shears, moments and deflections", case
# 1 (simple beam, 5/384), case 12 (fixed at one end, supported at the other, 1/185), case 15 (fixed
# at both ends, 1/384) and case 22 (cantilever, 1/8); the same figures as Roark's Formulas for
# Stress and Strain, Table 8.1 case 2 with the load over the whole span.
SAG_FACTORS = MappingProxyType(
    {
        "fixed-free": 8.0,
        "fixed-supported": 185.0,
        "fixed-fixed": 384.0,
        "supported-supported": 384.0 / 5.0,
    }
)


def screw_sag(
    mass_per_length, root_diameter, span, mounting, youngs_modulus=E_STEEL, gravity=9.80665
):
    r"""Largest sag of a horizontal screw under its own weight, the shaft as a uniform beam between
    its ends.

    .. math:: \delta = q L^4 / (k E I),\quad q = m' g,\quad I = \pi d_r^4 / 64

    mass_per_length : m' [kg/m] (the catalog's shaft mass per metre);  root_diameter : d_r [m] (the
        root section carries the bending: the threads are left out, the weight kept, so the sag is
        slightly high)
    span : L, between the end supports [m];  mounting : key of :data:`SAG_FACTORS` (k: 8 fixed-free,
        185 fixed-supported, 384 fixed-fixed, 384/5 supported-supported; AISC Table 3-23 cases 22,
        12, 15, 1).
    Returns delta [m].  A support that holds the shaft in a bearing set (the vendors' "fixed" end)
    is taken as clamped, as the critical-speed factors take it (THK A-695); the nut, which also
    carries the shaft, is left out, and so is the pretension of a fixed-fixed screw (a tensioned
    beam sags less): both leave the value conservative (docs/assumptions.md).
    """
    k = choose(SAG_FACTORS, mounting, "mounting")
    inertia = 3.141592653589793 * root_diameter**4 / 64.0
    return mass_per_length * gravity * span**4 / (k * youngs_modulus * inertia)
