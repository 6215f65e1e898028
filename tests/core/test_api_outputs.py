"""The Python functions never write over the files they read (issue 57 item 1, the command line's
check in cli/outputs.py, here for ``axisopt.study`` and the calibration writers a notebook
calls)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from axisopt.errors import InputError

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
STUDY = """name: guard-study
base:
  name: guard-base
  axis: {stroke: 400 mm, moving_mass: 120 kg, mounting: fixed-supported, max_speed: 30 m/min,
         axial_load: 2000 N, acceleration: 3 m/s^2, mean_speed: 8 m/min}
  objective: stiffness
  catalog: {vendors: [HIWIN], nut_types: [double], mountings: [fixed-supported]}
sweep:
  axis.moving_mass: [80 kg, 200 kg]
"""


def _unchanged(path: Path, text: str) -> None:
    assert path.read_text() == text


def test_study_refuses_an_out_that_would_replace_its_study_file(tmp_path):
    import axisopt

    spec = tmp_path / "report.md"  # a study file named as the report the study writes
    spec.write_text(STUDY)
    with pytest.raises(InputError) as exc:
        axisopt.study(spec, tmp_path)
    assert str(exc.value).splitlines() == [
        f"{tmp_path}/report.md: out: would overwrite the input {spec} with the study's report.md; "
        "give another out"
    ]
    _unchanged(spec, STUDY)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.md"]  # nothing written


def test_study_refuses_an_out_whose_case_folder_holds_its_base_problem(tmp_path):
    import axisopt

    (tmp_path / "out" / "cases").mkdir(parents=True)
    base = tmp_path / "out" / "cases" / "base.yaml"
    base_text = STUDY.split("base:\n", 1)[1].split("sweep:")[0]
    base.write_text("\n".join(line[2:] for line in base_text.splitlines()) + "\n")
    spec = tmp_path / "s.yaml"
    spec.write_text(
        "name: guard-study\nbase: out/cases/base.yaml\nsweep:\n  axis.moving_mass: [80 kg]\n"
    )
    with pytest.raises(InputError, match="the study's cases/ folder holds the input"):
        # overwrite would delete the case folder's files
        axisopt.study(spec, tmp_path / "out", overwrite=True)
    assert base.exists()


@pytest.mark.parametrize("kind", ["table", "time"])
def test_calibration_writers_refuse_their_data_and_design_files(tmp_path, kind):
    from axisopt.design import load_design
    from axisopt.identify.calibration import save_calibration
    from axisopt.identify.records.calibration import save_time_calibration

    data = tmp_path / "run1.csv"
    shutil.copy(PROBLEMS / "data" / "table_x_stiffness.csv", data)
    before = data.read_text()
    design = load_design(PROBLEMS / "data" / "table_x.yaml")
    save = save_calibration if kind == "table" else save_time_calibration
    # the check comes before the diagnosis is read: no diagnosis is needed to be refused
    with pytest.raises(
        InputError, match=r"would overwrite the input .*run1.csv with the calibration"
    ):
        save(None, data, design, [str(data)])
    _unchanged(data, before)
    with pytest.raises(
        InputError, match=r"would overwrite the input .*table_x.yaml with the calibration"
    ):
        save(None, design.source, design, [str(data)])
    with pytest.raises(InputError, match="does not exist"):
        save(None, tmp_path / "nodir" / "cal.yaml", design, [str(data)])
