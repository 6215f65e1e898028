"""A driven rotating-nut unit refused in one line, exit 2: on a screw not fixed at both ends (design
file), with a NaN, missing or out-of-range unit value (catalog CSV)."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
DESIGN = """name: rotating nut
{catalogs}axis:
  stroke: 1500 mm
  moving_mass: 300 kg
  mounting: {mounting}
  start_offset: 100 mm
  end_margin: 100 mm
  max_speed: 15 m/min
  axial_load: 3000 N
parts:
  screw: THK-DIR-40x10
  nut: {nut}
  bearing: THK-BK30
  guide: HIWIN-HG25-ZA
"""


def _nut_csv(tmp_path, **cells) -> str:
    """A user catalog directory with one rotating-nut row (THK DIR4010-6's values, id MY-DIR) whose
    cells named by their header (``unit_inertia [kg.cm^2]``) are replaced."""
    with open(ROOT / "catalogs" / "nuts.csv", newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    header, row = rows[0], next(r for r in rows if r[0] == "THK-DIR4010-6")
    rec = dict(zip(header, row), id="MY-DIR")
    rec.update(cells)
    d = tmp_path / "cat"
    d.mkdir()
    with open(d / "nuts.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerow([rec[h] for h in header])
    return "cat"


@pytest.mark.parametrize("mounting", ["fixed-free", "fixed-supported"])
def test_rotating_nut_needs_a_screw_fixed_at_both_ends(tmp_path, capsys, mounting):
    text = DESIGN.format(catalogs="", mounting=mounting, nut="THK-DIR4010-6")
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert (
        "parts.nut" in err
        and "rotating-nut unit" in err
        and "fixed-fixed" in err
        and mounting in err
    )


def test_rotating_nut_on_fixed_fixed_evaluates(tmp_path, capsys):
    text = DESIGN.format(catalogs="", mounting="fixed-fixed", nut="THK-DIR4010-6")
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 0
    out = capsys.readouterr().out
    assert "rotating-nut unit bearing" in out and "unit bearing L10 life" in out


@pytest.mark.parametrize(
    ("cells", "words"),
    [
        ({"unit_inertia [kg.cm^2]": "nan"}, ("unit_inertia", "not a finite number")),
        ({"unit_inertia [kg.cm^2]": ""}, ("unit_inertia", "missing value")),
        (
            {"unit_bearing_dynamic_load [kN]": "inf"},
            ("unit_bearing_dynamic_load", "not a finite number"),
        ),
        ({"unit_bearing_rigidity [N/um]": "-5"}, ("unit_bearing_rigidity", "must be positive")),
        ({"unit_inertia [kg.cm^2]": "0"}, ("unit_inertia", "must be positive")),
        ({"unit_max_speed [rpm]": "1e300"}, ("unit_max_speed", "out of range")),
        ({"rotating": "2"}, ("rotating", "0 or 1")),
    ],
)
def test_bad_unit_values_in_a_catalog(tmp_path, capsys, cells, words):
    cat = _nut_csv(tmp_path, **cells)
    text = DESIGN.format(catalogs=f"catalogs: [{cat}]\n", mounting="fixed-fixed", nut="MY-DIR")
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert "nuts.csv" in err and "line 2" in err and all(w in err for w in words), err
