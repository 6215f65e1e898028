"""Lines in motor and screw orders (time records only): a force periodic in the angle of a turning
part, seen at the table as a period in position shorter than the lead.

A part turning with the motor or the screw that pushes the table once per tooth, slot or ball makes
a force periodic in its own angle; with the design's lead ``l`` and reduction ``r`` (motor turns
per screw turn) an order ``k`` of the motor turn is the period ``l / (r k)`` of the table's
travel, an order ``k`` of the screw turn the period ``l / k``.  Each candidate is a sin, cos pair of
``2 pi q / P`` (the same sign both ways: a force, not a friction) fitted jointly with the rigid
baseline; its amplitude is ``sqrt(s^2 + c^2)``:

* ``motor_cogging``: an integer order of the motor turn -- cogging or torque ripple of the motor
  (its slot count, or a multiple of the pole pairs; the motor catalogs give neither, so every
  integer order the record resolves is tried, the best by RSS). Orders a screw-turn candidate
  already names (``lead_ripple``'s lead / 1, 2, 3, a belt's tooth order) are left out;
* ``belt_mesh``: the tooth mesh of a toothed-belt stage, order ``z1`` of the motor turn (the motor
  pulley's teeth) = ``z1 r`` of the screw turn; a candidate only when the design's reduction is a
  belt whose pulleys are known (:attr:`.plant.Plant.belt_teeth`);
* ``ball_pass``: the balls of the nut passing a point of the nut, a non-integer order of the screw
  turn, ``Z/2 (1 - D cos a / d_m)`` with ``Z = pi d_m / D`` balls per turn (a full-complement
  circuit; the rolling-bearing outer-race ball-pass frequency with the screw as the turning inner
  ring, e.g. T. A. Harris, Rolling Bearing Analysis, 4th ed., sec. 7.2), ``d_m`` taken as the
  nominal diameter: an estimate, so the order is searched within +-15 % of it.

Screw run-out (order 1 of the screw turn) and a lead error periodic in the screw turn are
``lead_ripple``'s lead / 1 and / 2, 3 (:mod:`.friction`).  The shortest period searched is the
one a quarter of the moving rows see below the fit band (:func:`shortest_period`): a line at ``v/P``
above it is filtered out of the rows with the effort.
"""

from __future__ import annotations

import math

import numpy as np

from .base import Effect, Shape, Term, TimeModel, register_effect
from .disturbance import golden, pair_amplitude, pair_implausible
from .friction import RIPPLE_HARMONICS

# the shape that holds each effect's period at the table, and the order each candidate expects
PERIOD_SHAPES = {
    "motor_cogging": "cog_period",
    "belt_mesh": "mesh_period",
    "ball_pass": "ball_period",
    "lead_ripple": "period",
}
EXPECTED = {
    "motor_cogging": "expected at the slot count or a multiple of the pole pairs per motor turn "
    "(the motor's catalog row gives neither: every integer order the record resolves was tried)",
    "belt_mesh": "expected at order {belt_teeth} of the motor turn (the motor pulley's teeth)",
    "ball_pass": "expected near order {ball_order:.4g} of the screw turn (Z/2 (1 - D cos a / d_m), "
    "Z = pi d_m / D balls per turn: an estimate)",
    "lead_ripple": "expected at order 1 of the screw turn (run-out, a bent screw) or 1 to 3 (a "
    "lead error periodic in the turn, a circuit per turn)",
}  # str.format of the record's Processing fields
MAX_ORDER = 200  # the largest order of the motor turn tried (bounds the work)
BALL_BAND = 0.15  # the ball-pass order is searched within +-15 % of the estimate
SEEN_SHARE = 0.2  # a period is resolved when this share of the moving rows see it in band


def ball_pass_order(pitch_diameter: float, ball_diameter: float, contact_angle: float) -> float:
    """Balls passing a point of the nut per screw turn: Z/2 (1 - D cos a / d_m), Z = pi d_m / D (a
    full-complement circuit); 0 when the geometry is not known."""
    if not (pitch_diameter > 0 and ball_diameter > 0):
        return 0.0
    z = math.pi * pitch_diameter / ball_diameter
    return 0.5 * z * (1.0 - ball_diameter * math.cos(contact_angle) / pitch_diameter)


def shortest_period(rows) -> float:
    """The shortest period in position [record unit] the rows resolve: a fifth of the moving rows
    see its line at or below the position filter's cut-off, where the residual still holds half of
    it or more (:func:`line_gain`)."""
    v = np.abs(rows.sig["v"][rows.keep])
    return float(np.quantile(v, SEEN_SHARE)) / rows.proc.fc if len(v) else math.inf


def line_gain(v, period: float, proc):
    """The share of a force line at ``f = |v| / period`` the regression's residual holds at each
    row.  The effort is u = M a + d + F; the line's force d moves the table by M a = -T d through
    the position loop, and the regression's M a comes from the position filtered by the
    zero-phase H = 1 / (1 + (f/f_c)^8), so the residual keeps g = 1 - (1 - H) T of the line: all
    of it below the loop's bandwidth (where H = 1 too), H above it (T = 1, the table takes the
    line).  g = H is taken throughout: the loop's bandwidth lies well below the position filter's
    cut-off, where the two differ."""
    return 1.0 / (1.0 + (np.abs(v) / (period * proc.fc)) ** 8)


def line_columns(sig, proc, period: float) -> tuple:
    """The sin, cos pair of a force line of ``period`` in position as the residual holds it
    (:func:`line_gain`).  Its own instruments in the IV fit (``simulated=False``): a period of a
    millimetre or less does not survive the re-simulated loop's position error."""
    a = line_gain(sig["v"], period, proc)
    ph = 2.0 * math.pi * sig["q"] / period
    return a * np.sin(ph), a * np.cos(ph)


def _column(k, key):
    return lambda sig, proc, shape: line_columns(sig, proc, shape[key])[k]


SCAN_ROWS = 2000  # the scans of a residual look at most this many rows (evenly spread)


def _share(rows, r, period) -> float:
    """Share of ``r`` a sin, cos pair of 2 pi q / period holds at the rows that see it in band
    (least squares); on at most :data:`SCAN_ROWS` of them (a scan only locates the line, the
    joint fit's RSS refines it)."""
    k = max(1, len(r) // SCAN_ROWS)
    keep = rows.keep[::k]
    r = r[::k]
    sig = {"q": rows.sig["q"][keep], "v": rows.sig["v"][keep]}
    G = np.column_stack([*line_columns(sig, rows.proc, period), np.ones(len(r))])
    coef, *_ = np.linalg.lstsq(G, r, rcond=None)
    rc = r - r.mean()
    return 1.0 - float(np.sum((r - G @ coef) ** 2)) / (float(rc @ rc) or 1.0)


def motor_orders(proc, pmin: float) -> list:
    """The integer orders of the motor turn a cogging line is tried at: period lead / (r k) at
    least ``pmin``, at most :data:`MAX_ORDER`, without the screw orders other candidates name."""
    red = proc.reduction or 1.0
    taken = set(RIPPLE_HARMONICS)
    if proc.belt_teeth:
        taken.add(round(proc.belt_teeth * red, 6))
    out = []
    for k in range(1, MAX_ORDER + 1):
        if proc.lead_q / (red * k) < pmin:
            break
        screw = red * k
        if any(abs(screw - j) < 1e-6 for j in taken):
            continue
        out.append(k)
    return out


def _cogging_search(rows, r0, rss) -> dict:
    proc = rows.proc
    orders = motor_orders(proc, shortest_period(rows))
    if not orders:
        return {"cog_period": proc.lead_q, "cog_order": 0.0}
    red = proc.reduction or 1.0
    # a scan on the residual at the rows, the best three refined on the joint fit's RSS
    scored = sorted(orders, key=lambda k: -_share(rows, r0, proc.lead_q / (red * k)))[:3]
    best = min(scored, key=lambda k: rss({"cog_period": proc.lead_q / (red * k)}))
    return {"cog_period": proc.lead_q / (red * best), "cog_order": float(best)}


def _cogging_skip(ctx) -> str:
    if ctx.lead_q <= 0:
        return "no lead known"
    if not motor_orders(ctx.rows.proc, shortest_period(ctx.rows)):
        return (
            "the record resolves no order of the motor turn beyond the lead's (too fast for its "
            "sampling)"
        )
    return ""


def _belt_skip(ctx) -> str:
    proc = ctx.rows.proc
    if ctx.lead_q <= 0:
        return "no lead known"
    if not proc.belt_teeth:
        return "the design has no toothed-belt stage with known pulleys"
    period = proc.lead_q / ((proc.reduction or 1.0) * proc.belt_teeth)
    if period < shortest_period(ctx.rows):
        return (
            "the tooth mesh's period is shorter than the record resolves (too fast for its "
            "sampling)"
        )
    return ""


def _ball_bounds(proc) -> tuple:
    return (
        proc.lead_q / (proc.ball_order * (1.0 + BALL_BAND)),
        proc.lead_q / (proc.ball_order * (1.0 - BALL_BAND)),
    )


def _ball_search(rows, r0, rss) -> dict:
    proc = rows.proc
    lo, hi = _ball_bounds(proc)
    lo = max(lo, shortest_period(rows))
    q = rows.sig["q"][rows.keep]
    span = float(np.ptp(q)) or proc.lead_q
    # grid points a phase error of pi/4 over the positions apart: dP/P = P / (8 span), at most 4,000
    rel = max(lo / (8.0 * span), (hi / lo) ** (1.0 / 4000) - 1.0)
    grid = lo * (1.0 + rel) ** np.arange(int(math.log(hi / lo) / math.log1p(rel)) + 2)
    # an integer order of the motor turn is motor_cogging's (or a belt's): left out within the
    # record's resolution, a drift of one period over the positions covered
    orders = proc.lead_q / grid
    red = proc.reduction or 1.0
    apart = np.abs(orders / red - np.rint(orders / red)) * red >= proc.lead_q / span
    grid = grid[apart] if apart.any() else grid
    p0 = float(max(grid, key=lambda P: _share(rows, r0, P)))
    step = p0 * rel
    p = golden(lambda P: rss({"ball_period": P}), max(lo, p0 - step), min(hi, p0 + step), 14)
    return {"ball_period": p, "ball_order": proc.lead_q / p}


def _ball_skip(ctx) -> str:
    proc = ctx.rows.proc
    if ctx.lead_q <= 0:
        return "no lead known"
    if not proc.ball_order > 0:
        return "the design's screw gives no ball diameter"
    if _ball_bounds(proc)[1] < shortest_period(ctx.rows):
        return (
            "the ball pass's period is shorter than the record resolves (too fast for its sampling)"
        )
    return ""


def _pair(prefix, label, key):
    return (
        Term(
            f"{prefix}s",
            f"{label}, sin(2 pi q/P) coefficient",
            "effort",
            _column(0, key),
            simulated=False,
        ),
        Term(
            f"{prefix}c",
            f"{label}, cos(2 pi q/P) coefficient",
            "effort",
            _column(1, key),
            simulated=False,
        ),
    )


@register_effect
class MotorCogging(Effect):
    """A force periodic at an integer order of the motor turn (cogging, torque ripple)."""

    name = "motor_cogging"
    title = "a force at an integer order of the motor turn (motor cogging or torque ripple)"
    time = TimeModel(
        "a force at an integer order of the motor turn (motor cogging or torque ripple: the slot "
        "count or a multiple of the pole pairs)",
        _pair("g", "motor-order force", "cog_period"),
        shape=Shape(
            "cog_period",
            "period at the table (integer motor orders scanned)",
            "position",
            search=_cogging_search,
            also=(("cog_order", "order of the motor turn", "ratio"),),
        ),
        skip=_cogging_skip,
        implausible=pair_implausible("gs", "gc", "a motor-order force"),
        evidence="a slow constant-speed pass with the motor decoupled from the screw (or at two "
        "reductions): the line keeps its order of the motor turn",
        derived=(
            ("cog_amp", "amplitude of the motor-order force", "effort", pair_amplitude("gs", "gc")),
        ),
    )


@register_effect
class BeltMesh(Effect):
    """A force at the tooth order of a toothed-belt stage."""

    name = "belt_mesh"
    title = "a force at a toothed belt's tooth mesh (order z1 of the motor turn)"
    time = TimeModel(
        "a force at the tooth mesh of the belt stage (order of the motor pulley's teeth)",
        _pair("b", "tooth-mesh force", "mesh_period"),
        shape=Shape(
            "mesh_period",
            "period of the tooth mesh at the table",
            "position",
            choices=lambda proc: [
                proc.lead_q / ((proc.reduction or 1.0) * max(proc.belt_teeth, 1))
            ],
        ),
        skip=_belt_skip,
        implausible=pair_implausible("bs", "bc", "a tooth-mesh force"),
        evidence="the same pass with the belt's tension changed, or with another pulley pair: the "
        "line follows the tooth count",
        derived=(
            ("mesh_amp", "amplitude of the tooth-mesh force", "effort", pair_amplitude("bs", "bc")),
        ),
    )


@register_effect
class BallPass(Effect):
    """A force at the balls' pass order of the nut (a non-integer order of the screw turn)."""

    name = "ball_pass"
    title = "a force at the nut's ball pass (a non-integer order of the screw turn)"
    time = TimeModel(
        "a force at the balls' pass in the nut (a non-integer order of the screw turn)",
        _pair("n", "ball-pass force", "ball_period"),
        shape=Shape(
            "ball_period",
            "period at the table (within 15 % of the estimate)",
            "position",
            search=_ball_search,
            also=(("ball_order", "balls passing per screw turn", "ratio"),),
        ),
        skip=_ball_skip,
        implausible=pair_implausible("ns", "nc", "a ball-pass force"),
        evidence="slow constant-speed passes at two speeds: the line keeps its non-integer order "
        "of the screw turn (a worn or contaminated ball track grows it)",
        derived=(
            ("ball_amp", "amplitude of the ball-pass force", "effort", pair_amplitude("ns", "nc")),
        ),
    )
