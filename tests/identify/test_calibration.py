"""Calibration files (:mod:`axisopt.identify.calibration`): the round trip from diagnose to
evaluate, what evaluate cannot represent, validation of a calibration file."""

import json

import numpy as np
import pytest
import yaml
from identify_helpers import DESIGN, dataset_csv, write
from test_diagnose_recovery import BASELINE, friction_doe

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.errors import InputError
from axisopt.identify import diagnose, plant_from_design
from axisopt.identify.calibration import apply_calibration
from axisopt.identify.tables.synth import simulate

GOOD_CAL = """axisopt_calibration: 1
design: {design}
baseline:
  screw_modulus: {{value: 200 GPa, kind: pressure}}
effects:
  - name: support_condition
    parameters:
      far_end_stiffness: {{value: 900 N/um, kind: stiffness}}
"""


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
    assert plant_from_design(new).coulomb == pytest.approx(
        diag.final.value("coulomb_friction"), rel=1e-6
    )


def test_bad_calibration_file_is_an_input_error(tmp_path):
    p = write(
        tmp_path,
        "axisopt_calibration: 1\nbaseline: {screw_modulus: {value: 200 kg, kind: pressure}}\n",
        "c.yaml",
    )
    with pytest.raises(InputError, match="line 2"):
        apply_calibration(load_design(DESIGN), p)


@pytest.mark.parametrize(
    "old, new, words",
    [
        (None, None, None),  # the file as written applies
        ("design: {design}", "design: another axis", "calibration is for design 'another axis'"),
        ("screw_modulus:", "screw_modulos:", "did you mean 'screw_modulus'"),
        (
            "far_end_stiffness:",
            "far_end_stifness:",
            "needs parameter 'far_end_stiffness' (given: far_end_stifness)",
        ),
        ("kind: stiffness", "kind: stifness", "is not one of"),
        ("kind: pressure", "kind: force", "'screw_modulus' is a pressure, not a force"),
        (
            "    parameters:\n      far_end_stiffness: {{value: 900 N/um, kind: stiffness}}\n",
            "    parameters: {{}}\n",
            "lists no parameters",
        ),
        ("name: support_condition", "name: support_conditon", "did you mean 'support_condition'"),
    ],
)
def test_calibration_file_is_validated(tmp_path, capsys, old, new, words):
    """A calibration applies only to its own design, with known keys and kinds (each bad case used
    to be applied silently or end in a KeyError traceback)."""
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


@pytest.mark.parametrize(
    "old, new",
    [
        ("value: 200 GPa", "value: 0 GPa"),
        ("value: 200 GPa", "value: -202.7 GPa"),
        ("value: 900 N/um", "value: -900 N/um"),
    ],
)
def test_calibration_values_must_be_physical(tmp_path, capsys, old, new):
    """A zero or negative modulus was a ZeroDivisionError / math domain traceback; a negative
    stiffness was applied."""
    design = load_design(DESIGN)
    p = write(tmp_path, GOOD_CAL.replace(old, new).format(design=design.name), "c.yaml")
    rc = main(["evaluate", str(DESIGN), "--calibration", str(p)])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and "\n" not in err and "not physical" in err, err


def test_verdict_numbers_are_the_saved_calibration(plant, tmp_path, capsys):
    """Two effects accepted in two rounds: the second round refits the first effect's value, and
    what the verdict and JSON print is what --save-calibration writes."""
    ds = simulate(
        plant,
        "friction",
        friction_doe(),
        baseline=BASELINE["friction"],
        noise=0.01,
        seed=7,
        effects={
            "stribeck": {"stribeck_rise": 200.0, "stribeck_velocity": 2e-3},
            "load_dependent_friction": {"friction_coefficient": 0.005},
        },
    )
    data = dataset_csv(ds, tmp_path / "fric.csv")
    js, cal = tmp_path / "d.json", tmp_path / "cal.yaml"
    assert (
        main(
            [
                "diagnose",
                str(data),
                "--design",
                str(DESIGN),
                "--json",
                str(js),
                "--save-calibration",
                str(cal),
            ]
        )
        == 0
    )
    d = json.loads(js.read_text())
    saved = yaml.safe_load(cal.read_text())
    assert len(d["accepted"]) == 2
    saved_params = {n: v for e in saved["effects"] for n, v in e["parameters"].items()}
    for a in d["accepted"]:
        for p in a["parameters"]:
            text = saved_params[p["name"]]["value"]
            value = float(str(text).split()[0])
            assert value == pytest.approx(p["value"], rel=1e-5), p["name"]
    out = capsys.readouterr().out
    assert "values of the final joint fit" in out
