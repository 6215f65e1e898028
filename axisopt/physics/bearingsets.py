"""Sets of matched angular-contact thrust bearings (screw supports: DB/DF, DBD/DFD, DBB/DFF,
DBT/DFT...) from their single bearings, by Hertz's point contact.

Each bearing of a group of ``n`` side by side carries F / n and deflects as delta = (F / (n
K))^(2/3) (the ball bearing's axial load-deflection law, delta ~ F^(2/3)).  The matched bearings of
a set are ground with the same axial offset, so a set of ``n_a`` against ``n_b`` bearings closes the
gap of a DB pair (2 delta_0 at the pair's preload F_DB) at its own preload, and an external load on
the ``n_a`` group unloads the ``n_b`` group when the ``n_a`` group has taken up the whole gap.
Three published tables follow from this alone:

* IBC TI-I-5010.2/E Table 2.2: the unloading point Fae = X Fv of every arrangement (X = 2.83, 5.66,
  8.49, 11.30 for 1, 2, 3, 4 bearings against 1; 5.66 for 2 against 2; 8.49 / 5.66 for 3 against 2)
  and the preload of the single bearing (1.36 / 1.57 / 1.71 Fv for 2 / 3 / 4 against 1), Fv the
  preload the bearings have as a DB pair: :func:`set_preload_ratio`, :func:`set_lift_off`;
* NSK super-precision bearings p. 168 (TAC B): triplex and quadruplex preload 1.37 and 1.98 times
  the duplex's and rigidity 1.46 and 1.96 times: :func:`set_preload_ratio`,
  :func:`set_rigidity_ratio`.

NSK prints its own split for sets of as many bearings each way (:func:`nsk_pair_halves`: NSK
super-precision bearings, life of preloaded angular-contact sets, DB p. 140 and DBB p. 141).

The load on each group under an external load (:func:`set_halves`) is IBC's linear split between the
preload and the set's own lift-off load (Table 2.2's form), above Hertz's exact (convex) split:
conservative.

All functions take floats, numpy arrays or CasADi symbols.
"""

from __future__ import annotations

import numpy as np

from .. import mathx as mx

__all__ = [
    "set_preload_ratio",
    "set_lift_off",
    "set_rigidity_ratio",
    "set_pressed_load",
    "set_halves",
    "hertz_set_halves",
    "nsk_pair_halves",
]

# fixed Newton steps of the Hertz split (one symbolic expression; converged to ~1e-15 as the double
# nut's)
HERTZ_STEPS = 12


def set_preload_ratio(n_a, n_b):
    r"""Preload of a set of ``n_a`` against ``n_b`` matched bearings over the preload of two of them
    as a DB pair (the same bearings, the same grinding offset): (2 / (n_a^{-2/3} +
    n_b^{-2/3}))^{3/2}. 1 against 1: 1; 2 against 1: 1.36; 3 against 1: 1.57; 4 against 1: 1.71; 2
    against 2: 2 (IBC Table 2.2, NSK p. 168)."""
    return (2.0 / (n_a ** (-2.0 / 3.0) + n_b ** (-2.0 / 3.0))) ** 1.5


def set_lift_off(preload, n_load, n_other):
    r"""External axial load [N] on the group of ``n_load`` bearings at which the opposite group of
    ``n_other`` unloads, for the set's own preload ``preload`` [N]: F (1 + (n_load /
    n_other)^{2/3})^{3/2}. 1 against 1: 2.83 F (SKF, THK, HIWIN); the single of 2 against 1 loaded:
    2.08 F; 3 loaded against 1: 5.41 F, which is IBC's 8.49 Fv with the set's preload 1.57 Fv."""
    return preload * (1.0 + (n_load / n_other) ** (2.0 / 3.0)) ** 1.5


def set_rigidity_ratio(n_a, n_b):
    r"""Axial rigidity of a set of ``n_a`` against ``n_b`` matched bearings over that of two of them
    as a DB
    pair: both groups act while both are loaded, each of rigidity 3/2 (n K)^{2/3} F^{1/3}, at the
    set's preload (:func:`set_preload_ratio`): (n_a^{2/3} + n_b^{2/3}) / 2 * ratio^{1/3}.  2
    against 1: 1.43, 2 against 2: 2 (NSK p. 168: 1.46 and 1.96); 3 against 1: 1.79."""
    return (
        0.5 * (n_a ** (2.0 / 3.0) + n_b ** (2.0 / 3.0)) * set_preload_ratio(n_a, n_b) ** (1.0 / 3.0)
    )


def set_pressed_load(preload, load, n_load, n_other):
    r"""Load [N] on the group of ``n_load`` bearings an axial ``load`` >= 0 [N] presses, in a set of
    preload ``preload`` against ``n_other``: IBC's linear split (TI-I-5010.2/E Table 2.2: A = a0
    Fv + a1 Fae up to the unloading point), the line from the preload at no load to the lift-off
    load L (:func:`set_lift_off`) where the group carries it all, F beyond.  Hertz's exact split is
    convex in F, so the line lies above it (by at most 7 % of the load for 3 against 1):
    conservative for the life."""
    lift = set_lift_off(preload, n_load, n_other)
    return mx.if_else(load < lift, preload + load * (lift - preload) / lift, load)


def set_halves(preload, load, n_plus, n_minus):
    """Loads [N] on the '+' group (``n_plus`` bearings) and the '-' group of a preloaded set under a
    signed axial ``load`` [N] (+ presses the '+' group): the pressed group :func:`set_pressed_load`,
    the other that less the load (zero after lift-off).  Returns (F_+, F_-)."""
    plus = set_pressed_load(preload, mx.fmax(load, 0.0), n_plus, n_minus)
    minus = set_pressed_load(preload, mx.fmax(-load, 0.0), n_minus, n_plus)
    pressed_plus = load >= 0.0
    return (
        mx.if_else(pressed_plus, plus, minus + load),
        mx.if_else(pressed_plus, plus - load, minus),
    )


def hertz_set_halves(preload, load, n_plus, n_minus):
    r"""Loads [N] on the '+' group (``n_plus`` bearings) and the '-' group of a preloaded set under
    a signed axial ``load`` [N] (+ presses the '+' group) by Hertz's contact law itself, as the
    set's maker rates it (NSK super-precision bearings pp. 110-111: each group's load from the
    bearings' load-deflection law): both groups carry the preload F at no load, each bearing
    deflects as (Q / K)^{2/3}, the pressed group's contacts close by the shift u the other's open.
    With r = (n_other / n_load)^{2/3} (the pressed group's preload deflection over the other's) and
    s = u over the other group's:

    .. math:: (1 + s / r)^{3/2} - (1 - s)_+^{3/2} = |F_{ext}| / F

    solved by fixed Newton steps (floats, arrays and CasADi symbols alike), lift-off at s = 1, i.e.
    at F (1 + (n_load/n_other)^{2/3})^{3/2} (:func:`set_lift_off`: IBC Table 2.2's X Fv).  Below the
    linear split of :func:`set_halves` everywhere (the exact split is convex).  Returns (F_+,
    F_-)."""
    f = mx.fabs(load) / mx.fmax(preload, 1e-12)
    pressed_plus = load >= 0.0
    n_load = mx.if_else(pressed_plus, n_plus, n_minus)
    n_other = mx.if_else(pressed_plus, n_minus, n_plus)
    r = (n_other / n_load) ** (2.0 / 3.0)
    lift = (1.0 + 1.0 / r) ** 1.5
    # past lift-off the pressed group carries it all: (1 + s / r)^{3/2} = f in closed form; below it
    # Newton from the small-load slope, the opened contact floored at 1e-6 of its preload deflection
    # (a load error below 1e-9 F; bounded derivatives for the solvers)
    after = r * (mx.fmax(f, 1e-12) ** (2.0 / 3.0) - 1.0)
    s = mx.fmin(f / (1.5 / r + 1.5), 1.0)
    if mx.is_symbolic(s, r, f) or not np.ndim(s):
        for _ in range(HERTZ_STEPS):
            s = _newton_step(s, r, f)
    else:
        s = _newton_array(s, r, f, lift)
    s = mx.if_else(f >= lift, after, s)
    # floored above 0: pow(0, 3/2)'s second derivative is not a number (the solvers' Hessian)
    pressed = preload * mx.fmax(1.0 + s / r, 1e-12) ** 1.5
    other = preload * mx.fmax(1.0 - s, 1e-12) ** 1.5
    return (
        mx.if_else(pressed_plus, pressed, other),
        mx.if_else(pressed_plus, other, pressed),
    )


def _newton_step(s, r, f):
    """One Newton step of the Hertz split's equation in s (see :func:`hertz_set_halves`)."""
    lo = mx.fmax(1.0 - s, 1e-6)
    hi = mx.fmax(1.0 + s / r, 1e-6)
    # x^{3/2} as x sqrt(x): the square roots serve the derivative too (a general power per element
    # is several times slower on arrays)
    root_hi, root_lo = mx.sqrt(hi), mx.sqrt(lo)
    g = hi * root_hi - lo * root_lo - f
    dg = 1.5 / r * root_hi + 1.5 * root_lo
    return mx.fmin(mx.fmax(s - g / dg, 0.0), 1.0)


def _newton_array(s, r, f, lift):
    """:data:`HERTZ_STEPS` Newton steps on arrays: an element whose step moves it by less than
    1e-15 (s lies in [0, 1]: converged to rounding) leaves the loop; the elements past lift-off
    (whose s the closed form replaces) do not enter it.  The search's arrays hold every bearing
    and preload: most elements settle in a few steps."""
    s, r, f, lift = np.broadcast_arrays(s, r, f, lift)
    out = np.array(s, dtype=float).reshape(-1)
    r, f = r.reshape(-1), f.reshape(-1)
    active = np.flatnonzero(~(f >= lift.reshape(-1)))
    for _ in range(HERTZ_STEPS):
        if not active.size:
            break
        old = out[active]
        new = _newton_step(old, r[active], f[active])
        out[active] = new
        active = active[np.abs(new - old) > 1e-15]
    return out.reshape(s.shape)


# NSK's printed split for sets of as many bearings each way: the pressed group takes 2/3 of the
# external load, the other gives up 1/3, until the other unloads at 3 x the set's preload
NSK_PRESSED_SHARE = 2.0 / 3.0
NSK_LIFT_OFF = 3.0


def nsk_pair_halves(preload, load):
    r"""Loads [N] on the '+' and '-' groups of a preloaded set of as many bearings each way (DB/DF,
    DBB/DFF) under a signed axial ``load`` [N] (+ presses the '+' group), as NSK prints it (NSK
    super-precision bearings, "life of preloaded angular-contact ball bearings": DB p. 140, F_a1 =
    2/3 F_ae + F_ap, F_a2 = F_ap - 1/3 F_ae, F_a1 = F_ae once F_a2 would fall below 0; DBB p. 141,
    per bearing 1/3 F_ae + F_ap and F_ap - 1/6 F_ae, the same for the group of two):

    .. math:: F_{pressed} = F + \tfrac{2}{3} |F_{ext}| \ (|F_{ext}| < 3 F),
              \quad |F_{ext}| \text{ beyond};\quad F_{other} = F_{pressed} - |F_{ext}|

    ``preload``: the set's preload F [N] (each group's load at no external load).  NSK's line
    meets the Hertz law (:func:`hertz_set_halves`) at no load and lies above it elsewhere (it
    unloads the other group at 3 F, Hertz at 2.83 F).  Returns (F_+, F_-)."""
    mag = mx.fabs(load)
    pressed = mx.if_else(mag < NSK_LIFT_OFF * preload, preload + NSK_PRESSED_SHARE * mag, mag)
    return pressed + mx.fmin(load, 0.0), pressed - mx.fmax(load, 0.0)
