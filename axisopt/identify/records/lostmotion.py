"""Lost motion (backlash) and windup between motor and table, measured by two encoders: a time
record with a ``motor_position`` column beside the table's ``position`` (:mod:`.timerecord`).

The motor-table difference e = motor_q - q carries the gap and the transmission's compliance,
:math:`e = e_0 + (b/2)\\operatorname{sgn}F + F/k - (c/k)\\,\\dot e`, F = f - m1 a1 the force the
transmission carries (lash with a linear spring and damper: M. Nordin, P.-O. Gutman, "Controlling
mechanical systems with backlash -- a survey", Automatica 38 (2002) 1633-1649).  It is judged like
an effect: significant, plausible and better on held-out rows by the time records' selection rule's
gain (:data:`.selection.TIME_RULE`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..selection import TIME_RULE
from .estimators import Estimate
from .regression import Rows, decimate, signals

# [m] table travel: a preloaded ball-screw axis loses at most a few um; a lost motion above 0.2 mm
# is a loose coupling, key or nut, reported as implausible, not fitted
LOST_MOTION_MAX = 0.2e-3
LOST_MOTION_T = 5.0  # the lost motion's estimate must be this many standard deviations above zero


@dataclass
class LostMotion:
    """Motor encoder against table position: e = motor_q - q = e0 + (b/2) sgn(F) + F/k - (c/k)
    de/dt, F = f - m1 a1 the force the transmission carries (f the effort, a1 the motor side's
    acceleration, m1 the motor-side mass or inertia, found by a 1-D search)."""

    width: float  # b, the lost motion [record coordinate]
    width_std: float
    stiffness: float  # k [effort / coordinate]; inf when the windup is not measurable
    motor_mass: float  # m1 [mass or inertia]
    rms_before: float  # [coordinate] held-out RMS of e with only offset and windup (no lost motion)
    rms_after: float
    gain: float  # [%]
    reason: str = ""  # why it is not accepted ('' when it is)

    @property
    def accepted(self) -> bool:
        return not self.reason


def lost_motion_rows(rows: Rows, m1: float, fmin: float):
    """(e, columns [1, sgn F, f, a1, de/dt]) at the rows where |F| = |f - m1 a1| > fmin (the side of
    the gap is certain there): e = e0 + (b/2) sgn F + f/k - (m1/k) a1 - (c/k) de/dt."""
    rec = rows.record
    # e, the motor side's own acceleration and de/dt, filtered as the effort is
    if "lost_motion" not in rows.sig:
        segs = rec.segments
        sm, se = (
            signals(rec.motor_q, rows.proc, segs),
            signals(rec.motor_q - rec.q, rows.proc, segs),
        )
        rows.sig["lost_motion"] = decimate(
            np.column_stack([se["q"], sm["a"], se["v"]]), rows.proc, rows.keep, segs
        )
    e, a1, de = rows.sig["lost_motion"].T
    F = rows.y - m1 * a1
    ok = np.abs(F) > fmin
    return e[ok], np.column_stack([np.ones(ok.sum()), np.sign(F[ok]), rows.y[ok], a1[ok], de[ok]])


def lost_motion(
    est_rows: Rows, val_rows: list, base: Estimate, noise: float, lead_m: float = 0.0
) -> LostMotion | None:
    """The lost motion and windup between motor and table when every record has a ``motor_position``
    column; judged like an effect: significant, plausible and better on the held-out rows
    (validation runs, else the estimation run's second half).  m1 enters linearly (the a1 column)
    but also decides which side of the gap each row is on: a coarse grid, then the fit's own m1
    until the sides stop changing."""
    if est_rows.record.motor_q is None or any(v.record.motor_q is None for v in val_rows):
        return None
    M = max(base.value("M"), 0.0)
    fmin = 3.0 * noise

    def fit(m1):
        e, G = lost_motion_rows(est_rows, m1, fmin)
        if len(e) < 20:
            return None
        th, *_ = np.linalg.lstsq(G, e, rcond=None)
        return float(np.sum((e - G @ th) ** 2)), m1, th, e, G

    fits = [f for f in (fit(m) for m in np.linspace(0.0, M, 21)) if f is not None]
    if not fits:
        return None
    best = min(fits, key=lambda f: f[0])
    for _ in range(20):
        th = best[2]
        m1 = float(np.clip(-th[3] / th[2], 0.0, M)) if th[2] > 0 else best[1]
        if abs(m1 - best[1]) <= 1e-6 * max(M, 1e-12):
            break
        nxt = fit(m1)
        if nxt is None or nxt[0] > best[0]:
            break
        best = nxt
    rss, m1, th, e, G = best
    dof = max(len(e) - G.shape[1], 1)
    cov = rss / dof * np.linalg.pinv(G.T @ G)
    half, half_std = float(th[1]), float(math.sqrt(max(cov[1, 1], 0.0)))
    k = 1.0 / th[2] if th[2] > 0 else float("inf")
    if val_rows:
        held = [lost_motion_rows(v, m1, fmin) for v in val_rows]
        fit_e, fit_G = e, G
    else:  # no validation run: fit on the first half, judge on the second
        n2 = len(e) // 2
        held, fit_e, fit_G = [(e[n2:], G[n2:])], e[:n2], G[:n2]
    th_full, *_ = np.linalg.lstsq(fit_G, fit_e, rcond=None)
    other = [0, 2, 3, 4]  # every column but the lost motion's
    th_base, *_ = np.linalg.lstsq(fit_G[:, other], fit_e, rcond=None)
    r_full = np.concatenate([he - hG @ th_full for he, hG in held])
    r_base = np.concatenate([he - hG[:, other] @ th_base for he, hG in held])
    before, after = float(np.sqrt(np.mean(r_base**2))), float(np.sqrt(np.mean(r_full**2)))
    gain = TIME_RULE.gain(before, after)
    width, width_std = 2.0 * half, 2.0 * half_std
    to_q = (
        1.0
        if est_rows.record.quantity == "force"
        else (2.0 * math.pi / lead_m if lead_m > 0 else float("inf"))
    )
    lim = LOST_MOTION_MAX * to_q
    reason = ""
    if width <= LOST_MOTION_T * width_std or width <= 0.0:
        reason = (
            f"not significant (b = {width:.3g} +- {width_std:.2g}, below {LOST_MOTION_T:g} "
            "standard deviations)"
        )
    elif gain < TIME_RULE.min_gain:
        reason = f"held-out gain {gain:.1f} % < {TIME_RULE.min_gain:g} %"
    elif width > lim:
        reason = (
            "would need a lost motion above 0.2 mm of table travel (a loose coupling, key or nut, "
            "not backlash)"
        )
    return LostMotion(width, width_std, k, m1, before, after, gain, reason)
