"""Carriage inputs (issue 25): bad geometry and a guide row without its moment ratings are one-line
errors naming the file and the key (exit 2); the geometry defaults; the carriage's outputs of an
evaluation."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from axisopt import model
from axisopt.cli import main
from axisopt.design import load_design

ROOT = Path(__file__).resolve().parents[2]
_CARRIAGE_KEYS = (
    "cross_load",
    "normal_load",
    "tool_height",
    "tool_offset",
    "cg_height",
    "cg_offset",
    "table_width",
    "block_spacing",
    "rail_spacing",
)
# the shipped design without its carriage keys (each test sets its own)
DESIGN = (
    "\n".join(
        ln
        for ln in (ROOT / "problems" / "vmc_x_design.yaml").read_text().splitlines()
        if not ln.strip().startswith(tuple(k + ":" for k in _CARRIAGE_KEYS))
    )
    + "\n"
)


def _run(tmp_path, capsys, text, name="d.yaml"):
    f = tmp_path / name
    f.write_text(text)
    rc = main(["evaluate", str(f)])
    err = capsys.readouterr().err.strip()
    return rc, err, f


@pytest.mark.parametrize(
    ("edit", "key", "needle"),
    [
        ("  tool_height: -50 mm\n", "axis.tool_height", "negative"),
        ("  cg_height: -1 mm\n", "axis.cg_height", "negative"),
        ("  block_spacing: 700 mm\n", "axis.block_spacing", "larger than the table"),
        (
            "  table_width: 400 mm\n  rail_spacing: 450 mm\n",
            "axis.rail_spacing",
            "larger than the table",
        ),
        ("  guide_static_safety: 0.5\n", "axis.guide_static_safety", ""),
        ("  orientation: ceiling\n", "axis.orientation", ""),
    ],
)
def test_bad_geometry_is_a_one_line_error(tmp_path, capsys, edit, key, needle):
    rc, err, f = _run(tmp_path, capsys, DESIGN.replace("  rails: 2\n", "  rails: 2\n" + edit))
    assert rc == 2
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    assert str(f) in err and key in err and needle in err


def test_blocks_must_be_shared_by_the_rails(tmp_path, capsys):
    rc, err, f = _run(tmp_path, capsys, DESIGN.replace("guide_blocks: 4", "guide_blocks: 3"))
    assert rc == 2 and len(err.splitlines()) == 1 and "axis.guide_blocks" in err and str(f) in err


def test_guide_row_missing_a_moment_rating_is_a_load_error(tmp_path, capsys):
    """A user catalog whose guide table lacks a moment column, or leaves a cell empty: one line
    naming the file."""
    src = ROOT / "catalogs" / "guides.csv"
    with src.open(encoding="utf-8", newline="") as fh:
        rows = list(csv.reader(fh))
    cat = tmp_path / "cat"
    cat.mkdir()
    j = rows[0].index("moment_pitch [N.m]")
    bad = [rows[0], rows[1][:]]
    bad[1][0] = "MY-HG15"
    bad[1][j] = ""
    with (cat / "guides.csv").open("w", newline="", encoding="utf-8") as fh:
        csv.writer(fh).writerows(bad)
    for t in ("screws", "nuts", "bearings"):
        (cat / f"{t}.csv").write_text(
            (ROOT / "catalogs" / f"{t}.csv").read_text(encoding="utf-8").splitlines()[0] + "\n"
        )
    text = "catalogs: [cat]\n" + DESIGN.replace("guide: HIWIN-HG35-ZB", "guide: MY-HG15")
    rc, err, _ = _run(tmp_path, capsys, text)
    assert rc == 2 and len(err.splitlines()) == 1
    assert "guides.csv" in err and "moment_pitch" in err
    # the column left out of the header altogether
    with (cat / "guides.csv").open("w", newline="", encoding="utf-8") as fh:
        csv.writer(fh).writerows([r[:j] + r[j + 1 :] for r in bad])
    rc, err, _ = _run(tmp_path, capsys, text)
    assert rc == 2 and len(err.splitlines()) == 1 and "guides.csv" in err and "moment_pitch" in err


def test_defaults_and_outputs(tmp_path):
    d = load_design(_write(tmp_path, DESIGN))
    a = d.axis
    assert a.block_spacing_eff == pytest.approx(0.6 * a.table_length)
    # table_width defaults to table_length
    assert a.rail_spacing_eff == pytest.approx(0.6 * a.table_length)
    assert a.tool_height_eff == pytest.approx(0.4 * a.table_length)
    v = model.evaluate(d).values
    # the stiffness at the tool is below the axial chain's everywhere, and the rocking term closes
    # the gap
    k, kt = np.asarray(v["k_total"]), np.asarray(v["k_tool"])
    assert (kt < k).all()
    np.testing.assert_allclose(1 / kt, 1 / k + v["c_rocking"], rtol=1e-12)
    assert v["guide_static_safety"] == pytest.approx(
        float(d.guide["static_load_rating"]) / v["guide_max_load"]
    )
    # the first frequency is the lowest of the axial, table, pitch and yaw modes
    assert float(np.min(v["f1"])) <= min(v["f_pitch"], v["f_yaw"], v["f_table"]) + 1e-9
    # a cut high above the table softens the tool point and loads the blocks more
    hi = load_design(
        _write(
            tmp_path,
            DESIGN.replace(
                "  rails: 2\n",
                "  rails: 2\n  tool_height: 500 mm\n  cross_load: 2000 N\n  normal_load: 3000 N\n",
            ),
        )
    )
    w = model.evaluate(hi).values
    assert float(np.min(w["k_tool"])) < float(np.min(kt))
    assert w["guide_max_load"] > v["guide_max_load"] and w["guide_life"] < v["guide_life"]


def _write(tmp_path, text):
    f = tmp_path / "x.yaml"
    f.write_text(text)
    return f


# issue 38: the support-bearing static safety, the nut lift-off safety, the load factor and the
# mounting stiffness
@pytest.mark.parametrize(
    ("edit", "key"),
    [
        ("  bearing_static_safety: 0.5\n", "axis.bearing_static_safety"),
        ("  bearing_static_safety: .nan\n", "axis.bearing_static_safety"),
        ("  bearing_static_safety: 1e300\n", "axis.bearing_static_safety"),
        ("  bearing_static_safety: -4\n", "axis.bearing_static_safety"),
        ("  nut_lift_off_safety: 0.9\n", "axis.nut_lift_off_safety"),
        ("  nut_lift_off_safety: .inf\n", "axis.nut_lift_off_safety"),
        ("  nut_lift_off_safety: two\n", "axis.nut_lift_off_safety"),
        ("  bearing_static_safty: 2\n", "bearing_static_safty"),
        ("  bearing_housing_stiffness: -2000 N/um\n", "axis.bearing_housing_stiffness"),
        ("  nut_bracket_stiffness: 1500 N\n", "axis.nut_bracket_stiffness"),
        ("  nut_bracket_stiffness: 1e300 N/um\n", "axis.nut_bracket_stiffness"),
    ],
)
def test_support_keys_reject_bad_values(tmp_path, capsys, edit, key):
    rc, err, f = _run(tmp_path, capsys, DESIGN.replace("  rails: 2\n", "  rails: 2\n" + edit))
    assert rc == 2
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    assert str(f) in err and key in err


def test_bearing_static_safety_overrides_the_vendor_figure(tmp_path, capsys):
    """The check's need scales with the safety the axis asks; without one, the rating's vendor's
    (NSK 1/0.7)."""
    base = load_design(_file(tmp_path, DESIGN, "a.yaml"))
    asked = load_design(
        _file(
            tmp_path,
            DESIGN.replace("  rails: 2\n", "  rails: 2\n  bearing_static_safety: 4\n"),
            "b.yaml",
        )
    )
    s0 = (
        float(base.bearing["static_safety"])
        if np.isfinite(float(base.bearing["static_safety"]))
        else 4.0
    )
    m0 = float(model.evaluate(base)["margin_bearing_static"])
    m1 = float(model.evaluate(asked)["margin_bearing_static"])
    assert m1 == pytest.approx(m0 * s0 / 4.0, rel=1e-9)


def _file(tmp_path, text, name):
    f = tmp_path / name
    f.write_text(text)
    return f
