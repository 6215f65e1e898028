"""What a time-record fit leaves unexplained (:mod:`axisopt.identify.records.unexplained`): an
effect the library does not have is reported with the residual's signature (a drag outside the
library, a ripple off the lead or at the lead, an external force at the wrong scale); null cases and
effects in the library leave nothing; the tests are quiet on white noise.

The records come from :mod:`axisopt.identify.records.synth`, the closed-loop simulator written apart
from the identification."""

import pytest
from identify_helpers import LEAD, records, truth_for, unexplained

from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.synth import AxisTruth, simulate_axis
from axisopt.identify.records.unexplained import analyse_residual
from axisopt.report.timediag import time_diagnosis_text

LIBRARY_BEFORE = ["stribeck", "direction_asymmetry", "position_friction", "extra_mode"]


# ------------------------------------------------------------------------------------- the
# unexplained verdict
def test_drag_outside_the_library_is_unexplained_with_its_signature(tmp_path, plant):
    """With the library as it was (no quadratic drag), the verdict says a misfit remains and that it
    grows with v|v|; and the reason for naming nothing is the true one (here Stribeck fits only with
    an excess beyond its range), not 'no effect lowers BIC'."""
    truth = truth_for(2, quadratic_drag=3000.0)
    diag = diagnose_time_files(records(tmp_path, truth, 2), plant=plant, candidates=LIBRARY_BEFORE)
    un = unexplained(diag)
    assert un["remaining"]
    sig = un["signatures"][0]
    assert sig["kind"] == "velocity" and "grows with v|v|" in sig["signature"]
    assert "quadratic drag" in sig["causes"] and sig["share"] > 0.5
    text = time_diagnosis_text(diag)
    assert "unexplained:" in text and "grows with v|v|" in text
    assert "no effect lowers BIC" not in text
    for c in diag.rounds[0]:
        assert c.reason  # every candidate not accepted carries its reason
        if c.dbic < -10 and c.gain >= 5:
            assert c.reason.startswith("would need"), c.reason


def test_ripple_off_the_lead_is_unexplained_with_its_period(tmp_path, plant):
    """A ripple over 25 mm (a recirculation circuit of 2.5 turns) is no harmonic of the 10 mm lead:
    no effect explains it, the verdict names its period and says it is not the lead; no
    extra_mode."""
    truth = truth_for(3, ripple=40.0, ripple_period=0.025)
    diag = diagnose_time_files(records(tmp_path, truth, 3), plant=plant)
    assert "extra_mode" not in diag.verdict and "lead_ripple" not in diag.verdict
    un = unexplained(diag)
    assert un["remaining"]
    sig = un["signatures"][0]
    assert sig["kind"] == "position_periodic"
    assert sig["period_mm"] == pytest.approx(25.0, rel=0.02)
    assert "the lead is 10 mm" in sig["signature"] and sig["share"] > 0.5


def test_ripple_at_the_lead_outside_the_library_names_the_lead(tmp_path, plant):
    truth = truth_for(4, ripple=40.0, ripple_period=LEAD)
    diag = diagnose_time_files(records(tmp_path, truth, 4), plant=plant, candidates=LIBRARY_BEFORE)
    assert "extra_mode" not in diag.verdict  # the spectral peak follows the position
    sig = unexplained(diag)["signatures"][0]
    assert sig["kind"] == "position_periodic" and "period 10.0 mm = the lead" in sig["signature"]
    assert "lead error or ball recirculation" in sig["causes"]


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_null_names_nothing_and_leaves_nothing_unexplained(tmp_path, plant, seed):
    diag = diagnose_time_files(records(tmp_path, truth_for(seed), seed), plant=plant)
    assert diag.verdict == []
    un = unexplained(diag)
    assert not un["remaining"] and un["signatures"] == []
    assert un["rms"] < 1.6 * un["noise_floor"]
    assert "residual: no structure beyond noise" in time_diagnosis_text(diag)


def test_existing_effect_leaves_nothing_unexplained(tmp_path, plant):
    truth = truth_for(21, stribeck=150.0, stribeck_v=0.005)
    diag = diagnose_time_files(records(tmp_path, truth, 21), plant=plant)
    assert diag.verdict == ["stribeck"]
    assert not unexplained(diag)["remaining"]


def test_residual_tests_are_quiet_on_white_noise(tmp_path, plant):
    """The structure tests on the final fit of a null record find no signature at the 1e-8 level."""
    diag = diagnose_time_files(records(tmp_path, truth_for(14), 14), plant=plant)
    u = analyse_residual([diag.estimation] + diag.validation, diag.final)
    assert all(p.log10_p > -8 for p in u.probes), [(p.kind, p.log10_p) for p in u.probes]


def test_external_force_at_the_wrong_scale_leaves_a_load_signature(tmp_path, plant):
    """An external_force column recorded at half its true value: the misfit follows the process
    force, and the verdict says so (whatever else is fitted)."""
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0, offset=20.0, process_force=300.0)
    rec = simulate_axis(truth, duration=12.0, seed=7)
    rec.extra["external_force"] = 0.5 * rec.extra["external_force"]
    path = tmp_path / "half.csv"
    rec.write_csv(path, columns=("time", "position", "force", "reference", "external_force"))
    un = unexplained(diagnose_time_files([path], plant=plant))
    assert un["remaining"] and un["signatures"][0]["kind"] == "load"
    assert "external force" in un["signatures"][0]["signature"]
