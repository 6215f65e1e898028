"""JSON Schemas of axisopt's YAML files, written from the readers' own key tables.

``json_schema(kind)`` turns the :class:`~axisopt.yamlio.Spec` a reader reads its file by
(``DESIGN_SPEC``, ``PROBLEM_SPEC``, ``STUDY_SPEC``, ``CALIBRATION_SPEC``) into a JSON Schema (draft
2020-12) for an editor's YAML language server: the key names, which are required, unknown keys as
errors, choices, bounds and the one-line description of every key.  There is no second copy of the
rules here, only their translation.

A quantity is a string, a number followed by a unit; its pattern lists the common units of its kind,
each one accepted by :func:`axisopt.units.unit_factor` (the loader's rule), so '800 kg' for a length
fails the schema as it fails the loader.  The loader accepts any unit pint knows of the
right dimension: a rare one the pattern does not list is flagged by the editor but still loads.
What a schema cannot say (a value checked against the catalogs, a unit that must match the swept
key) is left to the loader.
"""

from __future__ import annotations

import functools
import itertools
import re

from .yamlio import MAX_TEXT, Key, Spec

SCHEMA_DIALECT = "https://json-schema.org/draft/2020-12/schema"
# $id of a kind's schema: urn:axisopt:schema:<kind> (no web address to fetch)
SCHEMA_BASE = "urn:axisopt:schema:"
KINDS_OF_FILE = ("design", "problem", "study", "calibration", "machine", "machine-study")

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"  # units._QTY's number
_ANY_UNIT = r"[A-Za-z0-9_/*.^()%·µμ-]*"  # units._ALLOWED's characters
_NON_NEGATIVE = r"^\s*\+?[0-9.]"  # no minus sign
_ZERO = r"\+?(?:0+\.?0*|\.0+)(?:[eE][-+]?\d+)?(?![0-9.])"
_POSITIVE = rf"^\s*(?!{_ZERO})\+?[0-9.]"  # neither a minus sign nor a zero


def spec_of(kind: str) -> Spec:
    """The top-level Spec of a file kind (imported here, so that the readers stay the one
    source)."""
    if kind == "design":
        from .design import DESIGN_SPEC

        return DESIGN_SPEC
    if kind == "problem":
        from .problem import PROBLEM_SPEC

        return PROBLEM_SPEC
    if kind == "study":
        from .study.spec import STUDY_SPEC

        return STUDY_SPEC
    if kind == "calibration":
        from .identify.calibration import CALIBRATION_SPEC

        return CALIBRATION_SPEC
    if kind == "machine":
        from .machine.spec import MACHINE_FILE_SPEC

        return MACHINE_FILE_SPEC
    if kind == "machine-study":
        from .study.machine import MACHINE_STUDY_SPEC

        return MACHINE_STUDY_SPEC
    raise ValueError(f"unknown file kind '{kind}' (one of {', '.join(KINDS_OF_FILE)})")


# ------------------------------------------------------------------------------------------------
# units Candidate spellings per kind; each is kept only if units.unit_factor accepts it for that
# kind.
_LEN = ("m", "mm", "um", "µm", "μm", "nm", "cm", "dm", "km", "in", "inch", "ft", "micron")
_LEN_SHORT = ("m", "mm", "um", "µm", "μm", "cm", "in")
_MASS = ("kg", "g", "mg", "t", "tonne", "lb")
_TIME = (
    "s",
    "ms",
    "us",
    "µs",
    "min",
    "h",
    "hr",
    "hour",
    "hours",
    "d",
    "day",
    "days",
    "year",
    "years",
)
_FORCE = ("N", "kN", "MN", "mN", "daN", "lbf", "kgf")
_PER_TIME = ("s", "min", "h")
_TIMES = (".", "*", "·")
_SQUARE = ("^2", "**2", "2")
_CUBE = ("^3", "**3", "3")


def _compound(*groups) -> list:
    return ["".join(p) for p in itertools.product(*groups)]


def _candidates(kind: str) -> list:
    torque = _compound(_FORCE, _TIMES, ("m", "mm", "cm", "in", "ft"))
    c = {
        "length": list(_LEN),
        "distance": list(_LEN),
        "mass": list(_MASS),
        "time": list(_TIME),
        "force": list(_FORCE),
        "stiffness": _compound(_FORCE, ("/",), _LEN_SHORT),
        "compliance": _compound(_LEN_SHORT, ("/",), _FORCE),
        "torque": torque + ["Nm", "kNm"],
        "torsional_stiffness": torque + _compound(torque, ("/",), ("rad", "deg", "arcmin", "mrad")),
        "speed": _compound(_LEN, ("/",), _PER_TIME) + ["mps"],
        "acceleration": _compound(_LEN_SHORT, ("/",), ("s",), _SQUARE) + ["g0", "gravity"],
        "jerk": _compound(_LEN_SHORT, ("/",), ("s",), _CUBE),
        "angular_speed": [
            "rpm",
            "rps",
            "r/min",
            "rev/min",
            "rev/s",
            "rad/s",
            "deg/s",
            "1/s",
            "1/min",
            "Hz",
        ],
        "frequency": ["Hz", "kHz", "mHz", "1/s", "1/min", "rpm", "r/min", "rev/min", "rad/s"],
        "angle": ["rad", "mrad", "urad", "deg", "degree", "arcmin", "arcsec", "rev", "turn"],
        "mass_per_length": _compound(("kg", "g"), ("/",), ("m", "mm", "cm")),
        "damping": _compound(_FORCE, _TIMES, ("s", "ms"), ("/",), _LEN_SHORT),
        "pressure": ["Pa", "kPa", "MPa", "GPa", "bar", "mbar", "psi", "ksi"]
        + _compound(("N", "kN"), ("/",), ("m", "mm", "cm"), _SQUARE),
        "temperature": ["K", "degC", "degF", "celsius"],
        "temperature_difference": [
            "K",
            "mK",
            "degC",
            "delta_degC",
            "degF",
            "delta_degF",
            "celsius",
        ],
        "kinematic_viscosity": ["cSt", "St"]
        + _compound(("m", "mm", "cm"), _SQUARE, ("/",), ("s",)),
        "inertia": _compound(("kg", "g", "t"), _TIMES, ("m", "cm", "mm"), _SQUARE),
        "power": ["W", "kW", "mW", "MW", "hp"],
        "money": ["EUR"],
        "money_per_length": _compound(("EUR",), ("/",), ("m", "mm", "cm", "km")),
        "dn": _compound(("mm", "m"), _TIMES, ("rpm", "rad/s", "r/min")),
        "thermal_expansion": ["1/K", "1/degC", "ppm/K", "um/m/K", "1/delta_degC"],
        "dimensionless": ["%", "percent", "pct", "ppm"],
        "heat_transfer": [
            "W/(m^2.K)",
            "W/(m^2*K)",
            "W/m^2/K",
            "W/(m2.K)",
            "kW/(m^2.K)",
            "W/(cm^2.K)",
        ],
    }
    return c.get(kind, [])


@functools.lru_cache(maxsize=None)
def units_of(kind: str) -> tuple:
    """The unit spellings the schema lists for ``kind``: the candidates the loader accepts."""
    from .units import KINDS, unit_factor

    if kind not in KINDS:
        raise ValueError(f"unknown quantity kind '{kind}'")
    out = []
    for u in _candidates(kind):
        try:
            unit_factor(u, kind)
        except Exception:  # noqa: BLE001 - pint raises several types; a refused spelling is just left out
            continue
        out.append(u)
    return tuple(dict.fromkeys(out))


def quantity_pattern(kind: str | None) -> str:
    """A regular expression for a quantity of ``kind`` written as text (None: any unit)."""
    if kind is None:
        return rf"^\s*{_NUMBER}\s*{_ANY_UNIT}\s*$"
    units = sorted(units_of(kind), key=lambda u: (-len(u), u))
    alt = "|".join(re.escape(u) for u in units)
    optional = "?" if kind == "dimensionless" else ""
    return rf"^\s*{_NUMBER}\s*(?:{alt}){optional}\s*$"


# Example values per kind for the descriptions (in the vendor units users write).
_EXAMPLES = {
    "length": "800 mm",
    "mass": "300 kg",
    "time": "20000 h",
    "force": "4000 N",
    "stiffness": "150 N/um",
    "compliance": "0.002 um/N",
    "torque": "1.2 N.m",
    "torsional_stiffness": "75000 N.m/rad",
    "speed": "30 m/min",
    "acceleration": "3 m/s^2",
    "jerk": "50 m/s^3",
    "angular_speed": "3000 rpm",
    "frequency": "100 Hz",
    "angle": "1 deg",
    "mass_per_length": "5.6 kg/m",
    "damping": "500 N.s/m",
    "pressure": "200 GPa",
    "temperature": "20 degC",
    "temperature_difference": "3 K",
    "kinematic_viscosity": "32 mm^2/s",
    "inertia": "0.29 kg.cm^2",
    "power": "750 W",
    "money": "4000 EUR",
    "money_per_length": "120 EUR/m",
    "dn": "70000 mm.rpm",
    "thermal_expansion": "1.2e-5 1/K",
    "dimensionless": "0.03",
}


def example_of(kind: str | None) -> str:
    return _EXAMPLES.get(kind, "500 mm")


def unit_message(kind: str | None) -> str:
    """What an editor shows when a quantity's text fails its pattern (the schema's
    ``patternErrorMessage``, read by the YAML and JSON language servers in place of the regular
    expression): the kind, an example and a few of the units listed.  One short line."""
    if kind is None:
        return "a number and a unit, e.g. 500 mm"
    units = [u for u in units_of(kind) if u.isascii()]
    shown = ", ".join(units[:6]) + (", ..." if len(units) > 6 else "")
    what = "a number" + (
        ", optionally with %, percent or ppm"
        if kind == "dimensionless"
        else f" and a unit of {kind.replace('_', ' ')}"
    )
    return f"expected {what}, e.g. {example_of(kind)}" + (
        f" (units: {shown})" if kind != "dimensionless" else ""
    )


# -----------------------------------------------------------------------------------------------
# schema


class _Writer:
    """Writes one Spec tree; Specs used more than once go to ``$defs`` (by their name)."""

    def __init__(self, root: Spec):
        self.count: dict = {}
        self._walk_spec(root)
        self.defs: dict = {}
        self.names: dict = {}  # id(spec) -> $defs name
        self.kinds: set = set()

    def _walk_spec(self, spec: Spec) -> None:
        self.count[id(spec)] = self.count.get(id(spec), 0) + 1
        if self.count[id(spec)] > 1:
            return
        for k in list(spec.keys.values()) + ([spec.extra] if spec.extra is not None else []):
            self._walk_key(k)

    def _walk_key(self, k: Key) -> None:
        if k.type == "section" and k.spec is not None:
            self._walk_spec(k.spec)
        if k.items is not None:
            self._walk_key(k.items)
        for o in k.options:
            self._walk_key(o)

    def spec(self, spec: Spec, top: bool = False) -> dict:
        if top or self.count.get(id(spec), 0) <= 1:
            return self._object(spec)
        name = self.names.get(id(spec))
        if name is None:
            name = spec.name
            while name in self.defs:
                name += "_"
            self.names[id(spec)] = name
            self.defs[name] = {}  # reserved before writing: a Spec may (one day) refer to itself
            self.defs[name] = self._object(spec)
        return {"$ref": f"#/$defs/{name}"}

    def _object(self, spec: Spec) -> dict:
        out: dict = {"type": "object"}
        if spec.doc:
            out["description"] = spec.doc
        out["properties"] = {name: self.key(k) for name, k in spec.keys.items()}
        required = [name for name, k in spec.keys.items() if k.required]
        if required:
            out["required"] = required
        if spec.extra is None:
            out["additionalProperties"] = False
        else:
            extra = self.key(spec.extra)
            if spec.extra_doc:
                extra = {
                    **extra,
                    "description": _join(spec.extra_doc, extra.get("description", ""), ": "),
                }
            if spec.extra_pattern:
                out["patternProperties"] = {spec.extra_pattern: extra}
                out["additionalProperties"] = False
            else:
                out["additionalProperties"] = extra
        return out

    def key(self, k: Key) -> dict:
        out = getattr(self, "_" + k.type)(k)
        doc = _join(k.doc, out.pop("description", ""), "; ")
        return {"description": doc, **out} if doc else out

    def _quantity(self, k: Key) -> dict:
        if k.kind is None:
            return {
                "description": "a number with a unit, e.g. 500 mm",
                "anyOf": [
                    {"type": "number"},
                    {
                        "type": "string",
                        "pattern": quantity_pattern(None),
                        "patternErrorMessage": unit_message(None),
                    },
                ],
            }
        name = f"quantity_{k.kind}"
        if name not in self.defs:
            text = {
                "type": "string",
                "pattern": quantity_pattern(k.kind),
                "patternErrorMessage": unit_message(k.kind),
                "examples": [example_of(k.kind)],
            }
            self.defs[name] = (
                {"anyOf": [{"type": "number"}, text]} if k.kind == "dimensionless" else text
            )
        words = k.kind.replace("_", " ")
        sign = ""
        out: dict = {"$ref": f"#/$defs/{name}"}
        example = k.example if k.example is not None else example_of(k.kind)
        if k.positive:
            sign, out["pattern"] = ", positive", _POSITIVE
            out["patternErrorMessage"] = f"{words} must be positive, e.g. {example}"
            if k.kind == "dimensionless":
                out["exclusiveMinimum"] = 0
        elif k.non_negative:
            sign, out["pattern"] = ", not negative", _NON_NEGATIVE
            out["patternErrorMessage"] = f"{words} must not be negative, e.g. {example}"
            if k.kind == "dimensionless":
                out["minimum"] = 0
        if k.maximum is not None:
            sign += f", at most {k.maximum[1]}"
        return {"description": f"{words}{sign}, e.g. {example}", **out}

    def _number(self, k: Key) -> dict:
        out: dict = {"type": "integer" if k.integer else "number"}
        if k.minimum is not None:
            out["minimum"] = k.minimum
        if k.positive and (k.minimum is None or k.minimum <= 0):
            out["exclusiveMinimum"] = 0
        top = 1e9 if k.maximum is None else k.maximum  # Section.number's default bound
        out["maximum"] = int(top) if k.integer and float(top).is_integer() else top
        return out

    def _choice(self, k: Key) -> dict:
        return {"enum": list(k.choices)}

    def _string(self, k: Key) -> dict:
        if k.choices:
            return {"enum": list(k.choices)}
        return {"type": "string", "maxLength": MAX_TEXT}

    def _names(self, k: Key) -> dict:
        item = {"enum": list(k.choices)} if k.choices else {"type": ["string", "number"]}
        arr: dict = {"type": "array", "items": item}
        if k.minimum is not None:
            arr["minItems"] = int(k.minimum)
        if k.maximum is not None:
            arr["maxItems"] = int(k.maximum)
        return {"anyOf": [item, arr]}

    def _section(self, k: Key) -> dict:
        return self.spec(k.spec)

    def _list(self, k: Key) -> dict:
        out: dict = {"type": "array"}
        if k.items is not None:
            out["items"] = self.key(k.items)
        if k.minimum is not None:
            out["minItems"] = int(k.minimum)
        if k.maximum is not None:
            out["maxItems"] = int(k.maximum)
        return out

    def _one_of(self, k: Key) -> dict:
        return {"anyOf": [self.key(o) for o in k.options]}

    def _any(self, k: Key) -> dict:
        return {}


def _join(a: str, b: str, sep: str) -> str:
    return sep.join(x for x in (a, b) if x)


def json_schema(kind: str) -> dict:
    """The JSON Schema (draft 2020-12) of a ``kind`` file: design, problem, study or calibration."""
    spec = spec_of(kind)
    w = _Writer(spec)
    body = w.spec(spec, top=True)
    out = {
        "$schema": SCHEMA_DIALECT,
        "$id": f"{SCHEMA_BASE}{kind}",
        "title": f"axisopt {kind} file",
    }
    out.update(body)
    if w.defs:
        out["$defs"] = dict(sorted(w.defs.items()))
    return out


__all__ = [
    "json_schema",
    "spec_of",
    "units_of",
    "quantity_pattern",
    "unit_message",
    "KINDS_OF_FILE",
]
