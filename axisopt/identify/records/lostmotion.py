"""Lost motion (backlash) and windup between motor and table, measured by two encoders: a time
record with a ``motor_position`` column beside the table's ``position`` (:mod:`.timerecord`).

The motor-table difference e = motor_q - q carries the gap and the transmission's compliance.  The
motor side's own equation gives the force the transmission carries, S = f - m1 a1 - F1(v1), the
effort f less the motor side's inertia (m1, acceleration a1 of the motor encoder) and its own
friction F1 = Fc1 sgn(v1) + Fv1 v1 (motor and support bearings, seals: it acts before the gap),
and the transmission answers with
:math:`e = e_0 + (b/2)\\operatorname{sgn}S + S/k - (c/k)\\,\\dot e` (lash with a linear spring
and damper: M. Nordin, P.-O. Gutman, "Controlling mechanical systems with backlash -- a survey",
Automatica 38 (2002) 1633-1649).  Left in S, the motor-side friction reads as windup: the
stiffness comes out high by about (Fc1 + Fc2) / Fc2 and the gap is pulled towards it (both share
sgn v in steady motion).  Fc1 and Fv1 are fitted with the rest; what tells them from the windup is
the reversal: the table stands while the motor, past the gap, winds the transmission up against
the table's breakaway (the motor side moves one way at a nearly constant Fc1 while S grows from 0),
so the rows are those where the motor moves (not only those where the table does), and the
decelerations, where S and v1 have opposite signs.  It is judged like an effect: significant,
plausible and better on held-out rows by the time records' selection rule's gain
(:data:`.selection.TIME_RULE`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..selection import TIME_RULE
from .estimators import Estimate
from .regression import SIGN_KEEP, VMIN_REL, Rows, signals
from .signal import lowpass

# [m] table travel: a preloaded ball-screw axis loses at most a few um; a lost motion above 0.2 mm
# is a loose coupling, key or nut, reported as implausible, not fitted
LOST_MOTION_MAX = 0.2e-3
LOST_MOTION_T = 5.0  # the lost motion's estimate must be this many standard deviations above zero
# the columns of the lost-motion regression: offset, gap, effort, motor acceleration, stretch
# rate, motor-side Coulomb and viscous friction
COLUMNS = ("e0", "b/2", "1/k", "-m1/k", "-c/k", "-Fc1/k", "-Fv1/k")
GAP = 1  # the gap's column
STARTS = 4  # the fixed-point iteration starts from this many grid points
TRIM = 5.0  # rows off the fit by more than this many robust standard deviations are left out


@dataclass
class LostMotion:
    """Motor encoder against table position: e = motor_q - q = e0 + (b/2) sgn(S) + S/k - (c/k)
    de/dt, S = f - m1 a1 - Fc1 sgn(v1) - Fv1 v1 the force the transmission carries (f the effort,
    a1 and v1 the motor side's acceleration and speed, m1 its mass or inertia, Fc1 and Fv1 its own
    friction)."""

    width: float  # b, the lost motion [record coordinate]
    width_std: float
    stiffness: float  # k [effort / coordinate]; inf when the windup is not measurable
    motor_mass: float  # m1 [mass or inertia]
    rms_before: float  # [coordinate] held-out RMS of e with only offset and windup (no lost motion)
    rms_after: float
    gain: float  # [%]
    reason: str = ""  # why it is not accepted ('' when it is)
    # the motor side's own friction, taken out of the transmitted force [effort, effort s/coord]
    motor_coulomb: float = 0.0
    motor_viscous: float = 0.0
    stiffness_std: float = 0.0  # [effort / coordinate]

    @property
    def accepted(self) -> bool:
        return not self.reason


def _motor_signals(rows: Rows) -> tuple:
    """((e, a1, de, v1, f) low-passed at full rate, the rows where the motor moves one way for a
    whole filter window), cached with the rows: the table may stand there (winding up at a
    reversal)."""
    if "lost_motion" in rows.sig:
        return rows.sig["lost_motion"]
    rec, proc = rows.record, rows.proc
    segs = rec.segments
    sm, se = signals(rec.motor_q, proc, segs), signals(rec.motor_q - rec.q, proc, segs)
    v1 = sm["v"]
    # the effort the motor side carries: the drive's own, without a force on the table
    f = rec.effort
    full = np.column_stack([se["q"], sm["a"], se["v"], v1, f])
    dec = lowpass(full, proc.fs, proc.fdec, segments=segs)
    sf = lowpass(np.sign(v1), proc.fs, proc.fdec, segments=segs)
    edge = int(2.0 * proc.fs / min(proc.fc, proc.fdec)) + proc.nd
    idx = np.concatenate(
        [np.arange(a + edge, b - edge, proc.nd) for a, b in segs or ((0, rec.n),)]
    ).astype(int)
    w = int(proc.fs / proc.fdec)
    slow = (np.abs(v1) < VMIN_REL * float(np.max(np.abs(v1)))).astype(float)
    slow = np.convolve(slow, np.ones(2 * w + 1), mode="same") > 0
    idx = idx[~slow[idx] & (np.abs(sf[idx]) >= SIGN_KEEP)]
    rows.sig["lost_motion"] = dec, idx
    return rows.sig["lost_motion"]


def lost_motion_rows(rows: Rows, motor: tuple, fmin: float):
    """(e, columns :data:`COLUMNS`) at the rows where the motor moves and the transmitted force
    |S| = |f - m1 a1 - Fc1 sgn v1 - Fv1 v1| > fmin (the side of the gap is certain there);
    ``motor`` = (m1, Fc1, Fv1)."""
    full, idx = _motor_signals(rows)
    m1, fc1, fv1 = motor
    S_full = full[:, 4] - m1 * full[:, 1] - fc1 * np.sign(full[:, 3]) - fv1 * full[:, 3]
    # the side of the gap must hold for a whole filter window: a row beside a crossing of the gap
    # (S through zero, the motor flying across) carries the filtered jump
    proc, segs = rows.proc, rows.record.segments
    sure = np.abs(lowpass(np.sign(S_full), proc.fs, proc.fdec, segments=segs))[idx] >= SIGN_KEEP
    e, a1, de, v1, f = full[idx].T
    s1 = np.sign(v1)
    S = S_full[idx]
    ok = (np.abs(S) > fmin) & sure
    G = np.column_stack([np.ones(ok.sum()), np.sign(S[ok]), f[ok], a1[ok], de[ok], s1[ok], v1[ok]])
    return e[ok], G


def solve(G: np.ndarray, e: np.ndarray) -> np.ndarray:
    """Least squares of e on G with the motor side's friction held non-negative (Fc1, Fv1 >= 0: a
    column whose friction comes out negative is dropped, its coefficient 0, and the rest refitted):
    a negative friction would only trade against the gap, which shares its sign in steady
    motion."""
    cols = list(range(G.shape[1]))
    th = np.zeros(G.shape[1])
    for _ in range(3):
        sub, *_ = np.linalg.lstsq(G[:, cols], e, rcond=None)
        th[:] = 0.0
        th[cols] = sub
        neg = [j for j in (5, 6) if j in cols and th[2] > 0 and th[j] > 0]
        if not neg:
            break
        cols = [j for j in cols if j not in neg]
    return th


def _motor_side(th: np.ndarray, fallback: tuple, M: float) -> tuple:
    """(m1, Fc1, Fv1) from a fit's coefficients (``fallback`` when 1/k is not positive)."""
    if not th[2] > 0:
        return fallback
    m1 = float(np.clip(-th[3] / th[2], 0.0, M))
    return m1, max(float(-th[5] / th[2]), 0.0), max(float(-th[6] / th[2]), 0.0)


def lost_motion(
    est_rows: Rows, val_rows: list, base: Estimate, noise: float, lead_m: float = 0.0
) -> LostMotion | None:
    """The lost motion and windup between motor and table when every record has a ``motor_position``
    column; judged like an effect: significant, plausible and better on the held-out rows
    (validation runs, else the estimation run's second half).  m1, Fc1 and Fv1 enter linearly but
    also decide which side of the gap each row is on: a coarse grid in m1 (no motor friction), then
    the fit's own values until the sides stop changing."""
    if est_rows.record.motor_q is None or any(v.record.motor_q is None for v in val_rows):
        return None
    M = max(base.value("M"), 0.0)
    fmin = 3.0 * noise

    def fit(motor):
        e, G = lost_motion_rows(est_rows, motor, fmin)
        if len(e) < 20:
            return None
        th = solve(G, e)
        # a row on the wrong side of the gap (beside a crossing) is off by up to b: trimmed
        r = e - G @ th
        ok = np.abs(r) <= TRIM * 1.4826 * float(np.median(np.abs(r))) + 1e-300
        if ok.sum() >= 20 and not ok.all():
            e, G = e[ok], G[ok]
            th = solve(G, e)
        return float(np.mean((e - G @ th) ** 2)), motor, th, e, G

    # the sides of the gap move with m1 and Fc1 (the fit's own values need not lead out of a wrong
    # assignment: the motor friction and the gap share sgn v in steady motion): a grid over both,
    # Fc1 up to the axis's whole Coulomb friction, judged by the mean squared residual
    fc = max(abs(base.value("Fc")), 0.0)
    grid = [(m, c, 0.0) for m in np.linspace(0.0, M, 11) for c in np.linspace(0.0, fc, 9)]
    fits = [f for f in map(fit, grid) if f is not None]
    if not fits:
        return None
    scale = (max(M, 1e-12), max(fc, 1e-12), max(abs(base.value("Fv")), 1e-12))

    def settle(best):
        """The fit's own (m1, Fc1, Fv1) until the sides stop changing (the best fit seen when
        they flip between two sets)."""
        seen = [best]
        for _ in range(30):
            motor = _motor_side(best[2], best[1], M)
            if max(abs(a - b) / s for a, b, s in zip(motor, best[1], scale)) <= 1e-6:
                return best
            nxt = fit(motor)
            if nxt is None:
                break
            best = nxt
            seen.append(nxt)
        return min(seen, key=lambda f: f[0])

    # several starts (the best grid point of each Fc1 level): a wrong start can settle where the
    # gap and Fc1 trade against each other
    starts = {}
    for f in fits:
        c = f[1][1]
        if c not in starts or f[0] < starts[c][0]:
            starts[c] = f
    firsts = sorted(starts.values(), key=lambda f: f[0])[:STARTS]
    # a negative gap is no lost motion (it would be an overlap the transmission cannot have): a
    # settled fit with b >= 0 is preferred when the record leaves both nearly as good
    settled = [settle(f) for f in firsts]
    best = min(settled, key=lambda f: (f[2][GAP] < 0.0, f[0]))
    mse, motor, th, e, G = best
    rss = mse * len(e)
    dof = max(len(e) - G.shape[1], 1)
    cov = rss / dof * np.linalg.pinv(G.T @ G)
    half, half_std = float(th[GAP]), float(math.sqrt(max(cov[GAP, GAP], 0.0)))
    k = 1.0 / th[2] if th[2] > 0 else float("inf")
    k_std = float(math.sqrt(max(cov[2, 2], 0.0))) * k * k if th[2] > 0 else float("inf")
    m1, fc1, fv1 = _motor_side(th, motor, M)
    if val_rows:
        held = [lost_motion_rows(v, motor, fmin) for v in val_rows]
        fit_e, fit_G = e, G
    else:  # no validation run: fit on the first half, judge on the second
        n2 = len(e) // 2
        held, fit_e, fit_G = [(e[n2:], G[n2:])], e[:n2], G[:n2]
    th_full = solve(fit_G, fit_e)
    # every column but the lost motion's (the friction columns keep their index: 5 and 6 -> 4, 5)
    other = [i for i in range(len(COLUMNS)) if i != GAP]
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
    return LostMotion(width, width_std, k, m1, before, after, gain, reason, fc1, fv1, k_std)
