r"""The part vendors' selection formulas, written for tools/vendor_check.py apart from axisopt (no
axisopt import).

Units as the vendors print them: lengths in mm, forces in N, speeds in rpm (min^-1), rigidity in
N/um, life in revolutions / h / km.  Each function names its source: T-GC = THK General Catalog
(A-6xx..A-7xx ball screw, A-7..A-35 LM guide), H-BS = HIWIN Ballscrews BS-08-2-EN-1704-K (F 3.x),
H-LG = HIWIN Linear Guideway G99TE20-1808, NSK-SP = NSK super-precision bearings, IBC = IBC
TI-I-5010.2/E, IKO = IKO CAT-1578E.
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

G = 9.80665
E_THK = 2.06e5  # [N/mm^2] T-GC
RHO_THK = 7.85e-6  # [kg/mm^3] T-GC A-696
ALPHA_THK = 12e-6  # [1/K] T-GC A-715 eq. 38
ETA_THK = 0.9  # screw efficiency in THK's torque examples
DESIGN_RISE = 3.0  # [K] pretension target rise (T-GC A-715: 2-5 K; vendor practice 2-3 K)
# T-GC A-703 Table 18: machine tool with vibration or impact, 2.5 to 7 (lower bound)
NUT_STATIC_SAFETY = 2.5
WEIBULL_NUT = 10.0 / 9.0  # H-BS F 3.12
WEIBULL_IBC = 1.11  # IBC eq. 2.39

# conventions where the vendor's procedure and axisopt's differ on purpose (docs/validation.md)
CONVENTIONS = {
    "support bearing L10 life": "IBC Table 2.2 linear load split per bearing with the set's "
    "preload, no load factor, IBC eq. 2.39 over the bearings; axisopt: the 2^(3/2) preloaded-pair "
    "law on row groups, fw applied",
    "axial rigidity": "THK A-707 eq. 32 with the nut at its preload (A-710, no external load) and "
    "no torsion/"
    "coupling; axisopt's chain at its own least-stiff point without torsion and coupling terms",
    "RMS torque": "THK's friction f is constant (A-725); axisopt adds the guides' viscous friction "
    "at speed, and moves jerk-limited where the design gives a jerk (this checker: trapezoidal)",
    "unbalanced load torque": "THK's friction f is constant and the screw's eta 0.9 (A-725, "
    "A-745); axisopt's friction torque is its drag at the rapid speed (the guides' viscous term, "
    "the nut's preload torque by its own coefficient) through its screw efficiency",
    "nut lift-off": "THK's friction f is constant in each phase (A-725); axisopt takes the guides' "
    "friction at the rapid speed (with their viscous term) in every load case, as its life loads "
    "do",
    "holding torque": "THK A-745 credits the guide friction and divides by eta 0.9; axisopt: m g "
    "P_h / 2 pi",
    "unit support bearing L10 life": "THK gives the rotating-nut unit's bearing no procedure of "
    "its own (B-720 points to A-704): its printed Ca on the cycle's cubic-mean load, no preload; "
    "axisopt: a preloaded DB pair with an estimated 5 % Ca preload (the 2^(3/2) law), several "
    "times shorter",
    "reduction T2N": "the mean thrust's output torque with THK's constant guide friction (A-725: "
    "mu (m g + normal) + seals); axisopt's guide friction at the mean speed is its own (larger: "
    "its life_loads)",
    "guide static safety": "the largest block load with full feed, cross and normal forces and the "
    "peak acceleration together (this checker's load case); axisopt's load cases are its own",
}


UNITS = {
    "": 1.0,
    "-": 1.0,
    "mm": 1e-3,
    "m": 1.0,
    "um": 1e-6,
    "N": 1.0,
    "kN": 1e3,
    "kg": 1.0,
    "g": 1e-3,
    "h": 3600.0,
    "s": 1.0,
    "min": 60.0,
    "ms": 1e-3,
    "m/min": 1 / 60,
    "m/s": 1.0,
    "mm/s": 1e-3,
    "m/s^2": 1.0,
    "m/s2": 1.0,
    "m/s^3": 1.0,
    "N/um": 1e6,
    "N/m": 1.0,
    "K": 1.0,
    "deg": 1.0,
    "rpm": 1 / 60,
    "N.m": 1.0,
    "Nm": 1.0,
    "kg.cm^2": 1e-4,
    "kg.m^2": 1.0,
    "mm.rpm": 1.0,
    "km": 1e3,
    "EUR": 1.0,
    "W": 1.0,
    "N.m/rad": 1.0,
    "N.s/m": 1.0,
    "kg/m": 1.0,
    "EUR/m": 1.0,
    "mm^2/s": 1e-6,
    "W/(m^2.K)": 1.0,
    "%": 0.01,
    "arcmin": math.pi / 10800,
    "N.m/arcmin": 10800 / math.pi,
}
BECKHOFF_COMMISSIONING = "https://infosys.beckhoff.com/content/1033/ag2300_ba/8712251019.html"


def quantity(value) -> float:
    """'800 mm' -> 0.8; a bare number stays as it is."""
    if isinstance(value, (int, float)):
        return float(value)
    m = re.fullmatch(r"\s*([-+0-9.eE]+)\s*(\S*)\s*", str(value))
    if not m or m.group(2) not in UNITS:
        raise ValueError(f"cannot read the quantity {value!r}")
    return float(m.group(1)) * UNITS[m.group(2)]


@dataclass
class Row:
    check: str
    unit: str
    vendor: float  # the vendor's value (capacity or the quantity itself)
    limit: float | None  # what the vendor's criterion compares it with
    # vendor value / limit (>= 1 passes), or limit / value for "needed" quantities
    margin: float | None
    axisopt: float | None  # axisopt's value of the same quantity
    axis_margin: float | None
    kind: str  # AGREE / DIFF / CONV / INFO
    source: str
    note: str = ""
    # the vendor's procedure on axisopt's stated basis (its fw), compared instead
    same_basis: float | None = None

    @property
    def passes(self) -> bool:
        return bool(self.margin is None or self.margin >= 1.0 - 1e-9)


@dataclass
class Phase:
    dist: float  # travel [m] (>= 0)
    time: float  # [s]
    speed: float  # mean table speed in the phase [m/s]
    acc: float  # table acceleration [m/s^2], signed
    sign: int  # direction of motion (+1, -1, 0 at a dwell)
    proc: float  # process (feed) force against the motion [N] (>= 0)
    load: float  # axial force on the nut [N], signed, + along the axis (up on a vertical axis)


def move_phases(d, v, a, proc, moving, friction, weight):
    """A rest-to-rest move (trapezoidal profile, THK A-722) as accelerate / constant / decelerate
    phases with the nut load of each (T-GC A-725, A-739: Fa = m a + mu m g + f + process force, + m
    g vertical)."""
    s = 1 if d > 0 else -1
    # a counterbalanced head: the net weight by direction
    weight = weight(s) if callable(weight) else weight
    d = abs(d)
    v = min(v, math.sqrt(a * d)) if a > 0 else v
    ta = v / a if a > 0 else 0.0
    da = 0.5 * v * ta
    out = []
    for acc, dist, t in ((s * a, da, ta), (0.0, d - 2 * da, (d - 2 * da) / v), (-s * a, da, ta)):
        if t > 0:
            out.append(
                Phase(
                    dist, t, dist / t, acc, s, proc, moving * acc + s * (friction + proc) + weight
                )
            )
    return out


def duty_phases(ax, moving, friction, weight):
    """The duty cycle's phases (axis.duty_cycle), or, without one, the design's stated mean axial
    load with friction each way over the stroke (what the design says the nut sees on average).
    Returns (phases, given)."""
    # net weight by direction (+1 up, -1 down, 0 rest)
    w = weight if callable(weight) else (lambda _s: weight)
    if not ax.duty:
        f = ax.mean_load + friction
        v = ax.mean_speed
        return [
            Phase(ax.stroke, ax.stroke / v, v, 0.0, 1, ax.mean_load, f + w(1)),
            Phase(ax.stroke, ax.stroke / v, v, 0.0, -1, ax.mean_load, -f + w(-1)),
        ], False
    out = []
    for step in ax.duty:
        if "dwell" in step:
            t = quantity(step["dwell"])
            out.append(Phase(0.0, t, 0.0, 0.0, 0, 0.0, w(0)))
            continue
        v = quantity(step.get("speed", ax.v_max))
        a = quantity(step.get("acceleration", ax.a_max))
        # a twin drive's side: its share
        force = quantity(step.get("force", 0.0)) * getattr(ax, "force_share", 1.0)
        out += move_phases(quantity(step["move"]), v, a, force, moving, friction, w)
    return out, True


def default_drive_phases(ax, moving, friction, weight):
    """axisopt's documented default duty for the drive: the rapid move over the stroke and back, no
    dwell."""
    return move_phases(ax.stroke, ax.v_max, ax.a_max, 0.0, moving, friction, weight) + move_phases(
        -ax.stroke, ax.v_max, ax.a_max, 0.0, moving, friction, weight
    )


def mean_speed_rpm(phases, lead_mm):
    """Mean screw speed over the cycle, dwells included: revolutions / clock time (T-GC A-730 N_m =
    2 n l_S / P_h; H-BS F 3.4)."""
    total = sum(p.time for p in phases)
    return sum(p.dist for p in phases) * 1e3 / lead_mm / total * 60.0


def mean_travel_speed(phases):
    """Mean table speed over the cycle [m/s] (travel / clock time)."""
    return sum(p.dist for p in phases) / sum(p.time for p in phases)


def critical_speed(vendor, d1, lb, mounting):
    """Permissible speed from the shaft's dangerous speed [rpm].  HIWIN (H-BS F 3.27/F 3.28):
    n_k,max = 0.8 * 2.71e8 f_n d_k / l_s^2, f_n 1.0 / 0.692 / 0.147.  THK (T-GC A-696 eq. 8, 0.8
    included): N1 = lambda_2 d1 / l_b^2 * 1e7, lambda_2 21.9 / 15.1 / 3.4. d1 root diameter [mm], lb
    distance between the mounting surfaces [mm]."""
    if vendor == "HIWIN":
        fn = {"fixed-fixed": 1.0, "fixed-supported": 0.692, "fixed-free": 0.147}[mounting]
        return 0.8 * 2.71e8 * fn * d1 / lb**2, "H-BS F 3.27/3.28: 0.8 x 2.71e8 f_n d_k / l_s^2"
    lam = {"fixed-fixed": 21.9, "fixed-supported": 15.1, "fixed-free": 3.4}[mounting]
    return lam * d1 / lb**2 * 1e7, "T-GC A-696 eq. 8: lambda_2 d1 / l_b^2 x 1e7"


def dn_check(vendor, d0, d1, dw, n_max, dn_limit):
    """DN value.  HIWIN (H-BS F 3.29): DN = d_s n_max <= 90 000 ground (the catalog column).  THK
    (T-GC A-697 eq. 11, precision screw): N2 = 70 000 / D, D the ball centre diameter (here d1 +
    D_w, an estimate).  Returns (limit, value, source, note) in mm.rpm."""
    if vendor == "THK":
        d = d1 + dw
        return (
            70000.0,
            d * n_max,
            "T-GC A-697 eq. 11: D n <= 70 000",
            f"D = d1 + Dw = {d:.1f} mm (estimate)",
        )
    return dn_limit, d0 * n_max, "H-BS F 3.29: d_s n_max <= catalog DN limit", ""


def buckling_load(vendor, d1, la):
    """Permissible compressive (buckling) load [N], nut counted as a fixed end (T-GC A-726).
    HIWIN H-BS F 3.25/3.26: 0.5 * 4.072e5 f_k d_k^4 / l_s^2, f_k = 1 (fixed-fixed).
    THK T-GC A-694 eq. 6 (0.5 included): P1 = eta_2 d1^4 / l_a^2 * 1e4, eta_2 = 20 (fixed-fixed)."""
    if vendor == "HIWIN":
        return 0.5 * 4.072e5 * d1**4 / la**2, "H-BS F 3.25/3.26 (f_k 1.0, 0.5 safety)"
    return (
        20.0 * d1**4 / la**2 * 1e4,
        "T-GC A-694 eq. 6 (eta_2 20: nut-bearing section fixed-fixed, A-726)",
    )


def permissible_tension(d1):
    """T-GC A-694 eq. 7: P2 = sigma pi d1^2 / 4 = 116 d1^2 [N] (sigma = 147 MPa)."""
    return 147.0 * math.pi / 4.0 * d1**2


def thermal_pretension(d1, rise=None, vendor="THK"):
    """Pretension of a fixed-fixed screw that takes up a temperature rise [N]: the force that
    stretches the shaft by its thermal growth with Hooke's law, E A alpha dT; alpha 11.6e-6/K for
    HIWIN (H-BS F 3.36), 12e-6/K otherwise (T-GC A-715 eq. 38)."""
    alpha = 11.6e-6 if vendor == "HIWIN" else ALPHA_THK
    return E_THK * math.pi / 4.0 * d1**2 * alpha * (DESIGN_RISE if rise is None else rise)


def nut_load_factor(vendor, v_max, given):
    """Load factor of the nut: HIWIN fp 1.3-1.8 'operation under normal conditions' (H-BS p. 25;
    lower bound 1.3); THK fW Table 19 (A-704) by speed, lower bound: <= 0.25 m/s 1.0, <= 1 m/s 1.2,
    <= 2 m/s 1.5, else 2.0.  A larger axis.load_factor given in the design is used.  Returns
    (factor, text)."""
    if vendor == "HIWIN":
        fw, src = 1.3, "fp 1.3 (H-BS p. 25, normal operation)"
    else:
        fw = 1.0 if v_max <= 0.25 else 1.2 if v_max <= 1.0 else 1.5 if v_max <= 2.0 else 2.0
        src = f"fW {fw} (T-GC A-704 Table 19 at {v_max:.2f} m/s)"
    if given is not None and given > fw:
        return given, f"fW {given} (axis.load_factor)"
    return fw, src


def preloaded_halves(preload, f):
    """Loads on the two halves of a preloaded double nut under the signed load f (H-BS F 3.6, F 3.7
    and the flow chart p. 26): the pressed half (1 + |f|/(2^1.5 F_pr))^1.5 F_pr below F_lim = 2^1.5
    F_pr, |f| above it; the other half that minus |f| (0 after lift-off).  Returns (half +, half
    -)."""
    x = abs(f)
    pressed = (1 + x / (2**1.5 * preload)) ** 1.5 * preload if x < 2**1.5 * preload else x
    other = max(pressed - x, 0.0)
    return (pressed, other) if f >= 0 else (other, pressed)


def nut_life_h(c_dyn, preload, phases, fw, nm):
    """Nut L10 life [h].  Preloaded nut (HIWIN H-BS F 3.7-F 3.13): each half's cubic-mean load over
    the phases (weighted by revolutions = travel, with fp inside the mean, F 3.9), L_i =
    (C/F_bm,i)^3 1e6, L = (L1^(-10/9)
    + L2^(-10/9))^(-9/10), L_h = L / (60 n_m).  Single nut (THK A-704..A-706 eqs. 27, 28, 30): the
      greater of
    the two directions' cubic means (the other sign counted as zero over the whole travel), L =
    (Ca/(fW F_m))^3 1e6.  Returns (hours, source)."""
    moving = [p for p in phases if p.dist > 0]
    total = sum(p.dist for p in moving)
    if preload > 0:
        lives = []
        for k in (0, 1):
            fbm = (
                sum((preloaded_halves(preload, p.load)[k] * fw) ** 3 * p.dist for p in moving)
                / total
            ) ** (1 / 3)
            lives.append((c_dyn / fbm) ** 3 * 1e6)
        rev = sum(life**-WEIBULL_NUT for life in lives) ** (-1 / WEIBULL_NUT)
        return rev / (60 * nm), "H-BS F 3.7-3.13 (both halves, Weibull 10/9)"
    fm = max(
        (sum(max(s * p.load, 0.0) ** 3 * p.dist for p in moving) / total) ** (1 / 3)
        for s in (1, -1)
    )
    return (c_dyn / (fw * fm)) ** 3 * 1e6 / (
        60 * nm
    ), "T-GC A-704..A-706 eqs. 27, 28, 30 (greater direction)"


ROWS = {
    "DB": (1, 1),
    "DF": (1, 1),
    "DBD": (2, 1),
    "DFD": (2, 1),
    "DBB": (2, 2),
    "DFF": (2, 2),
    "DBT": (3, 1),
    "DFT": (3, 1),
}
# IBC TI-I-5010.2/E Table 2.2 (eqs. 2.8-2.31): per single bearing, (bearings in the load direction,
# opposite): unloading at X Fv; until then A = a0 Fv + a1 F (each loaded bearing), B = b0 Fv - b1 F
# (each opposite one); after: A = after F, B = 0
IBC_SPLIT = {
    (1, 1): (2.83, 1.00, 0.67, 1.00, 0.33, 1.0),
    (2, 1): (5.66, 0.84, 0.47, 1.36, 0.24, 0.617),
    (1, 2): (2.83, 1.36, 0.52, 0.84, 0.30, 1.0),
    (2, 2): (5.66, 0.84, 0.40, 0.84, 0.22, 0.617),
    (3, 1): (8.49, 0.73, 0.38, 1.57, 0.18, 0.463),
    # the single of 3:1 loaded is not a row of Table 2.2: this checker's line through its end
    # points, the single's 1.57 Fv at no load and the unloading at 2.83 Fv (X = 2.83 x the bearings
    # loaded, as every row of the table), the opposite three's 0.73 Fv (the 3:1 row's A) falling to
    # 0 there
    (1, 3): (2.83, 1.57, 0.445, 0.73, 0.258, 1.0),
}


# the preload force the set's catalog value names (the axial force across the set at no load) in
# units of IBC's Fv: the side of the set that carries it at Fae = 0 is 1 bearing x 1.0 Fv (DB/DF),
# the single bearing of a 2:1 set 1.36 Fv (IBC eq. 2.11/2.13), 2 bearings x 0.84 Fv (2:2, eq.
# 2.22/2.23).  NSK-SP p. 168 prints for 25TAC62B DF 3 150 N, DFD 4 300 N (4 300 / 1.36 = 3 162 N,
# the DF value: the reading holds), DFF 6 250 N.
IBC_SET_PRELOAD = {(1, 1): 1.0, (2, 1): 1.36, (2, 2): 1.68, (3, 1): 1.57}


LIFT_SET_PRELOAD = {(1, 1): 1.0, (2, 1): 1.36, (3, 1): 1.57, (2, 2): 2.0}


def bearing_lift_off(brg, f_max, pretension):
    """Lift-off of the support set by IBC Table 2.2 (unloading at Fae > X Fv, X of the bearings
    loaded against the opposite ones), each direction: the static pretension with the largest axial
    force on the rows facing it, the largest axial force alone on the others (a warm screw loses its
    pretension); the set mounted the way round that gives the larger margin.  Returns (available,
    needed, margin, note) [N]."""
    n1, n2 = ROWS[brg["arrangement"]]
    # the set's preload over the DB pair's for the unloading point: NSK p. 168 prints a quadruplex
    # (2:2) at 1.98 x its duplex, a triplex (2:1) at 1.37 x (IBC's single bearing of 2:1 / 3:1: 1.36
    # / 1.57 Fv); the 1.68 of IBC_SET_PRELOAD is the 2:2 set's per-bearing load factor (2 x 0.84)
    # the life reads, not its preload
    fv = brg["preload"] / LIFT_SET_PRELOAD[(max(n1, n2), min(n1, n2))]
    best = None
    for a, b in ((n1, n2), (n2, n1)):  # a: rows facing the pretension
        push, back = IBC_SPLIT[(a, b)][0] * fv, IBC_SPLIT[(b, a)][0] * fv
        m = min(push / (f_max + pretension), back / f_max)
        cand = (
            (push, f_max + pretension, m)
            if push / (f_max + pretension) <= back / f_max
            else (back, f_max, m)
        )
        if best is None or m > best[2]:
            best = cand + (
                f"{a} rows face the pretension: X {IBC_SPLIT[(a, b)][0]} / {IBC_SPLIT[(b, a)][0]}"
                f" x Fv {fv:.0f} N",
            )
    return best


def ibc_bearing_loads(n_load, n_other, fv, f):
    """Axial load of each bearing facing the load and of each opposite bearing (IBC Table 2.2), f
    >= 0."""
    x, a0, a1, b0, b1, after = IBC_SPLIT[(n_load, n_other)]
    if f > x * fv:
        return after * f, 0.0
    return a0 * fv + a1 * f, max(b0 * fv - b1 * f, 0.0)


def bearing_life_h(brg, phases, pretension, nm, fw=1.0):
    """Support-bearing set L10 life [h] by IBC TI-I-5010.2/E: the set's single-bearing rating (the
    printed set rating / i^0.7 for the printed rows, IBC eq. 2.4, NSK-SP p. 111), each bearing's
    axial load per phase from Table 2.2 (the rows facing each direction carry it), each bearing's
    cubic-mean load weighted by revolutions (eq. 2.34), L10 = (Ca/P)^3 1e6 (eq. 2.37), the set's
    life over its bearings (eq. 2.39, exponent 1.11).  The strong rows face the direction that gives
    the longer life (designer's choice); on a fixed-fixed screw the pretension presses the set, in
    the worse sense.  Returns (hours, source, note)."""
    n_plus, n_minus = ROWS[brg["arrangement"]]
    c_single = brg["dynamic_load_rating"] / max(n_plus, n_minus) ** 0.7
    fv = brg["preload"] / IBC_SET_PRELOAD[(max(n_plus, n_minus), min(n_plus, n_minus))]
    moving = [p for p in phases if p.dist > 0]
    total = sum(p.dist for p in moving)
    worst = math.inf
    for pre_sign in (1, -1) if pretension else (1,):
        best = 0.0
        for orient in (1, -1):
            np_, nm_ = (n_plus, n_minus) if orient == 1 else (n_minus, n_plus)
            cubes = {+1: 0.0, -1: 0.0}  # per bearing of the group facing + / -
            for p in moving:
                f = p.load + pre_sign * pretension
                face = 1 if f >= 0 else -1
                n_load, n_opp = (np_, nm_) if face == 1 else (nm_, np_)
                a, b = ibc_bearing_loads(n_load, n_opp, fv, abs(f))
                a, b = a * fw, b * fw
                cubes[face] += a**3 * p.dist
                cubes[-face] += b**3 * p.dist
            lives = []
            for face, count in ((1, np_), (-1, nm_)):
                pm = (cubes[face] / total) ** (1 / 3)
                # unloaded rows
                lives += [(c_single / pm) ** 3 * 1e6 if pm > 0 else math.inf] * count
            rev = sum(life**-WEIBULL_IBC for life in lives) ** (-1 / WEIBULL_IBC)
            best = max(best, rev / (60 * nm))
        worst = min(worst, best)
    angle = brg.get("contact_angle") or 60.0
    note = (
        f"{brg['arrangement']}: {n_plus}/{n_minus} rows, Ca single {c_single / 1e3:.1f} kN, set "
        f"preload {brg['preload']:.0f} N = IBC Fv {fv:.0f} N"
        + ("" if angle >= 59 else f"; IBC's table is for 60 deg, this set {angle:.0f} deg")
    )
    return worst, "IBC Table 2.2, eqs. 2.4, 2.34, 2.37, 2.39", note


def hertz_group_loads(preload, n_a, n_b, f):
    """Loads [N] on the group of ``n_a`` bearings and on the opposite ``n_b`` of a matched set with
    the set preload ``preload`` under an axial force ``f`` >= 0 on the ``n_a`` group: each bearing's
    contact deflects as (Q / K)^(2/3) (Hertz, ball on race), the groups' deflections change by the
    same amount in opposite senses, and Q_a - Q_b = f (found by bisection; K drops out).  Written
    here apart from axisopt's physics."""
    da0, db0 = (preload / n_a) ** (2 / 3), (preload / n_b) ** (2 / 3)

    def q(u):
        return n_a * (da0 + u) ** 1.5, n_b * max(db0 - u, 0.0) ** 1.5

    lo, hi = 0.0, 1.0
    while q(hi)[0] - q(hi)[1] < f:
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if q(mid)[0] - q(mid)[1] < f else (lo, mid)
    return q(0.5 * (lo + hi))


def nsk_printed_loads(preload, f):
    """Loads [N] on the pressed group and the other of an NSK set with as many bearings each way
    (DB/DF, DBB/DFF) under an axial force ``f`` >= 0, as NSK prints them (NSK-SP pp. 140-141, with
    no radial load): F_a1 = F_ap + 2/3 F_ae, F_a2 = F_ap - 1/3 F_ae; once F_a2 would be below 0,
    F_a1 = F_ae and F_a2 = 0 (DBB: per bearing half of each, the same per group)."""
    a, b = preload + 2.0 * f / 3.0, preload - f / 3.0
    return (f, 0.0) if b < 0.0 else (a, b)


def nsk_set_life_h(brg, phases, pretension, nm, fw=1.0):
    """Support-set L10 life [h] by the bearing maker's group ratings (NSK-SP pp. 110-111: Ca printed
    by the rows loaded; the other direction's rows by i^0.7) with each group's load from Hertz's
    contact law (:func:`hertz_group_loads`; for as many rows each way NSK's printed split,
    :func:`nsk_printed_loads`), the cubic mean over travel, L10 = (Ca / P)^3 1e6 per
    group, the groups' lives combined with NSK's exponent 1.1; the pretension on the rows the
    designer turns to it (the way round that lives longer).  Returns (hours, source, note)."""
    n1, n2 = ROWS[brg["arrangement"]]
    strong = max(n1, n2)
    rating = {n: brg["dynamic_load_rating"] * (n / strong) ** 0.7 for n in (n1, n2)}
    moving = [p for p in phases if p.dist > 0]
    total = sum(p.dist for p in moving)
    best = 0.0
    for a, b in ((n1, n2), (n2, n1)):  # a: the rows facing the pretension (+)
        ends = []
        # with a pretension (both ends held) the two ends' sets see the cycle in opposite senses:
        # the worse governs; one set alone is turned the way that lives longer
        for sign in (1, -1):
            cubes = [0.0, 0.0]
            for p in moving:
                f = sign * p.load + pretension
                if n1 == n2:
                    qa, qb = nsk_printed_loads(brg["preload"], abs(f))
                    qa, qb = (qa, qb) if f >= 0 else (qb, qa)
                elif f >= 0:
                    qa, qb = hertz_group_loads(brg["preload"], a, b, f)
                else:
                    qb, qa = hertz_group_loads(brg["preload"], b, a, -f)
                cubes[0] += (qa * fw) ** 3 * p.dist
                cubes[1] += (qb * fw) ** 3 * p.dist
            lives = [
                (rating[n] / (c / total) ** (1 / 3)) ** 3 * 1e6
                for n, c in zip((a, b), cubes)
                if c > 0
            ]
            ends.append(sum(life**-1.1 for life in lives) ** (-1 / 1.1) / (60 * nm))
        best = max(best, min(ends) if pretension else max(ends))
    return (
        best,
        "NSK-SP pp. 110-111 (Ca by rows loaded), "
        + (
            "pp. 140-141 split (2/3, 1/3 of the load to 3 x preload)"
            if n1 == n2
            else "Hertz load split (the contact law NSK states, p. 140; no printed line for 3 "
            "against 1)"
        ),
        (
            f"{brg['arrangement']}: groups {n1}/{n2}, Ca {rating[n1] / 1e3:.1f} / "
            f"{rating[n2] / 1e3:.1f} kN; "
            + (
                "the worse end's set (the cycle against the pretension one way at each end)"
                if pretension
                else "the set turned the way that lives longer"
            )
        ),
    )


def bearing_permissible_load(brg):
    """Permissible axial load of the set in its weaker direction [N].  60-degree screw-support sets
    (NSK TAC B, HIWIN WBK): 0.7 x the limiting axial load (NSK-SP p. 111 footnote 2), the printed
    value scaled to the weak direction's rows.  THK BK units: the printed permissible load (T-GC
    A-806).  Others: C0a / 2.5 (IBC eq. 2.6).  Returns (load, source, generic): ``generic`` when the
    rating has no vendor factor of its own (IBC's general S0)."""
    strong, weak = max(ROWS[brg["arrangement"]]), min(ROWS[brg["arrangement"]])
    c0 = brg["static_load_rating"] * weak / strong
    if brg["vendor"] == "THK":
        return c0, "T-GC A-806 permissible load", False
    if brg["arrangement"].startswith("DF") or "TAC" in str(brg.get("series", "")):
        return 0.7 * c0, "NSK-SP p. 111 fn. 2: 0.7 x limiting axial load", False
    return c0 / 2.5, "IBC eq. 2.6: C0a / S0, S0 = 2.5", True


def block_reactions(ax, forces):
    """Radial (vertical) and lateral reaction of each guide block on a rigid table (equal block
    stiffness, the least-norm statics THK's examples A-16..A-20 reduce to: P = F/4 +- M/(2 l0) +-
    M/(2 l1)).  forces: list of (force (x, y, z) [N], point (x, y, z) [m]); x along the axis, z up
    from the rail mounting plane; the screw takes the axial force at the origin (an estimate: screw
    axis at the rail plane under the table centre)."""
    per_rail = max(ax.blocks // 2, 1)
    xs = (
        np.linspace(-ax.block_spacing / 2, ax.block_spacing / 2, per_rail)
        if per_rail > 1
        else np.zeros(1)
    )
    pos = [(x, y) for y in (-ax.rail_spacing / 2, ax.rail_spacing / 2) for x in xs]
    n = len(pos)
    a = np.zeros((5, 2 * n))
    for i, (x, y) in enumerate(pos):
        a[:, i] = (1, 0, y, -x, 0)  # vertical reaction: sum, moment about x, about y
        a[:, n + i] = (0, 1, 0, 0, x)  # lateral reaction: sum, moment about z
    total = np.zeros(3)
    moment = np.zeros(3)
    for f, p in forces:
        f, p = np.asarray(f, float), np.asarray(p, float)
        total += f
        moment += np.cross(p, f)
    b = -np.array([total[2], total[1], moment[0], moment[1], moment[2]])
    r = np.linalg.lstsq(a, b, rcond=None)[0]
    return np.abs(r[:n]) + np.abs(r[n:])  # P_E = |P_R| + |P_T| (T-GC A-16, H-LG 1-4)


def table_forces(ax, moving, acc, feed, scale, sign_cross=1.0):
    """Forces on the table: weight at the centre of gravity, inertia, and the cut at the tool point
    (feed force against the motion `feed` signed along x, cross and normal components scaled by
    `scale`)."""
    gvec = (-G, 0, 0) if ax.vertical else (0, -G, 0) if ax.wall else (0, 0, -G)
    cg = (0.0, ax.y_cg, ax.h_cg)
    tool = (0.0, ax.y_tool, ax.h_tool)
    return [
        (tuple(moving * g for g in gvec), cg),
        ((-moving * acc, 0, 0), cg),
        ((feed, sign_cross * ax.cross * scale, -ax.normal * scale), tool),
    ]


def block_loads_max(ax, moving, a_peak):
    """Largest block load: full feed force either way, the peak acceleration either way, cross load
    either way."""
    worst = 0.0
    for fs in (1, -1):
        for ac in (1, -1):
            for cs in (1, -1):
                worst = max(
                    worst,
                    block_reactions(
                        ax, table_forces(ax, moving, ac * a_peak, fs * ax.axial_load, 1.0, cs)
                    ).max(),
                )
    return worst


GUIDE_BASIS = {
    ("HIWIN", "ball"): 50,
    ("HIWIN", "roller"): 100,
    ("THK", "ball"): 50,
    ("THK", "roller"): 100,
    ("IKO", "ball"): 50,
    ("IKO", "roller"): 50,
    ("NBS", "ball"): 50,
}


def guide_rating_life(c, p, kind, basis):
    """Rating life of a guide block [km]: L = (C/P)^e x basis, e = 3 ball, 10/3 roller (T-GC A-10
    eqs. 2/3, H-LG eqs. 1.2/1.3, IKO CAT-1578E III-7 eqs. 1/2); basis = the travel C is defined for
    [km]."""
    return (c / p) ** (3.0 if kind == "ball" else 10.0 / 3.0) * basis


def guide_static_safety(vendor, kind):
    """Least static safety factor C0/P for a machine tool axis (vibration / impact class, lower
    bound): HIWIN H-LG Table 1-1 3.0; THK T-GC A-9 Table 1 (normal motion, impact) 2.5; IKO Table
    2.1/2.2 (vibration and shock) ball 3, roller 4; others 3."""
    fs = {"HIWIN": 3.0, "THK": 2.5, "IKO": 3.0 if kind == "ball" else 4.0}.get(vendor, 3.0)
    return fs, {
        "HIWIN": "H-LG Table 1-1",
        "THK": "T-GC A-9 Table 1",
        "IKO": "IKO CAT-1578E Tables 2.1/2.2",
    }.get(vendor, "H-LG Table 1-1 (no vendor table)") + f": f_S >= {fs}"


def guide_life_km(guide, ax, phases, cycle_given, moving, fw_given=None):
    """Guide block L10 travel [km] of the most loaded block: its cubic-mean load over the phases
    (T-GC A-32) with the block preload (T-GC A-112, lift-off at 2.8 x preload), L = (C / (fW Pm))^e
    x basis (T-GC A-10 eqs. 4/5, H-LG eqs. 1.4/1.5, IKO III-7: e = 3 ball, 10/3 roller; basis = the
    vendor's rating distance); fW by speed (T-GC A-12 Table 3, H-LG Table 1-2; IKO Table 1 normal
    operation 1.2).  Returns (km, source, note)."""
    kind, vendor = guide["type"], guide["vendor"]
    basis = GUIDE_BASIS.get((vendor, kind), 50)
    fw = (
        1.2
        if vendor == "IKO"
        else (
            1.0 if ax.v_max <= 0.25 else 1.2 if ax.v_max <= 1.0 else 1.5 if ax.v_max <= 2.0 else 2.0
        )
    )
    if ax.load_factor is not None and ax.load_factor > fw:
        fw = ax.load_factor
    fw = fw if fw_given is None else fw_given
    moving_phases = [p for p in phases if p.dist > 0]
    cubes = None
    for p in moving_phases:
        scale = p.proc / ax.axial_load if ax.axial_load > 0 else 0.0
        loads = block_reactions(ax, table_forces(ax, moving, p.acc, -p.sign * p.proc, scale))
        cubes = loads**3 * p.dist if cubes is None else cubes + loads**3 * p.dist
    pm_ext = (cubes.max() / sum(p.dist for p in moving_phases)) ** (1 / 3)
    p0 = guide.get("preload") or 0.0
    # preload (T-GC A-112: "calculate the service life while taking into account the magnitude of
    # the preload"; its effect lasts to about 2.8 x the preload): the block's balls as a preloaded
    # pair (H-BS F 3.7 form)
    pm = preloaded_halves(p0, pm_ext)[0] if p0 > 0 else pm_ext
    km = guide_rating_life(guide["dynamic_load_rating"], fw * pm, kind, basis)
    note = (
        f"basis {basis} km ({vendor} {kind}; csv column "
        f"{guide.get('rating_distance', 0) / 1e3:.0f} km), fW {fw}, Pm {pm_ext:.0f} N, with "
        f"preload {p0:.0f} N: {pm:.0f} N"
        + ("" if cycle_given else "; no cycle: feed at mean_axial_load")
    )
    return km, "T-GC A-10/A-32, H-LG eq. 1.4/1.5, IKO III-7", note


def nut_rigidity(nut, preload, f_max):
    """Nut rigidity [N/um]: preloaded, K_N = 0.8 K (F_a0 / F_ref)^(1/3) (T-GC A-710, H-BS F 3.34
    with F_ref = 0.1 Ca, the catalog's `stiffness_preload`); single nut, the same law at the axial
    load (T-GC A-710 0.3 Ca, H-BS F 3.35 0.28 Cdyn)."""
    load = preload if nut["type"] == "double" else f_max
    return 0.8 * nut["stiffness"] / 1e6 * (load / nut["stiffness_preload"]) ** (1 / 3)


def feed_rigidity(ax, screw, nut, brg, preload, f_max):
    """Least axial rigidity of the feed system over the stroke [N/um], T-GC A-707 eq. 32: 1/K =
    1/K_S + 1/K_N + 1/K_B + 1/K_H; K_S = A E / (1000 L) (eq. 33, fixed-supported/free, L bearing to
    nut) and A E L / (1000 a b) (eq. 34, fixed-fixed, each side through its own bearing set in
    parallel).  Returns (K, source, note)."""
    d1 = screw["root_diameter"] * 1e3
    ae = math.pi / 4 * d1**2 * E_THK
    kn = nut_rigidity(nut, preload, f_max)
    kb = brg["axial_rigidity"] / 1e6
    kh = ax.housing_k / 1e6 if ax.housing_k else math.inf
    kbr = ax.bracket_k / 1e6 if ax.bracket_k else math.inf
    span = ax.span * 1e3
    worst = math.inf
    for x in np.linspace(ax.start, ax.start + ax.stroke, 81) * 1e3:
        paths = [1 / (1000 * x / ae + 1 / kb + 1 / kh)]
        if ax.mounting == "fixed-fixed":
            paths.append(1 / (1000 * (span - x) / ae + 1 / kb + 1 / kh))
        k = 1 / (1 / sum(paths) + 1 / kn + 1 / kbr)
        worst = min(worst, k)
    missing = [
        n for n, v in (("bearing housing", ax.housing_k), ("nut bracket", ax.bracket_k)) if not v
    ]
    note = f"K_N {kn:.0f}, K_B {kb:.0f} N/um" + (
        f"; K_H of {', '.join(missing)} not given: rigid" if missing else ""
    )
    return worst, "T-GC A-707 eqs. 32-34, A-710", note


def preload_torque(preload, lead, d_pcd):
    """Preload (drag) torque of a preloaded nut [N.m], T-GC A-688 eq. 5: T_p = 0.05 (tan b)^-0.5
    F_a0 P_h / 2 pi, tan b = P_h / (pi D).  lead, d_pcd [mm]."""
    tan_b = lead / (math.pi * d_pcd)
    return 0.05 * tan_b**-0.5 * preload * lead / (2 * math.pi) / 1e3


def screw_inertia(d0, length):
    """Screw shaft inertia [kg.m^2], a solid steel cylinder of the outer diameter d0 [m] over its
    length [m]: J = pi rho d^4 L / 32 (T-GC A-718 'J = m D^2 / 8', D the outer diameter; rho 7.85e3
    kg/m^3, A-696)."""
    return math.pi * RHO_THK * 1e9 * d0**4 * length / 32


def holding_torque(weight, friction, lead):
    """Screw torque holding a vertical axis at a stop [N.m], T-GC A-745: T_s = (m g - f) P_h / (2 pi
    eta), the guide resistance f credited, eta = 0.9 dividing.  weight m g, friction f [N]; lead
    [m]."""
    return max(weight - friction, 0.0) * lead / (2 * math.pi * ETA_THK)


def drive_rows(
    ax,
    screw,
    nut,
    brg,
    motor,
    coupling,
    moving,
    friction,
    weight,
    phases,
    preload,
    n_sets,
    ev,
    cycle_given,
    red=None,
    unit_inertia=None,
):
    """Inertia ratio (T-GC A-718 with J = m D^2 / 8 of the nominal diameter, FANUC/HIWIN F 3.20),
    RMS torque (T-GC A-734/A-746: T_rms = sqrt(sum T_i^2 t_i / sum t_i) <= rated) and the holding
    torque at a stop on a vertical axis (T-GC A-745: T_s = (m g - f) P_h / (2 pi eta)).  A reduction
    row ``red`` (catalogs/ reductions.csv) gives i, eta_G and its input inertia (T-GC A-717..A-720
    with A = 1/i: J_load / i^2 + J_G on the motor, T_motor = T_out / (i eta_G)) and its rows
    (:func:`reduction_rows`); a rotating-nut unit's printed inertia ``unit_inertia`` [kg.m^2] (T-GC
    B-721) takes the place of the standing screw's."""
    # the per-vendor servo and gearbox rules (imports this module: here, not on top)
    import vendor_rules as vr

    lead = screw["lead"]  # [m]
    d0, d1 = screw["nominal_diameter"], screw["root_diameter"]
    j_screw = screw_inertia(d0, ax.span) if unit_inertia is None else unit_inertia
    j_table = moving * (lead / (2 * math.pi)) ** 2
    j_coup = coupling["inertia"] if coupling else 0.29e-3
    i = ax.ratio
    j_load = (j_table + j_screw + j_coup) / i**2 + ax.red_inertia
    brake = ax.brake == "yes" or (ax.brake == "auto" and ax.vertical)
    j_rotor = (
        motor["rotor_inertia_brake"]
        if brake and motor.get("rotor_inertia_brake")
        else motor["rotor_inertia"]
    )
    ratio = j_load / j_rotor
    drive = ev.get("drive", {})
    rows = [
        Row(
            "inertia ratio load/rotor",
            "-",
            ratio,
            ax.max_inertia_ratio,
            ax.max_inertia_ratio / ratio,
            drive.get("inertia_ratio"),
            None,
            "",
            "T-GC A-718 (J = m D^2/8, D outer), H-BS F 3.20",
            (
                f"screw {j_screw * 1e4:.1f} kg.cm^2 (nominal {d0 * 1e3:.0f} mm over the span "
                f"{ax.span * 1e3:.0f} mm,"
                " journals not known)"
                if unit_inertia is None
                else f"rotating-nut unit {j_screw * 1e4:.1f} kg.cm^2 (THK's printed J, T-GC "
                "B-721), screw standing"
            )
            + (
                f"; reduction i {i:g}, its input J {ax.red_inertia * 1e4:.2f} kg.cm^2 (A-718, A = "
                "1/i)"
                if red
                else ""
            )
            + "; limit axis.max_inertia_ratio",
        )
    ]
    # ball centre diameter: d1 + ball diameter, or, where the row prints no ball, THK's D from its
    # DN rule
    d_pcd = (
        (d1 + screw["ball_diameter"]) * 1e3
        if screw.get("ball_diameter")
        else nut_rotation_speed_limit(d0 * 1e3, screw["dn_limit"])[1]
    )
    drag = preload_torque(preload, lead * 1e3, d_pcd) if nut["type"] == "double" else 0.0
    drag += n_sets * (brg.get("starting_torque") or 0.0)
    # a counterbalanced head: its net weight at rest
    w_rest = weight(0) if callable(weight) else weight
    hold = holding_torque(w_rest, friction if ax.vertical else 0.0, lead) / (i * ax.red_eff)
    drv = phases if cycle_given else default_drive_phases(ax, moving, friction, weight)
    sq, tt, out_sq, out_peak = 0.0, 0.0, 0.0, 0.0
    for p in drv:
        if p.sign == 0:
            t = hold
            t_out = hold * i * ax.red_eff
        else:
            f_ext = p.load - moving * p.acc  # friction, process force, weight
            t_screw = f_ext * lead / (2 * math.pi * ETA_THK) + p.sign * drag
            alpha = p.acc * 2 * math.pi / lead * i  # motor angular acceleration
            t = t_screw / (i * ax.red_eff) + (j_load + j_rotor) * alpha
            # at the reduction's output
            t_out = t_screw + (j_table + j_screw + j_coup) * alpha / i
        out_sq += t_out * t_out * p.time
        out_peak = max(out_peak, abs(t_out))
        sq += t * t * p.time
        tt += p.time
    trms = math.sqrt(sq / tt)
    rated = motor["rated_torque"]
    rms_f, _, rule = vr.servo_rule(motor["vendor"], getattr(ax, "rms_asked", None))
    rows.append(
        Row(
            "RMS torque",
            "N.m",
            trms,
            rms_f * rated,
            rms_f * rated / trms,
            drive.get("rms_torque_Nm"),
            None,
            "",
            f"T-GC A-734/A-746: T_rms (eta 0.9, preload torque A-688 eq. 5); limit: {rule}",
            ("the duty cycle" if cycle_given else "default: rapid over the stroke and back")
            + f"; trapezoidal moves; limit {rms_f:g} x rated {rated:.3g} N.m",
        )
    )
    if ax.vertical:
        # rising or lowering
        w_worst = max(abs(weight(1)), abs(weight(-1))) if callable(weight) else w_rest
        rows.append(
            vr.unbalance_row(
                motor,
                w_worst,
                friction,
                lead,
                drag,
                ETA_THK,
                i,
                ax.red_eff,
                drive.get("unbalance_torque_Nm"),
                rated,
            )
        )
    if ax.vertical:
        cap = motor.get("brake_torque") if brake else rated
        rows.append(
            Row(
                "holding torque at a stop",
                "N.m",
                hold,
                cap,
                (cap / hold) if cap and hold else None,
                drive.get("holding_torque_Nm"),
                None,
                "",
                "T-GC A-745: T_s = (m g - f) P_h / (2 pi eta)",
                "f = guide friction credited; limit: "
                + ("brake torque" if brake else "rated torque"),
            )
        )
    if red:
        # the feed thrust at feed speed (axis.axial_load) and the mean thrust (axis.mean_axial_load)
        # as steady output torques: the largest output torque is the larger of the cycle's and the
        # thrust's, the continuous one the larger of the cycle's RMS and the mean thrust's (T-GC
        # eta 0.9)
        steady = [
            (f + friction + w_rest) * lead / (2 * math.pi * ETA_THK) + drag
            for f in (ax.axial_load, ax.mean_load)
        ]
        rows += reduction_rows(
            red,
            motor,
            max(out_peak, steady[0]),
            max(math.sqrt(out_sq / tt), steady[1]),
            ax.v_max / lead * 60 * i,
            ev.get("checks", {}),
        )
        rows.append(
            vr.emergency_row(
                red,
                motor,
                getattr(ax, "torque_limit", None),
                ev.get("checks", {}).get("reduction_emergency_torque") or {},
            )
        )
    return rows


def reduction_rows(red, motor, t_out_peak, t_out_rms, n_motor, checks):
    """A planetary gearbox by Beckhoff's data (AG2400 'Mechanical data'): T2B, 'maximum acceleration
    torque, maximum 1000 cycles per hour' >= the cycle's largest output torque; T2N, 'nominal output
    torque' >= the cycle's RMS output torque; n1Max >= the largest input (motor) speed.  Torques
    [N.m], speed [rpm].  And Beckhoff's commissioning rule (AG2300 manual, 'Commissioning',
    :data:`BECKHOFF_COMMISSIONING`) as an INFO row: :func:`gearbox_current_limits`."""
    t2b, t2n, n1 = red["accel_torque"], red["rated_torque"], red["max_input_speed"] * 60
    src = f"Beckhoff AG2400 mechanical data ({red['id']})"
    belt = str(red.get("kind")) == "belt"
    if belt:
        # a timing-belt stage by its belt maker's rule: the torque the belt transmits, F_U =
        # FUspez z_e b on the pulley (ELATECH, the row's rated and peak torque), FUspez tabled up
        # to the stage's top input speed
        src = f"ELATECH PU belts cat. p. 20, pp. 52-54 ({red['id']})"

    def theirs(name):
        c = checks.get(name) or {}
        return c.get("available"), c.get("margin")

    peak, rated = gearbox_current_limits(
        motor["peak_torque"], motor["rated_torque"], red["ratio"], t2b, t2n
    )
    rows = [
        Row(
            "reduction T2B / peak output torque",
            "N.m",
            t2b,
            t_out_peak,
            t2b / t_out_peak,
            *theirs("reduction_accel_torque"),
            "",
            src + (": F_U = FUspez z_e b on the pulley" if belt else ": T2B, max. 1000 cycles/h"),
            "the larger of the cycle's (screw torque, eta 0.9, + load-side J x alpha, trapezoidal "
            "moves) and the feed thrust's (axis.axial_load + friction)",
        ),
        Row(
            "reduction T2N / RMS output torque",
            "N.m",
            t2n,
            t_out_rms,
            t2n / t_out_rms,
            *theirs("reduction_rated_torque"),
            "",
            src + (": F_U on the pulley, continuous" if belt else ": T2N nominal output torque"),
            "the larger of the drive cycle's RMS (the duty cycle, else the rapid over the stroke "
            "and back) and the mean thrust's (axis.mean_axial_load + friction)",
        ),
        Row(
            "reduction n1Max / motor speed",
            "rpm",
            n1,
            n_motor,
            n1 / n_motor,
            *theirs("reduction_speed"),
            "",
            src + (": FUspez tabled to this speed" if belt else ": n1Max max. input speed"),
        ),
        Row(
            "reduction commissioning current limits",
            "%",
            100 * peak,
            None,
            None,
            None,
            None,
            "INFO",
            "Beckhoff AG2300 'Commissioning': limit peak (rated) current to T2B / (M_pmax i) (T2N "
            "/ (M i)); " + BECKHOFF_COMMISSIONING,
            f"peak current limit {100 * peak:.0f} %, rated current limit {100 * rated:.0f} % "
            "(rated torque in place of Beckhoff's M0)",
        ),
    ]
    # Beckhoff's commissioning rule is a gearbox's: a belt stage has no such row
    return rows[:-1] if belt else rows


def gearbox_current_limits(m_peak, m_rated, ratio, t2b, t2n):
    """Beckhoff's current limits for a motor on a gearbox (AG2300 manual, 'Commissioning'): the
    motor torque times i must not exceed the gearbox's, else the current is limited to the fraction
    T2B / (M_pmax i) (peak) and T2N / (M0 i) (rated), at most 1.  Torques [N.m].  Returns (peak,
    rated) fractions."""
    return min(1.0, t2b / (m_peak * ratio)), min(1.0, t2n / (m_rated * ratio))


def nut_rotation_speed_limit(d0, dn_limit):
    """Permissible speed of a rotating nut [rpm] by THK's DN rule (T-GC A-697: D n <= 70 000, D the
    ball centre diameter [mm]) applied to the nut's rotation; the screw row stores 70 000 d0 / D, so
    D = 70 000 d0 / dn_limit.  A standing screw has no critical speed (T-GC A-772..A-774: the nut
    turns, the shaft does not)."""
    dp = 70000.0 * d0 / dn_limit
    return 70000.0 / dp, dp


def unit_bearing_life_h(ca, phases, fw, nm):
    """L10 life of a rotating-nut unit's support bearing [h]: L = (Ca / (fw F_m))^3 x 10^6 rev (ball
    bearing; T-GC B-720 sends the DIR/BLR service life to A-704), F_m the cubic mean of the axial
    load by revolutions (A-730), L_h = L / (60 N_m), N_m the mean nut speed [rpm].  ca [N] (the
    DIR/BLR table's support-bearing Ca, B-721)."""
    dist = sum(p.dist for p in phases if p.sign)
    fm = (sum(abs(p.load) ** 3 * p.dist for p in phases if p.sign) / dist) ** (1 / 3)
    return (ca / (fw * fm)) ** 3 * 1e6 / (60 * nm)


SAG_K = {
    "fixed-free": 8.0,
    "fixed-supported": 185.0,
    "fixed-fixed": 384.0,
    "supported-supported": 384.0 / 5,
}


def screw_sag(mass_per_length, d1, span, mounting):
    """Own-weight sag of a horizontal screw [m]: delta = q L^4 / (k E I), q = m' g, I = pi d1^4 / 64
    (root diameter), k 8 cantilever, 185 propped cantilever, 384 both ends fixed, 384/5 simply
    supported (AISC Steel Construction Manual Table 3-23 cases 22, 12, 15, 1; E 206 GPa, T-GC
    A-694).  mass_per_length [kg/m]; d1, span [m]."""
    i_sec = math.pi * d1**4 / 64
    return mass_per_length * G * span**4 / (SAG_K[mounting] * E_THK * 1e6 * i_sec)


def counterbalance_weights(cb, head_weight):
    """The weight a counterbalanced vertical head leaves on the screw [N], by direction (+1 rising,
    -1 lowering, 0 at rest), and the mass moving with the head besides it [kg].  A counterweight M_c
    on a chain of efficiency
    eta_c: Mitsubishi MR-J2S-A 11 (eq. 11-18..21) and Yaskawa Sigma-7 11.2.1 take the unbalanced
    load as (M - M_c) g; the chain's friction opposes the motion, so it balances M_c g eta_c rising
    and M_c g / eta_c lowering (at rest M_c g); the counterweight and its chain accelerate with the
    head (Yaskawa: J_L with
    M + M_c).  A balance cylinder F(x) = F_0 .. F_1 over the stroke, pressure tolerance +/- t: the
    end of its range that leaves the screw the largest net weight, in every phase; its piston moves
    with the head."""
    kind = cb.get("kind", "none")
    if kind == "counterweight":
        mc, eta = quantity(cb["mass"]), float(cb.get("efficiency", 0.95))
        chain = quantity(cb.get("chain_mass", 0.0))
        net = {
            1: head_weight - mc * G * eta,
            -1: head_weight - mc * G / eta,
            0: head_weight - mc * G,
        }
        return (lambda s: net[s]), mc + chain
    f0 = quantity(cb["force"])
    f1 = quantity(cb["force_at_end"]) if "force_at_end" in cb else f0
    tol = quantity(cb.get("tolerance", 0.0))
    ends = (min(f0, f1) * (1 - tol), max(f0, f1) * (1 + tol))
    net = max((head_weight - f for f in ends), key=abs)
    return (lambda _s: net), quantity(cb.get("piston_mass", 0.0))


def twin_side(tw, bridge, nut_mass, block_mass_total):
    """A twin-drive gantry's governing side (statics of a beam on two supports, the cross carriage
    at the end of its stroke nearest the side): force share r = 1/2 + s/2L, and the side's moving
    mass m/2 + m_c s/2L of the whole m (bridge, cross carriage, both nuts, the blocks).  Returns (r,
    side mass, whole mass) [-, kg, kg]."""
    span, s = quantity(tw["span"]), quantity(tw["cross_stroke"])
    mc = quantity(tw.get("cross_mass", 0.0))
    whole = bridge + mc + 2 * nut_mass + block_mass_total
    return 0.5 + s / (2 * span), 0.5 * whole + mc * s / (2 * span), whole


def lead_band_um(grade: str, travel: float) -> float | None:
    """e_p + v_u [um] of THK A-678 Table 1 (catalogs/lead_tolerances.csv, C0-C5) for the band
    holding ``travel`` [m]; None for a grade or travel the table does not hold."""
    mm = travel * 1e3
    with open(
        Path(__file__).resolve().parents[1] / "catalogs" / "lead_tolerances.csv", encoding="utf-8"
    ) as fh:
        for r in csv.DictReader(fh):
            lo, hi = float(r["length_over [mm]"]), float(r["length_upto [mm]"])
            if r["grade"] == grade and (lo < mm <= hi or (lo == 0 and mm <= hi)):
                return float(r["travel_deviation [um]"]) + float(r["variation [um]"])
    return None
