"""The position loop of a time record, fitted from its ``reference`` column: its structure, PD or a
P-PI cascade, stated by the design (``axis.controller``) or chosen from the record, and its gains.

* PD: :math:`u = K_p e + K_d \\dot e + K_{v,ff} \\dot r + K_{a,ff} \\ddot r`, e = r - q.
* P-PI cascade (position P, velocity PI; velocity feed-forward into the velocity command):
  :math:`u = K_v (K_x e + \\dot r - \\dot q) + (K_v/T_i) \\int (K_x e + \\dot r - \\dot q)\\,dt`,
  which is :math:`u = K_p e + K_d \\dot e + K_i \\int e\\,dt + u_0 + \\ldots` with
  :math:`K_p = K_v (K_x + 1/T_i)`, :math:`K_d = K_v`, :math:`K_i = K_v K_x / T_i` and u_0 the
  integrator's state where the record (or a window of a long record) starts.  K_x and 1/T_i enter
  the law alike: they are the two roots of :math:`z^2 - (K_p/K_d) z + K_i/K_d = 0`; the smaller is
  named K_x (the usual tuning puts the velocity loop's integral corner above the position gain,
  e.g. Siemens SINAMICS: position gain 1-3 (m/min)/mm = 17-50 1/s against T_n 10-30 ms).

Without a stated structure, the P-PI cascade is named when the integral term lowers the BIC of the
fit by more than :data:`BIC_MARGIN` and halves its residual at least (a PD loop leaves nothing for
it), with a positive integral gain; else PD.  A stated structure is fitted as stated; when the
other fits the record far better the controller carries a note saying so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..selection import TIME_RULE
from .regression import Rows
from .signal import derivatives, lowpass

STRUCTURES = {
    "pd": "PD position controller",
    "p_pi_cascade": "P-PI cascade (position P, velocity PI)",
}
BIC_MARGIN = 10.0
RSS_SHARE = 0.5  # the integral term must at least halve the PD fit's residual


@dataclass
class Controller:
    """u = Kp (r - q) + Kd (r' - q') + Kv r' + Ka r'' [+ Ki int(r - q) dt + u0] (SI of the record's
    coordinate)."""

    kp: float
    kd: float
    kv: float
    ka: float
    r2: float
    structure: str = "pd"
    ki: float = 0.0
    u0: tuple = ()  # the integrator's state at each segment's start
    source: str = "fitted"  # 'fitted' (chosen from the record) or 'design' (axis.controller)
    note: str = ""  # a stated structure the record contradicts
    # both fits' coefficients: PD (Kp, Kd, Kv, Ka) and with the integral (.., Ki)
    fits: tuple = ((), ())
    # [%] the integral term's gain in the effort's RMS on the validation runs (None: none)
    heldout_gain: float | None = None

    @property
    def cascade(self) -> tuple | None:
        """(Kx [1/s], Kv, Ti [s]) of a P-PI cascade (None for PD)."""
        if self.structure != "p_pi_cascade" or not self.kd > 0:
            return None
        s, p = self.kp / self.kd, self.ki / self.kd
        disc = math.sqrt(max(s * s - 4.0 * p, 0.0))
        kx, wi = (s - disc) / 2.0, (s + disc) / 2.0
        return kx, self.kd, (1.0 / wi if wi > 0 else float("inf"))

    def as_dict(self) -> dict:
        out = {
            "structure": self.structure,
            "source": self.source,
            "Kp": self.kp,
            "Kd": self.kd,
            "Kv_ff": self.kv,
            "Ka_ff": self.ka,
            "R2": self.r2,
        }
        casc = self.cascade
        if casc is not None:
            out.update(Ki=self.ki, Kx_per_s=casc[0], Kv=casc[1], Ti_s=casc[2])
        if self.note:
            out["note"] = self.note
        if self.heldout_gain is not None:
            out["integral_heldout_gain_percent"] = self.heldout_gain
        return out


def _columns(rows: Rows):
    """(PD columns, integral column, one constant per segment, effort, inner rows)."""
    rec, proc = rows.record, rows.proc
    segs = rec.segments or ((0, rec.n),)
    r, dr, ddr = derivatives(rec.reference, proc.fs, proc.fc, 2, rec.segments)
    e = r - rows.sig["q"]
    X = np.column_stack([e, dr - rows.sig["v"], dr, ddr])
    ie = np.concatenate([np.cumsum(e[a:b]) / proc.fs for a, b in segs])
    ones = np.zeros((rec.n, len(segs)))
    for j, (a, b) in enumerate(segs):
        ones[a:b, j] = 1.0
    y = lowpass(rec.effort, proc.fs, proc.fc, segments=rec.segments)
    edge = int(2.0 * proc.fs / proc.fc)
    inner = np.concatenate([np.arange(a + edge, b - edge) for a, b in segs])
    return X, ie, ones, y, inner


def _fit(X, y):
    sc = np.linalg.norm(X, axis=0)
    sc[sc == 0] = 1.0
    th, *_ = np.linalg.lstsq(X / sc, y, rcond=None)
    th = th / sc
    res = y - X @ th
    return th, float(res @ res)


def fit_controller(rows: Rows, structure: str | None = None) -> Controller | None:
    """The loop fitted to the record (None without a reference or with a constant effort);
    ``structure`` ('pd' | 'p_pi_cascade') as the design states it, None: chosen (module
    docstring)."""
    rec = rows.record
    if rec.reference is None:
        return None
    X, ie, ones, y, inner = _columns(rows)
    X, ie, ones, y = X[inner], ie[inner], ones[inner], y[inner]
    ss = float(np.sum((y - y.mean()) ** 2))
    if not ss > 0.0:  # a constant effort explains nothing about the controller
        return None
    th0, rss0 = _fit(X, y)
    X1 = np.column_stack([X, ie, ones])
    th1, rss1 = _fit(X1, y)
    n = len(y)
    dbic = n * math.log(max(rss1, 1e-300) / max(rss0, 1e-300)) + (1 + ones.shape[1]) * math.log(n)
    pi_fits = dbic < -BIC_MARGIN and rss1 < RSS_SHARE * rss0 and th1[4] > 0.0
    chosen = structure or ("p_pi_cascade" if pi_fits else "pd")
    note = ""
    if structure == "pd" and pi_fits:
        note = (
            f"the design states a PD loop, but an integral term fits the record far better "
            f"(residual {rss1 / rss0:.2g} of the PD fit's): a P-PI cascade?"
        )
    elif structure == "p_pi_cascade" and not th1[4] > 0.0:
        note = "the design states a P-PI cascade, but the record shows no positive integral gain"
    fits = (tuple(map(float, th0)), tuple(map(float, th1[:5])))
    if chosen == "pd":
        return Controller(
            *map(float, th0), 1.0 - rss0 / ss, "pd", source=_src(structure), note=note, fits=fits
        )
    kp, kd, kv, ka, ki = map(float, th1[:5])
    return Controller(
        kp,
        kd,
        kv,
        ka,
        1.0 - rss1 / ss,
        "p_pi_cascade",
        ki,
        tuple(map(float, th1[5:])),
        _src(structure),
        note,
        fits,
    )


def heldout_gain(ctrl: Controller, val_rows: list) -> float | None:
    """[%] how much the integral term lowers the RMS of the effort the loop predicts on the
    validation runs (each run's integrator state at its start fitted, the gains not): the held-out
    judge of the structure.  None without validation runs or a reference."""
    th0, th1 = (np.asarray(t) for t in ctrl.fits)
    if not len(th0) or not val_rows or any(v.record.reference is None for v in val_rows):
        return None
    r0, r1 = [], []
    for v in val_rows:
        X, ie, ones, y, inner = _columns(v)
        X, ie, ones, y = X[inner], ie[inner], ones[inner], y[inner]
        r0.append(y - X @ th0)
        y1 = y - np.column_stack([X, ie]) @ th1
        u0, *_ = np.linalg.lstsq(ones, y1, rcond=None)
        r1.append(y1 - ones @ u0)
    before = float(np.sqrt(np.mean(np.concatenate(r0) ** 2)))
    after = float(np.sqrt(np.mean(np.concatenate(r1) ** 2)))
    return TIME_RULE.gain(before, after)


def _src(structure):
    return "design" if structure else "fitted"


def control_effort(ctrl: Controller, r, dr, ddr, q, v, integ, seg: int) -> float:
    """The loop's effort at one sample (``integ``: the integral of r - q so far in the segment)."""
    u = ctrl.kp * (r - q) + ctrl.kd * (dr - v) + ctrl.kv * dr + ctrl.ka * ddr
    if ctrl.structure == "p_pi_cascade":
        u += ctrl.ki * integ + (ctrl.u0[seg] if seg < len(ctrl.u0) else 0.0)
    return u
