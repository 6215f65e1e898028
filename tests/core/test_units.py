from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from axisopt import units
from axisopt.errors import InputError
from axisopt.units import parse_quantity, split_header, unit_factor


@pytest.mark.parametrize(
    "text, kind, si",
    [
        ("800 mm", "length", 0.8),
        ("25 N/um", "stiffness", 25e6),
        ("25 N/µm", "stiffness", 25e6),
        ("3000 rpm", "angular_speed", 314.1592653589793),
        ("1.5 N.m", "torque", 1.5),
        ("30 m/min", "speed", 0.5),
        ("450 kg", "mass", 450.0),
        ("20000 h", "time", 7.2e7),
        ("4.4 kN", "force", 4400.0),
        ("70000 mm.rpm", "dn", 70000 * 1e-3 * 2 * 3.141592653589793 / 60),
        ("12 EUR/m", "money_per_length", 12.0),
        ("2e-3 kg.m^2", "inertia", 2e-3),
        ("32 mm^2/s", "kinematic_viscosity", 32e-6),
        ("20 degC", "temperature", 293.15),
    ],
)
def test_parse_quantity_to_si(text, kind, si):
    assert parse_quantity(text, kind) == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize("bad", [800, "800", "800 kg", "800 furlongs?", "mm 800", True, None, [1]])
def test_bad_lengths_are_one_line_errors_naming_the_key(bad):
    with pytest.raises(InputError) as exc:
        parse_quantity(bad, "length", source="axis.yaml", key="axis.stroke")
    msg = str(exc.value)
    assert msg.startswith("axis.yaml: axis.stroke: ") and "\n" not in msg


def test_split_header():
    assert split_header("lead [mm]") == ("lead", "mm")
    assert split_header("id") == ("id", None)
    assert split_header(" stiffness [N/um] ") == ("stiffness", "N/um")


def test_unit_factor_rejects_wrong_dimension():
    with pytest.raises(ValueError):
        unit_factor("kg", "length")


@given(st.floats(min_value=1e-6, max_value=1e6, allow_nan=False))
def test_mm_round_trip(v):
    assert parse_quantity(f"{v!r} mm", "length") == pytest.approx(v * 1e-3, rel=1e-12)


@pytest.mark.parametrize("unit,kind", sorted(units.KNOWN))
def test_known_units_equal_pint(unit, kind):
    """The table that spares pint's registry holds exactly what pint computes."""
    assert units._pint_factor(unit, units._normalise(unit), kind) == units.KNOWN[(unit, kind)]


def test_temperatures_without_pint_equal_pint():
    ureg = units._registry()
    for text in ("20 degC", "-40 degC", "300 K", "0.1 degC"):
        value, unit = text.split()
        want = float(ureg.Quantity(float(value), ureg.Unit(unit)).to("kelvin").magnitude)
        assert units.parse_quantity(text, "temperature") == want


def test_reading_a_problem_builds_no_unit_registry():
    import subprocess
    import sys

    code = (
        "import sys; from axisopt.problem import load_problem; "
        "load_problem('problems/teaching_problem.yaml'); print('pint' in sys.modules)"
    )
    root = Path(__file__).resolve().parents[2]
    out = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        cwd=root,
        env={**__import__("os").environ, "PYTHONPATH": str(root)},
        check=True,
    )
    assert out.stdout.strip() == "False"
