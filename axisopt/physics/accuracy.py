"""Positioning accuracy of a ball-screw axis: the rows of the error budget as THK's "Studying the
Positioning Accuracy" (General Catalog A-712..A-716) lists its causes, and how they add up (SI).

The causes (THK A-712): the lead angle accuracy of the screw (its grade, JIS B 1192 / ISO 3408), the
axial clearance (lost motion on a reversal), the axial rigidity of the feed screw system, the
thermal displacement (A-715, :func:`axisopt.physics.thermal.thermal_growth`) and the orientation
change of the guides while traveling (pitching and yawing times the distance from the screw axis,
A-716: the Abbe error).

Each row is the largest deviation of the table from its commanded position [m] over the stroke,
one-sided (the vendors' "+-" figures); the total adds them arithmetically
(:func:`worst_case_total`): every row at its worst at once, the conservative combination (no
statistical sum: the rows are systematic, not random).
"""

from __future__ import annotations

from axisopt import mathx as mx

__all__ = [
    "lead_error_tolerance",
    "lead_error_per_300",
    "required_error_per_300",
    "stiffness_positioning_error",
    "abbe_error",
    "worst_case_total",
    "repeatability_estimate",
    "repeatability_iso",
]


def lead_error_tolerance(travel_deviation, variation):
    r"""Largest lead (travel distance) error over the useful travel of a grade C0-C5 screw.

    .. math:: e_{lead} = e_p + v_u

    travel_deviation : e_p, the representative travel distance error (+-) allowed over the travel
        [m]
    variation        : v_u, the fluctuation (band width of the actual travel about the
                       representative line) [m]
    Returns [m]: the actual travel lies within e_p + v_u of the reference travel (conservative: the
    band about the least-squares line is not centred on it).  Source: THK General Catalog A-677 Fig.
    1 and A-678 Table 1 (JIS B 1192-1997); HIWIN S99TE20 Fig. 4.12 (e_p and V_up over the useful
    travel L_u).
    """
    return travel_deviation + variation


def lead_error_per_300(error_300, travel, per=0.300):
    r"""Lead error over a travel of a grade C7-C10 screw, whose tolerance is given per 300 mm.

    .. math:: e_{lead} = e_{300}\ \max(L, 300\ \mathrm{mm}) / 300\ \mathrm{mm}

    error_300 : the travel distance error per 300 mm [m] (+-50 um C7, +-100 um C8, +-210 um C10; THK
        A-678 Table 1)
    travel    : L [m];  per : the 300 mm [m].  Returns [m].  Source: THK A-723 and A-737 scale the
                error per 300 mm linearly to the travel (+-0.3 mm/1000 mm <-> +-0.09 mm/300 mm); a
                travel under 300 mm keeps the whole e_300 (the tolerance bounds any 300 mm, not
                less).
    """
    return error_300 * mx.fmax(travel, per) / per


def required_error_per_300(accuracy, travel, per=0.300):
    r"""The lead error per 300 mm a screw must meet for a positioning accuracy over a travel (THK
    A-723).

    .. math:: e_{300} = A\ (300\ \mathrm{mm}) / L

    accuracy : A, the required positioning accuracy (+-) over the travel [m];  travel : L [m].
        Returns [m].
    THK A-723: +-0.3 mm/1000 mm -> +-0.09 mm/300 mm -> grade C7 (+-0.05 mm/300 mm).
    """
    return accuracy * per / travel


def stiffness_positioning_error(force, k_soft, k_stiff=None):
    r"""Positioning error from the axial rigidity of the feed screw system under an axial force.

    .. math:: \delta = F / k_{soft} - F / k_{stiff}

    force   : F [N];  k_soft : the least stiffness over the stroke [N/m];  k_stiff : the largest
              [N/m], or None.
    With both: THK's positioning error of a constant load (a vertical axis's weight), the change of
    the deflection over the stroke (A-713/A-714: 1500 N, 776 and 111 N/um -> 1.9 and 13.5 um, error
    11.6 um).  Without ``k_stiff``: the whole deflection, for a force that comes and goes (the
    process force).  Returns [m].
    """
    d = force / k_soft
    return d if k_stiff is None else d - force / k_stiff


def abbe_error(distance, angle):
    r"""Positioning error from the orientation change of the guides while traveling (Abbe error).

    .. math:: A = l \sin\theta

    distance : l, from the ball screw's axis to the point whose position matters (vertical for
        pitching, horizontal for yawing) [m];  angle : theta, the pitching (yawing) over the stroke
        [rad].  Returns A [m].
    Source: THK General Catalog A-716 eq. (39).
    """
    return distance * mx.sin(angle)


def worst_case_total(*rows):
    r"""Positioning error of the axis: the rows added arithmetically, each at its worst at once.

    .. math:: E = \sum_i e_i

    rows : the budget's rows [m] (lead, thermal, elastic, Abbe, lost motion).  Returns E [m].  The
        vendors' selection examples take the positioning accuracy as the sum of these causes (THK
        A-712) and size the lead grade to the remainder; a statistical (root-sum-square) sum would
        be smaller and is not used.
    """
    total = 0.0
    for r in rows:
        total = total + r
    return total


def repeatability_iso(reversal, noise_band):
    r"""Bidirectional repeatability of the axis as ISO 230-2 defines it, the scatter of repeated
    approaches.

    .. math:: R = \max(2 s_\uparrow + 2 s_\downarrow + |B|,\ 4 s) = |B| + 4 s \quad (s_\uparrow = s_\downarrow = s)

    reversal : B, the reversal value (the lost motion: axial clearance, a reduction's backlash) [m];
    noise_band : 4 s, the band of the random scatter of one direction's approaches [m] (a scale's
        read-head repeatability band; a motor encoder's quantization, negligible: 0).  Returns R
        [m].  The thermal drift is a systematic change over time, not scatter: ISO 230-3 measures it
        apart (its own row of the budget)."""  # noqa: E501
    return reversal + noise_band


def repeatability_estimate(lost_motion, thermal):
    r"""Bidirectional repeatability of the axis (estimate).

    .. math:: R = B + e_{th}

    lost_motion : B, the reversal value of ISO 230-2 (axial clearance and backlash) [m];  thermal :
        the thermal growth at the nut over the duty cycle [m] (a position approached cold and warm
        lands that far apart).
    Returns R [m].  An estimate: the lead error and the deflection under a repeated force repeat and
    are left out; the random scatter of the approach (ISO 230-2's 4 s), which no catalog figure
    gives, is left out too.
    """
    return lost_motion + thermal
