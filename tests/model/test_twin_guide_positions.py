"""A twin gantry's guides with the cross carriage at its worst position (issue 53): its weight at
the end of its stroke across the rails adds the roll moment m_c g s/2, which the four-block pattern
shares as THK's formula for a horizontal table on two rails of two blocks (General Catalog A-84,
condition 1: P = W/4 + W l3 / (2 l1), l1 the rail spacing, l3 the load's distance across from the
pattern centre), written here apart from model.carriage."""

from dataclasses import replace

import pytest

from axisopt.design import load_design
from axisopt.model import evaluate

G = 9.80665
DESIGN = """name: twin
axis:
  stroke: 1000 mm
  moving_mass: 300 kg
  mounting: fixed-supported
  max_speed: 5 m/min
  axial_load: 0 N
  table_length: 600 mm
  table_width: 1500 mm
  rail_spacing: 1400 mm
  block_spacing: 400 mm
  twin_drive:
    span: 1200 mm
    cross_stroke: 1000 mm
    cross_mass: 200 kg
parts:
  screw: HIWIN-G-40x10-b6p35
  nut: HIWIN-R40-10K5-FDC
  bearing: HIWIN-WBK20-DF
  guide: HIWIN-HG20-ZA
"""


@pytest.mark.published
def test_cross_carriage_at_its_stroke_end_loads_the_near_blocks(tmp_path):
    f = tmp_path / "twin.yaml"
    f.write_text(DESIGN, encoding="utf-8")
    design = load_design(f)
    tw = design.axis.twin_drive
    centred = replace(design, axis=replace(design.axis, twin_drive=replace(tw, cross_stroke=0.0)))
    quarter_w = float(
        evaluate(centred).values["guide_max_load"]
    )  # W/4: the whole gantry on four blocks
    at_end = float(evaluate(design).values["guide_max_load"])
    l1, l3 = design.axis.rail_spacing, tw.cross_mass * (tw.cross_stroke / 2) / (4 * quarter_w / G)
    expected = quarter_w + (4 * quarter_w) * l3 / (2 * l1)  # THK A-84: W/4 + W l3 / (2 l1)
    assert at_end == pytest.approx(expected, rel=1e-3)
    assert at_end > quarter_w * 1.05
    # the life's mean block load takes the same end (the carriage may stand there)
    assert float(evaluate(design).values["guide_mean_load"]) > float(
        evaluate(centred).values["guide_mean_load"]
    )
