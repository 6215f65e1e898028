"""The servo block of ``evaluate`` (text and JSON) and the ``--ss`` file.  Nothing here prints."""

from __future__ import annotations

import math

import numpy as np

from ..fileio import atomic_file
from ..model.servo import CURRENT_LOOP_HZ, KV_M_MIN_PER_MM, ServoResult
from ..model.statespace import INPUT_UNITS, INPUTS, OUTPUT_UNITS, OUTPUTS, STATE_UNITS, STATES


def _num(v):
    v = float(v)
    return v if math.isfinite(v) else None


def servo_lines(r: ServoResult) -> list:
    """The servo block of ``evaluate`` (fits 100 columns)."""
    g = r.gains
    stable = (
        "stable"
        if all(r.stable)
        else "UNSTABLE at "
        + ", ".join(f"{p:.0f} mm" for p, s in zip(r.position_mm, r.stable) if not s)
    )
    notch = f", notch {g.notch_hz:.0f} Hz" if g.notch_hz > 0 else ""
    rows = [
        (
            "position-loop gain Kv",
            f"{g.kv:.1f} 1/s = {g.kv_m_min_per_mm:.2f} m/min/mm  (lowest axial mode "
            f"{g.f_n:.1f} Hz, motor held)",
        ),
        (
            "velocity loop",
            f"{g.velocity_hz:.1f} Hz, Ti {g.ti * 1e3:.2f} ms, filter {g.tf * 1e3:.2f} ms"
            f"{notch}, current {1 / (2 * math.pi * g.tc):.0f} Hz",
        ),
        (
            "following error v/Kv",
            f"{r.following_error_rapid * 1e3:.3f} mm at {r.rapid_speed * 60:.0f} m/min rapid, "
            f"{r.following_error_feed * 1e3:.3f} mm at {r.feed_speed * 60:.0f} m/min mean",
        ),
        (
            "closed loop on model",
            f"{stable} at {' / '.join(f'{p:.0f}' for p in r.position_mm)} mm (least damping "
            f"{min(r.min_damping) * 100:.1f} %)",
        ),
        (
            "  -3 dB bandwidth",
            "velocity "
            + " / ".join(f"{b:.0f}" for b in r.velocity_bandwidth_Hz)
            + " Hz, position "
            + " / ".join(f"{b:.1f}" for b in r.position_bandwidth_Hz)
            + " Hz",
        ),
    ]
    return (
        [
            "servo (semi-closed loop, no feedforward; FANUC f_n >= Kv, Yaskawa gain relations; "
            "model.servo)"
        ]
        + [f"  {k:<23}{v}" for k, v in rows]
        + [""]
    )


def servo_dict(r: ServoResult, kv_profile=None) -> dict:
    """JSON-ready servo values (1/s, m/min/mm, Hz, ms, mm, um/N)."""
    g = r.gains
    out = {
        "rule": g.rule,
        "kv_per_s": g.kv,
        "kv_m_per_min_per_mm": g.kv / KV_M_MIN_PER_MM,
        "lowest_axial_mode_Hz": g.f_n,
        "velocity_loop_gain_Hz": g.velocity_hz,
        "velocity_proportional_gain_Nms_per_rad": g.kvp,
        "integral_time_ms": g.ti * 1e3,
        "torque_filter_ms": g.tf * 1e3,
        "notch_Hz": g.notch_hz,
        "current_loop_Hz": 1.0 / (2.0 * math.pi * g.tc),
        "inertia_at_motor_kgm2": g.inertia,
        "rapid_speed_m_per_min": r.rapid_speed * 60.0,
        "feed_speed_m_per_min": r.feed_speed * 60.0,
        "following_error_rapid_mm": r.following_error_rapid * 1e3,
        "following_error_feed_mm": r.following_error_feed * 1e3,
        # per stroke position (not under a "positions" key: min_damping is signed, negative when
        # unstable)
        "closed_loop": [
            {
                "position_mm": p,
                "stable": bool(s),
                "min_damping": _num(z),
                "velocity_bandwidth_Hz": _num(v),
                "position_bandwidth_Hz": _num(b),
                "peak_compliance_um_per_N": _num(c),
            }
            for p, s, z, v, b, c in zip(
                r.position_mm,
                r.stable,
                r.min_damping,
                r.velocity_bandwidth_Hz,
                r.position_bandwidth_Hz,
                r.peak_compliance_um_per_N,
            )
        ],
    }
    if kv_profile is not None:
        out["kv_profile_per_s"] = [float(v) for v in np.asarray(kv_profile).ravel()]
    return out


def write_state_space(models: list, gains, path: str, *, held: list | None = None) -> None:
    """Write the open-loop models (and the tuned gains) as a numpy ``.npz``.

    Arrays: ``A`` (P, 6, 6), ``B`` (P, 6, 2), ``C`` (P, 3, 6), ``D`` (P, 3, 2) over the P positions
    ``position_mm``; ``A_held`` ... the same with the rotor held (its rows zero); names and units of
    the states, inputs and outputs; the servo gains (``kv_per_s``, ``velocity_loop_gain_Hz``,
    ``kvp_Nms_per_rad``, ``integral_time_s``, ``torque_filter_s``, ``notch_Hz``, ``current_loop_s``,
    ``lead_m``, ``ratio``).
    """
    arrays = {
        "A": np.stack([m.A for m in models]),
        "B": np.stack([m.B for m in models]),
        "C": np.stack([m.C for m in models]),
        "D": np.stack([m.D for m in models]),
        "position_mm": np.array([m.position_mm for m in models]),
        "states": np.array(STATES),
        "state_units": np.array(STATE_UNITS),
        "inputs": np.array(INPUTS),
        "input_units": np.array(INPUT_UNITS),
        "outputs": np.array(OUTPUTS),
        "output_units": np.array(OUTPUT_UNITS),
        "lead_m": np.array(models[0].lead),
        "ratio": np.array(models[0].ratio),
        "kv_per_s": np.array(gains.kv),
        "velocity_loop_gain_Hz": np.array(gains.velocity_hz),
        "kvp_Nms_per_rad": np.array(gains.kvp),
        "integral_time_s": np.array(gains.ti),
        "torque_filter_s": np.array(gains.tf),
        "notch_Hz": np.array(gains.notch_hz),
        "current_loop_s": np.array(gains.tc),
        "current_loop_Hz_default": np.array(CURRENT_LOOP_HZ),
    }
    if held:
        for k in "ABCD":
            arrays[f"{k}_held"] = np.stack([getattr(m, k) for m in held])
    with atomic_file(path, "wb", what="state-space file") as fh:
        np.savez(fh, **arrays)
