"""Close the loop: save a diagnosis as a calibration YAML; apply it to a design for
``axisopt evaluate``.

File layout (values carry units; ``kind`` names the quantity so the value parses strictly)::

    axisopt_calibration: 1
    design: table-x
    verdict: support_condition
    baseline:
      screw_modulus: {value: 201.3 GPa, sigma: 0.8 GPa, kind: pressure}
    effects:
      - name: support_condition
        parameters:
          far_end_stiffness: {value: 296 N/um, sigma: 9 N/um, kind: stiffness}
    applied: [...]          # informational, recomputed on apply
    not_applied: [...]

What ``evaluate`` cannot represent (Stribeck, backlash, thermal drift, damping, a periodic force
...) is listed as not applied.  Time records write theirs with
:func:`.timecalibration.time_calibration_dict` in the same layout.
"""

from __future__ import annotations

import math
from dataclasses import replace

import yaml

from ..errors import InputError
from ..physics.screw import E_STEEL
from ..units import KINDS
from ..yamlio import Key, Section, Spec, close_matches, read_yaml
from .effects import all_effects

FORMAT = 1


def _entry(p, value, sigma) -> dict:
    d = {
        "value": f"{p.show(value):.6g} {p.unit}".strip()
        if p.unit not in ("", "-")
        else float(f"{value:.6g}"),
        "kind": p.kind,
    }
    if math.isfinite(sigma):
        d["sigma"] = (
            f"{p.show(sigma):.3g} {p.unit}".strip()
            if p.unit not in ("", "-")
            else float(f"{sigma:.3g}")
        )
    return d


def calibration_dict(diag, design=None, sources=()) -> dict:
    """The calibration of a :class:`~.diagnose.Diagnosis` as a plain dict (YAML-ready)."""
    res = diag.final
    sig = dict(zip([p.name for p in res.params], res.sigma))
    owner = diag.param_owner
    base = {
        p.name: _entry(p, res.value(p.name), sig[p.name]) for p in res.params if p.name not in owner
    }
    effects = [
        {
            "name": e.name,
            "parameters": {
                p.name: _entry(p, res.value(p.name), sig[p.name])
                for p in res.params
                if owner.get(p.name) == e.name
            },
        }
        for e in diag.effects
    ]
    out = {
        "axisopt_calibration": FORMAT,
        "design": diag.plant.name,
        "data": [str(s) for s in sources],
        "verdict": diag.verdict,
        "baseline": base,
        "effects": effects,
    }
    if design is not None:
        _, applied, skipped = calibrate_design(design, out)
        out["applied"], out["not_applied"] = applied, skipped
    return out


def write_calibration(d: dict, path) -> dict:
    """Write a calibration record ``d`` (a table's or a time record's) as YAML to ``path``; returns
    ``d``."""
    from ..fileio import write_text_atomic

    write_text_atomic(
        path, yaml.safe_dump(d, sort_keys=False, allow_unicode=True), what="calibration"
    )
    return d


def check_calibration_path(path, design=None, sources=()) -> None:
    """Refuse, before anything is computed or written, a calibration ``path`` that is one of the
    measured files (``sources``) or the design file the calibration is fitted to, or that cannot be
    written."""
    from ..fileio import check_output_path, refuse_inputs

    refuse_inputs(path, [*map(str, sources), getattr(design, "source", "")], what="calibration")
    check_output_path(path, what="calibration")


def save_calibration(diag, path, design=None, sources=()) -> dict:
    """Save a friction-table diagnosis as a calibration YAML (never over its data or design
    file)."""
    check_calibration_path(path, design, sources)
    return write_calibration(calibration_dict(diag, design, sources), path)


def _read(path) -> dict:
    from ..units import parse_quantity

    root = Section(read_yaml(path), str(path), spec=CALIBRATION_SPEC)
    # any whole number: a clear message
    ver = root.number("axisopt_calibration", required=True, integer=True)
    if ver != FORMAT:
        raise root.error(
            "axisopt_calibration", f"unsupported calibration format {ver} (expected {FORMAT})"
        )
    design = root.read("design")
    root.read("verdict")
    root.raw("data")
    root.raw("applied")
    root.raw("not_applied")

    def values(sec, allowed=None, where=""):
        out = {}
        for key in sec.keys():
            if allowed is not None and key not in allowed:
                near = close_matches(key, sorted(allowed))
                hint = f"; did you mean '{near[0]}'?" if near else ""
                raise sec.error(
                    key,
                    f"unknown {where} parameter '{key}'{hint} (known: "
                    f"{', '.join(sorted(allowed))})",
                )
            s = sec.section(key)
            kind = s.choice("kind", tuple(KINDS), required=True)
            if allowed is not None and allowed[key] != kind:
                raise s.error("kind", f"'{key}' is a {allowed[key]}, not a {kind}")
            raw = s.value("value", required=True)
            v = parse_quantity(raw, kind, source=str(path), key=s.where("value"))
            if v < 0 and kind in NON_NEGATIVE_KINDS or (key in POSITIVE_PARAMS and not v > 0):
                raise s.error(
                    "value",
                    f"'{raw}' is not physical for {key} (must be "
                    f"{'positive' if key in POSITIVE_PARAMS else 'non-negative'})",
                )
            out[key] = v
            s.raw("sigma")
            s.done()
        return out

    base = values(
        root.read("baseline") or Section(_empty(), str(path), spec=BASELINE_SPEC),
        BASELINE_KINDS,
        "baseline",
    )
    effects = []
    node = root.raw("effects")
    if node is not None and node.value is not None and not isinstance(node.value, list):
        raise root.error("effects", "expected a list of effects")
    lib = all_effects()
    for item in node.value if node is not None and node.value else []:
        s = Section(item, str(path), "effects", EFFECT_SPEC)
        node = s.raw("name", None, required=True)  # the library now (effects may be registered)
        name = node.value
        # the hint first: the library is long, an error one line
        if not isinstance(name, str) or name not in lib:
            near = close_matches(str(name), list(lib), n=1)
            raise s.error(
                "name",
                f"unknown effect '{str(name)[:60]}'"
                + (f"; did you mean '{near[0]}'?" if near else "")
                + f" (known: {', '.join(lib)})",
            )
        ps = s.read("parameters")
        vals = values(ps)
        if not vals:
            raise s.error("parameters", f"effect '{name}' lists no parameters")
        effects.append((name, vals, s.where("parameters")))
        s.done()
    root.done()
    return {"design": design, "baseline": base, "effects": effects, "source": str(path)}


# Calibrated values that cannot be negative (a stiffness, damping coefficient, modulus, mass ...)
# and the ones that must be positive: a negative or zero one is refused, not applied.
NON_NEGATIVE_KINDS = frozenset(
    {"stiffness", "damping", "pressure", "mass", "inertia", "torsional_stiffness"}
)
POSITIVE_PARAMS = frozenset({"screw_modulus", "damping_ratio"})

# The baseline parameters a calibration may carry (identify.measure.baseline_params) and their
# kinds.
BASELINE_KINDS = {
    "screw_modulus": "pressure",
    "coulomb_friction": "force",
    "damping_ratio": "dimensionless",
}


# ------------------------------------------------------------------------------ the YAML keys (one
# table) The one declaration of a calibration file's keys: _read reads them by it and
# `axisopt schema calibration` writes it out.  An effect's parameter names are the effect's own (the
# library checks them on apply).


def _param_spec(name: str, doc: str, kind: str | None) -> Spec:
    """A calibrated value: {value, sigma, kind}; ``kind`` None: any units.KINDS kind, named in the
    file."""
    positive = name in POSITIVE_PARAMS
    return Spec(
        name,
        doc,
        {
            "value": Key(
                "quantity",
                "the calibrated value, with a unit of its kind"
                + (
                    " (positive)"
                    if positive
                    else " (not negative)"
                    if kind in NON_NEGATIVE_KINDS
                    else ""
                ),
                required=True,
                kind=kind,
                positive=positive,
                non_negative=not positive and kind in NON_NEGATIVE_KINDS,
            ),
            "sigma": Key("any", "its standard uncertainty (informational)"),
            "kind": Key(
                "choice",
                "the quantity kind the value is read as",
                required=True,
                choices=(kind,) if kind is not None else tuple(KINDS),
            ),
        },
    )


BASELINE_SPEC = Spec(
    "baseline",
    "calibrated baseline parameters (those diagnose fits)",
    {
        name: Key("section", spec=_param_spec(name, f"baseline {name.replace('_', ' ')}", kind))
        for name, kind in BASELINE_KINDS.items()
    },
)
PARAMETERS_SPEC = Spec(
    "parameters",
    "the effect's calibrated parameters, by the effect's parameter names",
    {},
    extra=Key("section", spec=_param_spec("parameter", "a calibrated effect parameter", None)),
    extra_doc="a parameter name of the effect",
)
EFFECT_SPEC = Spec(
    "effect",
    "an accepted effect with its calibrated parameters",
    {
        "name": Key(
            "choice",
            "the effect (axisopt's effect library)",
            required=True,
            choices=tuple(all_effects()),
        ),
        "parameters": Key("section", required=True, spec=PARAMETERS_SPEC),
    },
)
CALIBRATION_SPEC = Spec(
    "calibration",
    "a calibration saved by axisopt diagnose (applied by evaluate --calibration)",
    {
        "axisopt_calibration": Key(
            "number", "format version", required=True, integer=True, minimum=FORMAT, maximum=FORMAT
        ),
        "design": Key(
            "string",
            "name of the design the calibration was fitted on (applies to that design only)",
        ),
        "data": Key("any", "measurement files the fit used (informational)"),
        "verdict": Key("string", "diagnose's verdict (informational)"),
        "baseline": Key("section", spec=BASELINE_SPEC),
        "effects": Key("list", "accepted effects", items=Key("section", spec=EFFECT_SPEC)),
        "applied": Key("any", "what evaluate applies (informational, recomputed on apply)"),
        "not_applied": Key("any", "what evaluate cannot represent (informational)"),
    },
)


class _Reads(dict):
    """A parameter dict that remembers which keys were read (to name a parameter no effect uses)."""

    def __init__(self, *a):
        super().__init__(*a)
        self.read: set = set()

    def __getitem__(self, k):
        self.read.add(k)
        return super().__getitem__(k)

    def get(self, k, default=None):
        self.read.add(k)
        return super().get(k, default)


def _empty():
    from ..yamlio import Node

    return Node({}, 0)


def calibrate_design(design, cal) -> tuple:
    """Apply a calibration (dict as written, or as read by ``_read``) to a Design.

    Returns (design, applied descriptions, not-applied descriptions)."""
    written = [*(cal.get("baseline") or {}).values(), *cal.get("effects", [])]
    if any(isinstance(v, dict) for v in written):  # as written (values with units), not as read
        cal = _parse_dict(cal)
    applied, skipped = [], []
    base = cal["baseline"]
    if "screw_modulus" in base:
        e = base["screw_modulus"]
        d0 = float(design.screw["root_diameter"])
        d1 = d0 * math.sqrt(e / E_STEEL)
        screw = design.screw.copy()
        screw["root_diameter"] = d1
        design = replace(design, screw=screw)
        applied.append(
            f"screw modulus {e / 1e9:.1f} GPa applied as equivalent root diameter "
            f"{d0 * 1e3:.2f} -> {d1 * 1e3:.2f} mm (critical speed and buckling follow it)"
        )
    if "coulomb_friction" in base:
        from .plant import plant_from_design

        blocks = design.axis.guide_blocks
        plant = plant_from_design(design)
        f0 = float(design.guide["friction_force"])
        want = f0 + (base["coulomb_friction"] - plant.coulomb) / blocks
        f1 = max(want, 0.0)
        guide = design.guide.copy()
        guide["friction_force"] = f1
        design = replace(design, guide=guide)
        applied.append(
            f"guide friction force {f0:.1f} -> {f1:.1f} N per block (Coulomb "
            f"{base['coulomb_friction']:.1f} N at the table"
            + (", clamped at 0: the model's nut drag alone exceeds it)" if want < 0 else ")")
        )
    if "damping_ratio" in base:
        skipped.append(f"damping_ratio {base['damping_ratio']:.3f}: evaluate has no damping output")
    lib = all_effects()
    for name, vals, *where in cal["effects"]:
        vals = _Reads(vals)
        try:
            out = lib[name].calibrate(vals, design)
        except KeyError as exc:
            raise InputError(
                f"effect '{name}' needs parameter '{exc.args[0]}' (given: "
                f"{', '.join(sorted(vals))})",
                source=cal.get("source"),
                where=where[0] if where else None,
            ) from None
        unused = sorted(set(vals) - vals.read)
        if out is not None and unused:
            raise InputError(
                f"effect '{name}' has no parameter '{unused[0]}' (it uses "
                f"{', '.join(sorted(vals.read))})",
                source=cal.get("source"),
                where=where[0] if where else None,
            )
        if out is None:
            skipped.append(f"{name}: not representable in evaluate ({lib[name].title})")
        else:
            design, how = out
            applied.append(f"{name}: {how}")
    return design, applied, skipped


def _parse_dict(cal):
    from ..units import parse_quantity

    def vals(d):
        return {k: parse_quantity(v["value"], v["kind"]) for k, v in d.items()}

    return {
        "baseline": vals(cal["baseline"]),
        "effects": [(e["name"], vals(e["parameters"])) for e in cal["effects"]],
    }


def apply_calibration(design, path):
    """Read a calibration YAML saved by ``axisopt diagnose`` and return the calibrated Design."""
    cal = _read(path)
    if cal["design"] is not None and cal["design"] != design.name:
        raise InputError(
            f"calibration is for design '{cal['design']}', not '{design.name}' (a calibration "
            "fitted on another axis does not apply; edit its 'design' key only if the axis is the "
            "same)",
            source=str(path),
            where="key 'design'",
        )
    new, _, _ = calibrate_design(design, cal)
    return replace(new, name=f"{design.name} (calibrated)")
