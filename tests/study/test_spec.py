"""Study files: expansion into cases, and one-line errors naming the key for malformed studies."""

from __future__ import annotations

import pytest
from study_helpers import STUDIES, write_study

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.study import build_problem, load_study


def test_range_random_zip_and_inline_base(tmp_path):
    p = write_study(
        tmp_path,
        """\
        combine: zip
        base:
          axis: {stroke: 400 mm, moving_mass: 120 kg, mounting: fixed-supported, max_speed: 30 m/min,
                 axial_load: 2000 N}
          objective: stiffness
          catalog: {vendors: [HIWIN], nut_types: [double]}
        sweep:
          limits.max_cost: {from: 1000 EUR, to: 4000 EUR, steps: 4}
          axis.moving_mass: {random: {low: 50 kg, high: 150 kg, n: 4, seed: 3}}
          catalog.mountings: {random: {choice: [[fixed-supported], [fixed-fixed]], n: 4, seed: 1}}
          axis.acceleration: 2 m/s^2
        """,  # noqa: E501
    )
    st = load_study(p)
    assert len(st.cases) == 4
    assert [c.inputs()["limits.max_cost"] for c in st.cases] == [
        "1000 EUR",
        "2000 EUR",
        "3000 EUR",
        "4000 EUR",
    ]
    masses = [float(c.inputs()["axis.moving_mass"].split()[0]) for c in st.cases]
    assert all(50 <= m <= 150 for m in masses)
    # seeded
    assert masses == [float(c.inputs()["axis.moving_mass"].split()[0]) for c in load_study(p).cases]
    prob = build_problem(st.context(), st.cases[2])
    assert prob.axis.acceleration == 2.0 and prob.limit_map["max_cost"] == pytest.approx(3000.0)


@pytest.mark.parametrize(
    "sweep, needle",
    [
        ("axis.strok: [300 mm]", "axis.strok"),  # typo in a problem key
        ("axis.stroke: [300 mm, 300]", "axis.stroke"),  # a value without its unit
        ("limits.max_cost: {from: 1 EUR, to: 2 kEUR, steps: 3}", "to"),  # mixed units
        ("limits.max_cost: {from: 1 EUR, to: 2 EUR}", "steps"),  # missing key
        ("catalog.mountings: [[fixed-sideways]]", "catalog.mountings"),
        ("axis.stroke: {random: {low: 1 mm, high: 2 mm, n: 3}}", "seed"),
        ("axis.stroke: {step: 3}", "axis.stroke"),
        # base has 'objective: frequency' (a value)
        ("objective.mode: [stiffness]", "objective.mode"),
        # hardening: generators that crashed or exhausted memory
        ("axis.stroke: {random: {low: 1 mm, high: 2 mm, n: 3, seed: -1}}", "seed"),
        ("axis.stroke: {random: {low: -1e400 mm, high: 2 mm, n: 3, seed: 1}}", "low"),
        ("axis.stroke: {random: {low: 1 mm, high: 2 mm, n: 1000000000000000000, seed: 1}}", "n"),
        ("axis.stroke: {from: 1 mm, to: 2 mm, steps: 100000000}", "steps"),
        (
            "axis.stroke: {from: 1 mm, to: 2 mm, steps: 100000}\n          axis.moving_mass: "
            "{from: 1 kg, to: 2 kg, steps: 100000}",
            "sweep",
        ),
    ],
)
def test_malformed_study_is_one_line_naming_the_key(tmp_path, capsys, sweep, needle):
    p = write_study(
        tmp_path,
        f"""\
        base: @PROBLEMS@/vmc_x_problem.yaml
        sweep:
          {sweep}
        """,
    )
    with pytest.raises(InputError, match=needle):
        load_study(p)
    assert main(["study", str(p), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and needle in err and str(p) in err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    "body, needle",
    [
        ("base: missing.yaml\nsweep: {axis.stroke: [1 m]}\n", "base"),
        (
            "base: @PROBLEMS@/vmc_x_problem.yaml\nsweep: {axis.stroke: [1 m]}\nworkers: 3\n",
            "workers",
        ),
        ("base: @PROBLEMS@/vmc_x_problem.yaml\n", "sweep"),
        (
            "base: @PROBLEMS@/vmc_x_problem.yaml\ncombine: zip\nsweep: {axis.stroke: [1 m, 2 m], "
            "axis.moving_mass: [1 kg]}\n",
            "zip",
        ),
    ],
)
def test_malformed_study_file(tmp_path, body, needle):
    with pytest.raises(InputError, match=needle):
        load_study(write_study(tmp_path, body))


@pytest.mark.parametrize("name", sorted(p.name for p in STUDIES.glob("*.yaml")))
def test_shipped_studies_load(name):
    st = load_study(STUDIES / name)
    assert st.cases and len({c.case_id for c in st.cases}) == len(st.cases)
