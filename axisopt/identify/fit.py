"""One fitting engine: named parameters with units and bounds, residuals as CasADi expressions,
Levenberg-Marquardt with CasADi Jacobians, weighted by measurement noise.

A :class:`Problem` is a list of blocks, one per dataset: a CasADi row function
``(theta, z) -> [prediction; d prediction / d theta]`` mapped over the dataset's columns ``Z``, the
measurements ``y`` and the weights ``w = 1/sigma``.  :func:`fit` minimises ``sum (w (pred - y))^2``
over the parameters (in solver units ``theta / typical``, clipped to bounds) and returns estimates,
their covariance ``s^2 (J^T J)^-1`` and the information criteria.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..units import unit_factor


@dataclass(frozen=True)
class Param:
    """A fitted quantity.  ``init``, bounds and ``plausible`` are SI; ``unit`` is the display
    unit."""

    name: str
    label: str
    unit: str
    kind: str
    init: float
    lower: float = -math.inf
    upper: float = math.inf
    typical: float | None = None
    plausible: tuple | None = None
    plausible_note: str = ""

    @property
    def factor(self) -> float:
        """SI value per display unit."""
        return unit_factor(self.unit, self.kind) if self.unit not in ("", "-") else 1.0

    def show(self, value: float) -> float:
        return value / self.factor

    @property
    def scale(self) -> float:
        t = self.typical if self.typical else abs(self.init)
        return t if t > 0 else 1.0


@dataclass
class Block:
    """One dataset in a fit: the mapped row function and its data."""

    function: ca.Function  # (theta, z) -> [pred; grad], single row
    Z: np.ndarray  # nz x n
    y: np.ndarray
    w: np.ndarray
    _mapped: dict = field(default_factory=dict)

    def evaluate(self, theta: np.ndarray, jac: bool = True):
        key = "jac" if jac else "pred"
        if key not in self._mapped:
            f = self.function if jac else _pred_only(self.function)
            self._mapped[key] = f.map(self.Z.shape[1], "serial")
        out = np.asarray(self._mapped[key](theta, self.Z))
        return (out[0], out[1:].T) if jac else (out[0], None)


def _pred_only(f: ca.Function) -> ca.Function:
    th = ca.SX.sym("theta", f.size1_in(0))
    z = ca.SX.sym("z", f.size1_in(1))
    return ca.Function(f.name() + "_pred", [th, z], [f(th, z)[0]])


def row_function(predict, n_theta: int, nz: int, name: str = "row") -> ca.Function:
    """Build the CasADi row function from ``predict(theta_SX, z_SX) -> SX scalar``."""
    th = ca.SX.sym("theta", n_theta)
    z = ca.SX.sym("z", nz)
    y = predict(th, z)
    return ca.Function(name, [th, z], [ca.vertcat(y, ca.jacobian(y, th).T)])


@dataclass
class FitResult:
    params: tuple
    theta: np.ndarray  # SI
    cov: np.ndarray
    rss: float
    n: int
    residual: np.ndarray  # weighted (pred - y) on all rows
    prediction: np.ndarray
    converged: bool
    iterations: int
    status: str = "ok"
    extra: dict = field(default_factory=dict)

    @property
    def p(self) -> int:
        return len(self.params)

    @property
    def bic(self) -> float:
        return self.n * math.log(max(self.rss, 1e-300) / self.n) + self.p * math.log(self.n)

    @property
    def aicc(self) -> float:
        k = self.p
        aic = self.n * math.log(max(self.rss, 1e-300) / self.n) + 2 * k
        return aic + (2 * k * (k + 1) / (self.n - k - 1) if self.n - k - 1 > 0 else math.inf)

    @property
    def sigma(self) -> np.ndarray:
        return np.sqrt(np.maximum(np.diag(self.cov), 0.0)) if self.cov.size else np.zeros(0)

    def value(self, name: str) -> float:
        return float(self.theta[[p.name for p in self.params].index(name)])

    def values(self) -> dict:
        return {p.name: float(v) for p, v in zip(self.params, self.theta)}


class Problem:
    """Blocks sharing one parameter vector."""

    def __init__(self, params, blocks):
        self.params = tuple(params)
        self.blocks = list(blocks)
        self.y = np.concatenate([b.y for b in self.blocks])
        self.w = np.concatenate([b.w for b in self.blocks])

    def evaluate(self, theta, jac: bool = True):
        preds, jacs = zip(*(b.evaluate(theta, jac) for b in self.blocks))
        return np.concatenate(preds), (np.vstack(jacs) if jac else None)

    def predict(self, theta) -> np.ndarray:
        return self.evaluate(theta, jac=False)[0]


def fit(problem: Problem, theta0=None, mask=None, maxit: int = 60, tol: float = 1e-9) -> FitResult:
    """Weighted Levenberg-Marquardt with bounds (projected steps, bound-active parameters held).
    ``mask`` (bool per row) selects the rows fitted (grouped cross-validation); the result's
    prediction and residual cover every row."""
    params = problem.params
    lo = np.array([p.lower for p in params])
    hi = np.array([p.upper for p in params])
    scale = np.array([p.scale for p in params])
    theta = np.clip(
        np.array([p.init for p in params], float) if theta0 is None else np.asarray(theta0, float),
        lo,
        hi,
    )
    wm = problem.w * (1.0 if mask is None else mask.astype(float))

    def resid(th, jac=True):
        pred, J = problem.evaluate(th, jac)
        return pred, (pred - problem.y) * wm, (J * wm[:, None] * scale[None, :] if jac else None)

    pred, r, J = resid(theta)
    rss = float(r @ r)
    lam, converged, iterations = 1e-3, False, 0
    n_p = len(params)
    for iterations in range(1, maxit + 1):  # noqa: B007 (reported after the loop)
        if n_p == 0 or not np.isfinite(rss):
            converged = bool(np.isfinite(rss))
            break
        g = J.T @ r
        held = ((theta <= lo) & (g > 0)) | ((theta >= hi) & (g < 0))
        free = ~held
        if not free.any():
            converged = True
            break
        A = (J.T @ J)[np.ix_(free, free)]
        gf = g[free]
        d = np.diag(A).copy()
        d[d <= 0] = 1e-12
        improved = False
        for _ in range(10):
            try:
                sf = -np.linalg.solve(A + lam * np.diag(d) + 1e-14 * np.eye(len(gf)), gf)
            except np.linalg.LinAlgError:
                lam *= 10
                continue
            step = np.zeros(n_p)
            step[free] = sf
            th_new = np.clip(theta + step * scale, lo, hi)
            pred_n, r_n, _ = resid(th_new, jac=False)
            rss_n = float(r_n @ r_n)
            if np.isfinite(rss_n) and rss_n <= rss:
                improved = True
                break
            lam *= 8.0
        if not improved:
            converged = True
            break
        rel = (rss - rss_n) / max(rss, 1e-300)
        small_step = np.all(np.abs(th_new - theta) <= 1e-9 * (np.abs(theta) + scale))
        theta, rss = th_new, rss_n
        pred, r, J = resid(theta)
        lam = max(lam / 5.0, 1e-9)
        if rel < tol or small_step:
            converged = True
            break
    n = int(np.count_nonzero(wm))
    cov = covariance(J, rss, n, scale)
    full_r = (pred - problem.y) * problem.w
    return FitResult(
        params,
        theta,
        cov,
        rss,
        n,
        full_r,
        pred,
        converged,
        iterations,
        status="ok" if converged and np.isfinite(rss) else "not converged",
    )


def covariance(J, rss, n, scale):
    """sigma^2 (J^T J)^-1 in SI.  A parameter in a direction the data do not fix (a zero or
    dependent Jacobian
    column: a Stribeck velocity far below every test speed, a term held at its bound) gets an
    infinite variance -- "not identifiable" -- instead of the zero a pseudo-inverse would give
    it."""
    p = J.shape[1]
    if p == 0:
        return np.zeros((0, 0))
    s2 = rss / max(n - p, 1)
    try:
        _, sv, vt = np.linalg.svd(J, full_matrices=False)
    except np.linalg.LinAlgError:
        return np.full((p, p), np.inf)
    good = sv > 1e-9 * (sv.max() if sv.size else 0.0)
    if not good.any():
        return np.diag(np.full(p, np.inf))
    inv = (vt[good].T / sv[good] ** 2) @ vt[good]
    cov = s2 * inv * np.outer(scale, scale)
    if not good.all():
        weak = np.any(np.abs(vt[~good]) > 1e-3, axis=0)
        cov[weak, :] = 0.0
        cov[:, weak] = 0.0
        cov[weak, weak] = np.inf
    return cov
