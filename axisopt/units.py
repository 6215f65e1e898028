"""Parse quantities with units at the edges ("800 mm", "25 N/um", "3000 rpm") into SI floats.

This is the one place where units are converted.  Inside the code everything is SI:
m, kg, s, N, N/m, N*m, rad/s, Pa, K.  Money is kept in the catalog's currency (EUR here), a
dimension of its own so that "EUR/m" and "EUR" are checked like any other unit.

Parsing uses pint; vendor spellings such as ``N.m`` or ``mm.rpm`` (a dot for a product) and ``um``
for micrometre are accepted.  The units the shipped catalogs, problems and reports use are looked up
in :data:`KNOWN` (factors pint computed, each checked against pint by the tests), so that a command
that reads only those never builds pint's registry (half a second); any other unit goes to pint.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass

from .errors import InputError


@functools.lru_cache(maxsize=1)
def _registry():
    """pint's unit registry, built on first use (only for a unit that is not in :data:`KNOWN`)."""
    import pint

    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.define("EUR = [currency]")
    ureg.define("percent_ = 0.01 = pct")
    return ureg


# Expected dimension of each quantity kind, as a pint dimensionality string, and its SI unit.
KINDS: dict[str, tuple[str, str]] = {
    "length": ("[length]", "m"),
    # a travel (a guide's rating basis, a life in km): lengths beyond an axis
    "distance": ("[length]", "m"),
    "mass": ("[mass]", "kg"),
    "time": ("[time]", "s"),
    "force": ("[force]", "N"),
    "stiffness": ("[force]/[length]", "N/m"),
    "torque": ("[force]*[length]", "N*m"),
    "speed": ("[length]/[time]", "m/s"),
    "acceleration": ("[length]/[time]**2", "m/s**2"),
    "jerk": ("[length]/[time]**3", "m/s**3"),
    "angular_speed": ("1/[time]", "rad/s"),
    "angle": ("", "rad"),
    "dimensionless": ("", ""),
    "mass_per_length": ("[mass]/[length]", "kg/m"),
    "damping": ("[force]*[time]/[length]", "N*s/m"),
    "pressure": ("[pressure]", "Pa"),
    "temperature": ("[temperature]", "K"),
    "temperature_difference": ("[temperature]", "K"),
    "torsional_stiffness": ("[force]*[length]", "N*m"),
    "kinematic_viscosity": ("[length]**2/[time]", "m**2/s"),
    "inertia": ("[mass]*[length]**2", "kg*m**2"),
    "power": ("[power]", "W"),
    "money": ("[currency]", "EUR"),
    "money_per_length": ("[currency]/[length]", "EUR/m"),
    "dn": ("[length]/[time]", "m*rad/s"),
    "frequency": ("1/[time]", "Hz"),
    "compliance": ("[length]/[force]", "m/N"),
    "thermal_expansion": ("1/[temperature]", "1/K"),
    "heat_transfer": ("[power]/[length]**2/[temperature]", "W/(m**2*K)"),
}

_DOT_PRODUCT = re.compile(r"(?<=[A-Za-z])\.(?=[A-Za-z])")


_ALLOWED = re.compile(r"^[A-Za-z0-9_/*.^()%·µμ-]+$")


def _normalise(unit: str) -> str:
    if unit.strip() and not _ALLOWED.match(unit.strip()):
        raise ValueError(f"unknown unit '{unit}'")
    unit = unit.strip().replace("µ", "u").replace("μ", "u").replace("·", "*")
    unit = _DOT_PRODUCT.sub("*", unit)
    unit = unit.replace("^", "**")
    if unit in ("-", ""):
        return "dimensionless"
    return unit


# The unit each kind is written in at the edges (design YAML written back, catalog exports): vendor
# units, as users write them.
DISPLAY_UNITS = {
    "length": "mm",
    "mass": "kg",
    "time": "h",
    "force": "N",
    "stiffness": "N/um",
    "speed": "m/min",
    "acceleration": "m/s^2",
    "jerk": "m/s^3",
    "angle": "deg",
    "mass_per_length": "kg/m",
    "dn": "mm.rpm",
    "money_per_length": "EUR/m",
    "money": "EUR",
    "kinematic_viscosity": "mm^2/s",
    "inertia": "kg.m^2",
    "angular_speed": "rpm",
    "damping": "N.s/m",
    "torque": "N.m",
    "torsional_stiffness": "N.m/rad",
    "temperature_difference": "K",
    "power": "W",
    "heat_transfer": "W/(m^2.K)",
    "distance": "km",
}


@functools.lru_cache(maxsize=512)
def unit_factor(unit: str, kind: str) -> float:
    """Factor that turns a value in ``unit`` into SI for ``kind``.  Raises ValueError if unknown.

    Offset units (degC) are not allowed here; use :func:`to_si` for temperatures.
    """
    dim, si = KINDS[kind]
    text = _normalise(unit)
    if kind.startswith("money") and text in _EURO_WORDS:
        raise ValueError(f"unknown unit '{unit}'")
    if kind.startswith("money") and "EUR" not in text:  # no exchange rate is assumed
        raise ValueError(
            f"'{unit}' is not EUR, the catalogs' currency, and no exchange rate is assumed: "
            "convert at your rate"
        )
    known = KNOWN.get((text, kind))
    return known if known is not None else _pint_factor(unit, text, kind)


def _pint_factor(unit: str, text: str, kind: str) -> float:
    """:func:`unit_factor` by pint (``text``: the normalised ``unit``)."""
    _UREG = _registry()
    dim, si = KINDS[kind]
    if kind == "temperature_difference":  # a rise of 3 degC is 3 K
        text = {"degC": "delta_degC", "degF": "delta_degF", "celsius": "delta_degC"}.get(text, text)
    try:
        u = _UREG.Unit(text)
    except Exception as exc:  # pint raises several types for unparseable input
        raise ValueError(f"unknown unit '{unit}'") from exc
    q = _UREG.Quantity(1.0, u)
    if dim == "":
        if not q.dimensionless:
            raise ValueError(f"unit '{unit}' is not dimensionless (wanted {kind})")
    elif q.dimensionality != _UREG.get_dimensionality(dim):
        raise ValueError(f"unit '{unit}' is not a unit of {kind}")
    if kind == "temperature":
        return 1.0
    if kind in ("angular_speed", "frequency"):
        return _rate_factor(text, q, kind)
    target = _UREG.Unit(si) if si else _UREG.dimensionless
    return float(q.to(target).magnitude)


# (unit as :func:`_normalise` writes it, kind) -> factor to SI, as :func:`_pint_factor` computes it.
# The units of the shipped catalogs, problems, studies and reports, and a few common others;
# tests/core/test_units.py checks every entry against pint.  A unit missing here is still read (by
# pint), only slower the first time.
KNOWN: dict[tuple[str, str], float] = {
    ("1/K", "thermal_expansion"): 1.0,
    ("1/s", "frequency"): 1.0,
    ("EUR", "money"): 1.0,
    ("EUR/m", "money_per_length"): 1.0,
    ("GPa", "pressure"): 1000000000.0,
    ("Hz", "frequency"): 1.0,
    ("K", "temperature"): 1.0,
    ("K", "temperature_difference"): 1.0,
    ("MPa", "pressure"): 1000000.0,
    ("N", "force"): 1.0,
    ("N*m", "torque"): 1.0,
    ("N*m", "torsional_stiffness"): 1.0,
    ("N*m/arcmin", "torsional_stiffness"): 3437.7467707849396,
    ("N*m/rad", "torsional_stiffness"): 1.0,
    ("N*mm", "torque"): 0.001,
    ("N*s/m", "damping"): 1.0,
    ("N/m", "stiffness"): 1.0,
    ("N/um", "stiffness"): 1000000.0,
    ("Pa", "pressure"): 1.0,
    ("W", "power"): 1.0,
    ("cSt", "kinematic_viscosity"): 1.0000000000000002e-06,
    ("cm", "length"): 0.01,
    ("arcmin", "angle"): 0.00029088820866572163,
    ("deg", "angle"): 0.017453292519943295,
    ("degC", "temperature"): 1.0,
    ("degC", "temperature_difference"): 1.0,
    ("%", "dimensionless"): 0.01,
    ("dimensionless", "dimensionless"): 1.0,
    ("g", "mass"): 0.001,
    ("h", "time"): 3600.0,
    ("kN", "force"): 1000.0,
    ("kW", "power"): 1000.0,
    ("kg", "mass"): 1.0,
    ("kg*cm**2", "inertia"): 0.0001,
    ("kg*m**2", "inertia"): 1.0,
    ("kg*mm**2", "inertia"): 1e-06,
    ("kg/m", "mass_per_length"): 1.0,
    ("km", "distance"): 1000.0,
    ("m", "length"): 1.0,
    ("m**2/s", "kinematic_viscosity"): 1.0,
    ("m*rad/s", "dn"): 1.0,
    ("m/N", "compliance"): 1.0,
    ("m/min", "speed"): 0.016666666666666666,
    ("m/s", "speed"): 1.0,
    ("m/s**2", "acceleration"): 1.0,
    ("m/s**3", "jerk"): 1.0,
    ("min", "time"): 60.0,
    ("mm", "length"): 0.001,
    ("mm**2/s", "kinematic_viscosity"): 1e-06,
    ("mm*rpm", "dn"): 0.00010471975511965978,
    ("mm/min", "speed"): 1.6666666666666667e-05,
    ("mm/s", "speed"): 0.001,
    ("mm/s**2", "acceleration"): 0.001,
    ("ms", "time"): 0.001,
    ("rad", "angle"): 1.0,
    ("rad/s", "angular_speed"): 1.0,
    ("rpm", "angular_speed"): 0.10471975511965977,
    ("s", "time"): 1.0,
    ("um", "length"): 1e-06,
    ("um/N", "compliance"): 1e-06,
}
_KELVIN_OFFSET = {"K": 0.0, "degC": 273.15}  # temperature units read without pint


_ANGLE_WORDS = re.compile(r"rad|deg|rev|rpm|rps|turn|cycle", re.IGNORECASE)


def _rate_factor(text: str, q, kind: str) -> float:
    """Rates need care: pint counts a radian as dimensionless, so '1/min' and 'rad/s' look alike.

    A unit that names an angle (rad, deg, rev, rpm, ...) is an angular rate: its value in 1/s is
    rad/s.  Any other rate (Hz, 1/min, 1/s) counts cycles: its value in 1/s is cycles per second.
    angular_speed -> rad/s, frequency -> Hz.
    """
    per_s = float(q.to(_registry().Unit("1/s")).magnitude)
    angular = bool(_ANGLE_WORDS.search(text))
    if kind == "angular_speed":
        return per_s if angular else per_s * 2.0 * math.pi
    return per_s / (2.0 * math.pi) if angular else per_s


def to_si(value: float, unit: str, kind: str) -> float:
    """Convert ``value`` given in ``unit`` to SI; temperatures to kelvin (offsets handled)."""
    if kind == "temperature":
        unit_factor(unit, kind)  # validates
        text = _normalise(unit)
        if text in _KELVIN_OFFSET:  # as pint converts them: value * 1 + offset
            return value + _KELVIN_OFFSET[text]
        ureg = _registry()
        return float(ureg.Quantity(value, ureg.Unit(text)).to("kelvin").magnitude)
    return value * unit_factor(unit, kind)


_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")

# The largest magnitude (SI) any input of a kind may have: far beyond every machine-tool axis, well
# inside float range, so that no product or power of inputs in the model overflows to inf or NaN.
PLAUSIBLE_MAX = {
    "length": 1e3,
    "distance": 1e12,
    "mass": 1e7,
    "time": 1e10,
    "force": 1e9,
    "stiffness": 1e14,
    "torque": 1e7,
    "speed": 1e3,
    "acceleration": 1e5,
    "jerk": 1e8,
    "angular_speed": 1e6,
    "angle": 1e3,
    "dimensionless": 1e9,
    "mass_per_length": 1e6,
    "damping": 1e12,
    "pressure": 1e13,
    "temperature": 1e4,
    "temperature_difference": 1e4,
    "torsional_stiffness": 1e12,
    "kinematic_viscosity": 1e2,
    "inertia": 1e5,
    "power": 1e9,
    "money": 1e12,
    "money_per_length": 1e10,
    "dn": 1e6,
    "frequency": 1e7,
    "compliance": 1e3,
    "thermal_expansion": 1.0,
    "heat_transfer": 1e6,
}
PLAUSIBLE_MIN = 1e-15  # the smallest non-zero magnitude (SI) of any input
MAX_UNIT_CHARS = 40  # 'kg.m^2/s' is 8; a longer unit text is refused before pint parses it
# '450 u' is a metric prefix without its unit (pint: 'u' is the dalton)
PREFIX_ONLY = {"u", "µ", "μ", "k"}


def check_plausible(
    value: float, kind: str, text, *, source=None, key=None, tiny: bool = True
) -> float:
    """``value`` (SI) unless it is non-finite or outside what an axis input can be (one-line
    InputError).  ``tiny=False``: values close to zero pass (measured data, where they are noise
    around zero)."""
    if not math.isfinite(value):
        raise InputError(f"'{text}' is not a finite number", source=source, where=key)
    top = PLAUSIBLE_MAX.get(kind, 1e12)
    if abs(value) > top:
        raise InputError(
            f"'{text}' is out of range: at most {top:g} {KINDS.get(kind, ('', ''))[1] or ''}"
            f"".rstrip()
            + " in magnitude",
            source=source,
            where=key,
        )
    if tiny and 0 < abs(value) < PLAUSIBLE_MIN:
        raise InputError(
            f"'{text}' is too small to be meant (below {PLAUSIBLE_MIN:g} in SI units); write 0 "
            "if it is zero",
            source=source,
            where=key,
        )
    return value


def parse_quantity(text, kind: str, *, source: str | None = None, key: str | None = None) -> float:
    """Parse ``"800 mm"`` into SI for ``kind``.  A bare number is an error unless kind is
    dimensionless.

    Errors are :class:`InputError` naming ``source`` (file) and ``key``.
    """
    if isinstance(text, bool):
        raise InputError(f"expected a {kind} with a unit, got {text!r}", source=source, where=key)
    if isinstance(text, (int, float)):
        if kind == "dimensionless":
            return check_plausible(float(text), kind, text, source=source, key=key)
        raise InputError(
            f"'{text}' has no unit; write it with one, e.g. '{text} {_example_unit(kind)}'",
            source=source,
            where=key,
        )
    if not isinstance(text, str):
        raise InputError(
            f"expected a {kind} such as '1 {_example_unit(kind)}', got {text!r}",
            source=source,
            where=key,
        )
    if len(text) > MAX_UNIT_CHARS + 40:
        raise InputError(
            f"cannot read '{text[:40]}...' ({len(text):,} characters) as a number with a unit",
            source=source,
            where=key,
        )
    m = _QTY.match(text)
    if not m:
        raise InputError(f"cannot read '{text}' as a number with a unit", source=source, where=key)
    number, unit = float(m.group(1)), m.group(2)
    if not math.isfinite(number):
        raise InputError(f"'{text}' is not a finite number", source=source, where=key)
    if unit == "" and kind != "dimensionless":
        raise InputError(
            f"'{text}' has no unit; write it with one, e.g. '{text} {_example_unit(kind)}'",
            source=source,
            where=key,
        )
    if unit.strip() in PREFIX_ONLY:
        raise InputError(
            f"'{unit}' in '{text}' is a metric prefix without its unit; write the whole unit, "
            f"e.g. '{m.group(1)} {_example_unit(kind)}'",
            source=source,
            where=key,
        )
    # '0.4 g': standard gravity, not grams
    if kind == "acceleration" and unit.strip() in GRAVITY_WORDS:
        return check_plausible(number * STANDARD_GRAVITY, kind, text, source=source, key=key)
    try:
        v = to_si(number, unit, kind)
    except ValueError as exc:
        hint = unit_hint(m.group(1), unit, kind)
        raise InputError(
            f"{exc} in '{text}'" + (f"; {hint}" if hint else ""), source=source, where=key
        ) from None
    return check_plausible(v, kind, text, source=source, key=key)


# '0.4 g' where an acceleration is asked: standard gravity (ISO 80000-3, 9.80665 m/s^2), never grams
STANDARD_GRAVITY = 9.80665
GRAVITY_WORDS = ("g", "G", "gn", "g0", "g_n", "g_0")
_POWER_DIGIT = re.compile(r"([A-Za-z])([23])(?![0-9])")
_SUPERSCRIPTS = {"\u00b2": "^2", "\u00b3": "^3"}
_EURO_WORDS = ("\u20ac", "euro", "euros", "eur", "Euro", "Euros", "Eur")


def unit_hint(number: str, unit: str, kind: str) -> str:
    """What a person most likely meant by a unit text that could not be read (a thousands separator,
    a decimal comma, a power written without '^', a currency symbol), or ''."""
    u = unit.strip()
    grouped = re.match(r"^([,.' ]\d{3})+(?=\s|$)", u) or re.match(r"^\d{3}(\s\d{3})*(?=\s|$)", u)
    if grouped:
        rest = u[grouped.end() :].strip()
        digits = number + re.sub(r"\D", "", grouped.group(0))
        return f"write the number without digit groups: '{digits} {rest or _example_unit(kind)}'"
    dec = re.match(r"^,(\d+)\s*(.*)$", u)
    if dec:
        return (
            f"write the decimal point: '{number}.{dec.group(1)} "
            f"{dec.group(2) or _example_unit(kind)}'"
        )
    if u in _EURO_WORDS or "\u20ac" in u:
        return f"write the currency as EUR: '{number} EUR'"
    fixed = u
    for sup, rep in _SUPERSCRIPTS.items():
        fixed = fixed.replace(sup, rep)
    fixed = _POWER_DIGIT.sub(r"\1^\2", fixed)
    if fixed != u:
        return f"write a power with '^': '{number} {fixed}'"
    return ""


_EXAMPLES = {
    "length": "mm",
    "mass": "kg",
    "time": "s",
    "force": "N",
    "stiffness": "N/um",
    "torque": "N.m",
    "speed": "m/min",
    "acceleration": "m/s^2",
    "jerk": "m/s^3",
    "angular_speed": "rpm",
    "angle": "deg",
    "mass_per_length": "kg/m",
    "damping": "N.s/m",
    "temperature": "degC",
    "money": "EUR",
    "inertia": "kg.m^2",
    "frequency": "Hz",
    "dn": "mm.rpm",
    "money_per_length": "EUR/m",
    "temperature_difference": "K",
    "torsional_stiffness": "N.m/rad",
    "heat_transfer": "W/(m^2.K)",
    "distance": "km",
}


def _example_unit(kind: str) -> str:
    return _EXAMPLES.get(kind, KINDS.get(kind, ("", "SI"))[1])


def split_header(header: str) -> tuple[str, str | None]:
    """``'lead [mm]'`` -> ``('lead', 'mm')``; ``'id'`` -> ``('id', None)``."""
    m = re.match(r"^\s*([^\[\]]+?)\s*(?:\[([^\]]*)\])?\s*$", header)
    if not m:
        return header.strip(), None
    return m.group(1), m.group(2)


# N/m per N/um: catalogs, tables and solver scaling quote stiffness in N/um.
N_PER_UM = 1e6


# ------------------------------------------------------------------------------ strict unit CSV
# The readers of unit-headed CSV files (measured tables, time records, catalogs) share the header's
# and the cells' rules here: a header cell is ``name [unit]``, every column known and once, a unit
# in brackets exactly when the column has a quantity kind, every cell one finite number; each
# problem is an InputError naming the file, line and column.


@dataclass(frozen=True)
class CsvColumn:
    """One column of a unit-headed CSV: its name, the unit as written, its quantity kind (None: a
    plain number without unit) and the factor to SI (None when there is no unit, or the reader
    converts it itself)."""

    name: str
    unit: str | None
    kind: str | None
    factor: float | None


def read_header(header, *, line: int, source: str, kinds: dict, unknown, factor=None) -> list:
    """The :class:`CsvColumn` of a header row.  ``kinds``: column name -> quantity kind (None: no
    unit); ``unknown(name)``: the message for a column not in ``kinds``;
    ``factor(name, unit, kind, where)``: the SI factor of a unit (default :func:`unit_factor`; a
    ValueError becomes "<message> in column '<name>'")."""
    cols = []
    for j, h in enumerate(header, start=1):
        name, unit = split_header(h)
        where = f"line {line}, column {j}"
        if name not in kinds:
            raise InputError(unknown(name), source=source, where=where)
        if name in [c.name for c in cols]:
            raise InputError(f"duplicate column '{name}'", source=source, where=where)
        kind = kinds[name]
        f = None
        if kind is None:
            if unit not in (None, "", "-"):
                raise InputError(f"column '{name}' takes no unit", source=source, where=where)
        elif unit is None:
            raise InputError(
                f"column '{name}' needs a unit in brackets, e.g. '{name} [..]'",
                source=source,
                where=where,
            )
        else:
            try:
                f = (
                    factor(name, unit, kind, where)
                    if factor is not None
                    else unit_factor(unit, kind)
                )
            except ValueError as exc:
                raise InputError(f"{exc} in column '{name}'", source=source, where=where) from None
        cols.append(CsvColumn(name, unit, kind, f))
    return cols


def check_width(cells, columns: int, *, source: str, line: int) -> None:
    """A data row must have as many cells as the header."""
    if len(cells) != columns:
        raise InputError(
            f"has {len(cells)} cells, header has {columns}", source=source, where=f"line {line}"
        )


def read_number(cell: str, *, source: str, where: str) -> float:
    """One cell as a finite number (surrounding blanks allowed)."""
    try:
        val = float(cell)
    except ValueError:
        c = cell.strip()
        raise InputError(
            "empty cell" if not c else f"'{c}' is not a number", source=source, where=where
        ) from None
    if not math.isfinite(val):
        raise InputError(f"'{cell.strip()}' is not a finite number", source=source, where=where)
    return val
