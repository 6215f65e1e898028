"""Linear-motor drive as a sub-assembly: parameters in, outputs and margins out, on floats, numpy
arrays and CasADi symbols alike (the duty cycle enters as :func:`axisopt.physics.rack.cycle_gram`,
floats).  One drive side (a twin-drive gantry: the governing side).

HIWIN MM99TE07-1701 Appendix A: the force over the duty cycle, F = M a + (M g + Fa) mu (+ seal
friction, process force, weight on a vertical axis), its peak against the forcers' peak force and
its RMS against 0.7 x their continuous force (HIWIN: Ie / Ic "had better be less than 0.7") -- or
the steady thrust at feed where larger (the largest axial load against the peak, the mean one
against the RMS); the peak force for at most about 1 s (the longest acceleration phase, checked when
the peak exceeds the continuous force); the currents Ip = Fp / Kf, Ie = Fe / Kf where the row gives
Kf.  ``forcers`` forcers on one track add their forces (Siemens 1FN3 5.2).  The iron-core motor's
attraction Fa loads the guides (HIWIN: "must be taken up by the guide"): friction, block load, life
and static safety.  No screw: the feed-direction stiffness is the position loop's, M (2 pi f_bw)^2
at the servo bandwidth (an estimate); the first natural frequency is the table's on its guides.  The
positioning error is the stage's accuracy after compensation (the row's).

Keys of ``p`` (SI): m_axis, m_blocks, mu, f_seal, normal, vertical, forcers, fc, fp, kf (0: not
given), m_forcer, fa (per forcer), accuracy, t_acc (longest acceleration phase of the cycle),
bandwidth, k_n, blocks, thrust, mean_thrust.
"""

from __future__ import annotations

from .. import mathx as mx
from ..physics import linearmotor as plm
from ..physics import rack as pr
from ..physics.dynamics import table_mode_frequency
from .rackdrive import BIG


def lm_response(p, cycle) -> dict:
    """Outputs and margins of a linear-motor drive side (see the module)."""
    n = p["forcers"]
    m = p["m_axis"] + p["m_blocks"] + n * p["m_forcer"]
    fa = n * p["fa"]
    horiz = 1.0 - p["vertical"]
    resist = plm.friction_force(m * horiz, fa, p["mu"], p["normal"]) + p["f_seal"]
    weight = m * plm.G * p["vertical"]
    f_peak = mx.fmax(pr.peak_linear(cycle, m, resist, 1.0, weight), resist + p["thrust"] + weight)
    f_rms = mx.fmax(
        pr.rms_linear(cycle, m, resist, 1.0, weight), resist + p["mean_thrust"] + weight
    )
    k = plm.servo_stiffness(m, p["bandwidth"])
    has_kf = p["kf"] > 0.0
    kf = mx.fmax(p["kf"], 1e-9)
    out = {
        "moving_mass": m,
        "feed_force": f_peak,
        "feed_force_rms": f_rms,
        "attraction_force": fa,
        "peak_current": mx.if_else(has_kf, plm.current(f_peak / n, kf), 0.0),
        "rms_current": mx.if_else(has_kf, plm.current(f_rms / n, kf), 0.0),
        "stiffness": k,
        "frequency": table_mode_frequency(p["k_n"], p["blocks"], m),
        "lost_motion": 0.0 * m,
        "positioning_error": p["accuracy"],
    }
    margins = {
        "motor_peak": n * p["fp"] / f_peak,
        "motor_rms": plm.RMS_RATIO * n * p["fc"] / f_rms,
        "peak_time": mx.if_else(f_peak > n * p["fc"], plm.PEAK_TIME / p["t_acc"], BIG),
    }
    return {"outputs": out, "margins": margins}
