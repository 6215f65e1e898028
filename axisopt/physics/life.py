r"""Rating life under a duty cycle: the mean load of a load spectrum, the halves of a preloaded
pair, row groups.

The vendors' procedure for a ball screw nut and its support bearings when the load changes in steps:

* **Mean load** (THK General Catalog A-705 eq. 30; HIWIN S99TE20 M8/M9; Rexroth R310 eq. 6; IBC
  TI-I-5010 eq. 2.34): the cubic mean of the phase loads weighted by the travel (or, equivalently,
  the revolutions n_i t_i) under each load,

  .. math:: F_m = \left(\sum F_i^3 l_i / \sum l_i\right)^{1/3}

* **Load direction** (THK A-706): "if the sign for the fluctuating load changes ... calculate both
  the average axial load of the positive-sign load and that of the negative-sign load ... (when
  calculating the average axial load of the positive-sign load, assume the negative-sign load to be
  zero)", over the total travel.
* **Preloaded pair** (HIWIN Ballscrews & Accessories BS-08-2-EN-1704-K sec. 3.7.2, F 3.6, F 3.7 and
  the flow chart p. 26): in every phase the half the load presses carries F_b = (1 + F/(2^{3/2}
  F_pr))^{3/2} F_pr, the other half F_b - F, both halves' mean loads and lives are computed, and the
  pair's life is their Weibull combination (F 3.12)

  .. math:: L = (L_1^{-10/9} + L_2^{-10/9})^{-9/10}

  NSK (super-precision bearings, life of preloaded angular-contact sets) combines its rows' lives the same
  way with the exponent 1.1.
* **Mean speed** (THK A-730/A-742: N_m = 2 n l_S / P_h; HIWIN M7; Rexroth eq. 5): revolutions per
  unit of clock time over the whole cycle, dwells included.

Every function takes the phases as Python sequences of floats, numpy arrays or CasADi symbols.
"""  # noqa: E501

from __future__ import annotations

from axisopt import mathx as mx
from axisopt.physics.nut import preloaded_pair_load

__all__ = [
    "NUT_SET_EXPONENT",
    "BEARING_SET_EXPONENT",
    "LOAD_SCALE",
    "cubic_mean",
    "directional_means",
    "preloaded_halves",
    "set_life",
    "set_equivalent_load",
    "row_group_rating",
]

NUT_SET_EXPONENT = 10.0 / 9.0  # HIWIN H-BS F 3.12: L = (L1^(-10/9) + L2^(-10/9))^(-9/10)
# NSK super-precision bearings, life of a preloaded pair: (L1^-1.1 + L2^-1.1)^(-1/1.1)
BEARING_SET_EXPONENT = 1.1
LOAD_SCALE = 1000.0  # [N]: cubic means are taken on F / LOAD_SCALE (see cubic_mean)
# dynamic rating of i like rows loaded together: C_i = i^0.7 C_1 (NSK 1.62/2.16, IBC eq. 2.4)
ROW_EXPONENT = 0.7


def cubic_mean(loads, travels, scale=LOAD_SCALE):
    r"""Cubic mean of step loads weighted by the travel under each (THK A-705 eq. 30).

    .. math:: F_m = (\sum F_i^3 l_i / \sum l_i)^{1/3} = s\,(\sum (F_i/s)^3 l_i / \sum l_i)^{1/3}

    loads   : F_i [N] (>= 0: the load in the direction a bearing row or nut half carries it)
    travels : l_i, travel (or revolutions) under each load; their sum must be > 0.
    scale   : s [N], the load the cubes are taken relative to (:data:`LOAD_SCALE`): the same value
              up to rounding, but the sum of cubes stays of order one instead of 1e9-1e12 N^3.  A
              global solver (SCIP) compares with absolute tolerances (1e-6..1e-9); on the unscaled
              sum its bound propagation and probing proved feasible designs infeasible (the teaching
              problem).
    Returns F_m [N].
    """
    total = sum(travels)
    inv = 1.0 / scale
    acc = 0.0
    for f, l in zip(loads, travels):
        r = f * inv
        acc = acc + r * r * r * l
    return scale * mx.cbrt(acc / total)


def directional_means(loads, travels):
    r"""Cubic-mean loads of each direction (THK A-706): loads of the other sign count as zero, over
    the total travel of every phase.

    loads : F_i [N], signed;  travels : l_i (> 0 in sum).  Returns (F_m+, F_m-) [N], both >= 0.
    THK takes the greater of the two for a single nut's life.
    """
    pos = [mx.fmax(f, 0.0) for f in loads]
    neg = [mx.fmax(-f, 0.0) for f in loads]
    return cubic_mean(pos, travels), cubic_mean(neg, travels)


def preloaded_halves(preload, load):
    r"""Loads on the two halves of a preloaded pair under a signed external load (HIWIN H-BS F 3.7,
    p. 26).

    .. math:: F_{b,+} = F_b(|F|) + \min(F, 0),\quad F_{b,-} = F_b(|F|) - \max(F, 0)

    with F_b(x) = (1 + x/(2^{3/2} F_pr))^{3/2} F_pr below lift-off and x above it
    (:func:`axisopt.physics.nut.preloaded_pair_load`): the half the load presses carries F_b, the
    other F_b - |F| (zero after lift-off).  preload : F_pr [N];  load : F [N], signed (+ presses the
    '+' half).  Returns (F_b+, F_b-) [N].
    """
    mag = mx.fabs(load)
    pressed = preloaded_pair_load(preload, mag)
    return pressed + mx.fmin(load, 0.0), pressed - mx.fmax(load, 0.0)


def set_life(lives, exponent=NUT_SET_EXPONENT):
    r"""Life of a set whose members (nut halves, bearing row groups) each have a rating life
    (Weibull sum).

    .. math:: L = (\sum L_i^{-e})^{-1/e}

    lives : L_i (any one unit: revolutions, hours);  exponent : e, 10/9 (HIWIN H-BS F 3.12, nut
        halves) or 1.1 (NSK, bearing rows).  Returns L in the unit of the L_i.
    """
    acc = 0.0
    for life in lives:
        acc = acc + mx.power(life, -exponent)
    return mx.power(acc, -1.0 / exponent)


def set_equivalent_load(mean_loads, ratings, exponent=NUT_SET_EXPONENT):
    r"""The load that, on the first member's rating, gives the set's life (:func:`set_life` of the
    members' lives L_i = K (C_i / F_i)^3):

    .. math:: F_{eq} = C_1 \left(\sum (F_i / C_i)^{3e}\right)^{1/(3e)},\qquad L = K (C_1 / F_{eq})^3

    mean_loads : F_i [N] (> 0);  ratings : C_i [N];  exponent : e.  Returns F_eq [N].  The same life
        as :func:`set_life`, written on load ratios (of order 0.01-1) rather than on lives (of order
        1e9 rev).
    """
    q = 3.0 * exponent
    acc = 0.0
    for f, c in zip(mean_loads, ratings):
        acc = acc + mx.power(f / c, q)
    return ratings[0] * mx.power(acc, 1.0 / q)


def row_group_rating(set_rating, rows_loaded, rows_rated):
    r"""Dynamic rating of the rows of a bearing set that carry one load direction, from the set's
    printed rating (vendors print the direction with the most rows).

    .. math:: C_i = C_{set}\,(i / i_{set})^{0.7}

    set_rating : C_set [N], printed for ``rows_rated`` rows loaded together;  rows_loaded : i [-].
    Returns C_i [N].  Source: NSK super-precision bearings (TAC B: 1, 2, 3 rows 28.5 / 46.5 / 61.5
    kN for 25TAC62B; factors 1.62, 2.15 for 2, 3 rows), IBC TI-I-5010 eq. 2.4 (C_set = i^0.7
    C_single), NACHI TAB.
    """
    return set_rating * mx.power(rows_loaded / rows_rated, ROW_EXPONENT)
