"""Null and decoy records name none of the time-record classes of
:mod:`axisopt.identify.effects.disturbance` and show none of their signatures; bad input (a run too
short for the line asked, NaN time stamps); their calibration saved for evaluate; equally good
explanations; an effect named outside its plausible regime.  The hidden physics is in
test_timedisturbance.py (written apart from the identification)."""

import pytest
from identify_helpers import DESIGN, LEAD, records, truth_for, unexplained
from test_disturbance import NEW, SIGNATURES, periodic_force

from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.synth import simulate_axis
from axisopt.report.timediag import time_diagnosis_dict, time_diagnosis_text

# --------------------------------------------------------------------------------------- null and
# decoys
DECOYS = [
    (11, {}),
    (12, {}),
    (13, {}),
    (21, {"stribeck": 150.0, "stribeck_v": 0.005}),
    (22, {"quadratic_drag": 3000.0}),
    pytest.param(23, {"ripple": 40.0, "ripple_period": LEAD}, marks=pytest.mark.slow),
    (24, {"position_coeffs": (60.0, -40.0)}),
    (25, {"viscous_asym": 600.0}),
]


@pytest.mark.parametrize("seed, kw", DECOYS)
def test_null_and_decoy_records_name_none_of_the_new_classes(tmp_path, plant, seed, kw):
    diag = diagnose_time_files(records(tmp_path, truth_for(seed, **kw), seed), plant=plant)
    assert not set(diag.verdict) & set(NEW), diag.verdict
    kinds = [s["kind"] for s in unexplained(diag)["signatures"]]
    assert not set(kinds) & set(SIGNATURES), kinds
    if not kw:
        assert diag.verdict == [] and not unexplained(diag)["remaining"]


# ------------------------------------------------------------------------------------------------
# bad input
def test_a_run_too_short_for_the_line_asked_is_an_input_error(tmp_path, capsys):
    """time_periodic asked by name on 0.8 s of record: no line can be resolved (20 periods at the
    highest frequency fitted need more motion): one line naming the file, exit 2."""
    from axisopt.cli import main

    truth = truth_for(35, extra_force=periodic_force(12.0, 60.0, 0.0))
    path = tmp_path / "short.csv"
    simulate_axis(truth, duration=0.8, seed=35).write_csv(path)
    assert main(["diagnose", str(path), "--design", str(DESIGN), "--effects", "time_periodic"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "short.csv" in err[0] and "resolves no line" in err[0]


def test_nan_time_stamps_are_an_input_error(tmp_path, capsys):
    from axisopt.cli import main

    path = tmp_path / "nan.csv"
    simulate_axis(truth_for(36), duration=1.0, seed=36).write_csv(path)
    lines = path.read_text().splitlines()
    lines[5] = "nan" + lines[5][lines[5].index(",") :]
    path.write_text("\n".join(lines) + "\n")
    assert main(["diagnose", str(path), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "line 6, column 1 (time)" in err[0] and "not a finite number" in err[0]


# ------------------------------------------------------------------------------------------ --save-
# calibration
@pytest.mark.parametrize(
    "name, effect, key, true, unit",
    [
        ("pump", "time_periodic", "freq", 14.5, "Hz"),
        ("spot", "local_friction", "x0", 400.0, "mm"),
    ],
)
def test_save_calibration_of_a_time_record_is_read_by_evaluate(
    tmp_path, capsys, name, effect, key, true, unit
):
    """The shipped example (problems/data/generate_timerecord.py) saved as a calibration: the effect
    with its parameters in units; evaluate applies the Coulomb friction and lists the effect as not
    representable."""
    import yaml

    from axisopt.cli import main

    data = DESIGN.parent
    cal = tmp_path / "cal.yaml"
    assert (
        main(
            [
                "diagnose",
                str(data / f"table_x_{name}_est.csv"),
                str(data / f"table_x_{name}_val.csv"),
                "--design",
                str(DESIGN),
                "--save-calibration",
                str(cal),
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert f"not applied: {effect}: not representable in evaluate" in out
    saved = yaml.safe_load(cal.read_text())
    assert saved["verdict"] == effect and saved["effects"][0]["name"] == effect
    value, u = saved["effects"][0]["parameters"][key]["value"].split()
    assert u == unit and float(value) == pytest.approx(true, rel=0.02)
    assert "coulomb_friction" in saved["baseline"]
    assert main(["evaluate", str(DESIGN), "--calibration", str(cal)]) == 0
    assert "(calibrated)" in capsys.readouterr().out


# ------------------------------------------------------------------ equally good explanations, and
# the regime
@pytest.fixture
def twin_of_stribeck():
    """A second effect with Stribeck's columns under another name and its own evidence: the data
    cannot tell the two apart, whatever the record."""
    from dataclasses import replace as dc_replace

    from axisopt.identify.effects import Effect, register_effect, time_effects, unregister_effect

    class Twin(Effect):
        name = "stribeck_twin"
        time = dc_replace(time_effects()["stribeck"], evidence="the twin's own test")

    register_effect(Twin)
    yield
    unregister_effect("stribeck_twin")


def test_two_effects_that_explain_the_data_equally_are_said_to_be_and_separated(
    tmp_path, plant, twin_of_stribeck
):
    truth = truth_for(21, stribeck=150.0, stribeck_v=0.005)
    diag = diagnose_time_files(records(tmp_path, truth, 21), plant=plant)
    assert len(diag.verdict) == 1 and diag.verdict[0] in ("stribeck", "stribeck_twin")
    ((k, a, b, apart),) = diag.equivalent
    assert {a.effect.name, b.effect.name} == {"stribeck", "stribeck_twin"} and apart < 1.0
    text = time_diagnosis_text(diag)
    assert "explain the data equally well" in text and "the twin's own test" in text
    assert "constant speeds below 10 mm/s" in text  # stribeck's evidence
    eq = time_diagnosis_dict(diag)["equivalent"][0]
    assert eq["percent_apart"] == pytest.approx(apart) and set(eq["to_separate"]) == {
        "stribeck",
        "stribeck_twin",
    }


def test_an_effect_named_outside_its_plausible_regime_is_flagged(tmp_path, plant, monkeypatch):
    """A drag c v|v| hidden in a record that never exceeds 7 mm/s: when quadratic_drag is named, its
    declaration says the reading is implausible at that speed (churning and seal drag show from tens
    of mm/s)."""
    from axisopt.identify.records import synth as timesynth

    monkeypatch.setattr(
        timesynth.trapezoid_reference,
        "__defaults__",
        ((0.001, 0.002, 0.004, 0.007), timesynth.ACCELS),
    )
    truth = truth_for(26, quadratic_drag=4.0e6)
    diag = diagnose_time_files(records(tmp_path, truth, 26), plant=plant)
    assert diag.top_speed < 0.0075 and diag.verdict == ["quadratic_drag"]
    assert any(
        f.startswith("quadratic_drag: a drag growing with v|v| at a top speed of 7.")
        for f in diag.flags["final"]
    )
    assert "is the less plausible" in time_diagnosis_text(diag)
