"""Synthetic multi-vendor catalogs for the scaling benchmark (not shipped parts, not used by tests).

Rows look like real catalogs: a part's properties follow its size with the correlations vendors'
tables show, plus a vendor factor and scatter.  Anchors (checked against the shipped catalogs,
catalogs/*.csv):

* screws: nominal diameter 16-63 mm, root diameter ~ d - 1.1 ball, mass 7850 pi d_r^2/4 kg/m, price
  ~ 4 EUR/mm of diameter per metre;
* nuts: stiffness ~ 20-30 N/um per mm of diameter (HIWIN double nuts: 40x10 ~ 1 000 N/um), dynamic
  load rating ~ 0.9 kN per mm of diameter times sqrt(ball/4 mm) (HIWIN R40-10: 51 kN), double nuts
  preloaded to 8-10 % of C;
* bearing sets: rigidity ~ 30-50 N/um per mm of bore (NSK TAC DF: 25 mm ~ 1 000 N/um), rating ~ 1.1
  kN per mm of bore;
* guide blocks: rigidity ~ 15-25 N/um per mm of size (HIWIN HG35 ZA about 700 N/um), rating ~ 1.8 kN
  per mm of size, block mass ~ size^3;
* motors: rotor inertia ~ rated torque^1.5 (Yaskawa SGM7G: 8.3 N.m, 14 kg.cm^2), peak ~ 3 x rated,
  price ~ 150 EUR per N.m;
* couplings: rated torque 10-300 N.m, torsional stiffness ~ 1 000 x torque N.m/rad, inertia ~
  torque^1.3;
* reductions: planetary (i = 3-10, T2N 40-2000 N.m, T2B ~ 2.3 x T2N, Ct21 ~ 0.5 x T2N N.m/arcmin, J1
  ~ 0.03 x T2N^0.8 kg.cm^2, jt 3 arcmin: the Beckhoff AG2400/AG3400 rows of catalogs/reductions.csv)
  and belt stages (i = 1.5-3; no vendor stage data: illustrative).

``catalog(n_screws, nuts_per_screw, n_bearings, n_guides, n_motors, n_couplings, seed,
n_reductions)`` returns a :class:`axisopt.catalog.loading.Catalog`; the combination count of a
problem over it is about nuts x bearings x guides x (motor, coupling, reduction or none) drives.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from axisopt.catalog.columns import SCHEMA
from axisopt.catalog.loading import Catalog

RPM = 2 * math.pi / 60
VENDORS = ("VA", "VB", "VC")


def _vendor(rng):
    v = int(rng.integers(len(VENDORS)))
    return VENDORS[v], (0.9, 1.0, 1.15)[v]  # a vendor's stiffness / price level


def catalog(
    n_screws=20,
    nuts_per_screw=5,
    n_bearings=100,
    n_guides=100,
    n_motors=0,
    n_couplings=0,
    seed=0,
    n_reductions=0,
    rotating_share=0.0,
) -> Catalog:
    """``rotating_share``: the share of nuts made driven rotating-nut units (THK DIR-like: the
    unit's inertia about J = 1.5e-5 kg.cm^2 x (d/mm)^3.8, a fit of THK DIR B-721, its bearing's Ca
    0.5-0.7 x the nut's; max speed, bearing rigidity and drag left to the model's estimates), drawn
    from a generator of their own so the other rows stay as they are."""
    rng = np.random.default_rng(seed)
    # the other draws keep their order
    reductions = _reductions(n_reductions, np.random.default_rng(1000 + seed))
    unit_rng = np.random.default_rng(seed + 104729)
    screws, nuts, bearings, guides, motors, couplings = [], [], [], [], [], []
    for i in range(n_screws):
        vend, lvl = _vendor(rng)
        d = float(rng.choice([16, 20, 25, 32, 40, 50, 63]))
        ball = float(rng.choice([3.175, 3.969, 4.763, 6.35])) if d >= 25 else 3.175
        lead = float(rng.choice([5, 10, 16, 20, 25, 32]))
        dr = d - 1.1 * ball
        screws.append(
            {
                "id": f"S{i}",
                "vendor": vend,
                "series": "synthetic",
                "nominal_diameter": d * 1e-3,
                "lead": lead * 1e-3,
                "root_diameter": dr * 1e-3,
                "ball_diameter": ball * 1e-3,
                "max_length": float(min(6.0, 0.1 * d)),
                "mass_per_length": 7850 * math.pi * (dr * 1e-3) ** 2 / 4,
                "dn_limit": rng.choice([70e3, 90e3, 150e3]) * 1e-3 * RPM,
                "support_bore_min": round(0.6 * d) * 1e-3,
                "support_bore_max": round(0.8 * d) * 1e-3,
                "price_per_length": 4.0 * d * lvl * rng.uniform(0.9, 1.1),
                "price_fixed": 150 + 3 * d,
            }
        )
        for j in range(nuts_per_screw):
            c = 0.9e3 * d * math.sqrt(ball / 4.0) * rng.uniform(0.8, 1.2)
            double = bool(rng.random() < 0.7)
            k = rng.uniform(20, 30) * d * lvl * (1.0 if double else 0.7) * 1e6
            nuts.append(
                {
                    "id": f"N{i}_{j}",
                    "vendor": vend,
                    "screw_id": f"S{i}",
                    "type": "double" if double else "single",
                    "stiffness": k,
                    "stiffness_preload": (0.1 if double else 0.3) * c,
                    "preload_min": 0.03 * c if double else 0.0,
                    "preload_max": 0.1 * c if double else 0.0,
                    "dynamic_load_rating": c,
                    "static_load_rating": 2.5 * c,
                    "contact_angle": math.radians(45),
                    "axial_play": 0.0 if double else 2e-5,
                    "mass": 3e-5 * d**2.2 * rng.uniform(0.8, 1.2),
                    "price": (120 + 9 * d) * lvl * (1.6 if double else 1.0) * rng.uniform(0.9, 1.1),
                }
            )
            if rotating_share > 0 and unit_rng.random() < rotating_share:
                cb = c * unit_rng.uniform(0.5, 0.7)
                nuts[-1].update(
                    {
                        "rotating": 1,
                        "unit_inertia": 1.5e-9 * d**3.8 * unit_rng.uniform(0.8, 1.2),
                        "unit_bearing_dynamic_load": cb,
                        "unit_bearing_static_load": 1.5 * cb,
                        "price": nuts[-1]["price"] + 180 + 6 * d,
                    }
                )
    set_rng = np.random.default_rng(2000 + seed)  # the DFT draws: the other draws keep their order
    for i in range(n_bearings):
        vend, lvl = _vendor(rng)
        bore = float(rng.choice([12, 15, 17, 20, 25, 30, 35, 40]))
        cls, f = [("light", 0.7), ("medium", 1.0), ("heavy", 1.3)][int(rng.integers(3))]
        rows = int(rng.choice([2, 3, 4]))
        bearings.append(
            {
                "id": f"B{i}",
                "vendor": vend,
                "series": "synthetic",
                "arrangement": ("DF", "DFD", "DFF")[rows - 2],
                "rows": rows,
                "bore": bore * 1e-3,
                "outer_diameter": (2 * bore + 12) * 1e-3,
                "contact_angle": math.radians(60),
                "preload_class": cls,
                "preload": 110 * bore * f * rows / 2,
                "axial_rigidity": rng.uniform(30, 50) * bore * f * rows / 2 * lvl * 1e6,
                "lift_off_load": 3 * 110 * bore * f * rows / 2,
                "dynamic_load_rating": 1.1e3 * bore * (rows / 2) ** 0.7,
                "static_load_rating": 2.5e3 * bore * rows / 2,
                "limiting_speed": 1.6e5 / bore * RPM,
                "starting_torque": 0.008 * bore * f * rows / 2,
                "f0": 1.5,
                "f1": 0.0003,
                "mass": 0.02 * bore * rows / 2,
                "price": (8 * bore + 60) * lvl * rows / 2 * rng.uniform(0.9, 1.1),
            }
        )
        # issue 54: a 3-against-1 set, 3 x lift-off its strong way
        if rows == 4 and set_rng.random() < 0.5:
            bearings[-1].update(
                {
                    "arrangement": "DFT",
                    "lift_off_load_strong": 3 * bearings[-1]["lift_off_load"],
                    "lift_off_load": 0.64 * bearings[-1]["lift_off_load"],
                }
            )
    for i in range(n_guides):
        vend, lvl = _vendor(rng)
        size = float(rng.choice([15, 20, 25, 30, 35, 45]))
        level, f = [("light", 0.8), ("medium", 1.0), ("heavy", 1.2)][int(rng.integers(3))]
        roller = bool(rng.random() < 0.3)
        kn = rng.uniform(15, 25) * size * f * lvl * (1.6 if roller else 1.0) * 1e6
        c = 1.8e3 * size * (1.5 if roller else 1.0)
        guides.append(
            {
                "id": f"G{i}",
                "vendor": vend,
                "series": "synthetic",
                "type": "roller" if roller else "ball",
                "size": size * 1e-3,
                "preload_class": f"Z{int(rng.integers(3))}",
                "preload_level": level,
                "preload": 0.05 * c * f,
                "normal_rigidity": kn,
                "tangential_rigidity": 0.8 * kn,
                "dynamic_load_rating": c,
                "static_load_rating": 2 * c,
                "friction_force": 0.2 * size * f,
                "friction_coefficient": 0.003,
                "friction_viscous": 0.4 * size,
                "damping": 100 * size,
                "block_mass": 1.5e-5 * size**3,
                "rail_mass_per_length": 0.005 * size**2,
                "block_price": (3 * size + 40) * lvl,
                "rail_price_per_length": (2.5 * size + 30) * lvl,
                # static moment ratings about 1 % of C0 per metre of block, as HIWIN HG (C0/M ~
                # 100-200 1/m)
                "moment_roll": 0.012 * 2 * c,
                "moment_pitch": 0.008 * 2 * c,
                "moment_yaw": 0.008 * 2 * c,
            }
        )
    for i in range(n_motors):
        vend, lvl = _vendor(rng)
        t = float(rng.choice([1.3, 2.4, 3.2, 4.8, 6.4, 8.3, 11.5, 15, 20, 30]))
        brake = bool(rng.random() < 0.5)
        motors.append(
            {
                "id": f"M{i}",
                "vendor": vend,
                "series": "synthetic",
                "rated_power": t * 3000 * RPM * 0.5,
                "rated_torque": t,
                "peak_torque": 3 * t,
                "rated_speed": 1500 * RPM,
                "max_speed": 3000 * RPM,
                "rotor_inertia": 1.2e-4 * t**1.5 * rng.uniform(0.7, 1.4),
                "rotor_inertia_brake": 1.3e-4 * t**1.5,
                "brake_torque": 1.2 * t if brake else math.nan,
                "mass": 2 + 0.8 * t,
                "flange": math.nan,
                "price": 150 * t * lvl + 300,
            }
        )
    for i in range(n_couplings):
        vend, lvl = _vendor(rng)
        t = float(rng.choice([10, 20, 35, 60, 100, 150, 300]))
        couplings.append(
            {
                "id": f"C{i}",
                "vendor": vend,
                "series": "synthetic",
                "rated_torque": t,
                "torsional_stiffness": 1e3 * t * rng.uniform(0.6, 1.6),
                "inertia": 4e-6 * t**1.3,
                "max_speed": 8000 * RPM,
                "bore_min": 0.006,
                "bore_max": (10 + t**0.5 * 3) * 1e-3,
                "mass": 0.1 + 0.01 * t,
                "price": (40 + 1.2 * t) * lvl,
            }
        )

    def df(rows, name):
        d = pd.DataFrame.from_records(rows, columns=list(SCHEMA[name]))
        d["_source"] = "synthetic"
        d["status"] = "vendor"
        d["source"] = "synthetic (bench/synthetic_catalogs.py)"
        return d.set_index("id", drop=False)

    return Catalog(
        df(screws, "screws"),
        df(nuts, "nuts"),
        df(bearings, "bearings"),
        df(guides, "guides"),
        df(motors, "motors"),
        df(couplings, "couplings"),
        df(reductions, "reductions"),
    )


def _reductions(n, rng) -> list:
    out = []
    for i in range(n):
        vend, lvl = _vendor(rng)
        belt = bool(rng.random() < 0.3)
        ratio = float(rng.choice([1.5, 2.0, 3.0] if belt else [3, 4, 5, 7, 10]))
        t = float(rng.choice([40, 80, 125, 330, 1800]))
        out.append(
            {
                "id": f"R{i}",
                "vendor": vend,
                "series": "synthetic",
                "kind": "belt" if belt else "planetary",
                "ratio": ratio,
                "efficiency": 0.95 if belt else 0.97,
                "inertia": 3e-6 * t**0.8,
                "rated_torque": t,
                "accel_torque": 2.3 * t,
                # issue 54: a belt stage's spans are softer than a gearbox, its zero-gap pulleys
                # play-free
                "torsional_stiffness": (0.1 if belt else 0.5)
                * t
                * 10800
                / math.pi
                * rng.uniform(0.7, 1.3),
                "backlash": (0.0 if belt else 3.0) * math.pi / 10800,
                "max_input_speed": (6000 if t < 500 else 3000) * RPM,
                "mass": 0.05 * t**0.8,
                "price": (200 + 2.5 * t) * lvl,
            }
        )
    return out
