"""Effects that only time records show (:mod:`axisopt.identify.effects.disturbance`): a force
periodic in time, friction local to one place on the stroke and friction that drifts within a run.
Each is hidden in records simulated by :mod:`axisopt.identify.records.synth` (the closed loop
written apart from the identification) with its physics written here, in this file, as the
simulator's ``extra_force`` / ``extra_friction``: alone and beside an effect of the library, over
several seeds, noise levels and parameter values.  The diagnosis must name it with its parameters
within 10 % (frequency within 2 % of itself, position within 2 % of the stroke), give it no other
effect's name, and leave no unexplained structure; with the class left out of the library the
residual signature (:mod:`axisopt.identify.records.signature`) must locate it (frequency, position,
time constant).  Null and decoy records name none of the three and show none of the three
signatures."""

import math

import pytest
from identify_helpers import LEAD, records, truth_for, unexplained

from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.synth import LoopSettings
from axisopt.report.timediag import time_diagnosis_dict, time_diagnosis_text

NEW = ("time_periodic", "local_friction", "friction_drift")
SIGNATURES = ("line", "spot", "decay")
LIBRARY_BEFORE = [
    "stribeck",
    "direction_asymmetry",
    "position_friction",
    "extra_mode",
    "lead_ripple",
    "quadratic_drag",
]
STROKE = 0.8  # [m] of table_x.yaml


# ----------------------------------------------------------------------- the hidden physics (this
# file's own)
def periodic_force(f_hz, amp, phase):
    """A force in -x the drive must supply: amp sin(2 pi f t + phase) [N] (a pump's or spindle's
    unbalance)."""
    return lambda t, x, v: amp * math.sin(2.0 * math.pi * f_hz * t + phase)


def spot_friction(x0, width, height):
    """A Coulomb level raised by height exp(-(x - x0)^2 / 2 width^2) [N] (a dry or damaged spot)."""
    return lambda t, x: height * math.exp(-0.5 * ((x - x0) / width) ** 2)


def warm_up(amp, tau):
    """A Coulomb level raised by amp exp(-t/tau) [N] from the start of each run (the lubricant
    warming)."""
    return lambda t, x: amp * math.exp(-t / tau)


def shape(diag, name):
    return diag.final.shape[name]


def amplitude(est):
    return math.hypot(est.value("ps"), est.value("pc"))


# ------------------------------------------------------------------------------------------- named,
# alone
PERIODIC = [  # seed, frequency [Hz], amplitude [N], phase, force noise [N]
    (31, 9.5, 60.0, 0.7, 4.0),
    (32, 23.0, 40.0, -1.2, 4.0),
    (33, 21.0, 70.0, 2.5, 10.0),
]


@pytest.mark.parametrize("seed, f_hz, amp, phase, noise", PERIODIC)
def test_time_periodic_force_is_named_with_its_frequency_and_amplitude(
    tmp_path, plant, seed, f_hz, amp, phase, noise
):
    truth = truth_for(seed, extra_force=periodic_force(f_hz, amp, phase))
    diag = diagnose_time_files(
        records(tmp_path, truth, seed, loop=LoopSettings(force_noise=noise)), plant=plant
    )
    assert diag.verdict == ["time_periodic"]
    assert shape(diag, "freq") == pytest.approx(f_hz, rel=0.02)
    assert amplitude(diag.final) == pytest.approx(amp, rel=0.10)
    assert diag.accepted[0].gain > 20.0  # held-out gain: the validation run's own phase
    assert not unexplained(diag)["remaining"]
    text = time_diagnosis_text(diag)
    assert "freq" in text and "amplitude of the periodic force" in text
    params = {p["name"]: p["value"] for p in time_diagnosis_dict(diag)["final"]["parameters"]}
    assert params["freq"] == pytest.approx(f_hz, rel=0.02) and params["amp"] == pytest.approx(
        amp, rel=0.10
    )


SPOTS = [  # seed, x0 [m], width [m], height [N], force noise [N]
    (41, 0.30, 0.006, 120.0, 4.0),
    (42, 0.45, 0.010, 80.0, 4.0),
    (43, 0.55, 0.015, 150.0, 10.0),
]


@pytest.mark.parametrize("seed, x0, width, height, noise", SPOTS)
def test_local_friction_is_named_with_its_place_width_and_height(
    tmp_path, plant, seed, x0, width, height, noise
):
    truth = truth_for(seed, extra_friction=spot_friction(x0, width, height))
    diag = diagnose_time_files(
        records(tmp_path, truth, seed, loop=LoopSettings(force_noise=noise)), plant=plant
    )
    assert diag.verdict == ["local_friction"]
    assert abs(shape(diag, "x0") - x0) < 0.02 * STROKE
    assert shape(diag, "width") == pytest.approx(width, rel=0.10)
    assert diag.final.value("hs") == pytest.approx(height, rel=0.10)
    assert not unexplained(diag)["remaining"]


DRIFTS = [  # seed, amplitude [N], tau [s], force noise [N]
    (51, 150.0, 3.0, 4.0),
    (52, 90.0, 1.5, 4.0),
    (53, 200.0, 6.0, 10.0),
]


@pytest.mark.parametrize("seed, amp, tau, noise", DRIFTS)
def test_friction_drift_is_named_with_its_amplitude_and_time_constant(
    tmp_path, plant, seed, amp, tau, noise
):
    truth = truth_for(seed, extra_friction=warm_up(amp, tau))
    diag = diagnose_time_files(
        records(tmp_path, truth, seed, loop=LoopSettings(force_noise=noise)), plant=plant
    )
    assert diag.verdict == ["friction_drift"]  # not direction_asymmetry, not stribeck
    assert shape(diag, "tau") == pytest.approx(tau, rel=0.10)
    assert diag.final.value("Ad") == pytest.approx(amp, rel=0.10)
    assert not unexplained(diag)["remaining"]


# ------------------------------------------------------------------------------- named beside
# another effect seed, the hidden class and its physics, the library effect beside it, (shape, true
# value, tolerance)
BESIDE = [
    (
        61,
        "time_periodic",
        {"extra_force": periodic_force(17.0, 50.0, 0.3)},
        {"stribeck": 150.0, "stribeck_v": 0.004},
        ("freq", 17.0, 0.02 * 17.0),
    ),
    (
        62,
        "local_friction",
        {"extra_friction": spot_friction(0.4, 0.008, 110.0)},
        {"stribeck": 150.0, "stribeck_v": 0.004},
        ("x0", 0.4, 0.02 * STROKE),
    ),
    (
        63,
        "friction_drift",
        {"extra_friction": warm_up(120.0, 2.5)},
        {"quadratic_drag": 3000.0},
        ("tau", 2.5, 0.25),
    ),
    pytest.param(
        64,
        "time_periodic",
        {"extra_force": periodic_force(26.0, 45.0, 1.0)},
        {"ripple": 40.0, "ripple_period": LEAD},
        ("freq", 26.0, 0.02 * 26.0),
        marks=pytest.mark.slow,
    ),
]
BESIDE_NAME = {"stribeck": "stribeck", "quadratic_drag": "quadratic_drag", "ripple": "lead_ripple"}


@pytest.mark.parametrize("seed, name, hidden, other, expect", BESIDE)
def test_each_class_is_named_beside_a_library_effect(
    tmp_path, plant, seed, name, hidden, other, expect
):
    truth = truth_for(seed, **hidden, **other)
    diag = diagnose_time_files(records(tmp_path, truth, seed), plant=plant)
    assert set(diag.verdict) == {name, next(BESIDE_NAME[k] for k in other if k in BESIDE_NAME)}
    key, true, tol = expect
    assert abs(shape(diag, key) - true) < tol
    assert not unexplained(diag)["remaining"]


# ------------------------------------------------------------------- outside the library: the
# signature says it
def _signature(diag, kind):
    sigs = [s for s in unexplained(diag)["signatures"] if s["kind"] == kind]
    assert sigs, unexplained(diag)["signatures"]
    return sigs[0]


def test_a_line_left_unexplained_is_located_in_frequency_and_not_tied_to_speed(tmp_path, plant):
    truth = truth_for(34, extra_force=periodic_force(13.0, 60.0, 0.4))
    diag = diagnose_time_files(records(tmp_path, truth, 34), plant=plant, candidates=LIBRARY_BEFORE)
    sig = _signature(diag, "line")
    assert sig["frequency"] == pytest.approx(13.0, rel=0.02) and sig["amplitude"] == pytest.approx(
        60.0, rel=0.1
    )
    assert sig["fixed"] and "not tied to speed" in sig["signature"] and "pump" in sig["causes"]
    assert "13 Hz" in time_diagnosis_text(diag)


def test_a_line_above_the_fitted_band_is_no_resonance_and_is_located(tmp_path, plant):
    """29 Hz against a 47 Hz position filter: above the band time_periodic is fitted in (0.6x the
    cut-off, where the filter's attenuation of the table's response would bias the amplitude); the
    steady line is not taken for a resonance (extra_mode not tried), nothing is named and the
    signature gives the frequency."""
    truth = truth_for(33, extra_force=periodic_force(29.0, 70.0, 2.5))
    diag = diagnose_time_files(
        records(tmp_path, truth, 33, loop=LoopSettings(force_noise=10.0)), plant=plant
    )
    assert diag.verdict == [] and "steady line" in diag.skipped["extra_mode"]
    sig = _signature(diag, "line")
    assert sig["frequency"] == pytest.approx(29.0, rel=0.02) and sig["fixed"]
    assert "where time_periodic is fitted" in sig["signature"]


def test_a_line_from_a_ripple_in_position_is_tied_to_speed(tmp_path, plant):
    """A ripple over 25 mm (no lead harmonic) shows in time only at the speed where v/P is in
    the band: the line signature (when it shows) says it is tied to speed; the period signature
    comes first either way."""
    truth = truth_for(3, ripple=40.0, ripple_period=0.025)
    diag = diagnose_time_files(records(tmp_path, truth, 3), plant=plant)
    assert not set(diag.verdict) & set(NEW)
    sigs = unexplained(diag)["signatures"]
    assert sigs[0]["kind"] == "position_periodic"
    assert all(not s["fixed"] for s in sigs if s["kind"] == "line")


def test_a_spot_left_unexplained_is_located_on_the_stroke(tmp_path, plant):
    truth = truth_for(44, extra_friction=spot_friction(0.2, 0.008, 130.0))
    diag = diagnose_time_files(records(tmp_path, truth, 44), plant=plant, candidates=LIBRARY_BEFORE)
    sig = _signature(diag, "spot")
    assert abs(sig["x0_mm"] - 200.0) < 0.02 * STROKE * 1e3 and sig["width_mm"] == pytest.approx(
        8.0, rel=0.2
    )
    assert sig["directions"] == "both" and sig["friction"]
    assert f"bump at {sig['x0_mm']:.1f} mm" in sig["signature"] and "rail" in sig["causes"]


def test_a_drift_left_unexplained_gives_its_time_constant(tmp_path, plant):
    truth = truth_for(54, extra_friction=warm_up(150.0, 3.0))
    diag = diagnose_time_files(records(tmp_path, truth, 54), plant=plant, candidates=LIBRARY_BEFORE)
    sig = _signature(diag, "decay")
    # the probe's grid of time constants: 0.3 .. 30 s, 13 per two decades
    assert 2.0 <= sig["tau"] <= 4.5
    assert sig["friction_share"] > 0.5 and "warm-up" in sig["causes"]
    assert "direction_asymmetry" not in diag.verdict


def test_the_line_scan_of_windows_off_the_decimation_grid_equals_the_direct_sums():
    """A long record's windows start at any sample, so the kept rows (every 3rd sample in each
    window) lie on the sample grid but not on the grid of their smallest gap: the FFT form on the
    sample grid must give the direct Lomb-Scargle sums (the line at 13.7 Hz found at the same
    frequency, the scores within the interpolation of the finer grid)."""
    import numpy as np

    from axisopt.identify.effects import disturbance as dist

    rng = np.random.default_rng(0)
    fs = 1000.0
    idx = np.concatenate([np.arange(a, a + 800, 3) for a in (0, 5001, 12007, 20011)])
    t = idx / fs
    r = np.sin(2 * np.pi * 13.7 * t + 0.3) + rng.standard_normal(len(t))
    f1, s1 = dist.line_scan(t, r, 1.0, 60.0)  # small: the direct sums
    assert dist._grid_index(t, float(np.min(np.diff(t)))) is None
    k = dist._grid_index(t, 1.0 / fs, 0.02)
    assert k is not None and np.array_equal(k, idx)
    rc = r - r.mean()
    fft = dist._fft_scan(k, 1.0 / fs, rc, f1, 4.0) / float(rc @ rc)
    assert float(np.max(np.abs(s1 - fft))) < 0.01
    work, dist.FFT_SCAN_WORK = dist.FFT_SCAN_WORK, 0  # line_scan takes the FFT form
    try:
        f2, s2 = dist.line_scan(t, r, 1.0, 60.0, step=1.0 / fs)
    finally:
        dist.FFT_SCAN_WORK = work
    assert np.array_equal(f1, f2) and np.array_equal(s2, fft)
    assert float(np.max(np.abs(s1 - s2))) < 0.01
    assert f2[int(np.argmax(s2))] == pytest.approx(13.7, rel=2e-3)
    assert f1[int(np.argmax(s1))] == f2[int(np.argmax(s2))]
