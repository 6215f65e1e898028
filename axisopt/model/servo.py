r"""The servo a design allows: cascade position / velocity loop tuned by vendor rules against the
model.

Structure (semi-closed loop: position and velocity from the motor encoder, the common ball-screw
set-up)::

    x_ref -(+)- Kv -> v_cmd -(+)- PI: K_vp (1 + 1/(T_i s)) -> torque filter 1/(T_f s + 1) -> notch
             |-x_m            |-v_m                -> current loop 1/(T_c s + 1) -> T_m -> axis

with ``x_m = r theta_m`` the motor angle through the lead (r = P_h / 2 pi) and the plant the
open-loop :class:`axisopt.model.statespace.AxisStateSpace`.  The rule (``RULE``), from vendors'
tuning guidance:

1. Position-loop gain from the lowest mechanical natural frequency: the machine "should be designed
   so that the value of this natural frequency [Hz] will be more than or equal to the value of the
   position loop gain [sec^-1]" (FANUC AC servo motor alpha-i series descriptions B-65262EN/03, sec.
   2, "machine rigidity"; its example: 20 s^-1 needs 20 Hz).  Kv [1/s] = f_n [Hz] with f_n =
   ``f_axial``, the axial mode with the motor held (the table mode on the guides, ``f_table``, is
   normal to the feed and not in the loop).
2. Velocity-loop gain equal to it in Hz: Yaskawa's gain reference values give the same ranges for
   the position-loop gain Pn102 [1/s] and the speed-loop gain Pn100 [Hz] in each rigidity class
   (Sigma-II user's manual sec. 6.4.4: ball screws direct 50-70 / 50-70, through reducers 30-50 /
   30-50, belts 10-20 / 10-20).  Pn100 is the velocity-loop crossover when the inertia is set right
   (Pn103), so K_vp = 2 pi f_v J [N*m*s/rad at the motor] with J the axis's total inertia at the
   motor (THK eq. 45).
3. Integral time and torque filter from it (Yaskawa Sigma-7 / Sigma E-S manual, 8.8.1 manual
   tuning): Pn101 [ms] = 4000 / (2 pi Pn100 [Hz]) (its example: 40.0 Hz -> 15.92 ms) and Pn401 [ms]
   = 1000 / (2 pi Pn100 [Hz] 4) ("adjusted value for stable control").
4. A notch (Q 0.7) on the torque reference at the second drive-train mode (rotor against screw
   across the coupling), as drives set for a ball screw's torsion resonance; without it that lightly
   damped mode (0.2 %, steel) goes unstable behind the filter and current-loop lags.
5. The current loop is a first-order lag of ``CURRENT_LOOP_HZ`` (2 kHz, assumed: Yaskawa quotes a
   3.1 kHz speed frequency response for Sigma-7 drives, and a current loop is faster than its speed
   loop).

Following error at constant speed v without feedforward: e = v / Kv (Heidenhain iTNC 530 technical
manual, "interrelation of kv factor, feed rate and following error"); Kv in (m/min)/mm = Kv [1/s] *
60 / 1000.  The rule is a vendor rule of thumb, not an optimum: :func:`servo_response` closes the
loops on the model at each position and reports what the model then does (stability, damping,
bandwidths).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..physics.servo import (
    CURRENT_LOOP_HZ,
    KV_M_MIN_PER_MM,
    RULE,
    VELOCITY_HZ_PER_KV,
    following_error,
    kv_rule,
    yaskawa_gains,
)
from .function import Evaluation
from .statespace import AxisStateSpace, stroke_state_spaces

__all__ = [
    "RULE",
    "CURRENT_LOOP_HZ",
    "kv_rule",
    "ServoGains",
    "yaskawa_gains",
    "tune",
    "closed_loop",
    "ServoResult",
    "servo_response",
    "KV_M_MIN_PER_MM",
    "following_error",
    "frequency_response",
]


@dataclass(frozen=True)
class ServoGains:
    """Cascade gains (SI, at the motor shaft).

    kv               : position-loop gain [1/s]
    velocity_hz      : velocity-loop gain (crossover on the rigid axis) [Hz]
    kvp              : velocity-loop proportional gain [N*m*s/rad]
    ti, tf, tc       : velocity integral time, torque-filter and current-loop time constants [s]
    inertia          : total inertia at the motor the gain is set for [kg*m^2]
    f_n              : the natural frequency the rule started from [Hz]
    notch_hz         : torque-reference notch filter centre [Hz] (at the rotor-screw torsion
                       mode; 0: none)
    """

    kv: float
    velocity_hz: float
    kvp: float
    ti: float
    tf: float
    tc: float
    inertia: float
    f_n: float
    notch_hz: float = 0.0
    rule: str = RULE

    @property
    def kv_m_min_per_mm(self) -> float:
        return self.kv / KV_M_MIN_PER_MM


def tune(
    ev: Evaluation, current_loop_hz: float = CURRENT_LOOP_HZ, notch: bool = True
) -> ServoGains:
    """One set of gains for the axis (a drive has one): the rule at the lowest ``f_axial`` over the
    stroke;
    ``notch``: a torque-reference notch at the second drive-train mode (rotor against screw across
    the coupling), as drives set one for a ball screw's torsion resonance (Yaskawa Pn409-Pn40B)."""
    f_n = float(np.min(ev["f_axial"]))
    kv = float(kv_rule(f_n))
    f_v = VELOCITY_HZ_PER_KV * kv
    y = yaskawa_gains(f_v)
    inertia = float(ev["total_inertia"])
    f_notch = float(np.min(ev["f_axial_torsional_2"])) if notch else 0.0
    return ServoGains(
        kv=kv,
        velocity_hz=f_v,
        kvp=2.0 * math.pi * f_v * inertia,
        ti=y["Pn101_ms"] * 1e-3,
        tf=y["Pn401_ms"] * 1e-3,
        tc=1.0 / (2.0 * math.pi * current_loop_hz),
        inertia=inertia,
        f_n=f_n,
        notch_hz=f_notch,
    )


CL_INPUTS = ("position_command", "process_force")
CL_OUTPUTS = ("table_position", "tool_position", "motor_position", "motor_speed")
NOTCH_Q = 0.7  # notch quality factor (Yaskawa's default notch Q value 0.70)


def _series(a, b):
    """SISO state-space blocks (A, B, C, D) in series: a's output into b."""
    Aa, Ba, Ca, Da = a
    Ab, Bb, Cb, Db = b
    na, nb = Aa.shape[0], Ab.shape[0]
    A = np.block([[Aa, np.zeros((na, nb))], [Bb @ Ca, Ab]])
    B = np.vstack([Ba, Bb @ Da])
    C = np.hstack([Db @ Ca, Cb])
    return A, B, C, Db @ Da


def controller(g: ServoGains):
    """Velocity error at the motor [rad/s] -> motor torque [N*m]: PI, torque filter, notch, current
    loop."""

    def blk(A, B, C, D):
        return tuple(np.atleast_2d(np.asarray(v, dtype=float)) for v in (A, B, C, D))

    out = blk([[0.0]], [[1.0]], [[g.kvp / g.ti]], [[g.kvp]])
    out = _series(out, blk([[-1.0 / g.tf]], [[1.0 / g.tf]], [[1.0]], [[0.0]]))
    if g.notch_hz > 0:
        w = 2.0 * math.pi * g.notch_hz
        out = _series(
            out,
            blk(
                [[0.0, 1.0], [-w * w, -w / NOTCH_Q]], [[0.0], [1.0]], [[0.0, -w / NOTCH_Q]], [[1.0]]
            ),
        )
    return _series(out, blk([[-1.0 / g.tc]], [[1.0 / g.tc]], [[1.0]], [[0.0]]))


def closed_loop(ss: AxisStateSpace, g: ServoGains, *, position_loop: bool = True):
    """(A, B, C, D) of the axis with the cascade closed (inputs :data:`CL_INPUTS`: position command
    as table travel [m] and process force [N]; outputs :data:`CL_OUTPUTS`: table and tool position
    [m], motor angle through the lead [m], motor speed [rad/s at the motor]).
    ``position_loop=False`` leaves the position loop open and takes a velocity command [rad/s at the
    motor] as the first input (for the velocity-loop bandwidth).  The open-loop model must have the
    motor free.  States: the plant's, then the controller's."""
    if ss.motor_held:
        raise ValueError("closed_loop needs the open-loop model with the motor free")
    r = ss.lead / (2.0 * math.pi)
    i = ss.ratio
    Ac, Bc, Cc, _ = controller(g)
    n, m = ss.A.shape[0], Ac.shape[0]
    # velocity error at the motor: w_cmd - i omega_m with w_cmd = i Kv (x_ref - r theta_m) / r (or
    # the command)
    e_z = np.zeros(n)
    e_z[3] = -i
    e_u = np.zeros(2)
    if position_loop:
        e_z[0] = -i * g.kv
        e_u[0] = i * g.kv / r
    else:
        e_u[0] = 1.0
    A = np.zeros((n + m, n + m))
    A[:n, :n] = ss.A
    A[:n, n:] = np.outer(ss.B[:, 0], Cc[0])
    A[n:, :n] = np.outer(Bc[:, 0], e_z)
    A[n:, n:] = Ac
    B = np.zeros((n + m, 2))
    B[:n, 1] = ss.B[:, 1]
    B[n:, :] = np.outer(Bc[:, 0], e_u)
    C = np.zeros((4, n + m))
    C[0, 2] = 1.0
    C[1, 2] = 1.0
    C[2, 0] = r
    C[3, 3] = i
    return A, B, C, np.zeros((4, 2))


def _response(A, B, C, D, freqs, inp: int, out: int) -> np.ndarray:
    """Complex y_out / u_inp at ``freqs`` [Hz]: modal form C V (s - lambda)^-1 V^-1 B where A
    diagonalizes well, else one batched solve over the frequencies."""
    s = 2j * math.pi * np.asarray(freqs, dtype=float)
    lam, V = np.linalg.eig(A)
    if np.linalg.cond(V) < 1e8:
        left = C[out] @ V
        right = np.linalg.solve(V, B[:, inp])
        return (left * right / (s[:, None] - lam[None, :])).sum(axis=1) + D[out, inp]
    m = s[:, None, None] * np.eye(A.shape[0]) - A
    rhs = np.repeat(B[None, :, inp, None].astype(complex), len(s), axis=0)
    return np.linalg.solve(m, rhs)[..., 0] @ C[out] + D[out, inp]


def frequency_response(ev: Evaluation, freqs, gains: ServoGains | None = None) -> list:
    """Closed-loop compliance at the tool x_tool / F [m/N] (complex) at ``freqs`` [Hz], at stroke
    start, middle and end, with the tuned servo holding the position command."""
    g = gains or tune(ev)
    out = []
    for ss in stroke_state_spaces(ev):
        A, B, C, D = closed_loop(ss, g)
        out.append(_response(A, B, C, D, freqs, 1, 1))
    return out


def _bandwidth(A, B, C, D, inp: int, out: int, f_max: float) -> float:
    """-3 dB frequency of a unity-DC closed loop [Hz] (first crossing of |H| = 1/sqrt 2 on a fine
    grid)."""
    f = np.logspace(-1, math.log10(f_max), 400)
    h = np.abs(_response(A, B, C, D, f, inp, out))
    below = np.nonzero(h < 1.0 / math.sqrt(2.0))[0]
    if not len(below):
        return float("nan")
    j = int(below[0])
    if j == 0:
        return float(f[0])
    # log-linear interpolation between the grid points around the crossing
    a, b = h[j - 1], h[j]
    t = (a - 1.0 / math.sqrt(2.0)) / (a - b)
    return float(10 ** (math.log10(f[j - 1]) + t * (math.log10(f[j]) - math.log10(f[j - 1]))))


@dataclass(frozen=True)
class ServoResult:
    """The tuned servo on the model, per stroke position (start, middle, end as ``--frf``).

    gains              : :class:`ServoGains`
    position_mm        : nut positions along the stroke [mm]
    stable             : every closed-loop pole in the left half plane, per position
    min_damping        : smallest damping ratio of the closed-loop poles [-], per position
    velocity_bandwidth_Hz, position_bandwidth_Hz : -3 dB of the closed velocity / position loop [Hz]
    peak_compliance_um_per_N  : largest closed-loop compliance at the tool over frequency [um/N]
    rapid_speed, feed_speed   : the axis's max and mean speed [m/s]; ``following_error_rapid`` and
                         ``following_error_feed`` are v / Kv at them [m]
    """

    gains: ServoGains
    position_mm: tuple
    stable: tuple
    min_damping: tuple
    velocity_bandwidth_Hz: tuple
    position_bandwidth_Hz: tuple
    peak_compliance_um_per_N: tuple
    rapid_speed: float
    feed_speed: float

    @property
    def following_error_rapid(self) -> float:
        """Following error at rapid speed [m] (v / Kv, no feedforward)."""
        return following_error(self.rapid_speed, self.gains.kv)

    @property
    def following_error_feed(self) -> float:
        """Following error at the mean (feed) speed [m]."""
        return following_error(self.feed_speed, self.gains.kv)


def servo_response(
    ev: Evaluation,
    current_loop_hz: float = CURRENT_LOOP_HZ,
    *,
    gains: ServoGains | None = None,
    freqs=None,
) -> ServoResult:
    """Tune (:func:`tune`) and close the loops on the model at stroke start, middle and end."""
    g = gains or tune(ev, current_loop_hz)
    pos, stab, zmin, vbw, pbw, peak = [], [], [], [], [], []
    for ss in stroke_state_spaces(ev):
        A, B, C, D = closed_loop(ss, g)
        lam = np.linalg.eigvals(A)
        pos.append(ss.position_mm)
        stab.append(bool(np.all(lam.real < 0.0)))
        mag = np.abs(lam)
        z = -lam.real / np.where(mag > 0, mag, 1.0)
        zmin.append(float(np.min(z[mag > 1e-6])) if np.any(mag > 1e-6) else float("nan"))
        f_top = 10.0 * max(ss.natural_frequencies())
        pbw.append(_bandwidth(A, B, C, D, 0, 0, f_top))
        Av, Bv, Cv, Dv = closed_loop(ss, g, position_loop=False)
        vbw.append(_bandwidth(Av, Bv, Cv, Dv, 0, 3, f_top))
        f = np.logspace(0, math.log10(f_top), 600) if freqs is None else np.asarray(freqs, float)
        peak.append(float(np.max(np.abs(_response(A, B, C, D, f, 1, 1)))) * 1e6)
    a = ev.design.axis
    return ServoResult(
        g,
        tuple(pos),
        tuple(stab),
        tuple(zmin),
        tuple(vbw),
        tuple(pbw),
        tuple(peak),
        rapid_speed=float(a.max_speed),
        feed_speed=float(a.mean_speed_eff),
    )
