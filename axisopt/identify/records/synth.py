"""Synthetic time records of a feed axis under closed-loop position control (tests, benchmarks,
examples).

Written apart from the identification code (``timerecord``, ``idim``) and sharing nothing with it: a
test that identifies these records checks the identification against an independent model.

The axis (table side, SI): a moving mass ``mass`` driven by the motor force ``u`` (reflected to the
table), friction

.. math:: F(x, v) = F_c^\\pm \\operatorname{sgn} v + F_v^\\pm v
          + (F_s - F_c) e^{-|v|/v_s} \\operatorname{sgn} v + \\Delta F(\\xi) \\operatorname{sgn} v + F_0

with direction-dependent Coulomb and viscous levels (``coulomb_asym``, ``viscous_asym`` = level for
v > 0 minus level for v < 0), a Stribeck excess ``stribeck`` decaying with velocity constant
``stribeck_v``, a position-dependent Coulomb part :math:`\\Delta F = c_1 \\xi + c_2 (3\\xi^2 - 1)/2`
with :math:`\\xi = 2x/\\mathrm{stroke} - 1`, and a constant force ``offset`` :math:`F_0`.  Sticking
is exact (implicit Coulomb step: the table stays at rest while the drive force is inside the
breakaway band).  Optionally a second mass: the motor-side mass ``mode_mass`` carries the drive
force and is tied to the table by a spring-damper tuned to the resonance ``mode_hz`` (damping ratio
``mode_zeta``); the table carries the friction and its position is measured.

Effects the identification library may lack: a ripple periodic in position ``ripple`` sin(2 pi x /
``ripple_period`` + ``ripple_phase``), as a force in -x (the drive supplies it both ways) or, with
``ripple_friction``, added to the Coulomb level (it follows the direction); a drag
``quadratic_drag`` v|v|; lost motion ``backlash`` between the motor-side and table masses (a dead
zone of the spring; needs the second mass); a seeded piecewise-constant process force on the table,
``process_force`` (recorded as ``extra['external_force']`` and written as the ``external_force [N]``
column); and a caller's own force ``extra_force(t, x, v)`` or Coulomb level ``extra_friction(t, x)``
(tests write the physics of the effect they hide there, apart from the identification's columns).

The controller (sampled at ``fs``): PD on the measured position, the velocity from the backward
difference of the measured position through a first-order low-pass (``vel_filter_hz``),
:math:`u = K_p (r - x_m) + K_d (\\dot r - \\hat v)`.  The recorded force is ``u`` plus white sensor
noise ``force_noise``; the position is quantised to ``quantum`` (1 um) after white noise
``position_noise``.  The reference is a seeded sequence of trapezoidal moves at several speeds and
accelerations in both directions with dwells, inside the stroke.
"""  # noqa: E501

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

SPEEDS = (0.002, 0.005, 0.012, 0.03, 0.08, 0.2, 0.35)  # [m/s]
ACCELS = (0.5, 1.5, 3.0)  # [m/s^2]


@dataclass
class AxisTruth:
    """The simulated axis (SI, table side)."""

    mass: float = 650.0  # [kg] table + reflected screw/motor inertia
    viscous: float = 1500.0  # [N s/m]
    coulomb: float = 450.0  # [N]
    offset: float = 0.0  # [N]
    coulomb_asym: float = 0.0  # Fc(v>0) - Fc(v<0) [N]
    viscous_asym: float = 0.0  # Fv(v>0) - Fv(v<0) [N s/m]
    stribeck: float = 0.0  # Fs - Fc [N]
    stribeck_v: float = 0.005  # [m/s]
    position_coeffs: tuple = (0.0, 0.0)  # c1, c2 [N] of the position-dependent Coulomb part
    stroke: float = 0.8  # [m]
    mode_hz: float = 0.0  # 0: rigid axis
    mode_mass: float = 150.0  # motor-side share of ``mass`` [kg]
    mode_zeta: float = 0.03
    # [N] amplitude of a force ripple periodic in position (lead error, recirculation)
    ripple: float = 0.0
    ripple_period: float = 0.01  # [m]
    ripple_phase: float = 0.0  # [rad]
    # True: the ripple is a friction (follows sgn v); False: a force in +x
    ripple_friction: bool = False
    quadratic_drag: float = 0.0  # [N s^2/m^2] symmetric drag c v|v| (seals, lubricant churning)
    # [m] total lost motion between motor and table (needs mode_hz > 0: the motor side mass crosses
    # the gap with the table left behind)
    backlash: float = 0.0
    # [N] amplitude of a seeded piecewise-constant external force on the table
    process_force: float = 0.0
    # effects a caller writes itself (tests hide their own physics this way):
    # ``extra_force(t, x, v)`` [N] a force in -x the drive must supply; ``extra_friction(t, x)`` [N]
    # added to the Coulomb level of both directions (it opposes the motion and widens the breakaway
    # band at rest)
    extra_force: Callable | None = None
    extra_friction: Callable | None = None


@dataclass
class LoopSettings:
    fs: float = 1000.0  # [Hz]
    bandwidth_hz: float = 6.0  # closed-loop natural frequency of the PD loop on the nominal mass
    zeta: float = 0.8
    vel_filter_hz: float = 150.0
    force_noise: float = 4.0  # [N] rms
    position_noise: float = 0.3e-6  # [m] rms before quantisation
    quantum: float = 1e-6  # [m]
    substeps: int = 5
    gains: tuple | None = None  # (Kp [N/m], Kd [N s/m]); default from bandwidth and nominal mass


@dataclass
class Record:
    t: np.ndarray
    position: np.ndarray  # measured, quantised [m]
    force: np.ndarray  # recorded [N]
    reference: np.ndarray  # [m]
    truth: AxisTruth
    loop: LoopSettings
    gains: tuple
    extra: dict = field(default_factory=dict)  # 'external_force' [N] at every sample when simulated

    def write_csv(
        self,
        path,
        *,
        columns=("time", "position", "force", "reference"),
        effort="force",
        lead: float = 0.01,
        efficiency: float = 1.0,
        gain: float | None = None,
        position_unit: str = "mm",
    ) -> None:
        """Write as an axisopt time-record CSV.  ``effort``: 'force' [N], 'torque' [N.m] or
        'current' [A] (torque = force * lead / (2 pi efficiency), current = torque / gain with a
        ``# gain`` line).  ``position_unit`` 'mm' (table) or 'rad' (motor angle through
        ``lead``)."""
        if effort == "force":
            eff, head = self.force, "force [N]"
        else:
            torque = self.force * lead / (2.0 * math.pi * efficiency)
            eff, head = (
                (torque, "torque [N.m]") if effort == "torque" else (torque / gain, "current [A]")
            )
        if position_unit == "mm":
            pos, ref, ph = self.position * 1e3, self.reference * 1e3, "mm"
        else:
            pos, ref, ph = (
                self.position * 2 * math.pi / lead,
                self.reference * 2 * math.pi / lead,
                "rad",
            )
        data = {
            "time": (self.t, "time [s]", "{:.4f}"),
            "position": (pos, f"position [{ph}]", "{:.6g}"),
            "force": (eff, head, "{:.6g}"),
            "reference": (ref, f"reference [{ph}]", "{:.6g}"),
        }
        if "external_force" in self.extra:
            data["external_force"] = (self.extra["external_force"], "external_force [N]", "{:.6g}")
        if "motor_position" in self.extra:
            mp = self.extra["motor_position"] * (
                1e3 if position_unit == "mm" else 2 * math.pi / lead
            )
            data["motor_position"] = (mp, f"motor_position [{ph}]", "{:.9g}")
        from ...fileio import open_output

        with open_output(path, "w", what="time record") as fh:
            if effort == "current" and gain is not None:
                fh.write(f"# gain: {gain} N.m/A\n")
            w = csv.writer(fh)
            w.writerow([data[c][1] for c in columns])
            for i in range(len(self.t)):
                w.writerow([data[c][2].format(data[c][0][i]) for c in columns])


def trapezoid_reference(
    duration: float, fs: float, stroke: float, seed: int, speeds=SPEEDS, accels=ACCELS
) -> tuple:
    """Seeded trapezoidal moves (position, velocity [SI] at every sample) within 5..95 % of the
    stroke."""
    rng = np.random.default_rng(seed)
    n = int(round(duration * fs))
    t = np.arange(n) / fs
    segs = []  # (t0, x0, direction, v, a, t_acc, t_cruise)
    x, t0, k = 0.5 * stroke, 0.3, 0
    order = list(rng.permutation(len(speeds)))
    direction = 1.0 if rng.random() < 0.5 else -1.0
    while t0 < duration:
        if not order:
            order = list(rng.permutation(len(speeds)))
        v = speeds[order.pop()]
        a = accels[k % len(accels)] * rng.uniform(0.8, 1.2)
        k += 1
        t_acc = v / a
        # fast moves sweep the stroke
        t_cruise = rng.uniform(0.25, 0.6) if v < 0.05 else rng.uniform(0.5, 1.2)
        d = v * (t_acc + t_cruise)
        room = {1.0: 0.95 * stroke - x, -1.0: x - 0.05 * stroke}
        if d > room[direction] and room[-direction] > room[direction]:
            direction = -direction
        if d > room[direction]:  # shorten the cruise to stay inside the stroke
            t_cruise = room[direction] / v - t_acc
            if t_cruise < 0.0:
                continue
            d = v * (t_acc + t_cruise)
        segs.append((t0, x, direction, v, a, t_acc, t_cruise))
        x += direction * d
        t0 += 2 * t_acc + t_cruise + rng.uniform(0.1, 0.3)
        direction = -direction if rng.random() < 0.7 else direction
    pos = np.full(n, 0.5 * stroke)
    vel = np.zeros(n)
    for t0, x0, s, v, a, ta, tc in segs:
        tau = t - t0
        m = tau >= 0
        tt = tau[m]
        p = np.where(
            tt < ta,
            0.5 * a * tt**2,
            np.where(
                tt < ta + tc,
                0.5 * a * ta**2 + v * (tt - ta),
                np.where(
                    tt < 2 * ta + tc,
                    0.5 * a * ta**2 + v * tc + v * (tt - ta - tc) - 0.5 * a * (tt - ta - tc) ** 2,
                    v * (ta + tc),
                ),
            ),
        )
        vv = np.where(
            tt < ta,
            a * tt,
            np.where(tt < ta + tc, v, np.where(tt < 2 * ta + tc, v - a * (tt - ta - tc), 0.0)),
        )
        pos[m] = x0 + s * p
        vel[m] = s * vv
    return t, pos, vel


def simulate_axis(
    truth: AxisTruth | None = None,
    loop: LoopSettings | None = None,
    *,
    duration: float = 12.0,
    seed: int = 0,
    reference_seed: int | None = None,
    record_motor: bool = False,
) -> Record:
    """Simulate the closed loop; see the module docstring.  ``record_motor``: also record the
    motor-side position (an encoder of 0.1 um resolution in table travel; the table's own when the
    axis is rigid) as ``extra['motor_position']``, written as a ``motor_position`` column."""
    truth = truth or AxisTruth()
    loop = loop or LoopSettings()
    fs, ns = loop.fs, loop.substeps
    t, ref, dref = trapezoid_reference(
        duration, fs, truth.stroke, seed if reference_seed is None else reference_seed
    )
    rng = np.random.default_rng(seed + 1000)
    pos_noise = loop.position_noise * rng.standard_normal(len(t))
    f_noise = loop.force_noise * rng.standard_normal(len(t))
    if loop.gains is None:
        wn = 2 * math.pi * loop.bandwidth_hz
        kp, kd = truth.mass * wn**2, 2 * loop.zeta * wn * truth.mass
    else:
        kp, kd = loop.gains
    h = 1.0 / (fs * ns)
    fc_p = truth.coulomb + truth.coulomb_asym / 2
    fc_n = truth.coulomb - truth.coulomb_asym / 2
    fv_p = truth.viscous + truth.viscous_asym / 2
    fv_n = truth.viscous - truth.viscous_asym / 2
    c1, c2 = truth.position_coeffs
    fse, vs = truth.stribeck, truth.stribeck_v
    off = truth.offset
    rip, rip_k, rip_ph = truth.ripple, 2 * math.pi / truth.ripple_period, truth.ripple_phase
    rip_fr = truth.ripple_friction
    cq = truth.quadratic_drag
    gap = truth.backlash / 2
    f_ext = process_force_profile(t, truth.process_force, seed) if truth.process_force else None
    two = truth.mode_hz > 0
    if two:
        m1 = truth.mode_mass
        m2 = truth.mass - m1
        w = 2 * math.pi * truth.mode_hz
        k_s = w**2 * m1 * m2 / truth.mass
        c_s = 2 * truth.mode_zeta * w * m1 * m2 / truth.mass
        mt = m2
    else:
        m1 = m2 = k_s = c_s = 0.0
        mt = truth.mass
    alpha = 1.0 - math.exp(-2 * math.pi * loop.vel_filter_hz / fs)
    x = x1 = float(ref[0])
    v = v1 = 0.0
    xm_prev = round((x + pos_noise[0]) / loop.quantum) * loop.quantum
    vhat = 0.0
    q = loop.quantum
    n = len(t)
    meas = np.empty(n)
    force = np.empty(n)
    motor = np.empty(n) if record_motor else None
    xf, xr = truth.extra_force, truth.extra_friction
    for k in range(n):
        xm = round((x + pos_noise[k]) / q) * q
        if k:
            vhat += alpha * ((xm - xm_prev) * fs - vhat)
        xm_prev = xm
        u = kp * (ref[k] - xm) + kd * (dref[k] - vhat)
        meas[k] = xm
        force[k] = u + f_noise[k]
        if motor is not None:
            motor[k] = round((x1 if two else x) / 1e-7) * 1e-7
        for j in range(ns):
            if two:
                stretch = x1 - x
                if gap > 0.0:  # dead zone of the lost motion: no spring force inside the gap
                    stretch = (
                        stretch - gap
                        if stretch > gap
                        else (stretch + gap if stretch < -gap else 0.0)
                    )
                    spring = k_s * stretch + (c_s * (v1 - v) if stretch != 0.0 else 0.0)
                else:
                    spring = k_s * stretch + c_s * (v1 - v)
                v1 += h * (u - spring) / m1
                x1 += h * v1
                drive = spring - off
            else:
                drive = u - off
            if f_ext is not None:
                drive += f_ext[k]
            xi = 2 * x / truth.stroke - 1
            dpos = c1 * xi + c2 * (1.5 * xi * xi - 0.5)
            if xf is not None:
                drive -= xf(t[k] + j * h, x, v)
            if xr is not None:
                dpos += xr(t[k] + j * h, x)
            if rip:
                wave = rip * math.sin(rip_k * x + rip_ph)
                if rip_fr:
                    dpos += wave  # a friction: opposes the motion, like the Coulomb part
                else:
                    drive -= wave  # a force in -x: the drive must supply +wave
            if v == 0.0:
                bp = max(fc_p + fse + dpos, 0.0)
                bn = max(fc_n + fse + dpos, 0.0)
                if drive > bp:
                    v = h * (drive - bp) / mt
                elif drive < -bn:
                    v = h * (drive + bn) / mt
            else:
                if v > 0:
                    fr = fc_p + fv_p * v + fse * math.exp(-v / vs) + dpos + cq * v * v
                else:
                    fr = -fc_n + fv_n * v - fse * math.exp(v / vs) - dpos - cq * v * v
                vn = v + h * (drive - fr) / mt
                v = 0.0 if vn * v < 0 else vn
            x += h * v
    extra = {"external_force": f_ext} if f_ext is not None else {}
    if motor is not None:
        extra["motor_position"] = motor
    return Record(t, meas, force, ref, truth, loop, (kp, kd), extra)


def process_force_profile(t: np.ndarray, amplitude: float, seed: int) -> np.ndarray:
    """A seeded external force on the table [N]: constant levels within +-``amplitude`` held 0.3-1.2
    s each (cuts starting and stopping), ramped over 20 ms between levels."""
    rng = np.random.default_rng(seed + 2000)
    out = np.zeros(len(t))
    t0, level = 0.0, 0.0
    fs = 1.0 / float(t[1] - t[0])
    while t0 < t[-1]:
        new = rng.uniform(-amplitude, amplitude) if rng.random() < 0.75 else 0.0
        i0 = int(t0 * fs)
        out[i0:] = new
        ramp = min(int(0.02 * fs), len(out) - i0)
        out[i0 : i0 + ramp] = level + (new - level) * np.arange(1, ramp + 1) / ramp
        level = new
        t0 += rng.uniform(0.3, 1.2)
    return out
