"""Synthetic catalogs (SCHEMA columns, SI) and problems for the search tests; fixed seeds."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from axisopt.catalog.columns import SCHEMA
from axisopt.catalog.loading import Catalog
from axisopt.design import Axis
from axisopt.model import CHECKS
from axisopt.model.goals import Objective
from axisopt.problem import Problem, Restrictions

RPM = 2 * math.pi / 60


@dataclass(frozen=True)
class Ranges:
    """What the synthetic parts are drawn from (uniform between two values or a choice among
    several; SI except the marked ones).  The tests' catalogs use ``TESTS``; bench/bench_search.py's
    catalog of 10^6 combinations ``BENCH`` (its draws kept, so the figures docs/benchmarks.md quotes
    still hold)."""

    vendor: str
    diameters_mm: tuple
    leads_mm: tuple
    ball_first: bool  # the ball diameter drawn before the lead (the bench's order)
    max_length: tuple
    nut_rating: tuple
    nut_rigidity_per_um: tuple  # N/um
    single_preload: float  # the single nut's quoted stiffness load, x C
    bores_mm: tuple
    lift_off: tuple
    starting_torque: tuple


TESTS = Ranges(
    vendor="V",
    diameters_mm=(20, 25, 32, 40, 50),
    leads_mm=(5, 10, 20),
    ball_first=False,
    max_length=(1.5, 5),
    nut_rating=(10e3, 80e3),
    nut_rigidity_per_um=(150, 900),
    single_preload=0.3,
    bores_mm=(12, 15, 17, 20, 25, 30),
    lift_off=(3e3, 2e4),
    starting_torque=(0.05, 0.3),
)
BENCH = Ranges(
    vendor="SYN",
    diameters_mm=(25, 32, 40, 50, 63),
    leads_mm=(10, 16, 20),
    ball_first=True,
    max_length=(3, 6),
    nut_rating=(20e3, 120e3),
    nut_rigidity_per_um=(200, 1200),
    single_preload=0.28,
    bores_mm=(15, 17, 20, 25, 30),
    lift_off=(5e3, 3e4),
    starting_torque=(0.1, 0.5),
)


def frame(rows, name: str) -> pd.DataFrame:
    """Synthetic rows as a catalog table: the SCHEMA columns, indexed by id, source 'synthetic'."""
    d = pd.DataFrame.from_records(rows, columns=list(SCHEMA[name]))
    d["_source"] = "synthetic"
    return d.set_index("id", drop=False)


def make_catalog(
    rng: np.random.Generator,
    n_screws=3,
    nuts_per_screw=2,
    n_bearings=4,
    n_guides=4,
    carriage: bool = False,
    rotating: bool = False,
    ranges: Ranges = TESTS,
) -> Catalog:
    """``rotating``: about half the nuts are driven rotating-nut units (THK DIR/BLR-like unit
    values; some leave the max speed, bearing rigidity and starting torque to the model's
    estimates)."""
    r = ranges
    screws, nuts, bearings, guides = [], [], [], []
    for i in range(n_screws):
        d = rng.choice(r.diameters_mm) * 1e-3
        if r.ball_first:
            ball = rng.choice([3.175, 4.763, 6.35]) * 1e-3
            lead = rng.choice(r.leads_mm) * 1e-3
        else:
            lead = rng.choice(r.leads_mm) * 1e-3
            ball = rng.choice([3.175, 4.763, 6.35]) * 1e-3
        sid = f"S{i}"
        screws.append(
            {
                "id": sid,
                "vendor": r.vendor,
                "series": "synthetic",
                "nominal_diameter": d,
                "lead": lead,
                "root_diameter": d - 1.2 * ball,
                "ball_diameter": ball,
                "max_length": rng.uniform(*r.max_length),
                "mass_per_length": 7850 * math.pi * d**2 / 4,
                "dn_limit": rng.uniform(1.2e5, 2.2e5) * 1e-3 * RPM,
                "support_bore_min": 0.4 * d,
                "support_bore_max": d - 0.002,
                "price_per_length": rng.uniform(60, 250),
                "price_fixed": rng.uniform(100, 300),
            }
        )
        for j in range(nuts_per_screw):
            c = rng.uniform(*r.nut_rating)
            double = bool(rng.random() < 0.7)
            nuts.append(
                {
                    "id": f"N{i}_{j}",
                    "vendor": r.vendor,
                    "screw_id": sid,
                    "type": "double" if double else "single",
                    "stiffness": rng.uniform(*r.nut_rigidity_per_um) * 1e6,
                    "stiffness_preload": (0.1 if double else r.single_preload) * c,
                    "preload_min": 0.02 * c if double else 0.0,
                    "preload_max": 0.1 * c if double else 0.0,
                    "dynamic_load_rating": c,
                    "static_load_rating": 2 * c,
                    "contact_angle": math.radians(45),
                    "axial_play": 0.0 if double else 2e-5,
                    "mass": rng.uniform(0.5, 4),
                    "price": rng.uniform(200, 900),
                }
            )
            if rotating and rng.random() < 0.5:
                cb = rng.uniform(8e3, 60e3)
                nuts[-1].update(
                    {
                        "rotating": 1,
                        "unit_inertia": rng.uniform(0.5, 30) * 1e-4,
                        "unit_max_speed": rng.uniform(1500, 4000) * RPM
                        if rng.random() < 0.5
                        else math.nan,
                        "unit_bearing_dynamic_load": cb,
                        "unit_bearing_static_load": rng.uniform(1.1, 1.5) * cb,
                        "unit_bearing_rigidity": rng.uniform(200, 1500) * 1e6
                        if rng.random() < 0.5
                        else math.nan,
                        "unit_starting_torque": rng.uniform(0.1, 0.8)
                        if rng.random() < 0.5
                        else math.nan,
                        "price": nuts[-1]["price"] + rng.uniform(200, 500),
                    }
                )
    for i in range(n_bearings):
        bore = rng.choice(r.bores_mm) * 1e-3
        bearings.append(
            {
                "id": f"B{i}",
                "vendor": r.vendor,
                "series": "synthetic",
                "arrangement": "DB",
                "rows": 2,
                "bore": bore,
                "outer_diameter": bore + 0.03,
                "contact_angle": math.radians(60),
                "preload_class": rng.choice(["light", "medium", "heavy"]),
                "preload": rng.uniform(500, 3000),
                "axial_rigidity": rng.uniform(300, 1500) * 1e6,
                "lift_off_load": rng.uniform(*r.lift_off),
                "dynamic_load_rating": rng.uniform(15e3, 40e3),
                "static_load_rating": 4e4,
                "limiting_speed": rng.uniform(3000, 9000) * RPM,
                "f0": 1.5,
                "f1": 0.0003,
                "starting_torque": rng.uniform(*r.starting_torque)
                if rng.random() < 0.5
                else math.nan,
                "mass": rng.uniform(0.2, 1.0),
                "price": rng.uniform(100, 500),
            }
        )
    for i in range(n_guides):
        kn = rng.uniform(200, 900) * 1e6
        guides.append(
            {
                "id": f"G{i}",
                "vendor": r.vendor,
                "series": "synthetic",
                "type": "ball",
                "size": 0.025,
                "preload_class": "Z0",
                "preload_level": rng.choice(["light", "medium", "heavy"]),
                "preload": rng.uniform(500, 3000),
                "normal_rigidity": kn,
                "tangential_rigidity": 0.71 * kn,
                "dynamic_load_rating": 3e4,
                "static_load_rating": 5e4,
                "friction_force": rng.uniform(3, 30),
                "friction_coefficient": 0.003,
                "friction_viscous": rng.uniform(3, 20),
                "damping": 3000.0,
                "block_mass": rng.uniform(0.2, 1.5),
                "rail_mass_per_length": rng.uniform(2, 6),
                "block_price": rng.uniform(50, 200),
                "rail_price_per_length": rng.uniform(50, 150),
                "moment_roll": 400.0,
                "moment_pitch": 300.0,
                "moment_yaw": 300.0,
            }
        )
    # guides of several sizes: static and moment ratings that vary, for the carriage's checks
    if carriage:
        for g in guides:
            c = rng.uniform(8e3, 60e3)
            g.update(
                dynamic_load_rating=c,
                static_load_rating=rng.uniform(1.3, 1.8) * c,
                moment_roll=rng.uniform(0.008, 0.02) * c,
                moment_pitch=rng.uniform(0.006, 0.015) * c,
                moment_yaw=rng.uniform(0.006, 0.015) * c,
            )

    return Catalog(
        screws=frame(screws, "screws"),
        nuts=frame(nuts, "nuts"),
        bearings=frame(bearings, "bearings"),
        guides=frame(guides, "guides"),
    )


def make_double(catalog) -> None:
    """Turn every nut of a synthetic catalog into a preloaded double nut (preload 2-10 % C, quoted
    at 10 % C)."""
    n = catalog.nuts
    c = n["dynamic_load_rating"]
    n["type"] = "double"
    n["stiffness_preload"], n["preload_min"], n["preload_max"], n["axial_play"] = (
        0.1 * c,
        0.02 * c,
        0.1 * c,
        0.0,
    )


def make_problem(
    catalog,
    *,
    mode="stiffness",
    mountings=("fixed-supported", "fixed-fixed"),
    limits=None,
    stroke=0.6,
    objective=None,
    margins=None,
    backlash=None,
    **axis_kw,
) -> Problem:
    # fw 1.2 as given (THK Table 19's default for 18 m/min would be 1.5, issue 38): the problems
    # keep the sizes they were drawn for, with feasible combinations for every seed
    kw = {
        "moving_mass": 300.0,
        "max_speed": 0.3,
        "axial_load": 3000.0,
        "acceleration": 3.0,
        "load_factor": 1.2,
    }
    kw.update(axis_kw)
    axis = Axis(stroke=stroke, mounting=mountings[0], **kw)
    m = {c: 1.0 for c in CHECKS}
    m.update(margins or {})
    limits = dict(limits or {})
    # the problem reader's default (max_backlash 0) unless a test allows single nuts with play
    limits.setdefault("max_backlash", 0.0 if backlash is None else backlash)
    return Problem(
        axis=axis,
        catalog=catalog,
        objective=objective or Objective(mode=mode),
        limits=tuple(sorted(limits.items())),
        margins=tuple(m.items()),
        restrictions=Restrictions(mountings=tuple(mountings)),
        name="synthetic",
    )


def add_drives(
    catalog, rng: np.random.Generator, n_motors=4, n_couplings=2, rules=False
) -> Catalog:
    """Give a synthetic catalog servo motors (peak 3 x rated, some with a holding brake) and
    couplings.
    ``rules``: each motor also names a vendor's selection rule (model.motorrule: Yaskawa 1 / 1,
    Mitsubishi 0.8 / 0.6, FANUC 0.9 / 0.6, or none), drawn from a generator of its own."""
    motors, couplings = [], []
    for i in range(n_motors):
        t = rng.uniform(2.0, 15.0)
        j = rng.uniform(2e-4, 3e-3)
        brake = bool(rng.random() < 0.6)
        # intermittent-zone corner points (issue 26): half the motors list them, the rest take the
        # estimate; a generator of its own so that the draws above keep their sequence
        zr = np.random.default_rng(7919 + i)
        listed = bool(zr.random() < 0.5)
        motors.append(
            {
                "id": f"M{i}",
                "vendor": "V",
                "series": "synthetic",
                "rated_power": t * 300.0,
                "rated_torque": t,
                "peak_torque": 3.0 * t,
                "rated_speed": 2000 * RPM,
                "max_speed": rng.uniform(2500, 6000) * RPM,
                "rotor_inertia": j,
                "rotor_inertia_brake": 1.1 * j if brake else math.nan,
                "brake_torque": 1.5 * t if brake else math.nan,
                "mass": math.nan,
                "flange": math.nan,
                "price": 200 + 80 * t,
                "peak_corner_speed": zr.uniform(1000, 2500) * RPM if listed else math.nan,
                "peak_torque_at_max_speed": zr.uniform(1.0, 2.0) * t if listed else math.nan,
            }
        )
        if rules:
            rms, unb = ((1.0, 1.0), (0.8, 0.6), (0.9, 0.6), (math.nan, math.nan))[
                int(zr.integers(4))
            ]
            motors[-1].update({"rms_ratio": rms, "unbalance_ratio": unb})
    for i in range(n_couplings):
        couplings.append(
            {
                "id": f"C{i}",
                "vendor": "V",
                "series": "synthetic",
                "rated_torque": rng.uniform(30, 200),
                "torsional_stiffness": rng.uniform(2e4, 3e5),
                "inertia": rng.uniform(1e-4, 1e-3),
                "max_speed": 8000 * RPM,
                "bore_min": 0.01,
                "bore_max": 0.04,
                "mass": math.nan,
                "price": rng.uniform(60, 250),
            }
        )

    return catalog.replace(motors=frame(motors, "motors"), couplings=frame(couplings, "couplings"))


def add_reductions(catalog, rng: np.random.Generator, n=3, rules=False) -> Catalog:
    """Give a synthetic catalog reductions (planetary and belt rows, ratio 1.5-5, T2B 1.5-2.5 x T2N,
    torsional stiffness 1e4-1e6 N.m/rad, input speed limit 3000-8000 rpm): the search chooses one or
    none per drive."""
    rows = []
    for i in range(n):
        t = rng.uniform(20.0, 200.0)
        rows.append(
            {
                "id": f"R{i}",
                "vendor": "V",
                "series": "synthetic",
                "kind": ("planetary", "belt")[i % 2],
                "ratio": float(rng.choice([1.5, 2.0, 3.0, 5.0])),
                "efficiency": rng.uniform(0.9, 0.98),
                "inertia": rng.uniform(1e-5, 5e-4),
                "rated_torque": t,
                "accel_torque": t * rng.uniform(1.5, 2.5),
                "torsional_stiffness": 10 ** rng.uniform(4, 6),
                "backlash": rng.uniform(1.0, 10.0) * math.pi / 10800,  # 1-10 arcmin
                "max_input_speed": rng.uniform(3000, 8000) * RPM,
                "mass": math.nan,
                "price": rng.uniform(100, 800),
            }
        )
        if rules:  # an emergency-stop torque 1-2.5 x T2B, or none listed (T2B stands in)
            er = np.random.default_rng(104729 + i)
            rows[-1]["emergency_torque"] = (
                rows[-1]["accel_torque"] * er.uniform(1.0, 2.5) if er.random() < 0.7 else math.nan
            )
    d = pd.DataFrame.from_records(rows, columns=list(SCHEMA["reductions"]))
    d["_source"] = "synthetic"
    return catalog.replace(reductions=d.set_index("id", drop=False))


def add_support_sets(catalog, rng: np.random.Generator) -> Catalog:
    """Make about half the bearings of a synthetic catalog 3-against-1 sets (DFT: three rows each
    way's rating 3^0.7 / 1, the stronger direction's lift-off load three times the weaker's, as the
    Hertz set rule gives 5.41 / 1.80, physics.bearingsets) and some 2-against-1 (DFD), the rest DB
    pairs."""
    b = catalog.bearings.copy()
    b["lift_off_load_strong"] = math.nan
    for i in b.index:
        u = rng.random()
        if u < 0.5:
            b.loc[i, ["arrangement", "rows"]] = ["DFT", 4]
            b.loc[i, "dynamic_load_rating"] *= 3**0.7
            b.loc[i, "lift_off_load_strong"] = 3.0 * b.loc[i, "lift_off_load"]
        elif u < 0.75:
            b.loc[i, ["arrangement", "rows"]] = ["DFD", 3]
            b.loc[i, "dynamic_load_rating"] *= 2**0.7
    return catalog.replace(bearings=b)


def add_belt_stages(catalog, rng: np.random.Generator, n=2) -> Catalog:
    """Add ``n`` timing-belt stages to a synthetic catalog's reductions: ratio 1-3, no backlash,
    torsional stiffness 2e3-3e4 N.m/rad (a belt's spans: softer than a gearbox), T2B = T2N (the
    teeth's shear)."""
    rows = []
    for i in range(n):
        t = rng.uniform(15.0, 120.0)
        rows.append(
            {
                "id": f"BELT{i}",
                "vendor": "V",
                "series": "synthetic",
                "kind": "belt",
                "ratio": float(rng.choice([1.0, 1.5, 2.0, 3.0])),
                "efficiency": rng.uniform(0.95, 0.98),
                "inertia": rng.uniform(2e-4, 2e-3),
                "rated_torque": t,
                "accel_torque": t,
                "torsional_stiffness": 10 ** rng.uniform(3.3, 4.5),
                "backlash": 0.0,
                "max_input_speed": rng.uniform(3000, 5000) * RPM,
                "mass": math.nan,
                "price": rng.uniform(150, 400),
            }
        )
    d = pd.DataFrame.from_records(rows, columns=list(SCHEMA["reductions"]))
    d["_source"] = "synthetic"
    red = d.set_index("id", drop=False)
    if catalog.reductions is not None:
        red = pd.concat([catalog.reductions, red])
    return catalog.replace(reductions=red)


def assert_same_answer(a, b, preload: bool = True):
    """Two SolveResults give the same answer: status, objective, combination (and nut preload)."""
    import pytest

    assert a.status == b.status
    if a.best is None:
        assert b.best is None
        return
    assert a.best.objective == pytest.approx(b.best.objective, rel=1e-6)
    assert a.best.combination == b.best.combination
    if preload:
        assert a.best.nut_preload == pytest.approx(b.best.nut_preload, rel=1e-5, abs=1e-3)
