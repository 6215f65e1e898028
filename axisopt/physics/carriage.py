r"""The carriage on its guide blocks: moments of the applied forces, block loads by the vendors'
method, static safety, mean load for the life, and the table's rocking stiffness and modes.

Axes and signs (one convention for every function here).  x runs along the rail (feed), y across it
(cross), z out of the guide mounting plane towards the table.  Moments are taken about the centre of
the block pattern in the guide mounting plane; the ball screw's nut takes the feed force there (the
screw axis is taken to lie in the mounting plane under the centre of the pattern, so the feed
force's lever is its height above the plane, THK's l4/l5 "above the drive").  A force (f_x, f_y,
f_n), f_n pressing the table onto the rails, applied at (x, y, h) gives

.. math:: M_P = f_x h + f_n x,\quad M_R = f_y h + f_n y,\quad M_Y = f_y x - f_x y

(pitch about y, roll about x, yaw about z).  Block loads are those of a rigid table on equally
spaced blocks (THK "Calculating the Applied Load", General Catalog A-82..A-89, Table 2 patterns;
HIWIN G99TE20 §1-5 Tables 1-3 / 1-4): the radial load of a corner block (signs s_x, s_y = +-1 pick
the corner)

.. math:: P = f_n / n + s_x c_P M_P + s_y c_R M_R,\qquad P_t = f_y / n + s_x c_Y M_Y

with the moment shares c of :func:`moment_share` (the spacing method for two or more blocks per rail
and two or more rails; the block's own static moment rating, THK's moment-equivalent factor K =
C0/M, for one block per rail or one rail).  P > 0 presses the block onto the rail (radial), P < 0
pulls it off (reverse radial).
"""

from __future__ import annotations

from axisopt import mathx as mx

__all__ = [
    "carriage_moments",
    "moment_share",
    "block_radial_load",
    "block_lateral_load",
    "equivalent_block_load",
    "corner_block_loads",
    "max_block_load",
    "static_safety",
    "mean_load",
    "pattern_rocking_stiffness",
    "rocking_frequency",
    "box_inertia",
]

# The four corners of a block pattern (s_x, s_y): front/back block, left/right rail.
CORNERS = ((1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0))


def carriage_moments(feed_force, cross_force, normal_force, x, y, height):
    r"""Pitch, roll and yaw moment of one force about the centre of the block pattern.

    .. math:: M_P = f_x h + f_n x,\quad M_R = f_y h + f_n y,\quad M_Y = f_y x - f_x y

    feed_force   : f_x, along the rail [N]
    cross_force  : f_y, across the rail [N]
    normal_force : f_n, pressing the table onto the rails [N] (gravity of a horizontal table, a
        downward cut)
    x, y         : where the force acts, along / across the rail from the pattern centre [m]
    height       : h, above the guide mounting plane (= the screw axis, see the module notes) [m]
    Returns (M_P, M_R, M_Y) [N*m].  Source: statics of the rigid table (THK General Catalog
    A-82..A-89: the moments m g l2, m g l3, m alpha l5 of the worked examples are these products).
    """
    return (
        feed_force * height + normal_force * x,
        cross_force * height + normal_force * y,
        cross_force * x - feed_force * y,
    )


def moment_share(count, spacing, moment_factor, per_other):
    r"""Load on an outer block per unit moment [1/m]: the spacing method, or the block's moment
    rating.

    With ``count`` >= 2 equally spaced supports over ``spacing`` (blocks along a rail, or rails
    across the table) the moment is shared linearly, the outer support taking

    .. math:: c = \frac{x_{out}}{\sum x_i^2} = \frac{6 (k - 1)}{L\, k (k + 1)}

    (k = 2: 1/L), and the load is divided over the ``per_other`` supports in the other direction.
    With one support (one block per rail, one rail) the block takes the moment itself: its
    equivalent load is K M / per_other, K = C0 / M_0 the moment-equivalent factor (THK A-76..A-81,
    "P = K M"; HIWIN eq. 1.1 f_SM = M_0 / M uses the same ratio).

    count         : supports in the moment's direction, k [-] (a number; may be symbolic)
    spacing       : L, outer support to outer support [m]
    moment_factor : K = C0 / M_0 of one block for this moment [1/m] (used when count < 2)
    per_other     : supports sharing each position in the other direction [-]
    Returns c [1/m].  Source: THK General Catalog A-82..A-89 (4 blocks: m g l / (2 l0)); A-87
    single-block and two-blocks-in-contact examples (K M).
    """
    k = mx.fmax(count, 1.0)
    spread = 6.0 * (k - 1.0) / (spacing * k * (k + 1.0))
    return mx.if_else(count > 1.5, spread, moment_factor) / per_other


def block_radial_load(normal_force, pitch_moment, roll_moment, n_blocks, c_pitch, c_roll, sx, sy):
    r"""Radial load on the corner block (s_x, s_y) [N]; > 0 presses it onto the rail.

    .. math:: P = f_n / n + s_x c_P M_P + s_y c_R M_R

    normal_force : f_n [N];  pitch_moment, roll_moment : M_P, M_R [N*m];  n_blocks : n [-]
    c_pitch, c_roll : :func:`moment_share` [1/m];  sx, sy : +-1 [-]
    Source: THK General Catalog A-82..A-89, HIWIN G99TE20 Tables 1-3/1-4 (P_1..P_4 with +- per
    block).
    """
    return normal_force / n_blocks + sx * c_pitch * pitch_moment + sy * c_roll * roll_moment


def block_lateral_load(cross_force, yaw_moment, n_blocks, c_yaw, sx):
    r"""Lateral load on a block at the front (s_x = 1) or back (s_x = -1) of the pattern [N].

    .. math:: P_t = f_y / n + s_x c_Y M_Y

    cross_force : f_y [N];  yaw_moment : M_Y [N*m];  n_blocks : n [-];  c_yaw : [1/m];  sx : +-1 [-]
    Source: THK General Catalog A-104 (P_t = m alpha l3 / (2 l0)), HIWIN G99TE20 Table 1-3.
    """
    return cross_force / n_blocks + sx * c_yaw * yaw_moment


def equivalent_block_load(radial, lateral):
    r"""Equivalent load of a block under radial and lateral load [N].

    .. math:: P_E = |P_R| + |P_T|

    radial, lateral : P_R, P_T [N].  Source: THK General Catalog A-94 (4-way equal load types, e.g.
        HSR);
    HIWIN G99TE20 eq. 1.8 (HG, EG, RG, ... series: P_e = P_s + P_l); NBS p. 13 (P = |P_y| + |P_z|).
    IKO's X/Y scheme (1 and 0.6) gives at most this.
    """
    return mx.fabs(radial) + mx.fabs(lateral)


def corner_block_loads(
    normal_force,
    cross_force,
    pitch_moment,
    roll_moment,
    yaw_moment,
    n_blocks,
    c_pitch,
    c_roll,
    c_yaw,
):
    r"""Equivalent loads :func:`equivalent_block_load` of the four corner blocks (a tuple of 4) [N].

    Arguments as :func:`block_radial_load` and :func:`block_lateral_load`.  With one rail (c_roll
    from the block's rating) or one block per rail the "corners" are the signs of the rating terms
    (THK A-87 P_1..P_4).
    """
    out = []
    for sx, sy in CORNERS:
        p = block_radial_load(
            normal_force, pitch_moment, roll_moment, n_blocks, c_pitch, c_roll, sx, sy
        )
        t = block_lateral_load(cross_force, yaw_moment, n_blocks, c_yaw, sx)
        out.append(equivalent_block_load(p, t))
    return tuple(out)


def max_block_load(
    normal_force,
    cross_force,
    pitch_moment,
    roll_moment,
    yaw_moment,
    n_blocks,
    c_pitch,
    c_roll,
    c_yaw,
):
    r"""Largest equivalent block load of a load case [N]: the maximum of :func:`corner_block_loads`.

    Source: THK General Catalog A-106 (the static safety factor takes the largest P_E of all blocks
    and cases).
    """
    # the roll term's sign is free for either front/back row: max over s_y of |a + s_y c| = |a| +
    # |c|
    a, c, t = normal_force / n_blocks, c_roll * roll_moment, cross_force / n_blocks
    b, e = c_pitch * pitch_moment, c_yaw * yaw_moment
    front = mx.fabs(a + b) + mx.fabs(c) + mx.fabs(t + e)
    back = mx.fabs(a - b) + mx.fabs(c) + mx.fabs(t - e)
    return mx.fmax(front, back)


def static_safety(static_load_rating, load):
    r"""Static safety factor.

    .. math:: f_S = C_0 / P_{max}

    static_load_rating : C_0 (guide block) or C_0a (ball-screw nut) [N];  load : largest load [N] (>
        0).
    Returns f_S [-].  Source: THK General Catalog A-95 (LM Guide, f_S = f_H f_T f_C C_0 / P, with
    the hardness, temperature and contact factors 1 in normal use), A-703 eq. 26 (ball screw, F_amax
    = C_0a/f_S); HIWIN G99TE20 eq. 1.1; HIWIN BS-08 F 3.3 (S_0 F_amax < C_0).
    """
    return static_load_rating / load


def mean_load(loads, distances):
    r"""Mean load of a block over a cycle of load steps, for the life (ball blocks) [N].

    .. math:: P_m = \left( \frac{1}{L} \sum_n P_n^3 L_n \right)^{1/3},\qquad L = \sum_n L_n

    loads     : sequence of P_n, equivalent loads of the steps [N] (floats, arrays or symbols)
    distances : sequence of L_n, distance travelled under each [m] (positive sum)
    Source: THK General Catalog A-96 ("Calculating the Average Load", balls) and A-107 (worked
    example);
    HIWIN G99TE20 Table 1-5.  The cubic mean is kept for roller blocks too (THK uses the 10/3 power
    there; the difference is below 2 % for the load spreads of a feed axis).
    """
    total = 0.0
    weight = 0.0
    for p, s in zip(loads, distances):
        total = total + mx.power(mx.fabs(p), 3) * s
        weight = weight + s
    return mx.cbrt(total / weight)


def pattern_rocking_stiffness(block_stiffness, count, spacing, per_other, moment_factor):
    r"""Rocking (pitch or yaw) stiffness of the block pattern [N*m/rad].

    .. math:: K_\theta = k\, m \sum x_i^2 = k\, m\, L^2 \frac{k_n (k_n + 1)}{12 (k_n - 1)}

    for k_n >= 2 equally spaced blocks per rail over L, m rails (``per_other``), each block of
    stiffness k (normal for pitch, lateral for yaw).  One block per rail: its moment stiffness from
    the equivalent factor K = C0 / M_0 (a moment M loads the block like K M, deflecting it K M / k
    at the lever 1/K), K_theta = m k / K^2 [DERIVED; no vendor publishes a block's moment rigidity
    in the texts we have].

    block_stiffness : k [N/m];  count : k_n [-];  spacing : L [m];  per_other : m [-]
    moment_factor : K [1/m].  Returns K_theta [N*m/rad].
    """
    k = mx.fmax(count, 1.0)
    spread = spacing * spacing * k * (k + 1.0) / (12.0 * mx.fmax(k - 1.0, 1e-12))
    single = 1.0 / (moment_factor * moment_factor)
    return block_stiffness * per_other * mx.if_else(count > 1.5, spread, single)


def rocking_frequency(rocking_stiffness, inertia):
    r"""Natural frequency of the table rocking on its blocks [Hz].

    .. math:: f = \frac{1}{2\pi} \sqrt{K_\theta / J}

    rocking_stiffness : K_theta [N*m/rad];  inertia : J about the rocking axis [kg*m^2].  Returns f
        [Hz].
    """
    return mx.sqrt(rocking_stiffness / inertia) / (2.0 * mx.pi)


def box_inertia(mass, length, depth, offset):
    r"""Moment of inertia of a uniform box about an axis parallel to one of its central axes
    [kg*m^2].

    .. math:: J = m (a^2 + b^2) / 12 + m d^2

    mass : m [kg];  length, depth : a, b, the box's sides across the axis [m];  offset : d, axis to
        the centre of mass [m].  Source: rigid-body mechanics (parallel-axis theorem).
    """
    return mass * (length * length + depth * depth) / 12.0 + mass * offset * offset
