"""The design writer's figures read as a person would write them (issue 42 item 3): an angle given
in arcsec is not written back as 0.000833333333333 deg."""

import dataclasses
from pathlib import Path

import pytest
import yaml

from axisopt.design import design_to_yaml, load_design
from axisopt.units import to_si

BASE = load_design(Path(__file__).resolve().parents[2] / "problems" / "vmc_x_design.yaml")


# the fewest digits, then a figure of 1 or more, then deg before arcmin before arcsec
@pytest.mark.parametrize(
    "given, written",
    [
        ("3 arcsec", "3 arcsec"),
        ("1.5 arcmin", "1.5 arcmin"),
        ("0.5 deg", "0.5 deg"),
        ("0.1 deg", "6 arcmin"),
        ("0.0123 deg", "0.0123 deg"),
        ("0 deg", "0 deg"),
        ("7.2 arcsec", "0.002 deg"),
    ],
)
def test_angles_written_in_the_unit_that_reads_shortest(tmp_path, given, written):
    value, unit = given.split()
    pitch = to_si(float(value), unit, "angle")
    d = dataclasses.replace(
        BASE,
        axis=dataclasses.replace(BASE.axis, guide_pitch=pitch),
        assumed=tuple(k for k in BASE.assumed if k != "guide_pitch"),
    )
    text = design_to_yaml(d)
    assert yaml.safe_load(text)["axis"]["guide_pitch"] == written
    path = tmp_path / "d.yaml"
    path.write_text(text)
    assert load_design(path).axis.guide_pitch == pytest.approx(pitch, rel=1e-12)
