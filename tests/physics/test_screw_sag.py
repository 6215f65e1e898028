"""Sag of a horizontal screw under its own weight (physics.screw.screw_sag) against published beam
figures."""

from __future__ import annotations

import math

import pytest

from axisopt.physics.screw import SAG_FACTORS, screw_sag

G = 9.80665


@pytest.mark.published
def test_simply_supported_beam_matches_the_engineering_toolbox_example():
    # The Engineering ToolBox, "Beams - Supported at Both Ends - Continuous and Point Loads",
    # example "UB 305 x 127 x 42" beam: uniform load 6 N/mm, length 5000 mm, I = 81 960 000 mm^4, E
    # = 200 000 N/mm^2: delta_max = 5 (6 N/mm) (5000 mm)^4 / ((200000 N/mm^2) (81960000 mm^4) 384) =
    # 2.98 mm
    i_beam = 81_960_000e-12  # [m^4]
    d_equiv = (64.0 * i_beam / math.pi) ** 0.25  # a round section of that I
    sag = screw_sag(
        6000.0 / G, d_equiv, 5.0, "supported-supported", youngs_modulus=200e9, gravity=G
    )
    assert sag * 1e3 == pytest.approx(2.98, abs=0.005)


@pytest.mark.published
def test_end_conditions_follow_the_aisc_table():
    # AISC Steel Construction Manual Table 3-23: delta_max = 5 w l^4 / 384 EI (case 1, simple beam),
    # w l^4 / 185 EI (case 12, fixed and supported), w l^4 / 384 EI (case 15, both ends fixed), w
    # l^4 / 8 EI (case 22, cantilever)
    base = screw_sag(8.22, 0.0347, 2.2, "supported-supported")
    assert screw_sag(8.22, 0.0347, 2.2, "fixed-fixed") == pytest.approx(base / 5.0, rel=1e-12)
    assert screw_sag(8.22, 0.0347, 2.2, "fixed-supported") == pytest.approx(
        base * 384.0 / (5.0 * 185.0), rel=1e-12
    )
    assert screw_sag(8.22, 0.0347, 2.2, "fixed-free") == pytest.approx(
        base * 384.0 / (5.0 * 8.0), rel=1e-12
    )
    assert set(SAG_FACTORS) == {
        "fixed-free",
        "fixed-supported",
        "fixed-fixed",
        "supported-supported",
    }


def test_sag_scales_as_length_to_the_fourth_over_root_to_the_fourth():
    a = screw_sag(5.0, 0.03, 1.0, "fixed-fixed")
    assert screw_sag(5.0, 0.03, 2.0, "fixed-fixed") == pytest.approx(16.0 * a, rel=1e-12)
    assert screw_sag(5.0, 0.06, 1.0, "fixed-fixed") == pytest.approx(a / 16.0, rel=1e-12)
    with pytest.raises(ValueError, match="mounting"):
        screw_sag(5.0, 0.03, 1.0, "free-free")
