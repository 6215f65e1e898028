"""Friction that depends on the load (:mod:`axisopt.identify.effects.load`), hidden in data written
by the tests' own physics (``sim_tables`` for friction tables, ``sim_cascade`` for time records
under a P-PI cascade with coloured force noise), alone and beside a library effect, over seeds,
noise colours, jitter and parameter values.  The diagnosis must name it with its parameter within 10
%; nulls and decoys name nothing and claim no unexplained structure."""

import numpy as np
import pytest
from identify_helpers import unexplained
from sim_cascade import Axis, Loop, simulate, write
from sim_tables import friction_rows, write_table

from axisopt.identify import diagnose, read_dataset
from axisopt.identify.records.idim import diagnose_time_files
from axisopt.report.diagnosis import diagnosis_dict, diagnosis_text
from axisopt.report.timediag import time_diagnosis_text
from axisopt.report.timeresidual import NOISE_RATIO


def _table(tmp_path, plant, seed, **law):
    path = write_table(tmp_path / f"t{seed}.csv", friction_rows(np.random.default_rng(seed), **law))
    return diagnose([read_dataset(path)], plant)


def _names(diag):
    return [e.name for e in diag.effects]


def _no_structure(diag):
    return all(not u.remaining for u in diag.unexplained)


# ------------------------------------------------------------------------------ tables: the nut's
# axial load
AXIAL = [  # seed, k_a = 1/eta - 1, axial loads [N], speed jitter, position jitter [m], noise [N]
    (1, 0.08, (-3000, -1000, 0, 1500, 3000), 0.0, 0.0, 3.0),
    (2, 0.05, (0, 2000, 4000, 6000), 0.005, 0.001, 5.0),
    (3, 0.15, (-2000, 500, 2500), 0.005, 0.001, 3.0),
]


@pytest.mark.parametrize("seed, ka, loads, vj, pj, noise", AXIAL)
def test_nut_friction_growing_with_axial_load_is_named_in_a_table(
    tmp_path, plant, seed, ka, loads, vj, pj, noise
):
    diag = _table(
        tmp_path,
        plant,
        seed,
        axial_ratio=ka,
        axial_levels=loads,
        fv=plant.viscous,
        speed_jitter=vj,
        pos_jitter=pj,
        noise=noise,
    )
    assert _names(diag) == ["nut_axial_friction"]
    assert diag.final.value("nut_axial_ratio") == pytest.approx(ka, rel=0.10)
    assert _no_structure(diag)
    assert diag.gain > 30.0


def test_axial_load_share_is_signed_by_direction(tmp_path, plant):
    """A friction that grows with |F_a| both ways averages to nothing over the two directions: the
    misfit table takes its share of sgn(v) times the residual."""
    path = write_table(
        tmp_path / "a.csv",
        friction_rows(
            np.random.default_rng(5),
            axial_ratio=0.1,
            axial_levels=(0, 2000, 4000),
            fv=plant.viscous,
        ),
    )
    diag = diagnose([read_dataset(path)], plant, candidates=["viscous"])
    rows = diagnosis_dict(diag)["residuals_baseline"][0]
    share = {r["factor"]: r["eta2"] for r in rows}
    assert share["axial_load"] > 0.5


def test_nut_axial_friction_beside_stribeck(tmp_path, plant):
    diag = _table(
        tmp_path,
        plant,
        7,
        axial_ratio=0.07,
        axial_levels=(-2500, 0, 2500),
        stribeck=150.0,
        vs=0.004,
        delta=2.0,
        fv=plant.viscous,
        speeds=np.geomspace(0.0005, 0.3, 14),
    )
    assert set(_names(diag)) == {"nut_axial_friction", "stribeck"}
    assert diag.final.value("nut_axial_ratio") == pytest.approx(0.07, rel=0.10)
    assert diag.final.value("stribeck_rise") == pytest.approx(150.0, rel=0.10)


# ------------------------------------------------------------------ tables: guide load, with
# jittered logging
@pytest.mark.parametrize(
    "seed, mu, vj, pj",
    [(11, 0.004, 0.005, 0.001), (12, 0.0013, 0.005, 0.001), (13, 0.0045, 0.0, 0.0)],
)
def test_guide_friction_growing_with_payload_survives_jitter(tmp_path, plant, seed, mu, vj, pj):
    diag = _table(
        tmp_path,
        plant,
        seed,
        mu=mu,
        normal_levels=(0, 3000, 8000, 15000),
        fv=plant.viscous,
        speed_jitter=vj,
        pos_jitter=pj,
    )
    assert _names(diag) == ["load_dependent_friction"]  # not quadratic_drag
    assert diag.final.value("friction_coefficient") == pytest.approx(mu, rel=0.10)
    assert "replicate" in diag.obs[0].noise_method  # the jittered readings are still replicates
    assert _no_structure(diag)


def test_jittered_positions_keep_their_held_out_groups(tmp_path, plant):
    rows = friction_rows(
        np.random.default_rng(3),
        fv=plant.viscous,
        positions=(0.1, 0.3, 0.5, 0.7),
        pos_jitter=0.001,
        speed_jitter=0.005,
    )
    diag = diagnose([read_dataset(write_table(tmp_path / "p.csv", rows))], plant)
    assert diag.obs[0].group_name == "position"
    assert len(np.unique(diag.obs[0].groups)) == 4
    assert _names(diag) == [] and _no_structure(diag)
    assert "verdict: none" in diagnosis_text(diag)


@pytest.mark.parametrize("seed", [21, 22])
def test_null_table_with_loads_and_jitter_names_nothing(tmp_path, plant, seed):
    diag = _table(
        tmp_path,
        plant,
        seed,
        axial_levels=(-2000, 0, 2000),
        normal_levels=(0, 5000),
        mu=plant.mu,
        fv=plant.viscous,
        speed_jitter=0.005,
        pos_jitter=0.001,
    )
    assert _names(diag) == [] and _no_structure(diag)


# -------------------------------------------------------------------------------- time records (own
# physics)
def _records(tmp_path, ax, loop, seed, columns=("external_force",), est_s=6.0, val_s=4.0):
    est = write(tmp_path / f"e{seed}.csv", simulate(ax, loop, est_s, seed), columns)
    val = write(tmp_path / f"v{seed}.csv", simulate(ax, loop, val_s, seed + 500), columns)
    return [est, val]


# seed, 1 - eta, process-force amplitude [N], AR(1) coefficient of the force noise, fs [Hz]
TIME_AXIAL = [
    (31, 0.08, 3000.0, 0.0, 500.0),
    pytest.param(32, 0.05, 2500.0, 0.9, 500.0, marks=pytest.mark.slow),
    pytest.param(33, 0.12, 2000.0, 0.6, 1000.0, marks=pytest.mark.slow),
]


@pytest.mark.parametrize("seed, loss, amp, rho, fs", TIME_AXIAL)
def test_nut_friction_with_the_process_force_is_named_in_a_time_record(
    tmp_path, plant, seed, loss, amp, rho, fs
):
    ax = Axis(mass=550.0, fc=350.0, fv=1200.0, nut_loss=loss, load_amp=amp)
    diag = diagnose_time_files(_records(tmp_path, ax, Loop(fs=fs, rho=rho), seed), plant=plant)
    assert diag.verdict == ["nut_axial_friction"]
    assert diag.final.value("ka") == pytest.approx(loss, rel=0.10)
    # not absorbed by the Coulomb level
    assert diag.final.value("Fc") == pytest.approx(350.0, rel=0.10)
    assert not unexplained(diag)["remaining"]


@pytest.mark.slow
def test_nut_friction_beside_stribeck_in_a_time_record(tmp_path, plant):
    ax = Axis(nut_loss=0.06, load_amp=2500.0, fs_excess=150.0, vs=0.005)
    diag = diagnose_time_files(_records(tmp_path, ax, Loop(fs=1000.0, rho=0.5), 34), plant=plant)
    assert set(diag.verdict) == {"nut_axial_friction", "stribeck"}
    assert diag.final.value("ka") == pytest.approx(0.06, rel=0.10)
    assert diag.final.value("Fs") == pytest.approx(150.0, rel=0.10)


@pytest.mark.parametrize(
    "seed, rho, fs", [(41, 0.5, 500.0), pytest.param(42, 0.9, 1000.0, marks=pytest.mark.slow)]
)
def test_null_time_record_with_coloured_noise_names_nothing(tmp_path, plant, seed, rho, fs):
    """A process force without a load-dependent loss (a decoy for nut_axial_friction) and coloured
    force
    noise: no effect, no claimed structure (the noise floor sees the colour)."""
    ax = Axis(mass=700.0, fc=300.0, fv=1800.0, load_amp=2500.0)
    diag = diagnose_time_files(_records(tmp_path, ax, Loop(fs=fs, rho=rho), seed), plant=plant)
    assert diag.verdict == []
    assert not unexplained(diag)["remaining"]
    # "no structure beyond noise"
    assert diag.unexplained.rms < NOISE_RATIO * diag.unexplained.noise
    assert "no structure beyond noise" in time_diagnosis_text(diag)
