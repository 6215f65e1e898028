"""Friction tables written by the tests' own law (apart from axisopt's measurement model): a signed
friction force at constant speeds both ways, with optional axial load on the nut, payload on the
guides and temperature, jitter of the logged speeds and positions, and Gaussian noise."""

from __future__ import annotations

import math

import numpy as np

G = 9.80665
SPEEDS = np.geomspace(0.002, 0.3, 10)  # [m/s]


def friction_rows(
    rng,
    *,
    fc=300.0,
    fv=800.0,
    stribeck=0.0,
    vs=0.004,
    delta=1.0,
    drag=0.0,
    axial_ratio=0.0,
    mu=0.0,
    axial_levels=(),
    normal_levels=(),
    temps=(),
    beta=0.0,
    dfc_dT=0.0,
    speeds=SPEEDS,
    rep=2,
    noise=3.0,
    speed_jitter=0.0,
    pos_jitter=0.0,
    positions=(0.2, 0.5),
):
    """Rows (dict of columns, SI) of a friction test: every speed both ways at every axial load,
    normal load, temperature and position, ``rep`` readings each.  The logged speed and position
    carry a relative ``speed_jitter`` and an absolute ``pos_jitter`` (uniform); the friction follows
    the true values."""
    rows = {
        k: []
        for k in (
            "velocity",
            "friction_force",
            "axial_load",
            "normal_load",
            "temperature",
            "position",
        )
    }
    for fa in axial_levels or (None,):
        for nl in normal_levels or (None,):
            for tc in temps or (None,):
                for x in positions:
                    for v in np.r_[speeds, -speeds]:
                        for _ in range(rep):
                            dT = (tc - 20.0) if tc is not None else 0.0
                            s = math.copysign(1.0, v)
                            level = (
                                fc
                                + dfc_dT * dT
                                + stribeck * math.exp(-((abs(v) / vs) ** delta))
                                + axial_ratio * abs(fa or 0.0)
                                + mu * (nl or 0.0)
                            )
                            f = s * level + fv * math.exp(-beta * dT) * v + drag * v * abs(v)
                            f += noise * rng.standard_normal()
                            rows["velocity"].append(v * (1 + speed_jitter * rng.uniform(-1, 1)))
                            rows["friction_force"].append(f)
                            rows["axial_load"].append(fa)
                            rows["normal_load"].append(nl)
                            rows["temperature"].append(tc)
                            rows["position"].append(x + pos_jitter * rng.uniform(-1, 1))
    return {k: np.array(v, dtype=float) for k, v in rows.items() if v[0] is not None}


UNITS = {
    "velocity": ("mm/s", 1e3),
    "friction_force": ("N", 1.0),
    "axial_load": ("N", 1.0),
    "normal_load": ("N", 1.0),
    "temperature": ("degC", 1.0),
    "position": ("mm", 1e3),
}


def write_table(path, rows: dict):
    names = list(rows)
    head = ",".join(f"{n} [{UNITS[n][0]}]" for n in names)
    data = np.column_stack([rows[n] * UNITS[n][1] for n in names])
    path.write_text(head + "\n" + "\n".join(",".join(f"{v:.8g}" for v in r) for r in data) + "\n")
    return path
