"""Data formats (strict errors naming file, line, column), the CLI, the calibration round trip and
the plugin API."""

import json
from pathlib import Path

import numpy as np
import pytest
import yaml

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.errors import InputError
from axisopt.identify import Effect, diagnose, library, plant_from_design, read_dataset, register_effect
from axisopt.identify.calibration import apply_calibration
from axisopt.identify.effects import unregister_effect
from axisopt.identify.synth import simulate
from axisopt.model import evaluate

DATA = Path(__file__).resolve().parents[2] / "problems" / "data"
DESIGN = DATA / "table_x.yaml"
STIFF = DATA / "table_x_stiffness.csv"


def write(tmp_path, text, name="d.csv"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_units_convert_and_kind_is_detected(tmp_path):
    p = write(
        tmp_path,
        "position [m],force [kN],displacement [mm],temperature [degC]\n0.1,2,0.01,20\n0.2,-2,-0.012,21\n",
    )
    ds = read_dataset(p)
    assert ds.kind == "stiffness"
    assert ds.columns["position"][1] == pytest.approx(0.2)
    assert ds.columns["force"][0] == pytest.approx(2000.0)
    assert ds.columns["displacement"][1] == pytest.approx(-12e-6)
    assert ds.columns["temperature"][1] - ds.columns["temperature"][0] == pytest.approx(1.0)
    fr = read_dataset(write(tmp_path, "velocity [m/min],drag_torque [N.m]\n1.2,0.5\n-1.2,-0.5\n", "f.csv"))
    assert fr.kind == "friction" and fr.columns["velocity"][0] == pytest.approx(0.02)
    frf = read_dataset(
        write(
            tmp_path, "frequency [Hz],position [mm],magnitude [um/N],phase [deg]\n100,0,0.01,-90\n", "g.csv"
        )
    )
    assert frf.kind == "frf" and frf.columns["imag"][0] == pytest.approx(-1e-8)


@pytest.mark.parametrize(
    "text,where,what",
    [
        ("position [mm],force [N]\n0,1\n", "line 1", "missing column(s) displacement"),
        ("position [mm],force [N],displacement [blorp]\n0,1,2\n", "line 1, column 3", "unknown unit"),
        (
            "position [mm],force [N],displacement [um]\n0,1,2\n0,abc,2\n",
            "line 3, column 2 (force)",
            "not a number",
        ),
        (
            "position [mm],force [N],displacement [um]\n0,1,nan\n",
            "line 2, column 3 (displacement)",
            "not a finite",
        ),
        ("position [mm],force [N],displacement [um]\n0,,2\n", "line 2, column 2 (force)", "empty cell"),
        (
            "position [mm],force [N],displacment [um]\n0,1,2\n",
            "line 1, column 3",
            "did you mean 'displacement'",
        ),
        ("position [mm],force [N],displacement [um],direction\n0,1,2,0\n", "line 2, column 4", "+1 or -1"),
        ("position,force [N],displacement [um]\n0,1,2\n", "line 1, column 1", "needs a unit"),
        ("velocity [mm/s]\n1\n", "line 1", "friction_force or drag_torque"),
    ],
)
def test_bad_files_give_one_line_errors(tmp_path, text, where, what, capsys):
    p = write(tmp_path, text)
    with pytest.raises(InputError) as exc:
        read_dataset(p)
    msg = str(exc.value)
    assert str(p) in msg and where in msg and what in msg
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and where in err


def test_excluded_rows_are_reported(tmp_path):
    p = write(tmp_path, "velocity [mm/s],friction_force [N],exclude\n1,10,0\n0,3,0\n-1,-10,1\n2,11,0\n")
    ds = read_dataset(p)
    assert ds.n == 2
    assert ds.excluded == [(3, "velocity 0: friction direction undefined"), (4, "marked exclude = 1")]


def test_cli_shipped_example_end_to_end(tmp_path, capsys):
    cal = tmp_path / "cal.yaml"
    rep = tmp_path / "rep"
    js = tmp_path / "d.json"
    assert (
        main(
            [
                "diagnose",
                str(STIFF),
                "--design",
                str(DESIGN),
                "--report",
                str(rep),
                "--json",
                str(js),
                "--save-calibration",
                str(cal),
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert "verdict: support_condition" in out and "excluded line 42" in out
    d = json.loads(js.read_text())
    assert d["verdict"] == "support_condition"
    a = d["accepted"][0]
    assert a["parameters"][0]["value"] == pytest.approx(90.0, rel=0.1)  # N/um, as generated
    assert a["gain_percent"] > 30 and a["runner_up"]["effect"] == "compliance_offset"
    assert (rep / "report.md").read_text().count("![residuals") == 1 and (rep / "residuals_1.png").exists()
    saved = yaml.safe_load(cal.read_text())
    assert saved["effects"][0]["name"] == "support_condition"
    design = load_design(DESIGN)
    calibrated = apply_calibration(design, cal)
    assert calibrated.axis.mounting == "fixed-fixed"
    assert evaluate(calibrated).minimum("k_total")[0] > evaluate(design).minimum("k_total")[0]
    assert main(["evaluate", str(DESIGN), "--calibration", str(cal)]) == 0


def test_calibration_lists_what_evaluate_cannot_represent(tmp_path):
    design = load_design(DESIGN)
    plant = plant_from_design(design)
    ds = simulate(
        plant,
        "friction",
        dict(velocity=np.r_[np.geomspace(2e-4, 0.5, 40), -np.geomspace(2e-4, 0.5, 40)]),
        effects={"stribeck": {"stribeck_rise": 200.0, "stribeck_velocity": 2e-3}},
        baseline={"coulomb_friction": 520.0},
        noise=0.01,
        seed=3,
    )
    from axisopt.identify.calibration import save_calibration

    diag = diagnose([ds], plant)
    assert diag.verdict == "stribeck"
    d = save_calibration(diag, tmp_path / "c.yaml", design)
    assert any(s.startswith("stribeck: not representable") for s in d["not_applied"])
    assert any("guide friction force" in s for s in d["applied"])
    new = apply_calibration(design, tmp_path / "c.yaml")
    assert plant_from_design(new).coulomb == pytest.approx(diag.final.value("coulomb_friction"), rel=1e-6)


def test_bad_calibration_file_is_an_input_error(tmp_path):
    p = write(
        tmp_path,
        "axisopt_calibration: 1\nbaseline: {screw_modulus: {value: 200 kg, kind: pressure}}\n",
        "c.yaml",
    )
    with pytest.raises(InputError, match="line 2"):
        apply_calibration(load_design(DESIGN), p)


def test_user_effect_plugin_competes(tmp_path):
    class SensorGain(Effect):
        name = "sensor_gain"
        title = "displacement sensor reads a fixed fraction high"
        kinds = ("stiffness",)

        def params(self, ctx):
            from axisopt.identify import Param

            return [
                Param(
                    "gain_error",
                    "sensor gain error",
                    "percent",
                    "dimensionless",
                    0.0,
                    -0.5,
                    0.5,
                    typical=0.05,
                )
            ]

        def apply(self, kind, q, P, Z, plant):
            # a gain on the reading acts like extra compliance proportional to the whole chain
            q.c_extra = q.c_extra + P["gain_error"] * (q.c_bearing + 1.0 / plant.k_nut)

    register_effect(SensorGain)
    try:
        assert "sensor_gain" in library()
        plant = plant_from_design(load_design(DESIGN))
        pos = np.repeat(np.linspace(0, 0.8, 8), 8)
        f = np.tile(np.r_[np.linspace(500, 4000, 4), -np.linspace(500, 4000, 4)], 8)
        ds = simulate(
            plant,
            "stiffness",
            dict(position=pos, force=f),
            effects={"sensor_gain": {"gain_error": 0.2}},
            noise=0.01,
            seed=4,
        )
        diag = diagnose([ds], plant, candidates=["sensor_gain", "support_condition", "backlash"])
        assert diag.verdict == "sensor_gain"
        assert diag.final.value("gain_error") == pytest.approx(0.2, rel=0.1)
    finally:
        unregister_effect("sensor_gain")


def test_two_test_types_share_parameters():
    plant = plant_from_design(load_design(DESIGN))
    pos = np.repeat(np.linspace(0, 0.8, 8), 8)
    f = np.tile(np.r_[np.linspace(500, 4000, 4), -np.linspace(500, 4000, 4)], 8)
    eff = {"added_mass": {"added_mass": 80.0}}
    st = simulate(
        plant, "stiffness", dict(position=pos, force=f), baseline={"screw_modulus": 190e9}, noise=0.01, seed=8
    )
    fq = simulate(
        plant,
        "frequency",
        dict(position=np.linspace(0, 0.8, 30)),
        effects=eff,
        baseline={"screw_modulus": 190e9},
        noise=0.01,
        seed=9,
    )
    diag = diagnose([st, fq], plant)
    assert diag.verdict == "added_mass"
    assert diag.final.value("added_mass") == pytest.approx(80.0, rel=0.1)
    assert diag.final.value("screw_modulus") == pytest.approx(190e9, rel=0.03)


GOOD_CAL = """axisopt_calibration: 1
design: {design}
baseline:
  screw_modulus: {{value: 200 GPa, kind: pressure}}
effects:
  - name: support_condition
    parameters:
      far_end_stiffness: {{value: 900 N/um, kind: stiffness}}
"""


@pytest.mark.parametrize("old, new, words", [
    (None, None, None),  # the file as written applies
    ("design: {design}", "design: another axis", "calibration is for design 'another axis'"),
    ("screw_modulus:", "screw_modulos:", "did you mean 'screw_modulus'"),
    ("far_end_stiffness:", "far_end_stifness:", "needs parameter 'far_end_stiffness' (given: far_end_stifness)"),
    ("kind: stiffness", "kind: stifness", "is not one of"),
    ("kind: pressure", "kind: force", "'screw_modulus' is a pressure, not a force"),
    ("    parameters:\n      far_end_stiffness: {{value: 900 N/um, kind: stiffness}}\n", "    parameters: {{}}\n",
     "lists no parameters"),
    ("name: support_condition", "name: support_conditon", "did you mean 'support_condition'"),
])
def test_calibration_file_is_validated(tmp_path, capsys, old, new, words):
    """A calibration applies only to its own design, with known keys and kinds (each bad case used to be
    applied silently or end in a KeyError traceback)."""
    design = load_design(DESIGN)
    text = GOOD_CAL if old is None else GOOD_CAL.replace(old, new)
    p = write(tmp_path, text.format(design=design.name), "c.yaml")
    rc = main(["evaluate", str(DESIGN), "--calibration", str(p)])
    err = capsys.readouterr().err.strip()
    if old is None:
        assert rc == 0 and err == ""
        assert apply_calibration(design, p).axis.mounting == "fixed-fixed"
    else:
        assert rc == 2 and "\n" not in err and words in err, err


def test_calibration_baseline_names_match_the_fit():
    """The names and kinds a calibration may carry are the ones diagnose fits (measure.baseline_params)."""
    from axisopt.identify.calibration import BASELINE_KINDS
    from axisopt.identify.measure import baseline_params

    params = baseline_params({"stiffness", "friction", "frf"}, plant_from_design(load_design(DESIGN)))
    assert {p.name: p.kind for p in params} == BASELINE_KINDS


@pytest.mark.parametrize("old, new", [
    ("value: 200 GPa", "value: 0 GPa"),
    ("value: 200 GPa", "value: -202.7 GPa"),
    ("value: 900 N/um", "value: -900 N/um"),
])
def test_calibration_values_must_be_physical(tmp_path, capsys, old, new):
    """A zero or negative modulus was a ZeroDivisionError / math domain traceback; a negative stiffness
    was applied."""
    design = load_design(DESIGN)
    p = write(tmp_path, GOOD_CAL.replace(old, new).format(design=design.name), "c.yaml")
    rc = main(["evaluate", str(DESIGN), "--calibration", str(p)])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and "\n" not in err and "not physical" in err, err


def test_residual_plot_draws_direction_as_categories(tmp_path, monkeypatch):
    # direction is +-1: a category per tick, not a continuous axis from -1 to 1
    import axisopt.report.diagnosis as rep

    figs = []
    monkeypatch.setattr(rep, "save_figure", lambda fig, path, dpi=90: figs.append(fig))
    root = Path(__file__).resolve().parents[2] / "problems" / "data"
    assert main(["diagnose", str(root / "table_x_stiffness.csv"), "--design", str(root / "table_x.yaml"),
                 "--report", str(tmp_path / "r")]) == 0
    axes = {ax.get_xlabel(): ax for fig in figs for ax in fig.axes}
    d = axes["direction"]
    assert [t.get_text() for t in d.get_xticklabels()] == ["-1", "+1"]
    assert axes["position [mm]"].get_xticklabels()[0].get_text() != "-1"
    assert rep.categories("position", [0.0, 100.0, 200.0, 300.0]) is None
