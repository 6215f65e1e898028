"""The effect registry (:mod:`axisopt.identify.effects`): a user's effect competes like the
built-ins."""

from pathlib import Path

import numpy as np
import pytest

from axisopt.design import load_design
from axisopt.identify import Effect, diagnose, library, plant_from_design, register_effect
from axisopt.identify.effects import unregister_effect
from axisopt.identify.tables.synth import simulate

DATA = Path(__file__).resolve().parents[3] / "problems" / "data"


DESIGN = DATA / "table_x.yaml"


def test_user_effect_plugin_competes(tmp_path):
    class SensorGain(Effect):
        name = "sensor_gain"
        title = "displacement sensor reads a fixed fraction high"
        kinds = ("stiffness",)

        def params(self, ctx):
            from axisopt.identify import Param

            return [
                Param(
                    "gain_error",
                    "sensor gain error",
                    "percent",
                    "dimensionless",
                    0.0,
                    -0.5,
                    0.5,
                    typical=0.05,
                )
            ]

        def apply(self, kind, q, P, Z, plant):
            # a gain on the reading acts like extra compliance proportional to the whole chain
            q.c_extra = q.c_extra + P["gain_error"] * (q.c_bearing + 1.0 / plant.k_nut)

    register_effect(SensorGain)
    try:
        assert "sensor_gain" in library()
        plant = plant_from_design(load_design(DESIGN))
        pos = np.repeat(np.linspace(0, 0.8, 8), 8)
        f = np.tile(np.r_[np.linspace(500, 4000, 4), -np.linspace(500, 4000, 4)], 8)
        ds = simulate(
            plant,
            "stiffness",
            dict(position=pos, force=f),
            effects={"sensor_gain": {"gain_error": 0.2}},
            noise=0.01,
            seed=4,
        )
        diag = diagnose([ds], plant, candidates=["sensor_gain", "support_condition", "backlash"])
        assert diag.verdict == "sensor_gain"
        assert diag.final.value("gain_error") == pytest.approx(0.2, rel=0.1)
    finally:
        unregister_effect("sensor_gain")


def test_one_registry_serves_tables_and_time_records():
    from axisopt.identify.effects import TIME_ORDER, time_effects

    table, time = library(), time_effects()
    assert list(time) == list(TIME_ORDER)
    # the effects both kinds of data can show are declared once
    assert set(table) & set(time) == {
        "direction_asymmetry",
        "stribeck",
        "extra_mode",
        "quadratic_drag",
        "nut_axial_friction",
        "viscous_temperature",
        "coulomb_temperature",
    }
    assert "lead_ripple" not in table and "position_friction" not in table
    assert time["stribeck"].terms == ("Fs",) and time["stribeck"].shape.name == "vs"
    assert time["lead_ripple"].terms == ("rs", "rc", "ks", "kc")
