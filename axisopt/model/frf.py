"""Dynamic compliance X/F of the table over frequency at stroke start, middle and end (numpy only).

The lumped motor - coupling - screw - table chain of
:func:`axisopt.physics.dynamics.drive_train_compliance` with the evaluation's own stiffness, mass
and damper values at each position:

* motor and screw-side inertias: :func:`axisopt.model.modes.drive_inertias`;
* coupling k_c (torsional) with steel structural damping 2 zeta sqrt(k_c J_s), zeta = STEEL_DAMPING
  (seed Table 5);
* axial spring ``k_drive`` (the chain without the coupling) with the nut and bearing dampers
  referred to the chain (:func:`axisopt.model.modes.dampers`);
* table mass ``m_eff`` on the guide blocks' dampers.

With the motor free (default) the modes are ``f_axial_torsional`` and ``f_axial_torsional_2``.  The
second is mostly rotor against screw across the coupling: its pole nearly cancels with a zero of
X/F, so at the model's damping it shows at the table as a small kink, not a peak (lightly damped,
``damping_scale`` << 1, it peaks).  The first peak lies below f_axial_torsional by the damping
(about 2.5 % for problems/teaching_design.yaml).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..physics import dynamics as pdy
from .chain import drive_torsional_stiffness
from .function import Evaluation, design_params
from .modes import STEEL_DAMPING, dampers, drive_inertias

__all__ = ["frf", "frf_positions", "N_FREQUENCIES", "F_MIN"]

N_FREQUENCIES = 800
F_MIN = 5.0  # [Hz] lower end of the default grid


def frf_positions(ev: Evaluation) -> list[int]:
    """Indices into ev.x of stroke start, the point nearest mid-stroke and stroke end."""
    s = ev.x - ev.design.axis.start_offset
    mid = int(np.argmin(np.abs(s - ev.design.axis.stroke / 2.0)))
    return [0, mid, len(ev.x) - 1]


def chain_at(ev: Evaluation, p: dict, i: int) -> dict:
    """Springs, masses and dampers of the drive-train model at position index i (SI)."""
    j_m, j_s = drive_inertias(p)
    k_c = float(drive_torsional_stiffness(p))  # coupling and reduction in series
    chain = {
        "k_total": ev.at("k_total", i),
        "k_nut": float(ev["k_nut"]),
        "k_bearing": float(ev["k_bearing"]),
    }
    c = dampers(p, chain)
    return {
        "motor_inertia": float(j_m),
        "screw_inertia": float(j_s),
        "coupling_stiffness": k_c,
        "axial_stiffness": ev.at("k_drive", i),
        "mass": ev.at("m_eff", i),
        "lead": float(p["lead"]),
        "table_damping": float(p["guide_blocks"] * p["guide_damping"]),
        "chain_damping": float(c["c_nut"] + c["c_bearings"]),
        "coupling_damping": 2.0 * STEEL_DAMPING * math.sqrt(k_c * float(j_s)),
    }


def _modes(ev: Evaluation, m: dict, i: int, motor_held: bool) -> tuple[float, float]:
    if not motor_held:
        return ev.at("f_axial_torsional", i), ev.at("f_axial_torsional_2", i)
    f1, f2 = pdy.axial_torsional_frequencies(
        m["screw_inertia"], m["coupling_stiffness"], m["axial_stiffness"], m["mass"], m["lead"]
    )
    return float(f1), float(f2)


def _check_freqs(freqs) -> np.ndarray:
    try:
        f = np.asarray(freqs, dtype=float)
    except (TypeError, ValueError):
        raise InputError("frequencies must be numbers [Hz]") from None
    if f.ndim != 1 or f.size == 0:
        raise InputError("frequencies must be a non-empty list [Hz]")
    if not np.all(np.isfinite(f)) or np.any(f <= 0.0):
        raise InputError("frequencies must be finite and positive [Hz]")
    return f


def frf(
    ev: Evaluation, freqs=None, *, motor_held: bool = False, damping_scale: float = 1.0
) -> dict:
    """Table compliance X/F over frequency at stroke start, middle and end.

    ev         : an evaluation (:func:`axisopt.model.evaluate`)
    freqs      : frequencies [Hz], 1-D, positive; default 800 log-spaced points from 5 Hz to 3x the
                 highest second mode of the three positions
    motor_held : fix the motor rotor (static compliance 1/k_total); default free (position loop far
        slower)
    damping_scale : multiplies every damper (1: the model's values; small: to see the undamped
        modes)
    Returns {"design", "motor_held", "frequency_Hz", "positions": [per position: "index",
    "position_mm", "compliance_m_per_N" (complex), "magnitude_um_per_N", "phase_deg" (unwrapped),
    "modes_Hz" (f1, f2)]}.
    """
    if not (math.isfinite(damping_scale) and damping_scale >= 0.0):
        raise InputError(f"damping scale must be a finite number >= 0, got {damping_scale}")
    p = design_params(ev.design)
    idx = frf_positions(ev)
    models = [chain_at(ev, p, i) for i in idx]
    for m in models:
        for k in ("table_damping", "chain_damping", "coupling_damping"):
            m[k] *= damping_scale
    modes = [_modes(ev, m, i, motor_held) for m, i in zip(models, idx)]
    if freqs is None:
        f_top = 3.0 * max(f2 for _, f2 in modes)
        f = np.logspace(math.log10(F_MIN), math.log10(max(f_top, 10.0 * F_MIN)), N_FREQUENCIES)
    else:
        f = _check_freqs(freqs)
    out = []
    for i, m, md in zip(idx, models, modes):
        h = np.asarray(pdy.drive_train_compliance(f, motor_held=motor_held, **m), dtype=complex)
        out.append(
            {
                "index": i,
                "position_mm": float((ev.x[i] - ev.design.axis.start_offset) * 1e3),
                "compliance_m_per_N": h,
                "magnitude_um_per_N": np.abs(h) * 1e6,
                "phase_deg": np.degrees(np.unwrap(np.angle(h))),
                "modes_Hz": md,
            }
        )
    return {
        "design": ev.design.name,
        "motor_held": bool(motor_held),
        "frequency_Hz": f,
        "positions": out,
    }
