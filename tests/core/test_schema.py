"""``axisopt schema``: the JSON Schemas written from the readers' key tables (yamlio.Spec).

Every shipped YAML validates against its schema; a misspelt key, a unit of the wrong kind or a value
out of range fails both the schema and the loader; the schema holds every key the readers declare
(it is their translation, not a second copy); the command's bad input is one line and exit code 2.
"""

from __future__ import annotations

import copy
import json
from pathlib import Path

import fuzz_inputs as F
import jsonschema
import pytest
import yaml

from axisopt.cli import main
from axisopt.design import AXIS_SPEC, load_design
from axisopt.errors import InputError
from axisopt.identify.calibration import apply_calibration
from axisopt.machine import load_machine
from axisopt.problem import load_problem
from axisopt.schema import KINDS_OF_FILE, json_schema, quantity_pattern, spec_of, units_of
from axisopt.study.machine import load_machine_study
from axisopt.study.spec import load_study
from axisopt.units import KINDS, parse_quantity
from axisopt.yamlio import Spec

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"
DESIGN = PROBLEMS / "teaching_design.yaml"
DATA_DESIGN = PROBLEMS / "data" / "table_x.yaml"


@pytest.fixture(scope="module")
def validators():
    out = {}
    for kind in KINDS_OF_FILE:
        schema = json_schema(kind)
        jsonschema.Draft202012Validator.check_schema(schema)
        out[kind] = jsonschema.Draft202012Validator(schema)
    return out


def schema_errors(validator, data) -> list:
    return [
        f"{'.'.join(map(str, e.absolute_path))}: {e.message[:200]}"
        for e in validator.iter_errors(data)
    ]


def _kind_of(path: Path) -> str:
    """The kind of a shipped YAML by its name; the test then loads it with that kind's loader."""
    name = path.name
    if path.parent.name == "studies":
        return "study"
    if path.parent.name == "machines":
        return "machine-study" if name.endswith("_study.yaml") else "machine"
    if "design" in name or name.startswith("paper_") or "data" in path.parent.parts:
        return "design"
    if "problem" in name:
        return "problem"
    raise AssertionError(f"cannot tell the kind of {path}")


LOADERS = {
    "design": load_design,
    "problem": load_problem,
    "study": load_study,
    "machine": load_machine,
    "machine-study": load_machine_study,
}
SHIPPED = sorted(p for p in PROBLEMS.rglob("*.yaml"))


def test_the_shipped_yamls_are_the_expected_ones():
    kinds = [_kind_of(p) for p in SHIPPED]
    assert kinds.count("design") >= 7 and kinds.count("problem") >= 8 and kinds.count("study") >= 5


@pytest.mark.parametrize("path", SHIPPED, ids=[str(p.relative_to(PROBLEMS)) for p in SHIPPED])
def test_every_shipped_yaml_validates_against_its_schema(path, validators):
    kind = _kind_of(path)
    LOADERS[kind](path)  # the project's own loader reads it as that kind
    data = yaml.safe_load(path.read_text(encoding="utf-8"))
    assert schema_errors(validators[kind], data) == []


def _calibrations(tmp_path) -> list:
    saved = tmp_path / "saved.yaml"
    assert (
        main(
            [
                "diagnose",
                str(PROBLEMS / "data" / "table_x_stiffness.csv"),
                "--design",
                str(DATA_DESIGN),
                "--save-calibration",
                str(saved),
            ]
        )
        == 0
    )
    rich = tmp_path / "rich.yaml"
    rich.write_text(F.RICH_CALIBRATION, encoding="utf-8")
    return [saved, rich]


def test_calibrations_validate_against_their_schema(tmp_path, validators, capsys):
    design = load_design(DATA_DESIGN)
    for path in _calibrations(tmp_path):
        apply_calibration(design, path)
        assert schema_errors(validators["calibration"], yaml.safe_load(path.read_text())) == []


# --------------------------------------------------------------------- schema and loader reject the
# same input


def _set(tree: dict, path: tuple, value) -> dict:
    tree = copy.deepcopy(tree)
    node = tree
    for p in path[:-1]:
        node = node[p] if isinstance(node, list) else node.setdefault(p, {})
    node[path[-1]] = value
    return tree


def _rename(tree: dict, path: tuple, new: str) -> dict:
    tree = copy.deepcopy(tree)
    node = tree
    for p in path[:-1]:
        node = node[p]
    node[new] = node.pop(path[-1])
    return tree


def _write(tmp_path, tree, name="bad.yaml") -> Path:
    p = tmp_path / name
    p.write_text(yaml.safe_dump(tree, sort_keys=False), encoding="utf-8")
    return p


def _both_reject(tmp_path, validators, kind, tree, loader=None):
    errs = schema_errors(validators[kind], tree)
    assert errs, "the schema accepts it"
    p = _write(tmp_path, tree)
    if loader is None:
        with pytest.raises(InputError):
            LOADERS[kind](p)
    else:
        loader(p)
    return errs


DESIGN_TREE = yaml.safe_load(DESIGN.read_text())


@pytest.mark.parametrize(
    "path, value",
    [
        (("axis", "stroke"), "800 kg"),  # a unit of the wrong kind
        (("axis", "max_speed"), "30 N"),
        (("axis", "axial_load"), "-5 N"),  # negative
        (("axis", "max_speed"), "0 m/min"),  # must be positive
        (("axis", "guide_blocks"), 100),  # out of range (1..64)
        (("axis", "positions"), 2),  # out of range (3..2001)
        (("axis", "reduction_efficiency"), 1.5),
        (("axis", "brake_safety"), 0.5),
        (("axis", "mounting"), "fixed-flee"),  # not a choice
        (("axis", "orientation"), "diagonal"),
        (("axis", "stroke"), 800),  # no unit
        (("parts", "screw"), ["a", "list"]),
        (("name",), 42),
    ],
)
def test_bad_value_fails_schema_and_evaluate(tmp_path, validators, capsys, path, value):
    tree = _set(DESIGN_TREE, path, value)
    assert schema_errors(validators["design"], tree)
    p = _write(tmp_path, tree)
    assert main(["evaluate", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert err and "\n" not in err, err


@pytest.mark.parametrize(
    "path, new",
    [
        (("axis", "stroke"), "strok"),
        (("axis", "moving_mass"), "movingmass"),
        (("parts", "guide"), "guides"),
        (("name",), "nmae"),
    ],
)
def test_misspelt_key_fails_schema_and_evaluate(tmp_path, validators, capsys, path, new):
    tree = _rename(DESIGN_TREE, path, new)
    assert schema_errors(validators["design"], tree)
    assert main(["evaluate", str(_write(tmp_path, tree))]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and ("unknown key" in err or "missing required key" in err), err


def _wrong_unit(kind: str) -> str:
    return "800 mm" if kind != "length" else "800 kg"


@pytest.mark.parametrize("name", sorted(AXIS_SPEC.keys))
def test_every_axis_key_agrees(tmp_path, validators, name):
    """Per declared axis key: a misspelling, and for quantities a wrong unit kind and a sign out of
    range, are refused by the schema and by load_design alike; for numbers a value above the
    maximum."""
    key = AXIS_SPEC.keys[name]
    _both_reject(tmp_path, validators, "design", _set(DESIGN_TREE, ("axis", name + "_x"), "1 mm"))
    if key.type == "quantity":
        _both_reject(
            tmp_path, validators, "design", _set(DESIGN_TREE, ("axis", name), _wrong_unit(key.kind))
        )
        if key.positive or key.non_negative:
            unit = "mm" if key.kind == "length" else units_of(key.kind)[0]
            bad = f"{'0' if key.positive else '-1'} {unit}"
            _both_reject(tmp_path, validators, "design", _set(DESIGN_TREE, ("axis", name), bad))
    if key.type == "number":
        top = 1e9 if key.maximum is None else key.maximum
        _both_reject(tmp_path, validators, "design", _set(DESIGN_TREE, ("axis", name), top * 2 + 1))
        _both_reject(tmp_path, validators, "design", _set(DESIGN_TREE, ("axis", name), "two"))


def _mappings(tree, path=()):
    if isinstance(tree, dict):
        yield path
        for k, v in tree.items():
            yield from _mappings(v, path + (k,))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from _mappings(v, path + (i,))


@pytest.mark.parametrize(
    "kind, path",
    [
        ("design", DESIGN),
        ("design", PROBLEMS / "custom_parts_design.yaml"),
        ("design", PROBLEMS / "vmc_x_design.yaml"),
        ("problem", PROBLEMS / "teaching_problem.yaml"),
        ("problem", PROBLEMS / "duty_cycle_problem.yaml"),
        ("problem", PROBLEMS / "gantry_problem.yaml"),
    ],
)
def test_an_unknown_key_anywhere_fails_both(tmp_path, validators, kind, path):
    """Every mapping of the file refuses a key its table does not declare, in the schema and the
    loader."""
    tree = yaml.safe_load(path.read_text())
    seen = 0
    for where in _mappings(tree):
        if where[:1] == ("objective",) and where[1:2] in (("weights",), ("scale",)):
            # keys named by the weights: the schema lists both, the loader needs a weight's scale
            continue
        bad = _set(tree, where + ("bogus_key",), "1 mm") if where else {**tree, "bogus_key": "1 mm"}
        _both_reject(tmp_path, validators, kind, bad)
        seen += 1
    assert seen >= 3


PROBLEM_TREE = yaml.safe_load((PROBLEMS / "teaching_problem.yaml").read_text())


@pytest.mark.parametrize(
    "path, value",
    [
        (("limits", "max_cost"), "4000 kg"),
        (("limits", "min_stiffness"), "0 N/um"),
        (("limits", "margins", "buckling"), -1),
        (("limits", "margins", "bucklin"), 2),
        (("catalog", "mountings"), ["fixed-flee"]),
        (("catalog", "mountings"), []),
        (("catalog", "status"), ["bought"]),
        (("objective",), {"mode": "pareto", "pareto": ["stiffness", "speed"]}),
        (("objective",), {"mode": "sideways"}),
        (("continuous", "nut_preload", "max"), "5 kN.m"),
    ],
)
def test_bad_problem_fails_schema_and_loader(tmp_path, validators, path, value):
    _both_reject(tmp_path, validators, "problem", _set(PROBLEM_TREE, path, value))


STUDY_TREE = {
    "base": str(PROBLEMS / "teaching_problem.yaml"),
    "sweep": {
        "axis.stroke": ["300 mm", "400 mm"],
        "limits.max_cost": {"from": "2000 EUR", "to": "3000 EUR", "steps": 2},
    },
}


def test_a_small_study_validates(tmp_path, validators):
    p = _write(tmp_path, STUDY_TREE)
    assert len(load_study(p).cases) == 4
    assert schema_errors(validators["study"], STUDY_TREE) == []


@pytest.mark.parametrize(
    "path, value",
    [
        (("method",), "fastest"),
        (("combine",), "zipper"),
        (("sweep", "limits.max_cost", "steps"), 0),
        (("sweep", "limits.max_cost", "spacing"), "cubic"),
        (("sweep", "axis.stroke"), []),
        (
            ("sweep", "axis.stroke"),
            {"random": {"low": "300 mm", "high": "400 mm", "n": 3}},
        ),  # no seed
        (("sweep", "axis..stroke"), [1]),
        (("swep",), {}),
    ],
)
def test_bad_study_fails_schema_and_loader(tmp_path, validators, path, value):
    _both_reject(tmp_path, validators, "study", _set(STUDY_TREE, path, value))


CAL_TREE = yaml.safe_load(F.RICH_CALIBRATION)


@pytest.mark.parametrize(
    "path, value",
    [
        (("baseline", "screw_modulos"), {"value": "200 GPa", "kind": "pressure"}),
        (("baseline", "screw_modulus", "kind"), "force"),
        (("baseline", "screw_modulus", "value"), "-200 GPa"),
        (("baseline", "screw_modulus", "value"), "200 mm"),
        (("effects", 0, "name"), "support_conditon"),
        (("effects", 0, "parameters", "far_end_stiffness", "kind"), "stifness"),
        (("axisopt_calibration",), 2),
        (("verdikt",), "x"),
    ],
)
def test_bad_calibration_fails_schema_and_loader(tmp_path, validators, path, value):
    tree = _set(CAL_TREE, path, value)
    if path[-1] == "screw_modulos":
        tree["baseline"].pop("screw_modulus")
    errs = schema_errors(validators["calibration"], tree)
    assert errs
    with pytest.raises(InputError):
        apply_calibration(load_design(DATA_DESIGN), _write(tmp_path, tree))


# ------------------------------------------------------------------------------------ one source of
# the rules


def _resolve(schema: dict, node: dict) -> dict:
    while "$ref" in node:
        node = schema["$defs"][node["$ref"].rsplit("/", 1)[1]]
    return node


def _objects(schema, node):
    """The object schemas a key's schema allows (through $ref and anyOf)."""
    node = _resolve(schema, node)
    if node.get("type") == "object":
        yield node
    for sub in node.get("anyOf", ()):
        yield from _objects(schema, sub)


def _walk(spec: Spec, schema: dict, node: dict, path: str, seen: set) -> int:
    assert set(node["properties"]) == set(spec.keys), path
    assert set(node.get("required", ())) == {n for n, k in spec.keys.items() if k.required}, path
    assert (node.get("additionalProperties") is False) == (
        spec.extra is None or spec.extra_pattern is not None
    )
    n = len(spec.keys)
    if (id(spec), id(node)) in seen:
        return n
    seen.add((id(spec), id(node)))
    for name, key in spec.keys.items():
        specs = key.specs() or (key.items.specs() if key.items is not None else ())
        if not specs:
            continue
        objs = list(_objects(schema, node["properties"][name]))
        if not objs and node["properties"][name].get("type") == "array":
            objs = list(_objects(schema, node["properties"][name]["items"]))
        assert len(objs) == len(specs), f"{path}.{name}"
        for sub_spec, sub_node in zip(specs, objs):
            n += _walk(sub_spec, schema, sub_node, f"{path}.{name}", seen)
    return n


@pytest.mark.parametrize("kind", KINDS_OF_FILE)
def test_the_schema_holds_every_declared_key(kind):
    """Walk the Spec tree and the schema together: the same keys, the same required ones,
    everywhere."""
    schema = json_schema(kind)
    assert _walk(spec_of(kind), schema, schema, kind, set()) > 5


def test_every_quantity_kind_has_units_the_loader_accepts():
    for kind in KINDS:
        units = units_of(kind)
        if kind != "dimensionless":
            assert units, kind
        for u in units:
            parse_quantity(f"1 {u}", kind)
    import re

    assert re.search(quantity_pattern("length"), "800 mm") and not re.search(
        quantity_pattern("length"), "800 kg"
    )
    assert re.search(quantity_pattern("dimensionless"), "0.5")


def test_the_schema_is_json_and_describes_each_key():
    text = json.dumps(json_schema("design"))
    d = json.loads(text)
    stroke = (
        d["$defs"]["axis"]["properties"]["stroke"]
        if "axis" in d["$defs"]
        else d["properties"]["axis"]["properties"]["stroke"]
    )
    assert "length" in stroke["description"] and "e.g." in stroke["description"]


def test_schema_ids_are_urns_and_a_wrong_unit_reads_well(validators):
    """Issue 30 item 6: no example domain as $id; an editor shows the quantity's patternErrorMessage
    (kind, example, units) in place of the 200-character regular expression."""
    for kind in KINDS_OF_FILE:
        assert json_schema(kind)["$id"] == f"urn:axisopt:schema:{kind}"
    data = yaml.safe_load(DESIGN.read_text(encoding="utf-8"))
    data["axis"]["stroke"] = "800 kg"
    data["axis"]["moving_mass"] = "-60 kg"
    errors = {
        ".".join(map(str, e.absolute_path)): e for e in validators["design"].iter_errors(data)
    }
    assert set(errors) == {"axis.stroke", "axis.moving_mass"}
    shown = {k: e.schema["patternErrorMessage"] for k, e in errors.items()}
    assert shown["axis.stroke"].startswith(
        "expected a number and a unit of length, e.g. 800 mm (units: m, mm,"
    )
    assert shown["axis.moving_mass"] == "mass must be positive, e.g. 300 kg"
    assert all(len(m) < 120 and "\\s" not in m for m in shown.values())
    with pytest.raises(InputError, match="stroke"):  # the loader refuses the same value
        parse_quantity("800 kg", "length", source="d.yaml", key="axis.stroke")
