"""Vendor checks of the axis as margins (value / limit, >= 1 passes) and the values behind them."""

from __future__ import annotations

import math
from types import MappingProxyType

import numpy as np

from .. import mathx as mx
from ..physics import bearings as pb
from ..physics import bearingsets as psets
from ..physics import checks as pc
from ..physics import life as pl
from ..physics import nut as pn
from ..physics import screw as ps
from .limits import CHECK_TABLE, margin_output
from .loads import unit

# The checks, their labels and units are declared once in model.limits (CHECK_TABLE).
CHECKS = tuple(c.name for c in CHECK_TABLE)
# Drive checks (model.drive); they apply only when the design has a motor (coupling).
DRIVE_CHECKS = tuple(c.name for c in CHECK_TABLE if c.drive)
CHECK_LABELS = MappingProxyType({c.name: c.label for c in CHECK_TABLE})

# Buckling end condition.  The compressed length runs from the thrust (fixed) bearing to the nut,
# and the guided nut counts as a fixed end whatever the screw mounting: THK worked examples
# A-724..A-727 and A-738..A-740 take "fixed-fixed" (eta_2 = 20) for a fixed-supported screw, with
# l_a the distance between the mounting positions.  The critical speed keeps the screw's own
# mounting (lambda_2 of the mounting).
BUCKLING_END_CONDITION = "fixed-fixed"
# How the nut holds the shaft (axis.buckling_nut_end): "fixed" (a long nut in a rigid bracket on a
# guided table: the THK examples above, the default), or "supported" (the nut a pinned end: MiSUMi
# "Selection of Ball Screws 2"
# p. 1676, whose example takes a fixed-support shaft's m = 10 over the distance between the points
# of buckling load, d 12.5 mm, l 820 mm: 3 630 N, half the fixed-end figure)
BUCKLING_NUT_ENDS = {"fixed": "fixed-fixed", "supported": "fixed-supported"}
# Above this a margin says only "not limiting" (e.g. buckling when pretension keeps the screw in
# tension).
MARGIN_CAP = 1e3
# THK catalog A15 eq. 6: permissible tensile/compressive load of the shaft, P2 = sigma A, sigma =
# 147 MPa.
SCREW_YIELD_STRESS = 147e6

# DN: each screw vendor states its limit on its own diameter (catalogs/SOURCES.md stores every row's
# limit on the nominal diameter the model divides by): THK on the ball centre-to-centre diameter dp
# (A-697, stored as limit x d / dp), HIWIN GmbH (H-BS 3.7.6) and Rexroth (R310RU 3301 p. 99) on the
# nominal diameter, HIWIN Taiwan (S99TE20 p. 33) on the pitch-circle diameter.
DN_RULES = MappingProxyType(
    {
        "THK": "THK A-697: DN on the ball centre diameter dp",
        "HIWIN": "HIWIN H-BS 3.7.6: d0 x n on the nominal diameter",
        "Bosch Rexroth": "Rexroth R310 p. 99: d0 x n on the nominal diameter",
    }
)
DN_RULE_OTHER = "d x n on the nominal diameter (the row's own limit)"

# Margin of a check that does not apply to the design (a rotating-nut check on a nut that does not
# turn, the whirl of a screw that does not turn)
NOT_APPLICABLE = 1e9

# A margin passes at >= 1 less float rounding: the search holds each limit exactly by bisection, and
# the evaluation path may round the same ratio (e.g. 19 999.999999999996 h against 20 000 h) one ulp
# lower.
MARGIN_RTOL = 1e-9


def passes(margin) -> bool:
    """True when a check margin (value / limit) meets its limit, within float rounding."""
    return bool(margin >= 1.0 - MARGIN_RTOL)


def nut_life_load(p, preload, loads, travels):
    """The equivalent load [N] on the nut's rating that gives its L10 life over the duty cycle's
    phase loads (physics.life).  A preloaded nut as HIWIN computes it (H-BS F 3.7-3.12): both
    halves' cubic-mean loads over the phases, each half's life at the nut's rating, their Weibull
    sum (e = 10/9).  A single nut as THK does (A-706): the greater of the two directions' cubic
    means."""
    c = p["nut_dynamic_load"]
    pre = mx.fmax(preload, 1e-9)
    halves = _per_load(lambda f: pl.preloaded_halves(pre, f), loads, (pre,))
    means = [mx.fmax(pl.cubic_mean([h[k] for h in halves], travels), 1e-9) for k in (0, 1)]
    pair = pl.set_equivalent_load(means, (c, c), pl.NUT_SET_EXPONENT)
    plus, minus = pl.directional_means(loads, travels)
    return mx.if_else(p["nut_double"] > 0.5, pair, mx.fmax(mx.fmax(plus, minus), 1e-9))


def bearing_life_load(p, loads, travels, static):
    """The equivalent load [N] on the support-bearing set's printed rating that gives the set's
    L10 life: the rows carrying each direction as the two halves of a preloaded pair, each rated by
    its row count (the printed set rating for the stronger direction, i^0.7 scaled for the other:
    NSK TAC B, IBC), the static set load (pretension, thermal force) pressing the weaker rows, and
    the rows' lives summed as NSK sums a preloaded set's (e = 1.1).  The set is mounted with its
    stronger rows facing the direction that gives the longer life (the designer's choice): either
    way round against the cycle's loads, and with either group of rows facing the static load (a
    3-against-1 set's three rows take a pretension, IBC TI-I-5010.2; for a set of as many rows each
    way both choices are one).  A screw held at both ends has a set at each, mirrored: the cycle's
    loads press one end's set the way the other's is spared, so the worse of the two governs
    there."""
    c_strong = p["bearing_dynamic_load"]
    n_s, n_w = p["bearing_rows_strong"], p["bearing_rows_weak"]
    c_weak = pl.row_group_rating(c_strong, n_w, n_s)
    pre = p["bearing_preload"]
    two_ends = p["bearing_sets"] > 1.5
    best = None
    orders = (((c_strong, c_weak), (n_s, n_w)), ((c_weak, c_strong), (n_w, n_s)))
    if not mx.is_symbolic(n_s, n_w) and np.all(np.asarray(n_s) == np.asarray(n_w)):
        # as many rows each way everywhere: the two ways round are one (the rows' ratings are
        # equal, C (1/1)^0.7 = C), computed once
        orders = orders[:1]
    for ratings, rows in orders:
        ends = []
        for orient in (1.0, -1.0):
            # the groups' loads by the set maker's rule (_set_halves): NSK's printed split or
            # HIWIN's pair law for as many rows each way; where the groups differ in rows, the
            # maker's split up to the set's own lift-off load
            sym, hz = n_s == n_w, p["bearing_hertz_split"]
            halves = _per_load(
                lambda f, o=orient, r=rows, s=sym, h=hz: _set_halves(pre, o * f - static, r, s, h),
                loads,
                (pre, static, sym, hz, *rows),
            )
            means = [mx.fmax(pl.cubic_mean([h[k] for h in halves], travels), 1e-9) for k in (0, 1)]
            # the equivalent load on the printed (stronger) rating
            ends.append(
                pl.set_equivalent_load(means, ratings, pl.BEARING_SET_EXPONENT)
                * (c_strong / ratings[0])
            )
        load = mx.if_else(two_ends, mx.fmax(*ends), mx.fmin(*ends))
        best = load if best is None else mx.fmin(best, load)
    return best


def _per_load(halves, loads, others) -> list:
    """``[halves(f) for f in loads]`` (``halves``: a load's two (pair or row group) loads;
    ``others``: the other values it reads).  On numbers the loads are stacked on a leading axis and
    evaluated at once (the same operations on each element: the same values), on symbols one by
    one."""
    if mx.is_symbolic(*others, *loads) or len(loads) < 2:
        return [halves(f) for f in loads]
    f = [np.asarray(x, dtype=float) for x in loads]
    shape = np.broadcast_shapes(*(x.shape for x in f))
    nd = max(np.ndim(v) for v in (*others, *f))
    stacked = np.stack([np.broadcast_to(x, shape) for x in f])
    plus, minus = halves(stacked.reshape((len(f),) + (1,) * (nd - len(shape)) + shape))
    both = np.broadcast_shapes(np.shape(plus), np.shape(minus))
    plus, minus = np.broadcast_to(plus, both), np.broadcast_to(minus, both)
    return [(plus[i], minus[i]) for i in range(len(f))]


def _set_halves(preload, load, rows, symmetric, hertz=0.0):
    """The two row groups' loads of a support set (see :func:`bearing_life_load`) by the set
    maker's rule (``hertz`` 1: NSK): for as many rows each way NSK's printed split
    (physics.bearingsets.nsk_pair_halves), else HIWIN's pair law; where the groups differ NSK's
    Hertz split (physics.bearingsets.hertz_set_halves: NSK prints no line for 3 against 1), else
    IBC's linear split (physics.bearingsets.set_halves)."""
    pair = pl.preloaded_halves(preload, load)
    if not (isinstance(hertz, (int, float)) and not hertz):
        # a maker that prints its own split for as many rows each way (NSK: DB, DBB)
        nsk = psets.nsk_pair_halves(preload, load)
        pair = tuple(mx.if_else(hertz > 0.5, a, b) for a, b in zip(nsk, pair))
    if isinstance(symmetric, (bool, np.bool_)) and symmetric:
        return pair
    linear = psets.set_halves(preload, load, rows[0], rows[1])
    if isinstance(hertz, (int, float)) and not hertz:
        rows_halves = linear
    elif not mx.is_symbolic(preload, load, rows[0], rows[1], hertz, symmetric):
        rows_halves = _hertz_where(preload, load, rows, symmetric, hertz, linear)
    else:
        exact = psets.hertz_set_halves(preload, load, rows[0], rows[1])
        rows_halves = tuple(mx.if_else(hertz > 0.5, e, li) for e, li in zip(exact, linear))
    return tuple(mx.if_else(symmetric, a, b) for a, b in zip(pair, rows_halves))


def _hertz_where(preload, load, rows, symmetric, hertz, linear):
    """Numbers: the linear split with the Hertz split put in only where it applies (a maker's
    unequal set), computed on those elements alone (the search's arrays hold every bearing)."""
    args = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (preload, load, rows[0], rows[1], hertz)),
        np.asarray(symmetric, dtype=bool),
    )
    use = (args[4] > 0.5) & ~args[5]
    if not use.any():
        return linear
    out = [np.array(np.broadcast_to(li, use.shape), dtype=float) for li in linear]
    exact = psets.hertz_set_halves(*(a[use] for a in args[:4]))
    for o, e in zip(out, exact):
        o[use] = e
    return tuple(out) if use.ndim else tuple(float(o) for o in out)


def bearing_static(p, f_max, static):
    """(margin, available, needed) of the support-bearing set's static check [N]: the set is mounted
    with its stronger rows facing the static set load (pretension, thermal force), which they carry
    with the largest axial force; the other rows carry the largest axial force alone (the static
    load comes and goes with the screw's temperature: a warm pretensioned screw leaves the sets
    nearly unloaded).  Each direction's rows are rated in proportion to their count
    (physics.bearings.row_static_rating) with the least static safety the rating's vendor asks (or
    the axis's)."""
    c_strong = p["bearing_static_load"]
    c_weak = pb.row_static_rating(c_strong, p["bearing_rows_weak"], p["bearing_rows_strong"])
    s0 = p["bearing_static_safety"]
    push = f_max + static
    margin = pb.support_static_margin(c_strong, c_weak, push, f_max, s0)
    strong_governs = c_strong / push <= c_weak / f_max
    return (
        margin,
        mx.if_else(strong_governs, c_strong, c_weak),
        s0 * mx.if_else(strong_governs, push, f_max),
    )


def bearing_lift_off(p, f_max, static):
    """(margin, available, needed) of the support set's lift-off check [N]: the rows facing the
    static set load (pretension, thermal force) carry it with the largest axial force up to the
    set's stronger lift-off load (``bearing_lift_off_strong``, a 3-against-1 set's 8.49 Fv,
    physics.bearingsets); the other rows carry the largest axial force alone (a warm pretensioned
    screw leaves the sets nearly unloaded, as in :func:`bearing_static`) up to the weaker
    direction's ``bearing_lift_off``.  A set that lists one lift-off load has it both ways: its
    margin is the stronger direction's, lift-off / (largest force + static)."""
    push = f_max + static
    strong = p["bearing_lift_off_strong"] / push
    weak = p["bearing_lift_off"] / f_max
    strong_governs = strong <= weak
    return (
        mx.fmin(strong, weak),
        mx.if_else(strong_governs, p["bearing_lift_off_strong"], p["bearing_lift_off"]),
        mx.if_else(strong_governs, push, f_max),
    )


def unit_checks(p, mounting, loads, omega, mean_omega) -> dict:
    """The driven rotating-nut unit's own checks (margins, available and needed values;
    :data:`NOT_APPLICABLE` for a nut on a rotating screw).  THK DIR/BLR (T-GC A-772-A-779) and HIWIN
    AME (H-BS 7.1) turn the nut in a built-in support bearing on a stationary screw:

    * ``unit_speed``: the unit's max speed (HIWIN's n max; THK prints none for DIR/BLR: the screw's
      DN rule for the nut's rotation, an estimate, model.params.rotating_nut_params) over the nut's
      speed 2 pi v / P_h;
    * ``unit_bearing_life``: the built-in bearing (a preloaded pair: THK "two rows of DB type
      angular bearings", B-721) rated as the end sets are (:func:`bearing_life_load`: its printed
      Ca, one row each way, its preload the 5 % Ca estimate, no static set load: the screw's
      pretension stays in the screw); L10 at the cycle's mean nut speed, the life rule of
      physics.checks (THK A-704);
    * ``unit_bearing_static``: its printed C0a against the largest axial force with Rexroth's
      machine-tool static safety (a true C0a whose vendor names no factor,
      physics.bearings.STATIC_SAFETY_MACHINE_TOOL);
    * ``rotating_mount`` (a compatibility rule): the stationary screw is held and tensioned at both
      ends (THK A-779's mountings hold the shaft at its ends), so a unit fits only a fixed-fixed
      screw.
    """
    r = unit(p, "nut_rotating") > 0.5
    ca, c0 = unit(p, "unit_bearing_dynamic_load"), unit(p, "unit_bearing_static_load")
    # no unit: no bearing of its own
    absent = NOT_APPLICABLE * p["required_life"] + 0.0 * mean_omega
    if not mx.is_symbolic(r) and not np.any(r):  # numbers without a unit: the life is not computed
        life = absent
    else:
        q = dict(p)
        q.update(
            {
                "bearing_dynamic_load": ca,
                "bearing_rows_strong": 1.0,
                "bearing_rows_weak": 1.0,
                "bearing_sets": 1.0,
                "bearing_preload": unit(p, "unit_bearing_preload"),
            }
        )
        load = bearing_life_load(q, loads["life_loads"], loads["life_travels"], 0.0)
        life = mx.if_else(r, pc.life_time(ca, load, mean_omega, p["load_factor"]), absent)
    f_max = loads["max_axial_force"]
    s0 = pb.STATIC_SAFETY_MACHINE_TOOL
    held = 1.0 if mounting == "fixed-fixed" else 0.0
    margins = {
        "unit_speed": mx.if_else(r, unit(p, "unit_max_speed") / omega, NOT_APPLICABLE),
        "unit_bearing_life": mx.if_else(r, life / p["required_life"], NOT_APPLICABLE),
        "unit_bearing_static": mx.if_else(r, c0 / (s0 * f_max), NOT_APPLICABLE),
        "rotating_mount": mx.if_else(r, held + 0.0 * omega, NOT_APPLICABLE),
    }
    out = {margin_output(k): v for k, v in margins.items()}
    out["unit_bearing_life"] = life
    out.update(
        check_pairs(
            {
                "unit_speed": (unit(p, "unit_max_speed"), omega),
                "unit_bearing_life": (life, p["required_life"]),
                "unit_bearing_static": (c0, s0 * f_max),
                "rotating_mount": (held, 1.0),
            }
        )
    )
    return out


def checks(p, mounting, preload, loads) -> dict:
    """Check margins ``margin_<check>`` and the physical values they compare (SI).

    A driven rotating nut (``nut_rotating`` 1, :func:`unit_checks`) leaves the screw standing: no
    whirl (the critical speed does not apply; THK A-774: "the screw shaft does not rotate ... this
    model does not show skipping"), and the end bearings do not turn (their life and speed checks do
    not apply; their static check stays).  The DN check stays: the balls run at the nut's speed
    relative to the screw.  ``screw_sag``: the sag of a horizontal screw under its own weight
    (physics.screw.screw_sag; 0 on a vertical axis)."""
    span = p["span"]
    omega = 2.0 * math.pi * p["max_speed"] / p["lead"]
    mean_omega = 2.0 * math.pi * p["mean_speed"] / p["lead"]
    f_max = loads["max_axial_force"]
    x_far = p["start_offset"] + p["stroke"]
    # the dangerous speed by the screw's vendor (issue 53): HIWIN's F 3.27/3.28 for its screws,
    # THK's A-696 for the others
    crit = pc.critical_speed(p["root_diameter"], span, mounting)
    hiwin = p.get("screw_hiwin_rule", 0.0)
    if not (isinstance(hiwin, (int, float)) and not hiwin):
        crit = mx.if_else(
            hiwin > 0.5, pc.critical_speed_hiwin(p["root_diameter"], span, mounting), crit
        )
    # buckling: bearing to nut at the far stroke end (fixed-fixed: the longer of the two sides, THK
    # "evaluate both"), nut counted as fixed (BUCKLING_END_CONDITION)
    buck_len = x_far if mounting != "fixed-fixed" else mx.fmax(x_far, span - p["start_offset"])
    # 1: the nut a fixed end, 0: a supported one (BUCKLING_NUT_ENDS)
    held = p.get("buckling_nut_fixed", 1.0)
    buck = held * pc.buckling_load(p["root_diameter"], buck_len, BUCKLING_END_CONDITION) + (
        1.0 - held
    ) * pc.buckling_load(p["root_diameter"], buck_len, BUCKLING_NUT_ENDS["supported"])
    compression = mx.fmax(loads["screw_compression"], buck / MARGIN_CAP)
    yield_load = SCREW_YIELD_STRESS * math.pi * p["root_diameter"] ** 2 / 4.0
    tension = mx.fmax(loads["screw_tension"], f_max)
    life = pc.life_time(
        p["nut_dynamic_load"],
        nut_life_load(p, preload, loads["life_loads"], loads["life_travels"]),
        mean_omega,
        p["load_factor"],
    )
    brg_load = bearing_life_load(
        p, loads["life_loads"], loads["life_travels"], loads["bearing_static_load"]
    )
    brg_life = pc.life_time(p["bearing_dynamic_load"], brg_load, mean_omega, p["load_factor"])
    # guide blocks: the load per block with the block preload acting like a preloaded pair of ball
    # rows (the most loaded block's cubic mean load over the duty cycle, model.carriage)
    guide_load = pn.preloaded_pair_load(p["guide_preload"], loads["guide_mean_load"])
    guide_life = pc.guide_life_distance(
        p["guide_dynamic_load"],
        guide_load,
        p["load_factor"],
        p["guide_roller"],
        p["guide_rating_distance"],
    )
    dn = pc.dn_value(p["nominal_diameter"], omega)
    lift = pn.lift_off_force(mx.fmax(preload, 1e-9))
    brg_max = f_max + loads["bearing_static_load"]
    bore = p["bearing_bore"]
    ceiling = pn.preload_ceiling(p["nut_dynamic_load"])
    brg_static, brg_c0, brg_c0_need = bearing_static(p, f_max, loads["bearing_static_load"])
    # each load case with its own load (model.loads.lift_off_load: THK A-725's phases), not all at
    # once
    lift_need = p["nut_lift_off_safety"] * loads["lift_off_load"]
    lift_margin, lift_avail, lift_load = bearing_lift_off(p, f_max, loads["bearing_static_load"])
    turning = unit(p, "nut_rotating") < 0.5  # the screw turns (a nut on a rotating screw)
    margins = {
        "critical_speed": mx.if_else(turning, crit / omega, NOT_APPLICABLE),
        "buckling": buck / compression,
        "screw_yield": yield_load / tension,
        "nut_life": life / p["required_life"],
        "bearing_life": mx.if_else(turning, brg_life / p["required_life"], NOT_APPLICABLE),
        "guide_life": guide_life / (p["required_life"] * p["mean_speed"]),
        "dn": p["dn_limit"] / dn,
        # a single nut has no preload to lose: the check does not apply (margin reported as inf)
        "nut_lift_off": mx.if_else(p["nut_double"] > 0.5, lift / lift_need, 1e9),
        # the vendors' preload ceiling (10 % Ca); a nut with play carries no preload
        "nut_preload": mx.if_else(p["nut_double"] > 0.5, ceiling / mx.fmax(preload, 1e-9), 1e9),
        "bearing_lift_off": lift_margin,
        "bearing_speed": mx.if_else(turning, p["bearing_limiting_speed"] / omega, NOT_APPLICABLE),
        # the bearing journal is machined on the screw end: its vendor lists the bores it takes
        "bearing_fit": mx.fmin(p["support_bore_max"] / bore, bore / p["support_bore_min"]),
        "screw_length": p["screw_max_length"] / span,
        # static safety of the guide blocks (largest block load of the load cases) and of the nut
        "guide_static": p["guide_static_load"]
        / (p["guide_static_safety"] * loads["guide_max_load"]),
        "nut_static": p["nut_static_load"] / (p["nut_static_safety"] * f_max),
        "bearing_static": brg_static,
    }
    values = {
        "critical_speed": crit,
        "buckling_load": buck,
        "yield_load": yield_load,
        "life": life,
        "bearing_life": brg_life,
        "guide_life": guide_life,
        "dn": dn,
        "nut_lift_off_force": lift,
        "bearing_max_load": brg_max,
        "nut_static_safety": p["nut_static_load"] / f_max,
        "screw_slenderness": span / p["nominal_diameter"],
        "screw_sag": (1.0 - p["gravity_axial"])
        * ps.screw_sag(p["screw_mass_per_length"], p["root_diameter"], span, mounting),
    }
    # what each margin compares, in SI: the available capacity and the needed value (margin =
    # available / needed, except bearing_fit, whose "needed" is the bore and "available" the largest
    # bore the end takes)
    pairs = {
        "critical_speed": (crit, omega),
        "buckling": (buck, loads["screw_compression"]),
        "screw_yield": (yield_load, tension),
        "nut_life": (life, p["required_life"]),
        "bearing_life": (brg_life, p["required_life"]),
        "guide_life": (guide_life, p["required_life"] * p["mean_speed"]),
        "dn": (p["dn_limit"], dn),
        "nut_lift_off": (lift, lift_need),
        "nut_preload": (ceiling, preload),
        "bearing_lift_off": (lift_avail, lift_load),
        "bearing_speed": (p["bearing_limiting_speed"], omega),
        "bearing_fit": (p["support_bore_max"], bore),
        "screw_length": (p["screw_max_length"], span),
        "guide_static": (
            p["guide_static_load"],
            p["guide_static_safety"] * loads["guide_max_load"],
        ),
        "nut_static": (p["nut_static_load"], p["nut_static_safety"] * f_max),
        "bearing_static": (brg_c0, brg_c0_need),
    }
    out = {margin_output(k): v for k, v in margins.items()}
    out.update(values)
    out.update(check_pairs(pairs))
    out.update(unit_checks(p, mounting, loads, omega, mean_omega))
    return out


def check_pairs(pairs: dict) -> dict:
    """``available_<check>`` and ``needed_<check>`` outputs from {check: (available, needed)}."""
    out = {}
    for k, (have, need) in pairs.items():
        out[f"available_{k}"] = have
        out[f"needed_{k}"] = need
    return out
