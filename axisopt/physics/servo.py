"""Servo-loop rules of thumb from drive and CNC vendors (pure formulas; tuning on the model:
model.servo)."""

from __future__ import annotations

import math

__all__ = [
    "RULE",
    "CURRENT_LOOP_HZ",
    "KV_PER_HZ",
    "VELOCITY_HZ_PER_KV",
    "KV_M_MIN_PER_MM",
    "kv_rule",
    "yaskawa_gains",
    "following_error",
]

RULE = "FANUC B-65262EN f_n [Hz] >= Kv [1/s]; Yaskawa Pn100 [Hz] = Pn102 [1/s], Pn101, Pn401"
# [Hz] current-loop bandwidth (first-order lag), assumed: below the 3.1 kHz speed
CURRENT_LOOP_HZ = 2000.0
# frequency response Yaskawa quotes for Sigma-7 drives (a current loop is faster than the speed
# loop)
KV_PER_HZ = 1.0  # FANUC: position-loop gain [1/s] at most the natural frequency [Hz]
# Yaskawa reference values: speed-loop gain [Hz] = position-loop gain [1/s]
VELOCITY_HZ_PER_KV = 1.0
KV_M_MIN_PER_MM = 1000.0 / 60.0  # 1 (m/min)/mm in 1/s


def kv_rule(f_axial):
    r"""Achievable position-loop gain from the lowest axial natural frequency (motor held).

    .. math:: K_v\,[1/s] = f_n\,[Hz]     (FANUC B-65262EN/03: f_n >= K_v)

    f_axial : f_n [Hz] (float, array or CasADi).  Returns K_v [1/s].  Rises with the nut preload as
        f_n does.
    """
    return KV_PER_HZ * f_axial


def yaskawa_gains(speed_loop_hz: float) -> dict:
    """Yaskawa's manual-tuning relations for a speed-loop gain Pn100 [Hz] (Sigma-7 / E-S manual
    8.8.1).

    Returns {"Pn100_Hz", "Pn101_ms" = 4000 / (2 pi Pn100), "Pn401_ms" = 1000 / (2 pi Pn100 4),
    "Pn102_per_s" = Pn100 (reference values, Sigma-II 6.4.4)}.
    """
    return {
        "Pn100_Hz": speed_loop_hz,
        "Pn101_ms": 4000.0 / (2.0 * math.pi * speed_loop_hz),
        "Pn401_ms": 1000.0 / (2.0 * math.pi * speed_loop_hz * 4.0),
        "Pn102_per_s": speed_loop_hz,
    }


def following_error(speed, kv):
    r"""Steady following error of a P position loop without feedforward.

    .. math:: e = v / K_v      (Heidenhain iTNC 530 technical manual: s_a = v_e / k_v)

    speed : v [m/s];  kv : K_v [1/s].  Returns e [m].
    """
    return speed / kv
