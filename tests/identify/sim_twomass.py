"""A two-mass feed axis simulated by the tests' own physics, written apart from axisopt (neither the
identification's columns nor axisopt.identify.records.synth): a motor-side mass with its own
Coulomb and viscous friction (motor and support bearings, seals), tied through a spring with a dead
zone (the lost motion) and a damper to the table, which carries the guides' friction (optionally a
Stribeck rise) and a piecewise-constant process force.  The loop is either PD or a P-PI cascade
(position P, velocity PI) on the table's scale, velocity from a filtered backward difference of the
quantised position; the recorded force carries AR(1) (coloured) noise; the samples may be taken
with jitter about their nominal instants (the time column stays nominal).

    m1 a1 = u - S - sgn(v1) Fc1 - Fv1 v1
    m2 a2 = S - sgn(v2) [Fc2 + Fs exp(-|v2|/vs)] - Fv2 v2 + F_ext
    S = k dz(x1 - x2) + c (v1 - v2) inside contact, 0 inside the gap (dz: dead zone of width b)

Written as the CSV the diagnosis reads (time, position, reference, force, motor_position).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass
class TwoMass:
    m1: float = 150.0  # motor side, reflected to the table [kg]
    m2: float = 450.0  # table [kg]
    k: float = 4e6  # transmission stiffness [N/m]
    zeta: float = 0.1  # damping ratio of the transmission mode
    gap: float = 0.0  # lost motion b [m]
    fc1: float = 0.0  # motor-side Coulomb friction [N]
    fv1: float = 0.0  # motor-side viscous friction [N s/m]
    fc2: float = 350.0
    fv2: float = 1200.0
    stribeck: float = 0.0  # table-side Stribeck excess [N]
    vs: float = 0.004  # [m/s]
    load_amp: float = 0.0  # piecewise-constant process force on the table [N]
    stroke: float = 0.8

    @property
    def c(self) -> float:
        mu = self.m1 * self.m2 / (self.m1 + self.m2)
        return 2.0 * self.zeta * math.sqrt(self.k * mu)


@dataclass
class Servo:
    kind: str = "pd"  # 'pd' | 'ppi'
    fs: float = 1000.0
    bw: float = 3.0  # PD: closed-loop natural frequency on the total mass [Hz]
    kx: float = 8.0  # P-PI: position gain [1/s]
    bw_v: float = 4.0  # P-PI: velocity loop bandwidth on the total mass [Hz]
    ti: float = 0.12  # P-PI: integral time [s]
    noise: float = 3.0  # force noise std [N]
    rho: float = 0.0  # AR(1) coefficient of the noise
    jitter: float = 0.0  # sampling jitter, uniform +- this share of the sample period
    quantum: float = 1e-7
    substeps: int = 10


def moves(rng, duration, fs, stroke):
    """Trapezoidal moves (speed log-uniform 2..250 mm/s, acceleration 0.5..3 m/s^2) with dwells,
    both directions, smoothed over 30 ms."""
    n = int(duration * fs)
    r = np.empty(n)
    x, k = 0.5 * stroke, 0
    while k < n:
        dwell = int(rng.uniform(0.1, 0.35) * fs)
        r[k : k + dwell] = x
        k += dwell
        if k >= n:
            break
        v = math.exp(rng.uniform(math.log(0.002), math.log(0.25)))
        acc = rng.uniform(0.5, 3.0)
        d = min(rng.uniform(0.3, 1.0) * v + 0.5 * v * v / acc, 0.35 * stroke)
        s = rng.choice([-1.0, 1.0])
        if not 0.1 * stroke < x + s * d < 0.9 * stroke:
            s = -s
        ta = v / acc
        if d < v * ta:
            v = math.sqrt(d * acc)
            ta = v / acc
        tc = d / v - ta
        T = 2 * ta + tc
        t = np.arange(1, int(T * fs) + 1) / fs
        p = np.where(
            t < ta,
            0.5 * acc * t**2,
            np.where(t < ta + tc, 0.5 * acc * ta**2 + v * (t - ta), d - 0.5 * acc * (T - t) ** 2),
        )
        m = min(len(p), n - k)
        r[k : k + m] = x + s * p[:m]
        k += m
        x += s * d
    w = max(1, int(0.03 * fs))
    pad = np.r_[np.full(w, r[0]), r, np.full(w, r[-1])]
    return np.convolve(pad, np.ones(w) / w, "same")[w:-w]


def _levels(rng, n, fs, amp):
    out = np.empty(n)
    k = 0
    while k < n:
        m = int(rng.uniform(0.4, 1.5) * fs)
        out[k : k + m] = amp * rng.uniform(-1.0, 1.0)
        k += m
    w = max(1, int(0.05 * fs))
    pad = np.r_[np.full(w, out[0]), out, np.full(w, out[-1])]
    return np.convolve(pad, np.ones(w) / w, "same")[w:-w]


def _coulomb_step(v, net, fc, visc, m, h):
    """One explicit step of a mass with Coulomb friction that sticks exactly: new velocity."""
    if v == 0.0:
        if abs(net) <= fc:
            return 0.0
        return h * (net - math.copysign(fc, net)) / m
    vn = v + h * (net - math.copysign(fc, v) - visc * v) / m
    return 0.0 if vn * v < 0.0 else vn


def simulate(ax: TwoMass, sv: Servo, duration: float, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    fs = sv.fs
    n = int(duration * fs)
    ref = moves(rng, duration, fs, ax.stroke)
    load = _levels(rng, n, fs, ax.load_amp) if ax.load_amp else np.zeros(n)
    e = 0.0
    noise = np.empty(n)
    for i in range(n):
        e = sv.rho * e + rng.standard_normal() * sv.noise * math.sqrt(1.0 - sv.rho**2)
        noise[i] = e
    jit = rng.uniform(-sv.jitter, sv.jitter, n) if sv.jitter else np.zeros(n)
    M = ax.m1 + ax.m2
    if sv.kind == "pd":
        w = 2 * math.pi * sv.bw
        kp, kd = M * w * w, 2 * 0.8 * w * M
    else:
        kv = M * 2 * math.pi * sv.bw_v
        ki = kv / sv.ti
    ns = sv.substeps
    dt, h = 1.0 / fs, 1.0 / (fs * ns)
    k_s, c_s, half = ax.k, ax.c, ax.gap / 2
    alpha = 1.0 - math.exp(-2 * math.pi * 150.0 * dt)
    x1 = x2 = float(ref[0])
    v1 = v2 = 0.0
    xm_prev, vf, integ, u = x2, 0.0, 0.0, 0.0
    # states at every substep (the samples are read at jittered instants between them)
    X2, X1, U = np.empty(n * ns + 1), np.empty(n * ns + 1), np.empty(n * ns + 1)
    j = 0
    q = sv.quantum
    for i in range(n):
        xm = round(x2 / q) * q  # the controller reads the nominal instant
        vf += alpha * ((xm - xm_prev) * fs - vf) if i else 0.0
        xm_prev = xm
        vff = (ref[min(i + 1, n - 1)] - ref[i]) * fs
        if sv.kind == "pd":
            u = kp * (ref[i] - xm) + kd * (vff - vf)
        else:
            ev = sv.kx * (ref[i] - xm) + vff - vf
            integ += ki * ev * dt
            u = kv * ev + integ
        for _ in range(ns):
            X2[j], X1[j], U[j] = x2, x1, u
            j += 1
            d = x1 - x2
            if d > half:
                s = k_s * (d - half) + c_s * (v1 - v2)
            elif d < -half:
                s = k_s * (d + half) + c_s * (v1 - v2)
            else:
                s = 0.0
            v1n = _coulomb_step(v1, u - s, ax.fc1, ax.fv1, ax.m1, h)
            net2 = s + load[i]
            fc2 = ax.fc2 + (ax.stribeck * math.exp(-abs(v2) / ax.vs) if v2 else ax.stribeck)
            v2n = _coulomb_step(v2, net2, fc2, ax.fv2, ax.m2, h)
            v1, v2 = v1n, v2n
            x1 += h * v1
            x2 += h * v2
    X2[j], X1[j], U[j] = x2, x1, u
    grid = np.arange(n * ns + 1) * h
    tt = np.arange(n) * dt
    at = np.clip(tt + jit * dt, 0.0, grid[-1])
    pos = np.round(np.interp(at, grid, X2) / q) * q
    mot = np.round(np.interp(at, grid, X1) / q) * q
    force = np.interp(at, grid, U) + noise
    return {
        "time": tt,
        "position": pos,
        "motor_position": mot,
        "reference": ref,
        "force": force,
        "external_force": load,
    }


def write(path, rec: dict, external: bool = False):
    cols = ["time [s]", "position [mm]", "reference [mm]", "force [N]", "motor_position [mm]"]
    data = [
        rec["time"],
        rec["position"] * 1e3,
        rec["reference"] * 1e3,
        rec["force"],
        rec["motor_position"] * 1e3,
    ]
    if external:
        cols.append("external_force [N]")
        data.append(rec["external_force"])
    lines = [",".join(cols)]
    lines += [",".join(f"{v:.10g}" for v in row) for row in np.column_stack(data)]
    path.write_text("\n".join(lines) + "\n")
    return path
