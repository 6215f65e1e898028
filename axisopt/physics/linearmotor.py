"""Linear motors (iron-core and ironless): the vendors' sizing, all SI, on floats, numpy arrays and
CasADi symbols alike.

Sources:
- HIWIN Mikrosystem, Linear Motor System Technical Information MM99TE07-1701, Appendix A "Motor
  Sizing": Fp = M a + (M g + Fa) mu; Fe = sqrt(((Fi+Ff)^2 t1 + Ff^2 t2 + (Fi-Ff)^2 t3) /
  (t1+t2+t3+t4)); Ip = Fp / Kf below the peak current, Ie = Fe / Kf below the continuous current, Ie
  / Ic "had better be less than 0.7"; the 1/3-1/3-1/3 profile Vmax = 1.5 X / T, a = 4.5 X /
  T^2.  Definitions: the attraction force Fa of an iron-core motor "must be taken up by the guide";
  the peak force is available for about 1 s.
- Siemens SIMOTICS L-1FN3 Configuration Manual 10/2018 5.2: normal force on the guides
  F_n = F_perp + F_magn; friction mu F_n.
- Mitsubishi MR-J3-B linear servo selection: F_ma = M a + F_f, F_md = -M a + F_f, the RMS over t0.
"""

from __future__ import annotations

from .. import mathx as mx

G = 9.80665
RMS_RATIO = 0.7  # HIWIN Appendix A: Ie / Ic "had better be less than 0.7"
PEAK_TIME = 1.0  # [s] HIWIN: the peak force for about 1 s


def friction_force(mass, attraction, friction_coefficient, normal_force=0.0):
    """Guide friction [N]: mu (M g + Fa + F_n) (HIWIN Appendix A, Siemens 1FN3 5.2)."""
    return friction_coefficient * (mass * G + attraction + normal_force)


def peak_force(mass, acceleration, attraction, friction_coefficient, process_force=0.0):
    """HIWIN Appendix A: Fp = M a + (M g + Fa) mu (+ a process force) [N]."""
    return (
        mass * acceleration + friction_force(mass, attraction, friction_coefficient) + process_force
    )


def effective_force(inertia_force, friction, t1, t2, t3, t4):
    """HIWIN Appendix A: the RMS force of a cyclic move (accelerate t1, cruise t2, decelerate t3,
    dwell t4) [N]."""
    return mx.sqrt(
        (
            (inertia_force + friction) ** 2 * t1
            + friction**2 * t2
            + (inertia_force - friction) ** 2 * t3
        )
        / (t1 + t2 + t3 + t4)
    )


def trapezoid_profile(distance, time):
    """HIWIN Appendix A 1/3-1/3-1/3 trapezoid: (Vmax, a) = (1.5 X / T, 4.5 X / T^2)."""
    return 1.5 * distance / time, 4.5 * distance / time**2


def current(force, force_constant):
    """Current [A rms] for a force [N]: I = F / Kf."""
    return force / force_constant


def servo_stiffness(mass, bandwidth):
    """Static-equivalent stiffness of a direct drive's position loop at its bandwidth [N/m]:
    k = M (2 pi f)^2 -- the table held by the servo alone (no screw), an estimate of ours."""
    return mass * (2.0 * mx.pi * bandwidth) ** 2


def block_load(mass, attraction, normal_force, blocks):
    """Load on each guide block [N], evenly shared: (M g + Fa + F_n) / n (the attraction loads the
    guides)."""
    return (mass * G + attraction + normal_force) / blocks
