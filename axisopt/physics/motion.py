r"""Motion of the table over a duty cycle, as phases of linearly varying acceleration.

A duty cycle is a list of moves and dwells.  A move starts and ends at rest: it accelerates to its
speed (at the axis acceleration, limited by the jerk when one is given), cruises, and decelerates; a
short move never reaches its speed (triangular or, with jerk, S-shaped profile).  A dwell stands
still.  Each phase carries what the motor torque needs
(:func:`axisopt.physics.drive.phase_torques`): its duration, the table acceleration at its start and
end (linear in between, so a jerk-limited ramp is exact), the direction of motion (+1, -1, 0 at
standstill), the external axial force opposing the motion, the largest speed reached and the moving
mass when the entry names its own (a workpiece loaded or unloaded).

Pure Python on floats: the cycle is the axis's, the same for every design; the design enters only in
the torque (inertia, lead, friction), so the phases are built once per axis.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Segment:
    """One entry of a duty cycle (SI).  ``kind`` 'move' or 'dwell'."""

    kind: str
    distance: float = 0.0  # signed [m] (move)
    speed: float = 0.0  # cruise speed, magnitude [m/s] (move)
    acceleration: float = 0.0  # [m/s^2] (move)
    jerk: float | None = None  # [m/s^3] (move); None: trapezoidal
    duration: float = 0.0  # [s] (dwell)
    # external axial force opposing the motion [N] (a dwell: held against gravity's side)
    force: float = 0.0
    # table + workpiece during the entry [kg]; None: the axis's moving_mass
    moving_mass: float | None = None


@dataclass(frozen=True)
class Phase:
    """A piece of the cycle with linearly varying acceleration."""

    duration: float  # [s]
    a0: float  # table acceleration at the start [m/s^2], signed
    a1: float  # ... at the end
    direction: float  # +1, -1, or 0 (standstill)
    force: float  # external axial force opposing the motion [N]
    speed: float  # largest |speed| in the phase [m/s]
    # table speed at the start [m/s], signed (the speed over the phase: v0 + integral of a)
    v0: float = 0.0
    # table + workpiece in the phase [kg]; None: the axis's moving_mass
    moving_mass: float | None = None

    def speed_at(self, t):
        """Signed table speed [m/s] at time ``t`` into the phase (acceleration linear in t)."""
        return self.v0 + self.a0 * t + 0.5 * (self.a1 - self.a0) * t * t / self.duration


def ramp(speed: float, acceleration: float, jerk: float | None) -> tuple[list, float, float]:
    """Acceleration pieces [(duration, a0, a1)] taking the table from rest to ``speed``, and the
    time and distance this takes.  With jerk: a jerk-limited (S-curve) ramp, which reaches the full
    acceleration only when ``speed >= acceleration**2 / jerk``."""
    # no acceleration given: speed changes count as instantaneous
    if speed <= 0.0 or acceleration <= 0.0:
        return [], 0.0, 0.0
    if jerk is None or not math.isfinite(jerk):
        t = speed / acceleration
        return [(t, acceleration, acceleration)], t, 0.5 * speed * t
    a_peak = min(acceleration, math.sqrt(speed * jerk))
    tj = a_peak / jerk
    tc = speed / a_peak - tj  # at constant acceleration
    pieces = (
        [(tj, 0.0, a_peak)] + ([(tc, a_peak, a_peak)] if tc > 0.0 else []) + [(tj, a_peak, 0.0)]
    )
    t = 2.0 * tj + max(tc, 0.0)
    return pieces, t, 0.5 * speed * t  # symmetric S-ramp: mean speed is half the final speed


def move_phases(seg: Segment) -> list[Phase]:
    """Phases of a point-to-point move (rest to rest)."""
    dist = abs(seg.distance)
    if dist == 0.0:
        return []
    s = 1.0 if seg.distance > 0 else -1.0
    v = seg.speed
    pieces, t_ramp, d_ramp = ramp(v, seg.acceleration, seg.jerk)
    if v <= 0.0:
        return []
    # never reaches the speed: the largest speed whose two ramps fit the distance
    if 2.0 * d_ramp > dist:
        lo, hi = 0.0, v
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            if 2.0 * ramp(mid, seg.acceleration, seg.jerk)[2] > dist:
                hi = mid
            else:
                lo = mid
        v = lo
        pieces, t_ramp, d_ramp = ramp(v, seg.acceleration, seg.jerk)
    cruise = (dist - 2.0 * d_ramp) / v if v > 0 else 0.0
    out, u = [], 0.0  # u: speed at the start of each ramp piece, from rest up to v and back
    for t, a0, a1 in pieces:
        if t > 0:
            out.append(Phase(t, s * a0, s * a1, s, seg.force, v, s * u, seg.moving_mass))
        u += 0.5 * (a0 + a1) * t
    if cruise > 0:
        out.append(Phase(cruise, 0.0, 0.0, s, seg.force, v, s * v, seg.moving_mass))
    u = v
    for t, a0, a1 in reversed(pieces):
        if t > 0:
            out.append(Phase(t, -s * a1, -s * a0, s, seg.force, v, s * u, seg.moving_mass))
        u -= 0.5 * (a0 + a1) * t
    return out


class Phases(tuple):
    """The phases of a duty cycle (a tuple), whether the heat balance sets the temperature rise
    (``heat``) and whether the cycle is the user's (``given``; else the default rapid cycle, which
    the life checks do not read): properties of the axis, the same for every design, so the model
    branches on them in Python instead of carrying both forms symbolically.  Equal only with the
    same phases and flags (cache keys)."""

    heat: bool = False
    given: bool = False

    def __new__(cls, phases=(), heat: bool = False, given: bool = False):
        obj = super().__new__(cls, phases)
        obj.heat = bool(heat)
        obj.given = bool(given)
        return obj

    def __eq__(self, other):
        return (
            tuple.__eq__(self, other)
            and getattr(other, "heat", False) == self.heat
            and getattr(other, "given", False) == self.given
        )

    def __ne__(self, other):
        return not self.__eq__(other)

    def __hash__(self):
        return hash((tuple(self), self.heat, self.given))

    def __reduce__(self):
        return (Phases, (tuple(self), self.heat, self.given))


def cycle_phases(segments) -> tuple[Phase, ...]:
    """All phases of a duty cycle, in order."""
    out: list[Phase] = []
    for seg in segments:
        if seg.kind == "dwell":
            if seg.duration > 0:
                out.append(Phase(seg.duration, 0.0, 0.0, 0.0, seg.force, 0.0, 0.0, seg.moving_mass))
        else:
            out.extend(move_phases(seg))
    return tuple(out)


def rapid_cycle(
    stroke: float, speed: float, acceleration: float, jerk: float | None
) -> tuple[Segment, ...]:
    """The default cycle when none is given: a rapid move over the whole stroke and back, without
    dwell (continuous reversing: a conservative duty for the RMS torque)."""
    mv = dict(speed=speed, acceleration=acceleration, jerk=jerk)
    return (Segment("move", distance=stroke, **mv), Segment("move", distance=-stroke, **mv))


def cycle_time(phases) -> float:
    return sum(ph.duration for ph in phases)


def phase_travel(ph: Phase) -> float:
    r"""Distance the table travels in a phase [m] (>= 0): :math:`|v_0 T + (2 a_0 + a_1) T^2 / 6|`,
    exact for an acceleration linear in time (the speed keeps its sign within a phase)."""
    t = ph.duration
    return abs(ph.v0 * t + (2.0 * ph.a0 + ph.a1) * t * t / 6.0)


def mean_speed(phases) -> float:
    """Mean table speed over a cycle [m/s]: its travel over its time, dwells included (THK A-730:
    the mean rotational speed N_m = 2 n l_S / P_h over the clock minute); 0 for a cycle without
    time."""
    t = cycle_time(phases)
    return sum(phase_travel(ph) for ph in phases) / t if t > 0 else 0.0


def phase_speeds(phases) -> list[tuple[float, float]]:
    """Table speed magnitude at the start and end of each phase [m/s] (for torque-speed plots)."""
    return [
        (abs(ph.v0), abs(ph.speed_at(ph.duration))) if ph.duration > 0 else (abs(ph.v0), abs(ph.v0))
        for ph in phases
    ]
