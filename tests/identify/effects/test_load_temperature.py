"""Friction laws in temperature (:mod:`axisopt.identify.effects.load`): the viscous friction
following the lubricant's viscosity, the Coulomb level changing with temperature, hidden in friction
tables (``sim_tables``) and time records (``sim_cascade``) written by the tests' own physics.  A
warm-up recorded with its temperature is told from a drift with time (``friction_drift``) by the
validation run that starts warm.  A temperature column with a NaN is a one-line error."""

import numpy as np
import pytest
from sim_cascade import Axis, Loop, simulate, write
from sim_tables import friction_rows, write_table

from axisopt.identify import diagnose, read_dataset
from axisopt.identify.records.idim import diagnose_time_files


def _names(diag):
    return [e.name for e in diag.effects]


@pytest.mark.parametrize(
    "seed, beta, temps, vj",
    [
        (1, 0.035, (20, 26, 32, 40), 0.0),
        (2, 0.02, (18, 25, 35, 45), 0.005),
        (3, 0.06, (22, 28, 34), 0.005),
    ],
)
def test_viscous_friction_falling_with_temperature_is_named_in_a_table(
    tmp_path, plant, seed, beta, temps, vj
):
    rows = friction_rows(
        np.random.default_rng(seed),
        beta=beta,
        temps=temps,
        fv=1200.0,
        speed_jitter=vj,
        pos_jitter=0.001 if vj else 0.0,
    )
    diag = diagnose([read_dataset(write_table(tmp_path / "t.csv", rows))], plant)
    assert _names(diag) == ["viscous_temperature"]  # not viscous, not quadratic drag
    assert diag.final.value("viscosity_beta") == pytest.approx(beta, rel=0.10)
    assert diag.final.value("viscous_at_20C") == pytest.approx(1200.0, rel=0.10)
    assert all(not u.remaining for u in diag.unexplained)


@pytest.mark.parametrize("seed, slope", [(4, -3.0), (5, 2.0)])
def test_coulomb_friction_changing_with_temperature_is_named_in_a_table(
    tmp_path, plant, seed, slope
):
    rows = friction_rows(
        np.random.default_rng(seed), dfc_dT=slope, temps=(20, 28, 36, 44), fv=plant.viscous
    )
    diag = diagnose([read_dataset(write_table(tmp_path / "t.csv", rows))], plant)
    assert _names(diag) == ["coulomb_temperature"]
    assert diag.final.value("coulomb_per_kelvin") == pytest.approx(slope, rel=0.10)


def test_temperature_beside_nut_axial_friction_in_a_table(tmp_path, plant):
    rows = friction_rows(
        np.random.default_rng(6),
        beta=0.03,
        temps=(20, 30, 40),
        axial_ratio=0.06,
        axial_levels=(0, 2000, 4000),
        fv=1000.0,
    )
    diag = diagnose([read_dataset(write_table(tmp_path / "t.csv", rows))], plant)
    assert set(_names(diag)) == {"viscous_temperature", "nut_axial_friction"}
    assert diag.final.value("viscosity_beta") == pytest.approx(0.03, rel=0.10)
    assert diag.final.value("nut_axial_ratio") == pytest.approx(0.06, rel=0.10)


def test_null_table_with_temperature_names_nothing(tmp_path, plant):
    rows = friction_rows(
        np.random.default_rng(7), temps=(20, 30, 40), fv=plant.viscous, speed_jitter=0.005
    )
    diag = diagnose([read_dataset(write_table(tmp_path / "t.csv", rows))], plant)
    assert _names(diag) == [] and all(not u.remaining for u in diag.unexplained)


# -----------------------------------------------------------------------------------------------
# time records
def _warmup(tmp_path, ax, seed, fs=1000.0, start=12.0):
    loop = Loop(fs=fs, rho=0.5)
    est = write(tmp_path / "e.csv", simulate(ax, loop, 10.0, seed), ("temperature",))
    warm = Axis(**{**ax.__dict__, "temp_start": start})  # the validation run starts warm
    val = write(tmp_path / "v.csv", simulate(warm, loop, 5.0, seed + 500), ("temperature",))
    return [est, val]


@pytest.mark.slow
def test_viscous_warm_up_in_a_time_record_follows_temperature_not_time(tmp_path, plant):
    # 20 -> 38 degC with 4 s, viscous friction halving at +20 K
    ax = Axis(beta=0.035, temp=(20.0, 20.0, 4.0))
    diag = diagnose_time_files(_warmup(tmp_path, ax, 61), plant=plant)
    # not friction_drift: the warm run does not restart cold
    assert diag.verdict == ["viscous_temperature"]
    assert diag.final.shape["beta"] == pytest.approx(0.035, rel=0.10)
    assert diag.final.value("Fvt") == pytest.approx(1500.0, rel=0.10)
    drift = [c for r in diag.rounds[:1] for c in r if c.effect.name == "friction_drift"]
    assert drift and drift[0].gain < 5.0


@pytest.mark.slow
def test_coulomb_drift_with_temperature_in_a_time_record(tmp_path, plant):
    ax = Axis(dfc_dT=-4.0, temp=(20.0, 15.0, 4.0))
    diag = diagnose_time_files(_warmup(tmp_path, ax, 62, fs=500.0, start=10.0), plant=plant)
    assert diag.verdict == ["coulomb_temperature"]
    assert diag.final.value("dFc_dT") == pytest.approx(-4.0, rel=0.10)


def test_a_temperature_column_with_nan_is_a_one_line_error(tmp_path, plant):
    import subprocess
    import sys

    path = write(
        tmp_path / "e.csv",
        simulate(Axis(temp=(20.0, 5.0, 4.0)), Loop(fs=500.0), 1.0, 1),
        ("temperature",),
    )
    lines = path.read_text().splitlines()
    cells = lines[50].split(",")
    cells[-1] = "nan"
    lines[50] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    from pathlib import Path

    design = Path(__file__).resolve().parents[3] / "problems" / "data" / "table_x.yaml"
    out = subprocess.run(
        [sys.executable, "-m", "axisopt", "diagnose", str(path), "--design", str(design)],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2
    err = out.stderr.strip().splitlines()
    assert len(err) == 1 and "line 51" in err[0] and "temperature" in err[0] and "nan" in err[0]
