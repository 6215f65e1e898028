"""The reduced tables' residuals: the noise floor of each test, where misfit concentrates along the
recorded factors, and the structure the final fit leaves (the "unexplained" verdict, tested with
:mod:`.residual`).

Noise floor, in order of preference: the pooled scatter of replicates (rows with the same value of
every recorded factor), else second differences of the residual along one continuous factor,
var(e1 - 2 e2 + e3) = 6 sigma^2 for white noise (median-absolute-deviation form, so structure only
adds).  Misfit per factor level: the share of residual variance the levels explain (eta^2, the
correlation ratio).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import residual as rs
from ..levels import cluster_levels
from .measure import FEATURES, Y_UNIT, Obs

# Factors whose levels alternate between neighbouring rows of a test (load direction, cycle, mode):
# the noise floor never takes differences across them.
_CATEGORICAL_FACTORS = ("direction", "cycle", "mode")
MIN_REPLICATE_DOF = 5


def noise_sigma_rel(o: Obs, resid: np.ndarray) -> tuple[float, str]:
    """Noise floor relative to the weight scale, and how it was estimated.

    1. Replicates: rows with the same value of every recorded factor (a reading repeated at the same
       position, load, direction, cycle, ...) differ by noise alone, whatever the model gets wrong;
       the pooled within-replicate standard deviation is used when it has at least 5 degrees of
       freedom.
    2. Otherwise second differences of the residual along one continuous factor within rows that
       share all other factors (:func:`_second_difference_sigma`): misfit constant or linear along
       it cancels, and an effect that alternates between neighbouring rows (hysteresis, a
       direction-dependent friction) is never differenced across."""
    r = resid / o.scale
    if o.factors:
        # every model feature too: an FRF's real and imaginary rows share their factors but are no
        # replicates levels logged with jitter are one level (:mod:`.levels`)
        feats = FEATURES[o.kind]
        keys = np.column_stack(
            [cluster_levels(v, k) for k, v in o.factors.items()]
            + [cluster_levels(z, feats[i] if i < len(feats) else "") for i, z in enumerate(o.Z)]
        )
        _, inv, counts = np.unique(keys, axis=0, return_inverse=True, return_counts=True)
        inv = np.asarray(inv).ravel()
        rep = counts[inv] >= 2
        dof = int(rep.sum() - np.count_nonzero(counts >= 2))
        if dof >= MIN_REPLICATE_DOF:
            means = np.bincount(inv, weights=r, minlength=len(counts)) / counts
            ss = float(np.sum(((r - means[inv]) ** 2)[rep]))
            s = math.sqrt(ss / dof)
            return (
                max(s, 1e-6),
                f"pooled scatter of {int(np.count_nonzero(counts >= 2))} replicate groups "
                f"({dof} degrees of freedom)",
            )
    s, how = _second_difference_sigma(o, r)
    if s is not None:
        return s, how
    return 0.01, "assumed 1 % (too few rows to estimate)"


def _second_difference_sigma(o: Obs, r: np.ndarray):
    """Noise from second differences of the residual along one continuous factor, within rows that
    share every other factor (and the factor's sign): misfit that is constant or linear along that
    factor cancels (an offset per load direction, a stiffness error growing with the load, a
    friction term set by the normal load).  Tried along each continuous factor with four or more
    levels; the smallest estimate is kept (structure only adds).  Gaussian noise: var(e1 - 2 e2 +
    e3) = 6 sigma^2; median-absolute-deviation form."""
    names = list(o.factors)
    if not names:
        return None, ""
    cols = {k: np.asarray(o.factors[k], dtype=float) for k in names}
    best = None
    for inner in names:
        v = cols[inner]
        # cycles are ordered: a trend cancels
        if inner in ("direction", "mode") or len(np.unique(v)) < 4:
            continue
        keys = [cols[k] for k in names if k != inner] + [np.sign(v)]
        order = np.lexsort((v, *keys))
        same = np.ones(len(order) - 1, dtype=bool)
        for k in keys:
            ks = k[order]
            same &= ks[1:] == ks[:-1]
        rs = r[order]
        d2 = rs[2:] - 2.0 * rs[1:-1] + rs[:-2]
        ok = same[1:] & same[:-1]
        d2 = d2[ok]
        if len(d2) < 5:
            continue
        s = 1.4826 * float(np.median(np.abs(d2 - np.median(d2)))) / math.sqrt(6.0)
        if best is None or s < best[0]:
            best = (
                max(s, 1e-6),
                f"second differences along {inner} within rows sharing the other factors",
            )
    return best if best is not None else (None, "")


@dataclass
class TableUnexplained:
    """Structure left in the final noise-weighted residual of one test (1 = the noise floor)."""

    kind: str
    source: str
    rms: float  # noise-weighted RMS of the final residual [-]
    # residual.Probe, one per recorded factor (and the velocity shape of friction data)
    probes: list

    @property
    def remaining(self) -> list:
        """Significant probes, largest share first -- only when the misfit exceeds the noise
        floor."""
        if self.rms < UNEXPLAINED_RMS:
            return []
        return sorted([p for p in self.probes if p.significant], key=lambda p: -p.share)


# a noise-weighted residual RMS below this is at the noise floor, whatever its pattern
UNEXPLAINED_RMS = 1.5


def table_unexplained(obs, resid_w, effects=()) -> list:
    """Test the final residual of every test for structure along its recorded factors (see
    :mod:`.residual`): the share of the residual variance each factor's levels hold, its
    significance; for friction data the velocity dependence's shape (v|v|, v, low-speed rise,
    direction)."""
    out = []
    for o, r in zip(obs, resid_w):
        r = np.asarray(r, dtype=float)
        probes = [
            rs.factor_probe(name, signed(o, name, r), vals, max_bins=8 if name == "velocity" else 6)
            for name, vals in o.factors.items()
            if len(np.unique(vals)) > 1
        ]
        if o.kind == "friction":
            v = o.feature("velocity")
            vs = float(np.quantile(np.abs(v), 0.25)) or 1e-3
            shapes = {
                "v|v|": v * np.abs(v),
                "v": v,
                "low_speed": np.sign(v) * np.exp(-np.abs(v) / vs),
            }
            if np.ptp(np.sign(v)) > 0:
                shapes.update({"|v|": np.abs(v), "sgn": np.sign(v)})
            # the shapes are compared after what the model already fits along velocity: its Coulomb
            # level, and its viscous slope when the viscous effect is in the model
            W = np.column_stack(
                [np.sign(v), v] if "viscous" in [e.name for e in effects] else [np.sign(v)]
            )
            if "viscous" in [e.name for e in effects]:
                shapes.pop("v")
            for pr in probes:
                if pr.kind == "velocity":
                    nm, sh = rs.best_shape(r, shapes, W)
                    # one smooth column can hold more than the level means do (bins average it out)
                    pr.detail.update(
                        shape=nm, shape_share=min(sh / pr.share, 1.0) if pr.share > 0 else 0.0
                    )
                    pr.share = max(pr.share, sh)
        out.append(
            TableUnexplained(o.kind, str(o.dataset.source), float(np.sqrt(np.mean(r**2))), probes)
        )
    return out


def table_signature(p, disp) -> tuple:
    """(what, causes, measurement) of a table probe; ``disp(name, value)`` formats a factor
    level."""
    d = p.detail
    lo, hi = d.get("worst", (0.0, 0.0))
    where = f" (largest at {disp(p.kind, lo)}" + (f"..{disp(p.kind, hi)})" if hi != lo else ")")
    if p.kind == "velocity" and d.get("shape_share", 0.0) >= 0.7:
        what, causes, measure = rs.VELOCITY_WORDS[d["shape"]]
        return f"depends on velocity: {what}", causes, measure
    if p.kind == "velocity":
        return (
            "depends on velocity in a shape none of the library's terms has" + where,
            "a friction law outside the library",
            "a friction curve over the whole speed range, both ways",
        )
    what, causes, measure = rs.FACTOR_WORDS.get(
        p.kind,
        (f"varies with {p.kind}", "an effect outside the library", f"vary {p.kind} on purpose"),
    )
    return what + where, causes, measure


# Factors of a friction test whose friction follows the direction of motion (a load or temperature
# raises the friction both ways, so the signed residual changes sign with v): their level means are
# taken of sgn(v) r, or the two directions would average the effect away.
SIGNED_FACTORS = ("axial_load", "normal_load", "temperature")


def signed(o: Obs, name: str, r: np.ndarray) -> np.ndarray:
    """The residual as a factor's level means should see it: times sgn(v) for the friction test's
    loads and temperature (:data:`SIGNED_FACTORS`), as it is otherwise."""
    if o.kind == "friction" and name in SIGNED_FACTORS:
        return r * np.sign(o.feature("velocity"))
    return r


def residual_table(o: Obs, resid: np.ndarray, max_bins: int = 6) -> list:
    """Where misfit concentrates: for every recorded factor, the share of residual variance
    explained by its levels (eta^2), the worst level and its RMS.  ``resid`` = prediction - y
    (SI)."""
    unit, f = Y_UNIT[o.kind]
    r = resid * f
    # misfit in compliance: a wrong stiffness would otherwise just track |F|
    if o.kind == "stiffness":
        force = o.feature("force")
        ok = np.abs(force) > 0.05 * np.max(np.abs(force))
        r = np.where(ok, resid / np.where(ok, force, 1.0), 0.0) * 1e6
        unit = "um/N"
    total = float(np.sum((r - r.mean()) ** 2)) or 1e-300
    rows = []
    r_all = r
    for name, vals in o.factors.items():
        r = signed(o, name, r_all)
        levels = np.unique(vals)
        if len(levels) < 2:
            continue
        if len(levels) > max_bins:
            edges = np.quantile(vals, np.linspace(0, 1, max_bins + 1)[1:-1])
            idx = np.searchsorted(edges, vals, side="right")
            labels = [
                f"{_disp(name, vals[idx == i].min())}..{_disp(name, vals[idx == i].max())}"
                for i in range(max_bins)
            ]
        else:
            idx = np.searchsorted(levels, vals)
            labels = [_disp(name, v) for v in levels]
        between, worst = 0.0, (None, -1.0)
        for i in np.unique(idx):
            ri = r[idx == i]
            between += len(ri) * (ri.mean() - r.mean()) ** 2
            rms = float(np.sqrt(np.mean(ri**2)))
            if rms > worst[1]:
                worst = (labels[i], rms)
        rows.append(
            {
                "factor": name,
                "eta2": between / total,
                "worst_level": worst[0],
                "worst_rms": worst[1],
                "rms": float(np.sqrt(np.mean(r**2))),
                "unit": unit,
            }
        )
    rows.sort(key=lambda d: -d["eta2"])
    return rows


_DISP = {
    "position": (1e3, "mm"),
    "velocity": (1e3, "mm/s"),
    "frequency": (1.0, "Hz"),
    "force": (1.0, "N"),
    "normal_load": (1.0, "N"),
    "axial_load": (1.0, "N"),
    "time": (1.0, "s"),
    "temperature": (1.0, "K"),
}


def _disp(name, v):
    f, u = _DISP.get(name, (1.0, ""))
    return f"{v * f:.4g}{(' ' + u) if u else ''}"


def display_value(name, v) -> str:
    """A factor's value in its display unit (e.g. a velocity in mm/s), as text."""
    return _disp(name, v)
