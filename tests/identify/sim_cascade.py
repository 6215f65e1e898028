"""A feed axis simulated by the tests' own physics, written apart from axisopt (neither the
identification's columns nor axisopt.identify.records.synth): a P-PI cascade (position P, velocity
PI on a filtered backward difference of the quantised position), a generalised Stribeck curve,
friction growing with the nut's axial force and the guides' normal load, viscous and Coulomb levels
in temperature, a cogging force periodic in the motor angle, and coloured (AR(1)) noise on the
recorded force.  Records are written as the CSV the diagnosis reads.

The axis (table side, SI): m a = u - F_fric - F_load(t) with

    F_fric = sgn(v) [Fc(T) + (Fs - Fc) exp(-(|v|/vs)^delta) + (1 - eta) |u| + mu N] + Fv(T) v
    Fv(T) = Fv exp(-beta (T - T0)),  Fc(T) = Fc + dfc_dT (T - T0)

where (1 - eta) |u| is the nut's loss on the drive force u it converts (screw efficiency eta),
F_load a piecewise-constant process force and N a piecewise-constant extra normal load.  Sticking:
at rest the table stays while |u - F_load| is below the breakaway force.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass
class Axis:
    mass: float = 600.0
    fc: float = 400.0
    fv: float = 1500.0
    offset: float = 0.0  # a constant force in -x the drive supplies [N]
    fs_excess: float = 0.0  # Fs - Fc [N]
    vs: float = 0.004
    delta: float = 1.0  # Stribeck exponent (generalised)
    nut_loss: float = 0.0  # the nut's loss per force the drive supplies, 1 - eta
    mu: float = 0.0  # guide friction per normal load
    load_amp: float = 0.0  # amplitude of the piecewise-constant process force [N]
    normal_amp: float = 0.0  # extra normal load range [N] (piecewise constant, 0..normal_amp)
    beta: float = 0.0  # viscous friction falls as exp(-beta (T - T0)) [1/K]
    dfc_dT: float = 0.0  # Coulomb change per K [N/K]
    # (T0 [degC], rise [K], tau [s]): T = T0 + rise (1 - exp(-t/tau)) from the run's start
    temp: tuple = ()
    temp_start: float = 0.0  # [K] added at the run's start (a run that starts warm)
    cog_amp: float = 0.0  # cogging force at the table [N], periodic in the motor angle
    cog_order: int = 0  # cogging periods per motor turn
    travel_per_motor_turn: float = 0.01  # [m]
    # further forces periodic in the table's position, (amplitude [N], period [m], phase [rad])
    # each: a belt's tooth mesh, the balls passing in the nut, a screw's run-out
    lines: tuple = ()
    vmax: float = 0.3  # the fastest move of the reference [m/s]
    tone: tuple = ()  # a force periodic in time, (amplitude [N], frequency [Hz]): a pump
    stroke: float = 0.8
    extra: dict = field(default_factory=dict)


@dataclass
class Loop:
    fs: float = 1000.0
    kx: float = 25.0  # position P [1/s]
    bw_v: float = 12.0  # velocity loop bandwidth [Hz]
    ti: float = 0.04  # integral time [s]
    noise: float = 4.0  # force noise std [N]
    rho: float = 0.0  # AR(1) coefficient of the force noise (0: white)
    quantum: float = 1e-7  # 0.1 um scale
    substeps: int = 4
    # bandwidth of the current loop (0: the force is the command, held per sample)
    current_hz: float = 0.0
    pos_jitter: float = 0.0  # RMS noise of the recorded position before its quantisation [m]


def reference(rng, duration, fs, stroke, vmax=0.3):
    """Trapezoidal moves of random speed (log-uniform 3 mm/s..vmax) and acceleration, at most 1.2 s
    each, with dwells of 0.15-0.4 s, jerk limited."""
    n = int(duration * fs)
    r = np.empty(n)
    x, k = 0.5 * stroke, 0
    while k < n:
        dwell = int(rng.uniform(0.15, 0.4) * fs)
        r[k : k + dwell] = x
        k += dwell
        v = math.exp(rng.uniform(math.log(0.003), math.log(vmax)))
        acc = rng.uniform(0.8, 3.0)
        lo, hi = 0.08 * stroke, 0.92 * stroke
        # a move of at most 1.2 s at its speed, either way inside the stroke
        reach = min(rng.uniform(0.3, 1.2) * v, 0.5 * (hi - lo))
        sign = rng.choice([-1.0, 1.0])
        if not lo <= x + sign * reach <= hi:
            sign = -sign
        target = x + sign * reach
        d = target - x
        if abs(d) < 1e-4:
            continue
        ta = v / acc
        if abs(d) < v * ta:
            v = math.sqrt(abs(d) * acc)
            ta = v / acc
        tc = abs(d) / v - ta
        T = 2 * ta + tc
        m = int(T * fs)
        t = np.arange(1, m + 1) / fs
        s = np.where(
            t < ta,
            0.5 * acc * t**2,
            np.where(
                t < ta + tc,
                0.5 * acc * ta**2 + v * (t - ta),
                abs(d) - 0.5 * acc * np.clip(T - t, 0, None) ** 2,
            ),
        )
        seg = x + math.copysign(1.0, d) * s
        r[k : k + m] = seg[: max(0, min(m, n - k))]
        k += m
        x = target
    w = max(1, int(0.04 * fs))  # jerk limited: the acceleration ramps over 40 ms (a moving average)
    return np.convolve(np.r_[np.full(w, r[0]), r, np.full(w, r[-1])], np.ones(w) / w, "same")[w:-w]


def _steps(rng, n, fs, amp, lo_frac=-1.0):
    """Levels held 0.5-2 s, uniform in amp*[lo_frac, 1], changing by linear ramps of 0.3 s (a
    process force builds up over a tool's entry, a payload is set down)."""
    out = np.empty(n)
    k = 0
    while k < n:
        m = int(rng.uniform(0.5, 2.0) * fs)
        out[k : k + m] = amp * rng.uniform(lo_frac, 1.0)
        k += m
    w = max(1, int(0.3 * fs))
    return np.convolve(np.r_[np.full(w, out[0]), out, np.full(w, out[-1])], np.ones(w) / w, "same")[
        w:-w
    ]


def simulate(ax: Axis, loop: Loop, duration: float, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    fs, dt = loop.fs, 1.0 / loop.fs
    n = int(duration * fs)
    r = reference(rng, duration, fs, ax.stroke, ax.vmax)
    load = _steps(rng, n, fs, ax.load_amp) if ax.load_amp else np.zeros(n)
    normal = _steps(rng, n, fs, ax.normal_amp, 0.0) if ax.normal_amp else np.zeros(n)
    tt = np.arange(n) * dt
    if ax.temp:
        t0, rise, tau = ax.temp
        temp_c = t0 + ax.temp_start + rise * (1.0 - np.exp(-tt / tau))
    else:
        temp_c = np.full(n, 20.0)
    kv = ax.mass * 2 * math.pi * loop.bw_v
    ki = kv / loop.ti
    h = dt / loop.substeps
    cl = 1.0 - math.exp(-2.0 * math.pi * loop.current_hz * h) if loop.current_hz else 1.0
    fa = 0.0
    x, v, integ, vf, xm_prev = r[0], 0.0, 0.0, 0.0, r[0]
    aw = math.exp(-2 * math.pi * 150.0 * dt)
    xs, us = np.empty(n), np.empty(n)
    e = 0.0
    noise = np.empty(n)
    for k in range(n):
        e = loop.rho * e + rng.standard_normal() * loop.noise * math.sqrt(1 - loop.rho**2)
        noise[k] = e
    for k in range(n):
        xs[k] = x  # measured at the sample instant
        xm = round(x / loop.quantum) * loop.quantum
        vraw = (xm - xm_prev) / dt if k else 0.0
        vf = aw * vf + (1 - aw) * vraw
        xm_prev = xm
        vff = (r[min(k + 1, n - 1)] - r[k]) * fs
        vcmd = loop.kx * (r[k] - xm) + vff
        ev = vcmd - vf
        integ += ki * ev * dt
        u = kv * ev + integ
        # the recorded force: the command, or the current loop's
        us[k] = u if not loop.current_hz else fa
        dT = temp_c[k] - (ax.temp[0] if ax.temp else 20.0)
        fc_t = ax.fc + ax.dfc_dT * dT
        fv_t = ax.fv * math.exp(-ax.beta * dT)
        for j in range(loop.substeps):
            fa += (u - fa) * cl  # the current loop: the force follows the command
            cog = 0.0
            if ax.cog_amp:
                cog = ax.cog_amp * math.sin(
                    2 * math.pi * ax.cog_order * x / ax.travel_per_motor_turn
                )
            for amp, period, phase in ax.lines:
                cog += amp * math.sin(2 * math.pi * x / period + phase)
            if ax.tone:
                cog += ax.tone[0] * math.sin(2 * math.pi * ax.tone[1] * (tt[k] + j * h) + 0.5)
            drive = fa - load[k] - ax.offset - cog
            level = fc_t + ax.mu * normal[k] + ax.nut_loss * abs(fa)
            if v == 0.0:
                brk = level + ax.fs_excess
                if abs(drive) <= brk:
                    continue
                fr = math.copysign(brk, drive)
                v = (drive - fr) / ax.mass * h
                x += v * h
                continue
            sv = 1.0 if v > 0 else -1.0
            fr = sv * (level + ax.fs_excess * math.exp(-((abs(v) / ax.vs) ** ax.delta))) + fv_t * v
            vn = v + (drive - fr) / ax.mass * h
            if vn * v < 0.0:
                vn = 0.0
            v = vn
            x += v * h
    # the current sensor averages over the sample period centred on the instant
    if not loop.current_hz:
        us = np.r_[us[0], 0.5 * (us[1:] + us[:-1])]
    if loop.pos_jitter:
        xs = xs + loop.pos_jitter * np.random.default_rng(seed + 7919).standard_normal(n)
    pos = np.round(xs / loop.quantum) * loop.quantum
    return {
        "time": tt,
        "position": pos,
        "reference": r,
        "force": us + noise,
        "external_force": -load,
        "normal_load": normal,
        "temperature": temp_c,
    }


def write(path, rec: dict, columns=("external_force",), header_lines=(), current_gain=None):
    cols = ["time [s]", "position [mm]", "reference [mm]"]
    data = [rec["time"], rec["position"] * 1e3, rec["reference"] * 1e3]
    if current_gain:
        cols.append("current [A]")
        data.append(rec["force"] / current_gain)
    else:
        cols.append("force [N]")
        data.append(rec["force"])
    units = {"external_force": "N", "normal_load": "N", "temperature": "degC", "payload": "kg"}
    for c in columns:
        cols.append(f"{c} [{units[c]}]")
        data.append(rec[c])
    lines = list(header_lines) + [",".join(cols)]
    arr = np.column_stack(data)
    lines += [",".join(f"{v:.9g}" for v in row) for row in arr]
    path.write_text("\n".join(lines) + "\n")
    return path
