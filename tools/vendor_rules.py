"""The per-vendor rules of the independent checker (tools/vendor_check.py), written apart
from axisopt: which motor rule, the nut lift-off's load cases, the gearbox's emergency-stop torque.
Nothing here imports axisopt.

Sources (the rule as each vendor prints it):
* Yaskawa Sigma-7 product manual 11.2.1 / E-S product manual 2.4.1: effective torque <= rated
  torque, load torque TL <= rated torque.
* Mitsubishi MDS-D-SVJ3/SPJ3 Specifications Manual 7-1 (3): Trms <= 0.8 Tst (eq. 7-10); unbalanced
  axis TL <= 0.6 Tst (eq. 7-12); MR-J2S-A 11-5: TU = (W1 - W2) g dS / (2e3 pi eta).
* FANUC B-65262EN/03 3.1: Trms within the stall torque (example: 0.9 Ts), gravity holding <= 60 % of
  stall.
* Siemens 1FT7 PFT7S 2.4.3: RMS within the S1 characteristic.
* THK General Catalog A-725 / A-739: each phase's axial load (accelerating, constant, decelerating)
  on its own.
* Beckhoff AG2400 / AG3400 "Mechanical data": T2Em.stop, the output torque the gear unit may see
  1000 times in its life; Siemens 1FT7 5.4.1 and apexdyna / SEW current limitation: motor peak x i
  against it, or limit the current.
"""

from __future__ import annotations

import math
from dataclasses import replace

from vendor_procedures import Row, quantity

# vendor: (Trms / rated, unbalanced-axis load torque / rated, source)
SERVO_RULES = {
    "Yaskawa": (1.0, 1.0, "Yaskawa Sigma-7 11.2.1: T_rms <= T_rated; E-S 2.4.1: T_L <= T_rated"),
    "Mitsubishi Electric": (
        0.8,
        0.6,
        "Mitsubishi MDS-D-SVJ3 7-1 eq. 7-10/7-12: T_rms <= 0.8 T_st, T_L <= 0.6 T_st",
    ),
    "FANUC": (0.9, 0.6, "FANUC B-65262EN 3.1: T_rms <= 0.9 T_s (example), gravity <= 0.6 T_s"),
    "Siemens": (1.0, 1.0, "Siemens 1FT7 PFT7S 2.4.3: RMS within S1"),
}
NO_RULE = (0.8, 0.6, "no rule for this vendor: Mitsubishi's 0.8 / 0.6")


def servo_rule(vendor: str, asked=None) -> tuple:
    """(rms factor, unbalance factor, source) of a motor vendor; ``asked``: the design's
    rms_torque_ratio."""
    rms, unb, src = SERVO_RULES.get(vendor, NO_RULE)
    if asked is not None:
        return (
            float(asked),
            unb,
            f"axis.rms_torque_ratio {float(asked):g} (asked by the design); " + src,
        )
    return rms, unb, src


def unbalance_row(motor, weight_net, friction, lead, drag, eta, ratio, red_eff, theirs, rated):
    """Mitsubishi's unbalanced-axis rule (and FANUC's gravity-holding one): T_L = (|W g| +
    F_friction) P_h / (2 pi eta) + the nut's and bearings' drag, at the motor through the reduction,
    <= factor x rated."""
    _, unb, src = servo_rule(motor["vendor"])
    tl = ((abs(weight_net) + friction) * lead / (2 * math.pi * eta) + drag) / (ratio * red_eff)
    limit = unb * rated
    return Row(
        "unbalanced load torque",
        "N.m",
        tl,
        limit,
        limit / tl,
        theirs,
        None,
        "",
        src,
        f"weight net of a counterbalance {abs(weight_net):.0f} N + guide friction {friction:.0f} "
        f"N; limit {unb:g} x rated {rated:.3g} N.m",
    )


def emergency_row(red, motor, torque_limit, check):
    """The gearbox's emergency-stop torque against the motor's peak (or the drive's torque limit) x
    ratio."""
    stop = red.get("emergency_torque")
    listed = stop is not None and math.isfinite(stop)
    t2 = stop if listed else red["accel_torque"]
    peak = motor["peak_torque"] if torque_limit is None else min(motor["peak_torque"], torque_limit)
    need = peak * red["ratio"]
    return Row(
        "reduction T2Stop / motor peak x i",
        "N.m",
        t2,
        need,
        t2 / need,
        check.get("available"),
        check.get("margin"),
        "",
        f"Beckhoff AG2400/AG3400 ({red['id']}): T2Em.stop; Siemens 1FT7 5.4.1",
        ("T2Em.stop" if listed else "no T2Em.stop listed: T2B")
        + f"; motor peak {peak:.3g} N.m"
        + ("" if torque_limit is None else " (axis.torque_limit)")
        + f" x i {red['ratio']:g}",
    )


def lift_off_need(ax, phases, rapid_phases, friction, net, f_max, cut_while_accelerating):
    """The largest load the nut's preload must hold, each load case its own (THK A-725): the cut at
    feed speed (axis.axial_load + friction + weight), each duty phase's load (or, without a cycle,
    the rapid's), or all at once when the design says the cut happens while accelerating."""
    if cut_while_accelerating:
        return f_max, "the cut while accelerating: all at once"
    cut = ax.axial_load + friction + net
    loads = [abs(p.load) for p in phases if p.sign != 0]
    loads += [abs(p.load) + p.proc for p in phases if p.sign == 0]
    loads += [abs(p.load) for p in rapid_phases]
    return max(
        [cut] + loads
    ), "each load case its own load (T-GC A-725): the cut at feed, each phase"


def torque_limit(axis_yaml: dict):
    """The design's axis.torque_limit [N.m] or None."""
    return quantity(axis_yaml["torque_limit"]) if "torque_limit" in axis_yaml else None


def misumi_buckling(d1, la):
    """MiSUMi "Selection of Ball Screws 2" (Economy catalog p. 1676): P = m d^4 / l^2 x 1e4 [N] with
    m = 10 for a fixed-support shaft, l the distance between the points of buckling load [mm]: the
    nut a supported end."""
    return (
        10.0 * d1**4 / la**2 * 1e4,
        "MiSUMi p. 1676: P = m d^4 / l^2 x 1e4, m 10 (nut a supported end)",
    )


def cross_carriage_at(ax, whole, cross_mass, y):
    """The axis as the guides see a twin gantry with its cross carriage at y across the rails [m]:
    the whole moving mass's centre of gravity moved by the carriage's moment m_c y / m (the bridge
    stays where it is); the block statics then take the weight and the inertia there (THK
    A-16..A-20, A-84: P = W/4 + W l3 / 2 l1).
    """
    return replace(ax, y_cg=ax.y_cg + cross_mass * y / whole)
