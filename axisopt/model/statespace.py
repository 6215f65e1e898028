r"""The lumped axis as a linear state-space model (numpy), for control design.

The drive train of seed Fig. 1 with the evaluation's own springs, masses and dampers at one nut
position (the same values as :mod:`axisopt.model.frf` and the modes of :mod:`axisopt.model.modes`):

* DOFs ``q = [theta_m, theta_s, x]``: motor rotor with its half of the coupling (``J_m``, the rotor
  and the reduction reflected to the screw side, :func:`axisopt.model.modes.drive_inertias`), screw
  with the other half (``J_s``), table (``m_eff``, the table with the Rayleigh share of the screw
  mass);
* springs: coupling ``k_c`` between ``theta_m`` and ``theta_s``; the axial chain without the
  coupling ``k_drive`` (bearings, screw tension and torsion, nut, bracket) on ``x - r theta_s``, r =
  P_h / (2 pi);
* dampers: coupling 2 zeta sqrt(k_c J_s) (steel, seed Table 5), the nut and bearing dampers across
  the chain (seed Table 6, :func:`axisopt.model.modes.dampers`), the guide blocks from the table to
  the frame (Table 7).

.. math:: M \ddot q + C_d \dot q + K q = B_q u,\qquad
          K = \begin{bmatrix} k_c & -k_c & 0\\ -k_c & k_c + k r^2 & -k r\\ 0 & -k r & k\end{bmatrix}

State ``z = [q, dq/dt]``; ``dz/dt = A z + B u``, ``y = C z + D u`` with

* inputs ``u = [motor torque T_m at the motor shaft [N*m], process force F on the table, +x [N]]``
  (the torque acts on ``theta_m`` through the reduction: ``i T_m``, i = motor turns per screw turn);
* outputs ``y = [motor angle at the motor shaft i theta_m [rad], table position x [m], position at
  the tool [m]]``.  The table is one rigid body here, so the tool point (on the workpiece the table
  carries) moves as ``x``; the row is kept apart for a carriage model with its own compliance.

With ``motor_held`` the rotor is fixed (``theta_m = 0``: the motor held by a stiff position loop,
the headline first frequency's model); the torque input then acts on nothing and the motor angle
output is 0.  Open loop (motor free) there is one rigid-body mode (two eigenvalues at 0) and two
elastic modes, the drive-train frequencies ``f_axial_torsional`` and ``f_axial_torsional_2``; motor
held, the two modes of :func:`axisopt.physics.dynamics.axial_torsional_frequencies` (the first is
``f_axial`` less the screw's rotary inertia on the coupling: 0.01 % lower on
problems/vmc_x_design.yaml).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .frf import chain_at, frf_positions
from .function import Evaluation, design_params

__all__ = ["AxisStateSpace", "state_space", "stroke_state_spaces", "STATES", "INPUTS", "OUTPUTS"]

STATES = ("theta_m", "theta_s", "x", "omega_m", "omega_s", "v")
INPUTS = ("motor_torque", "process_force")
OUTPUTS = ("motor_angle", "table_position", "tool_position")
STATE_UNITS = ("rad", "rad", "m", "rad/s", "rad/s", "m/s")
INPUT_UNITS = ("N.m", "N")
OUTPUT_UNITS = ("rad", "m", "m")


@dataclass(frozen=True)
class AxisStateSpace:
    """A linear state-space model of the axis at one nut position (SI).

    A, B, C, D  : dz/dt = A z + B u, y = C z + D u  (:data:`STATES`, :data:`INPUTS`, :data:`OUTPUTS`)
    mass, stiffness, damping : the second-order matrices M, K, C_d over the free DOFs [kg, kg*m^2;
        N/m, ...]
    position_mm : nut position along the stroke [mm];  x : fixed bearing to nut [m]
    motor_held  : the rotor is fixed (its rows stay, as zeros)
    lead, ratio : screw lead [m]; motor turns per screw turn (reduction) [-]
    """  # noqa: E501

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    mass: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    position_mm: float
    x: float
    motor_held: bool
    lead: float
    ratio: float
    states: tuple = STATES
    inputs: tuple = INPUTS
    outputs: tuple = OUTPUTS
    free: tuple = field(default=(0, 1, 2))  # indices of the DOFs that move

    def natural_frequencies(self) -> np.ndarray:
        """Undamped natural frequencies of the elastic modes [Hz], ascending (rigid-body modes left
        out)."""
        lam = np.linalg.eigvals(np.linalg.solve(self.mass, self.stiffness)).real
        lam = np.sort(lam)
        scale = max(float(np.max(np.abs(lam))), 1.0)
        lam = lam[lam > 1e-9 * scale]
        return np.sqrt(lam) / (2.0 * math.pi)

    def poles(self) -> np.ndarray:
        """Eigenvalues of A [1/s] (the rows of a held rotor left out)."""
        keep = self._kept()
        return np.linalg.eigvals(self.A[np.ix_(keep, keep)])

    def _kept(self) -> list:
        n = len(STATES) // 2
        return [i for i in range(2 * n) if (i % n) in self.free]

    def frequency_response(
        self, freqs, inp: str = "process_force", out: str = "table_position"
    ) -> np.ndarray:
        """Complex frequency response y/u at ``freqs`` [Hz] from one input to one output (SI
        ratio)."""
        keep = self._kept()
        a = self.A[np.ix_(keep, keep)]
        b = self.B[keep, self.inputs.index(inp)]
        c = self.C[self.outputs.index(out), keep]
        d = self.D[self.outputs.index(out), self.inputs.index(inp)]
        eye = np.eye(len(keep))
        s = 2j * math.pi * np.asarray(freqs, dtype=float)
        return np.array([c @ np.linalg.solve(si * eye - a, b) + d for si in s])

    def to_control(self):
        """The model as a python-control ``StateSpace`` (the optional extra ``control``), with
        signal names."""
        import control

        keep = self._kept()
        return control.ss(
            self.A[np.ix_(keep, keep)],
            self.B[keep, :],
            self.C[:, keep],
            self.D,
            states=[STATES[i] for i in keep],
            inputs=list(self.inputs),
            outputs=list(self.outputs),
            name=f"axis_{self.position_mm:.0f}mm{'_held' if self.motor_held else ''}",
        )


def second_order(m: dict):
    """(M, K, C_d) over [theta_m, theta_s, x] from the drive-train values of
    :func:`axisopt.model.frf.chain_at`."""
    r = m["lead"] / (2.0 * math.pi)
    kc, k = m["coupling_stiffness"], m["axial_stiffness"]
    cc, ca = m["coupling_damping"], m["chain_damping"]
    mass = np.diag([m["motor_inertia"], m["screw_inertia"], m["mass"]])
    stiff = np.array([[kc, -kc, 0.0], [-kc, kc + k * r**2, -k * r], [0.0, -k * r, k]])
    damp = np.array(
        [[cc, -cc, 0.0], [-cc, cc + ca * r**2, -ca * r], [0.0, -ca * r, ca + m["table_damping"]]]
    )
    return mass, stiff, damp


def _assemble(m: dict, ratio: float, motor_held: bool):
    mass, stiff, damp = second_order(m)
    free = (1, 2) if motor_held else (0, 1, 2)
    n = 3
    A = np.zeros((2 * n, 2 * n))
    B = np.zeros((2 * n, 2))
    C = np.zeros((3, 2 * n))
    D = np.zeros((3, 2))
    f = list(free)
    Mi = np.linalg.inv(mass[np.ix_(f, f)])
    for i in f:
        A[i, n + i] = 1.0
    A[np.ix_([n + i for i in f], f)] = -Mi @ stiff[np.ix_(f, f)]
    A[np.ix_([n + i for i in f], [n + i for i in f])] = -Mi @ damp[np.ix_(f, f)]
    bq = np.zeros((n, 2))
    if not motor_held:
        bq[0, 0] = ratio  # motor torque through the reduction onto theta_m (screw side)
    bq[2, 1] = 1.0  # process force on the table
    B[[n + i for i in f], :] = Mi @ bq[f, :]
    C[0, 0] = ratio  # motor shaft angle
    C[1, 2] = 1.0
    C[2, 2] = 1.0  # the tool point moves with the rigid table
    sub = np.ix_(f, f)
    return A, B, C, D, mass[sub], stiff[sub], damp[sub], free


def state_space(
    ev: Evaluation, i: int, *, motor_held: bool = False, damping_scale: float = 1.0
) -> AxisStateSpace:
    """The axis at position index ``i`` of ``ev.x`` as an :class:`AxisStateSpace`.

    ev : an evaluation (:func:`axisopt.model.evaluate`);  motor_held : rotor fixed;
    damping_scale : multiplies every damper (0: the undamped model whose eigenvalues are the modes).
    """
    p = design_params(ev.design)
    m = chain_at(ev, p, i)
    for k in ("table_damping", "chain_damping", "coupling_damping"):
        m[k] *= damping_scale
    ratio = float(p["reduction_ratio"])  # the reduction part's, else the axis's
    A, B, C, D, mass, stiff, damp, free = _assemble(m, ratio, motor_held)
    return AxisStateSpace(
        A,
        B,
        C,
        D,
        mass,
        stiff,
        damp,
        position_mm=float((ev.x[i] - ev.design.axis.start_offset) * 1e3),
        x=float(ev.x[i]),
        motor_held=bool(motor_held),
        lead=float(p["lead"]),
        ratio=ratio,
        free=free,
    )


def stroke_state_spaces(ev: Evaluation, *, motor_held: bool = False) -> list:
    """:func:`state_space` at stroke start, the point nearest mid-stroke and stroke end (as
    ``--frf``)."""
    return [state_space(ev, i, motor_held=motor_held) for i in frf_positions(ev)]
