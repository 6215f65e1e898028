"""Time-record identification (:mod:`axisopt.identify.records.idim`, LS and IV): baseline recovery,
hidden effects named with their parameters, null cases and decoys, implausible effects not accepted.

The records come from :mod:`axisopt.identify.records.synth`, a closed-loop simulator written apart
from the identification code (PD loop, exact stick-slip, 1 um quantisation, force noise, 1 kHz)."""

import math

import numpy as np
import pytest
from identify_helpers import assert_timesynth_axis, baseline_truth, close, records

from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.synth import AxisTruth, LoopSettings


@pytest.fixture(scope="module")
def plant(plant):
    return assert_timesynth_axis(plant)


def _stribeck(rng):
    fs, vs = rng.uniform(80, 200), rng.uniform(0.003, 0.008)
    return dict(stribeck=fs, stribeck_v=vs), None, {"Fs": (fs, 0.10), "vs": (vs, 0.20)}


def _asym(rng):
    dfv = rng.choice([-1.0, 1.0]) * rng.uniform(400, 900)
    dfc = rng.choice([-1.0, 1.0]) * rng.uniform(20, 80)
    return dict(viscous_asym=dfv, coulomb_asym=dfc), None, {"dFv": (dfv, 0.10)}


def _position(rng):
    c = rng.choice([-1.0, 1.0], 2) * rng.uniform(80, 150, 2)
    return dict(position_coeffs=(c[0], c[1])), None, {"c1": (c[0], 0.10), "c2": (c[1], 0.10)}


def _mode(rng):
    f = rng.uniform(25, 40)
    return (
        dict(mode_hz=f, mode_zeta=0.1, mode_mass=rng.uniform(100, 200)),
        LoopSettings(bandwidth_hz=3.0),
        {"f_r": (f, 0.10)},
    )


EFFECT_CASES = {
    "stribeck": _stribeck,
    "direction_asymmetry": _asym,
    "position_friction": _position,
    "extra_mode": _mode,
}


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_baseline_recovered_by_ls_and_iv_and_null_names_nothing(tmp_path, plant, seed):
    truth = baseline_truth(np.random.default_rng(seed))
    diag = diagnose_time_files(records(tmp_path, truth, seed=seed), plant=plant)
    for est in (diag.baseline_ls, diag.baseline_iv):
        close(est, "M", truth.mass, 0.10)
        close(est, "Fv", truth.viscous, 0.10)
        close(est, "Fc", truth.coulomb, 0.10)
        close(est, "offset", truth.offset, 0.10)
    assert diag.baseline_iv.converged and diag.baseline_iv.iterations >= 2
    assert diag.verdict == []
    assert diag.validation and diag.validation[0].n > 200


@pytest.mark.parametrize("name,seed", [(n, s) for n in EFFECT_CASES for s in (21, 22)])
def test_hidden_effect_named_first_with_its_parameter(tmp_path, plant, name, seed):
    rng = np.random.default_rng(seed)
    kw, loop, expect = EFFECT_CASES[name](rng)
    truth = baseline_truth(rng, **kw)
    diag = diagnose_time_files(records(tmp_path, truth, seed, loop=loop), plant=plant)
    assert diag.verdict and diag.verdict[0] == name, diag.verdict
    assert diag.accepted[0].gain >= 30.0
    fin = diag.final
    assert fin.method == "IV"
    for term, (true, rel) in expect.items():
        got = (
            fin.shape["vs"]
            if term == "vs"
            else (
                math.sqrt(fin.value("M") / fin.value("beta")) / (2 * math.pi)
                if term == "f_r"
                else fin.value(term)
            )
        )
        assert got == pytest.approx(true, rel=rel), (term, got, true)
    close(fin, "M", truth.mass, 0.10)
    # the Coulomb half-difference is a constant while moving: in the offset
    if name == "direction_asymmetry":
        close(fin, "offset", truth.offset + truth.coulomb_asym / 2, 0.10)


def test_decoy_offset_is_not_an_asymmetry(tmp_path, plant):
    truth = AxisTruth(offset=150.0)
    diag = diagnose_time_files(records(tmp_path, truth, seed=31), plant=plant)
    assert diag.verdict == []
    close(diag.final, "offset", 150.0, 0.05)


def test_decoy_strong_viscous_is_not_stribeck(tmp_path, plant):
    truth = AxisTruth(viscous=5000.0, coulomb=150.0)
    diag = diagnose_time_files(records(tmp_path, truth, seed=32), plant=plant)
    assert "stribeck" not in diag.verdict
    assert diag.verdict == []
    close(diag.final, "Fv", 5000.0, 0.05)


def test_decoy_stribeck_is_not_viscous_or_position(tmp_path, plant):
    # slow decay over the speed range
    truth = AxisTruth(stribeck=120.0, stribeck_v=0.02, viscous=800.0)
    diag = diagnose_time_files(records(tmp_path, truth, seed=33), plant=plant, max_effects=2)
    assert diag.verdict == ["stribeck"]
    close(diag.final, "Fv", 800.0, 0.10)


def test_implausible_time_effect_is_not_accepted(tmp_path, plant):
    """Friction that *drops* at low speed (a negative Stribeck excess, -40 % of Coulomb) fits the
    Stribeck term only with Fs < 0, outside its physical range: with Stribeck the only candidate,
    nothing is accepted and the output says what it would need.  Control: the same record with a
    positive excess is accepted."""
    rng = np.random.default_rng(7)
    base = dict(mass=500.0, viscous=1200.0, coulomb=400.0, offset=20.0)
    bad = AxisTruth(**base, stribeck=-160.0, stribeck_v=0.005)
    diag = diagnose_time_files(
        records(tmp_path, bad, seed=int(rng.integers(100))), plant=plant, candidates=["stribeck"]
    )
    assert diag.verdict == []
    assert (
        diag.rejected
        and diag.rejected[0][1].effect.name == "stribeck"
        and "Fs" in diag.rejected[0][2]
    )
    good = AxisTruth(**base, stribeck=160.0, stribeck_v=0.005)
    diag = diagnose_time_files(
        records(tmp_path, good, seed=3), plant=plant, candidates=["stribeck"]
    )
    assert diag.verdict == ["stribeck"]
