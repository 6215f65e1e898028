"""YAML load(dump(design)) == design, for catalog and inline parts (hypothesis over the axis
values)."""

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from axisopt.design import design_to_yaml, load_design
from axisopt.model import evaluate

ROOT = Path(__file__).resolve().parents[2]
BASE = load_design(ROOT / "problems" / "vmc_x_design.yaml")


def _same(a, b):
    for f in dataclasses.fields(a.axis):
        va, vb = getattr(a.axis, f.name), getattr(b.axis, f.name)
        if isinstance(va, float):
            assert vb == pytest.approx(va, rel=1e-11), f.name
        else:
            assert va == vb, f.name
    assert a.part_ids() == b.part_ids()
    assert b.preload == pytest.approx(a.preload, rel=1e-11)


@settings(max_examples=25, deadline=None)
@given(
    stroke=st.floats(0.05, 4.0),
    mass=st.floats(1.0, 5000.0),
    speed=st.floats(0.01, 2.0),
    load=st.one_of(st.just(0.0), st.floats(1e-3, 5e4)),
    inline=st.booleans(),
    mounting=st.sampled_from(["fixed-free", "fixed-supported", "fixed-fixed"]),
)
def test_yaml_round_trip(tmp_path_factory, stroke, mass, speed, load, inline, mounting):
    # the mean speed and load at most the top ones (the reader refuses a mean above its maximum)
    d = dataclasses.replace(
        BASE,
        axis=dataclasses.replace(
            BASE.axis,
            stroke=stroke,
            moving_mass=mass,
            max_speed=speed,
            axial_load=load,
            mounting=mounting,
            mean_speed=min(BASE.axis.mean_speed, speed),
            mean_axial_load=min(BASE.axis.mean_axial_load, load),
        ),
    )
    path = tmp_path_factory.mktemp("rt") / "d.yaml"
    path.write_text(design_to_yaml(d, inline_parts=inline))
    back = load_design(path)
    _same(d, back)
    assert np.allclose(evaluate(back)["k_total"], evaluate(d)["k_total"], rtol=1e-10)


@pytest.mark.parametrize("inline", [False, True])
def test_yaml_round_trip_with_a_reduction(tmp_path, inline):
    """A design with a reduction part writes it (id or inline, vendor units) and leaves out the
    axis's reduction values (the part sets them; the reader refuses both): load(dump(d)) evaluates
    the same."""
    from axisopt.catalog.loading import default_catalog

    red = default_catalog().part("reductions", "BK-NPT035-MF-4")
    d = dataclasses.replace(
        BASE,
        reduction=red,
        axis=dataclasses.replace(BASE.axis, reduction_ratio=2.0),
        assumed=tuple(k for k in BASE.assumed if k != "reduction_ratio"),
    )
    path = tmp_path / "d.yaml"
    text = design_to_yaml(d, inline_parts=inline)
    assert "reduction_ratio" not in text
    path.write_text(text)
    back = load_design(path)
    assert back.part_ids()["reduction"] == "BK-NPT035-MF-4"
    for k in ("k_total", "margin_reduction_accel_torque", "backlash", "cost"):
        assert np.allclose(evaluate(back)[k], evaluate(d)[k], rtol=1e-10), k
