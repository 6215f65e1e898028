"""Twin-drive inputs (issue 40): ``axis.twin_drive`` read, written back and evaluated; bad input is
a one-line error naming the file and the key (exit 2); the twin model's outputs against the
single-drive model of one side."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from axisopt import model
from axisopt.cli import main
from axisopt.design import load_design
from axisopt.design.writer import design_to_yaml
from axisopt.physics import gantry as pg

ROOT = Path(__file__).resolve().parents[2]
TWIN = "  twin_drive:\n    span: 1000 mm\n    cross_stroke: 600 mm\n    cross_mass: 150 kg\n"
BASE = (ROOT / "problems" / "vmc_x_design.yaml").read_text()
DESIGN = BASE.replace("  rails: 2\n", "  rails: 2\n" + TWIN)


def _run(tmp_path, capsys, text, cmd="evaluate", name="d.yaml"):
    f = tmp_path / name
    f.write_text(text)
    rc = main([cmd, str(f)])
    err = capsys.readouterr().err.strip()
    return rc, err, f


@pytest.mark.parametrize(
    ("old", "new", "key", "needle"),
    [
        (
            "cross_stroke: 600 mm",
            "cross_stroke: 1200 mm",
            "axis.twin_drive.cross_stroke",
            "leave the bridge",
        ),
        ("span: 1000 mm", "span: -1000 mm", "axis.twin_drive.span", ""),
        ("span: 1000 mm", "span: 0 mm", "axis.twin_drive.span", ""),
        ("span: 1000 mm", "span: .nan mm", "axis.twin_drive.span", ""),
        ("span: 1000 mm", "span: 1e300 mm", "axis.twin_drive.span", ""),
        ("span: 1000 mm", "span: 1000", "axis.twin_drive.span", ""),
        ("cross_mass: 150 kg", "cross_mass: .inf kg", "axis.twin_drive.cross_mass", ""),
        ("cross_mass: 150 kg", "cross_mass: -5 kg", "axis.twin_drive.cross_mass", ""),
        ("cross_mass: 150 kg", "cross_mass: 150 mm", "axis.twin_drive.cross_mass", ""),
        ("cross_mass: 150 kg", "cross_mas: 150 kg", "cross_mas", "cross_mass"),
        (
            "cross_mass: 150 kg",
            "cross_mass: 150 kg\n    bridge_yaw_inertia: -3 kg.m^2",
            "bridge_yaw_inertia",
            "",
        ),
        ("    span: 1000 mm\n", "", "axis.twin_drive.span", ""),
        (
            "  mounting: fixed-supported\n",
            "  mounting: fixed-supported\n  orientation: vertical\n",
            "axis.twin_drive",
            "horizontal",
        ),
        (
            "  mounting: fixed-supported\n",
            "  mounting: fixed-supported\n  orientation: wall\n",
            "axis.twin_drive",
            "horizontal",
        ),
        (
            "  twin_drive:\n    span: 1000 mm\n    cross_stroke: 600 mm\n    cross_mass: 150 kg\n",
            "  twin_drive: 2\n",
            "axis.twin_drive",
            "",
        ),
    ],
)
def test_bad_twin_drive_is_a_one_line_error(tmp_path, capsys, old, new, key, needle):
    assert old in DESIGN
    rc, err, f = _run(tmp_path, capsys, DESIGN.replace(old, new))
    assert rc == 2
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    assert str(f) in err and key in err and needle in err


def test_bad_twin_drive_in_a_problem(tmp_path, capsys):
    text = (
        (ROOT / "problems" / "gantry_twin_problem.yaml")
        .read_text()
        .replace("cross_stroke: 1800 mm", "cross_stroke: 2500 mm")
    )
    rc, err, f = _run(tmp_path, capsys, text, cmd="solve", name="p.yaml")
    assert (
        rc == 2
        and len(err.splitlines()) == 1
        and "axis.twin_drive.cross_stroke" in err
        and str(f) in err
    )


def test_round_trip_and_estimate(tmp_path):
    f = tmp_path / "d.yaml"
    f.write_text(DESIGN)
    d = load_design(f)
    tw = d.axis.twin_drive
    assert (tw.span, tw.cross_stroke, tw.cross_mass) == pytest.approx((1.0, 0.6, 150.0))
    assert tw.bridge_yaw_inertia is None
    g = tmp_path / "back.yaml"
    g.write_text(design_to_yaml(d))
    assert load_design(g).axis.twin_drive == tw
    p = model.design_params(d)
    # no inertia or uprights given: the estimate of half the bridge (axis.moving_mass) in its
    # uprights at the drives, m/2 L^2/12 + m/2 (L/2)^2 = m L^2 / 6
    assert p["bridge_yaw_inertia"] == pytest.approx(450.0 * 1.0**2 / 6.0)
    assert "twin_drive" not in load_design(tmp_path / "d.yaml").assumed


def _pair(tmp_path):
    f = tmp_path / "d.yaml"
    f.write_text(DESIGN)
    twin = load_design(f)
    one = replace(twin, axis=replace(twin.axis, twin_drive=None))
    return twin, one, model.evaluate(twin).values, model.evaluate(one).values


def test_twin_outputs_against_one_side(tmp_path):
    """The governing side is the single-drive model of one side: with the cross carriage at the
    stroke end (r = 1/2 + s/2L = 0.8) each drive moves m/2 + m_c s/2L and carries r of the process
    force; the pair costs the second drive's parts more; the gantry's frequencies are the 2-DOF
    model's."""
    twin, one, tv, ov = _pair(tmp_path)
    r = 0.5 + 0.6 / 2.0
    p = model.design_params(twin)
    nut, blocks = float(p["nut_mass"]), float(p["guide_blocks"] * p["guide_block_mass"])
    whole = 450.0 + 150.0 + 2 * nut + blocks
    assert tv["gantry_moving_mass"] == pytest.approx(whole)
    assert tv["moving_mass"] == pytest.approx(whole / 2 + 150.0 * 0.6 / 2.0)
    assert p["axial_load"] == pytest.approx(r * 3000.0) and p["mean_axial_load"] == pytest.approx(
        r * 800.0
    )
    second = (
        p["screw_price_per_length"] * p["span"]
        + p["screw_price_fixed"]
        + p["nut_price"]
        + p["bearing_sets"] * p["bearing_price"]
        + p["motor_price"]
        + p["coupling_price"]
        + p["reduction_price"]
    )
    assert tv["cost"] == pytest.approx(ov["cost"] + second)
    # the guides carry the whole gantry: more than the single axis's 450 kg table
    assert tv["guide_max_load"] > ov["guide_max_load"]
    # the gantry modes: the 2-DOF model with both chains at every position
    m_r = tv["m_eff"] - tv["moving_mass"]
    j_b = 450.0 / 6.0 + 2 * m_r * 0.25
    lo_end, hi_end = pg.gantry_frequencies(
        whole - 150.0 + 2 * m_r, j_b, 150.0, 0.3, tv["k_total"], tv["k_total"], 1.0, tv["k_yaw"]
    )
    np.testing.assert_allclose(tv["f_racking"], hi_end, rtol=1e-9)
    assert np.all(tv["f_gantry"] <= lo_end * (1 + 1e-12))
    assert np.all(tv["f1"] <= tv["f_gantry"] * (1 + 1e-12))
    # a single-drive axis: no gantry mode, outputs of the axis as before
    assert np.all(ov["f_gantry"] > 1e29)


def test_single_drive_outputs_are_unchanged_by_the_twin_parameters(tmp_path):
    """The neutral twin parameters leave a single-drive evaluation exactly as without them (a bare
    dict)."""
    _, one, _, ov = _pair(tmp_path)
    p = model.design_params(one)
    bare = {k: v for k, v in p.items() if k not in model.gantry.TWIN_PARAMS}
    x = model.positions(one.axis)
    a = model.axis_response(bare, x, one.axis.mounting, one.preload)
    b = model.axis_response(p, x, one.axis.mounting, one.preload)
    for k in (
        "f1",
        "k_total",
        "cost",
        "total_mass",
        "moving_mass",
        "max_axial_force",
        "life",
        "peak_torque",
    ):
        np.testing.assert_array_equal(a[k], b[k])
