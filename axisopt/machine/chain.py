"""The machine's lumped chain: masses on springs from the frame to the tool, per direction (numpy,
vectorised).

Each axis is one lumped mass (its own moving structure, its moving parts, and the stationary parts
and counterweight of the axis it carries) joined to its carrier by one spring per direction: its
drive chain along its travel, its guide blocks across it, each in series with the frame under it.  A
chain of n masses m_1..m_n, m_1 on the frame through k_1 and m_i on m_{i-1} through k_i, has the
stiffness matrix

.. math:: K_{ii} = k_i + k_{i+1},\\quad K_{i,i+1} = K_{i+1,i} = -k_{i+1}\\quad (k_{n+1} = 0)

and its natural frequencies are :math:`f = \\sqrt{\\lambda}/2\\pi` for the eigenvalues
:math:`\\lambda` of :math:`M^{-1/2} K M^{-1/2}` (e.g. S. S. Rao, *Mechanical Vibrations*, the
n-degree-of-freedom spring-mass chain; the 2-DOF and uniform n-DOF closed forms are the tests'
checks).  Dunkerley's formula bounds the lowest from below:
:math:`1/\\omega_1^2 \\le \\sum_i m_i a_{ii}` with the flexibility
:math:`a_{ii} = \\sum_{j \\le i} 1/k_j` (a conservative cross-check).
"""

from __future__ import annotations

import numpy as np

TWO_PI = 2.0 * np.pi


def chain_stiffness_matrix(k: np.ndarray) -> np.ndarray:
    """(..., n) springs [N/m] (k[..., 0] to the frame) -> (..., n, n) stiffness matrix [N/m]."""
    k = np.asarray(k, dtype=float)
    n = k.shape[-1]
    K = np.zeros(k.shape + (n,))
    for i in range(n):
        K[..., i, i] += k[..., i]
        if i + 1 < n:
            K[..., i, i] += k[..., i + 1]
            K[..., i, i + 1] = -k[..., i + 1]
            K[..., i + 1, i] = -k[..., i + 1]
    return K


def chain_modes(m, k):
    """Natural frequencies [Hz] (ascending) and mass-normalised mode shapes of the chain(s).

    m, k : (..., n) masses [kg] and springs [N/m], index 0 on the frame.
    Returns (f (..., n), phi (..., n, n): column r the r-th mode's displacements)."""
    m = np.asarray(m, dtype=float)
    s = 1.0 / np.sqrt(m)
    A = chain_stiffness_matrix(k) * s[..., :, None] * s[..., None, :]
    lam, v = np.linalg.eigh(A)
    return np.sqrt(np.clip(lam, 0.0, None)) / TWO_PI, v * s[..., :, None]


def lowest_frequency(m, k) -> np.ndarray:
    """The chain's lowest natural frequency [Hz] (..., ).  Chains of up to three masses (every
    machine's here) by the closed form of the symmetric 3x3 eigenvalue problem
    (:func:`_lowest_eigenvalue_3`), longer ones by LAPACK; the closed form is polished by Newton
    steps on the chain's characteristic polynomial."""
    m = np.asarray(m, dtype=float)
    k = np.asarray(k, dtype=float)
    n = m.shape[-1]
    if n == 1:
        return np.sqrt(np.clip(k[..., 0] / m[..., 0], 0.0, None)) / TWO_PI
    if n <= 3:  # M^-1/2 K M^-1/2: its diagonal and off-diagonal
        d = [(k[..., i] + (k[..., i + 1] if i + 1 < n else 0.0)) / m[..., i] for i in range(n)]
        e = [-k[..., i + 1] / np.sqrt(m[..., i] * m[..., i + 1]) for i in range(n - 1)]
        lam = _lowest_eigenvalue_3(d, e)
    else:
        s = 1.0 / np.sqrt(m)
        lam = np.linalg.eigvalsh(chain_stiffness_matrix(k) * s[..., :, None] * s[..., None, :])[
            ..., 0
        ]
    return np.sqrt(np.clip(lam, 0.0, None)) / TWO_PI


def _lowest_eigenvalue_3(d: list, e: list) -> np.ndarray:
    """The least eigenvalue of symmetric tridiagonal matrices, n = 2 or 3 (``d`` the n diagonals,
    ``e`` the n - 1 off-diagonals, each an array (...,)): the trigonometric closed form of the cubic
    (O. K. Smith, "Eigenvalues of a symmetric 3 x 3 matrix", Comm. ACM 4 (1961) 168; n = 2 its
    quadratic), then two Newton steps on det(A - lambda I) by the tridiagonal recurrence (to
    round-off)."""
    n = len(d)
    if n == 2:
        h = 0.5 * (d[0] - d[1])
        lam = 0.5 * (d[0] + d[1]) - np.sqrt(h * h + e[0] ** 2)
    else:
        q = (d[0] + d[1] + d[2]) / 3.0
        p1 = e[0] ** 2 + e[1] ** 2
        p = np.sqrt(((d[0] - q) ** 2 + (d[1] - q) ** 2 + (d[2] - q) ** 2 + 2.0 * p1) / 6.0)
        ps = np.where(p > 0, p, 1.0)
        b0, b1, b2 = (d[0] - q) / ps, (d[1] - q) / ps, (d[2] - q) / ps
        f0, f1 = e[0] / ps, e[1] / ps
        r = 0.5 * (b0 * (b1 * b2 - f1 * f1) - f0 * (f0 * b2))
        phi = np.arccos(np.clip(r, -1.0, 1.0)) / 3.0
        lam = np.where(p > 0, q + 2.0 * p * np.cos(phi + 2.0 * np.pi / 3.0), q)
    for _ in range(2):  # det(A - x I) and its derivative by the three-term recurrence
        p0, dp0 = np.ones_like(lam), np.zeros_like(lam)
        p_1, dp_1 = d[0] - lam, -np.ones_like(lam)
        for i in range(1, n):
            p_2 = (d[i] - lam) * p_1 - e[i - 1] ** 2 * p0
            dp_2 = -p_1 + (d[i] - lam) * dp_1 - e[i - 1] ** 2 * dp0
            p0, dp0, p_1, dp_1 = p_1, dp_1, p_2, dp_2
        step = np.where(dp_1 != 0, p_1 / np.where(dp_1 != 0, dp_1, 1.0), 0.0)
        lam = lam - step
    return lam


def dunkerley_frequency(m, k) -> np.ndarray:
    """Dunkerley's lower bound of the lowest frequency [Hz]:
    :math:`1/\\omega^2 = \\sum_i m_i \\sum_{j\\le i} 1/k_j`."""
    m = np.asarray(m, dtype=float)
    a = np.cumsum(1.0 / np.asarray(k, dtype=float), axis=-1)
    return 1.0 / np.sqrt((m * a).sum(-1)) / TWO_PI


def strain_shares(m, k, mode: int = 0) -> np.ndarray:
    """Each spring's share of the strain energy in mode ``mode`` (..., n): the spring that limits it
    has the largest share."""
    f, phi = chain_modes(m, k)
    x = phi[..., :, mode]
    d = np.diff(np.concatenate([np.zeros(x.shape[:-1] + (1,)), x], axis=-1), axis=-1)
    e = np.asarray(k, dtype=float) * d**2
    return e / e.sum(-1, keepdims=True)
