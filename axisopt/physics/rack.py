"""Rack and pinion drive: the vendors' sizing, all SI, on floats, numpy arrays and CasADi symbols
alike.

Sources:
- THK General Catalog A-241 (LM Guide GSR-R, "Checking Strength"): the largest thrust on the pinion
  against the pinion's permissible power-transmission capacity divided by an overload factor (Table
  4, excerpt of JGMA 401-01: uniform 1.0, medium impact 1.25, large impact 1.75 for an electric
  motor).
- Apex Dynamics / Yaskawa Sigma-7 manual 11.2.4: feed force F = m g mu + m a + F_process, pinion
  torque T = F d / 2, pinion speed n = v / (pi d); the rotary inertia of the linear mass m (d/2)^2.
- ISO 6336-1 (method B): mean mesh stiffness of steel spur and helical gears c_gamma ~ 20 N/(mm um)
  of face width.  No rack vendor publishes a mesh stiffness: :func:`mesh_stiffness` is this
  guidance, an estimate.
"""

from __future__ import annotations

from .. import mathx as mx

MESH_STIFFNESS_PER_WIDTH = (
    20e9  # c_gamma [N/m per m of face width] = 20 N/(mm um), ISO 6336-1 (an estimate)
)
OVERLOAD_FACTORS = {
    "uniform": 1.0,
    "medium": 1.25,
    "large": 1.75,
}  # THK A-241 Table 4 (JGMA 401-01)


def feed_force(
    mass, acceleration, friction_coefficient, normal_force, process_force, weight_along=0.0
):
    r"""Force the pinion pushes the axis with (Apex Dynamics, Yaskawa 11.2.4).

    .. math:: F = m a + \mu (m g + F_n) + F_p + W_\parallel

    mass : moving mass m [kg];  acceleration : a [m/s^2];  friction_coefficient : mu [-];
    normal_force : F_n, load pressing on the guides besides the weight [N];  process_force : F_p
        [N];
    weight_along : the weight's component along the axis (vertical axis: m g) [N].  Returns F [N].
    """
    return (
        mass * acceleration
        + friction_coefficient * (mass * 9.80665 + normal_force)
        + process_force
        + weight_along
    )


def pinion_torque(force, pitch_diameter):
    """Torque on the pinion shaft [N m] for a feed force [N]: T = F d / 2."""
    return force * pitch_diameter / 2.0


def pinion_speed(speed, pitch_diameter):
    """Pinion angular speed [rad/s] at a table speed [m/s]: omega = 2 v / d."""
    return 2.0 * speed / pitch_diameter


def linear_inertia(mass, pitch_diameter):
    """The moving mass as a rotary inertia at the pinion [kg m^2]: m (d/2)^2 (Yaskawa: GD^2 = W
    d^2)."""
    return mass * (pitch_diameter / 2.0) ** 2


def tooth_margin(permissible_force, overload_factor, force):
    r"""THK A-241: the pinion passes when the largest thrust does not exceed the permissible
    capacity divided by the overload factor; the margin is

    .. math:: \eta = \frac{P / K_o}{F_{max}}

    permissible_force : P [N];  overload_factor : K_o [-];  force : F_max [N] (> 0).  Returns the
        margin [-].
    """
    return permissible_force / overload_factor / force


def mesh_stiffness(face_width, pinions=1.0):
    """Feed-direction stiffness of the mesh [N/m]: c_gamma b per meshing pinion (ISO 6336-1
    guidance, an estimate), ``pinions`` meshing in parallel (2 for a preloaded twin pinion)."""
    return pinions * MESH_STIFFNESS_PER_WIDTH * face_width


def torsion_at_rack(torsional_stiffness, pitch_diameter):
    """A torsional stiffness [N m/rad] at the pinion seen at the rack [N/m]: k_t / (d/2)^2."""
    return torsional_stiffness / (pitch_diameter / 2.0) ** 2


def series(*stiffnesses):
    """Stiffnesses in series [N/m]."""
    c = 0.0
    for k in stiffnesses:
        c = c + 1.0 / k
    return 1.0 / c


def lost_motion(backlash, pitch_diameter, preloaded=0.0):
    """Lost motion at the rack [m] from a gearbox backlash [rad] at its output: backlash d/2; a
    preloaded twin pinion (``preloaded`` 1) holds both flanks and has none."""
    return (1.0 - preloaded) * backlash * pitch_diameter / 2.0


def pitch_error(error_per_metre, travel):
    """Cumulative pitch error of the rack over a travel [m] from its error per metre of rack [m/m];
    a rack of several pieces adds per metre (the quality class's cumulative tolerance per piece,
    worst case)."""
    return error_per_metre * travel


def cycle_gram(phases) -> dict:
    r"""Design-independent integrals of a duty cycle whose acceleration is linear in time within a
    phase.

    A drive force (or torque) of the form
    :math:`X(t) = \alpha a(t) + \beta s(t) + \varphi q(t) + \gamma`, with ``s`` the phase's
    direction of motion (-1, 0, +1) and :math:`q = F_{process} s` the phase's process force against
    the motion, has :math:`\int X^2 dt = c^T G c` exactly for
    :math:`c = (\alpha, \beta, \varphi, \gamma)` and the Gram matrix
    :math:`G_{ij} = \int u_i u_j dt` of :math:`u = (a, s, q, 1)` (:func:`rms_linear`); its extremes
    lie at the phases' corners (:func:`peak_linear`).  ``phases``: objects with ``duration``,
    ``a0``, ``a1``, ``direction``, ``force`` (:class:`axisopt.physics.motion.Phase`).  Returns
    ``{"gram": 4x4 nested tuple, "time": cycle time, "corners": ((a, s, q), ...)}``."""
    g = [[0.0] * 4 for _ in range(4)]
    corners = set()
    total = 0.0
    for ph in phases:
        t, a0, a1, d = ph.duration, ph.a0, ph.a1, float(ph.direction)
        q = d * ph.force
        const = (d, q, 1.0)  # s, q, 1 are constant within a phase
        g[0][0] += t * (a0 * a0 + a0 * a1 + a1 * a1) / 3.0
        for j, c in enumerate(const, start=1):
            g[0][j] += c * t * (a0 + a1) / 2.0
            for k, e in enumerate(const, start=1):
                g[j][k] += c * e * t
        total += t
        corners.update({(a0, d, q), (a1, d, q)})
    for j in range(1, 4):
        g[j][0] = g[0][j]
    return {"gram": tuple(tuple(r) for r in g), "time": total, "corners": tuple(sorted(corners))}


def rms_linear(cycle: dict, alpha, beta, phi=1.0, gamma=0.0):
    """RMS over the cycle of X = alpha a + beta s + phi q + gamma (see :func:`cycle_gram`)."""
    c = (alpha, beta, phi, gamma)
    g = cycle["gram"]
    q = 0.0
    for i in range(4):
        for j in range(4):
            if g[i][j] != 0.0:
                q = q + g[i][j] * c[i] * c[j]
    return mx.sqrt(mx.fmax(q / cycle["time"], 0.0))


def peak_linear(cycle: dict, alpha, beta, phi=1.0, gamma=0.0):
    """Largest |alpha a + beta s + phi q + gamma| over the cycle's phase corners (the extremes of a
    ramp)."""
    out = None
    for a, s, q in cycle["corners"]:
        x = mx.fabs(alpha * a + beta * s + phi * q + gamma)
        out = x if out is None else mx.fmax(out, x)
    return out
