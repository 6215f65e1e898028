"""Study files: a base problem plus sweeps over any of its fields, expanded into cases.

.. code-block:: yaml

    name: vmc-stroke
    description: free text
    base: ../vmc_x_problem.yaml        # a problem YAML (relative to this file), or an inline problem mapping
    method: default                    # solve method for every case (default | exhaustive | bonmin)
    combine: product                   # product (every combination, default) | zip (n-th value of each key)
    sweep:                             # dotted paths into the problem YAML
      axis.stroke: [600 mm, 800 mm, 1000 mm]                     # a list of values
      limits.max_cost: {from: 3000 EUR, to: 6000 EUR, steps: 4}  # an evenly spaced grid (same unit)
      catalog.mountings: [[fixed-supported], [fixed-fixed]]      # values may be lists
      axis.moving_mass: {random: {low: 300 kg, high: 700 kg, n: 20, seed: 1}}   # seeded uniform samples
      catalog.guide_preload: {random: {choice: [[medium], [heavy]], n: 20, seed: 2}}
      axis.acceleration: 4 m/s^2                                  # a single value: set for every case

Every case is the base YAML tree with the swept values written in, read by the same
:func:`axisopt.problem.read_problem` as ``axisopt solve`` uses, so its validation is identical.
Each distinct list value (and each range's ends) is checked against the base when the study is
read: a typo in a key or a bad value is a one-line :class:`InputError` naming the study key.
Combinations that only fail together (e.g. a preload min above a swept max) become failed cases.
"""  # noqa: E501

from __future__ import annotations

import copy
import math
import re
from dataclasses import replace
from pathlib import Path

import numpy as np

from ..design import DESCRIPTION_KEY, NAME_KEY
from ..errors import InputError
from ..problem import PROBLEM_SPEC
from ..yamlio import Key, Section, Spec, plain, read_yaml, require_kind
from .cases import (
    Study,
    Sweep,
    check_base,
    expand,
    unique_values,
)

METHODS = ("default", "exhaustive", "bonmin")
COMBINE = ("product", "zip")
_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


# ------------------------------------------------------------------------------ the YAML keys (one
# table) The one declaration of a study file's keys: load_study reads them by it and
# `axisopt schema study` writes it out.  A sweep's keys are the user's (dotted paths into the
# problem); their values are checked against the base problem when the study is read, which no table
# can say.

MAX_VALUES = 100_000  # values of one sweep (random n, grid steps)
SWEEP_KEY = r"[A-Za-z_][A-Za-z0-9_-]*(\.[A-Za-z_][A-Za-z0-9_-]*)*"

_END = Key(
    "quantity",
    "a number with the swept key's unit (the same unit at both ends)",
    required=True,
    example="500 mm",
)
_N = Key("number", "number of samples", required=True, integer=True, minimum=1, maximum=MAX_VALUES)
_SEED = Key(
    "number",
    "seed of the random generator",
    required=True,
    integer=True,
    minimum=0,
    maximum=2**63 - 1,
)
RANDOM_RANGE_SPEC = Spec(
    "random_range",
    "seeded uniform samples between low and high",
    {
        "low": _END,
        "high": _END,
        "n": _N,
        "seed": _SEED,
        "integer": Key(
            "choice", "round the samples to whole numbers", choices=(True, False), default=False
        ),
    },
)
RANDOM_CHOICE_SPEC = Spec(
    "random_choice",
    "seeded random picks from a list of values",
    {
        "choice": Key(
            "list",
            "the values to pick from",
            required=True,
            minimum=1,
            items=Key("any", "a value of the swept key"),
        ),
        "n": _N,
        "seed": _SEED,
    },
)
RANDOM_SWEEP_SPEC = Spec(
    "random_sweep",
    "seeded random values",
    {
        "random": Key(
            "one_of",
            "samples of a range, or picks from a list",
            required=True,
            options=(
                Key("section", spec=RANDOM_RANGE_SPEC),
                Key("section", spec=RANDOM_CHOICE_SPEC),
            ),
        ),
    },
)
RANGE_SPEC = Spec(
    "range",
    "an evenly spaced grid from..to",
    {
        "from": _END,
        "to": _END,
        "steps": Key(
            "number",
            "number of grid values",
            required=True,
            integer=True,
            minimum=1,
            maximum=MAX_VALUES,
        ),
        "spacing": Key(
            "choice", "linear, or log (even ratios)", choices=("linear", "log"), default="linear"
        ),
    },
)
SWEEP_SPEC = Spec(
    "sweep",
    "the swept keys: dotted paths into the problem (e.g. axis.stroke)",
    {},
    extra=Key(
        "one_of",
        "the values of a swept key",
        options=(
            Key(
                "list", "a list of values", minimum=1, items=Key("any", "a value of the swept key")
            ),
            Key("section", spec=RANGE_SPEC),
            Key("section", spec=RANDOM_SWEEP_SPEC),
            Key(
                "one_of",
                "one value, set for every case",
                options=(Key("string"), Key("number"), Key("choice", choices=(True, False))),
            ),
        ),
    ),
    extra_doc="a dotted path into the problem YAML, e.g. axis.stroke or limits.max_cost",
    extra_pattern=f"^{SWEEP_KEY}$",
)
STUDY_SPEC = Spec(
    "study",
    "a study: a base problem and sweeps over its keys, expanded into cases",
    {
        "name": NAME_KEY,
        "description": DESCRIPTION_KEY,
        "base": Key(
            "one_of",
            "the base problem",
            required=True,
            options=(
                Key("string", "path of a problem YAML, relative to this file"),
                Key("section", "an inline problem", spec=PROBLEM_SPEC),
            ),
        ),
        "method": Key("choice", "solve method for every case", choices=METHODS, default="default"),
        "combine": Key(
            "choice",
            "product: every combination; zip: the n-th value of each key",
            choices=COMBINE,
            default="product",
        ),
        "sweep": Key("section", "the swept keys", required=True, spec=SWEEP_SPEC),
    },
)


def load_study(path) -> Study:
    """Read a study YAML into a :class:`Study` with its expanded cases (InputError naming the
    key)."""
    path = Path(path)
    src = str(path)
    root = Section(require_kind(read_yaml(path), src, "study"), src, spec=STUDY_SPEC)
    name = root.read("name", path.stem)
    description = root.read("description", "") or ""
    method = root.read("method")
    combine = root.read("combine")
    base_node = root.raw("base", required=True)
    if isinstance(base_node.value, str):
        bpath = path.parent / base_node.value
        if not bpath.is_file():
            raise root.error(
                "base", f"base problem '{base_node.value}' not found (relative to the study file)"
            )
        base = read_yaml(bpath)
        base_source, base_dir = str(bpath), str(bpath.parent)
    elif isinstance(base_node.value, dict):
        base, base_source, base_dir = base_node, src, str(path.parent)
    else:
        raise root.error("base", "expected the path of a problem YAML or an inline problem mapping")
    sweep_sec = root.read("sweep")
    sweeps = tuple(read_sweep(sweep_sec, k) for k in sweep_sec.keys())
    if not sweeps:
        raise root.error("sweep", "list at least one key to sweep")
    root.done()
    study = Study(
        name=name,
        description=description,
        source=src,
        base=base,
        base_source=base_source,
        base_dir=base_dir,
        method=method,
        combine=combine,
        sweeps=sweeps,
    )
    cases = expand(study, sweep_sec)  # checks zip lengths
    check_base(study, root)
    return replace(study, cases=cases)


# ------------------------------------------------------------------------------------------ sweeps


def read_sweep(sec: Section, key: str) -> Sweep:
    node = sec.raw(key)
    where = sec.where(key)
    if not re.fullmatch(SWEEP_KEY, key):
        raise sec.error(
            key, f"sweep key '{key}' must be a dotted path into the problem, e.g. axis.stroke"
        )
    v = node.value
    if isinstance(v, list):
        values = tuple(plain(n) for n in v)
        if not values:
            raise sec.error(key, "empty list of values")
        return Sweep(key, values, "list", node.line, tuple(unique_values(values)))
    if isinstance(v, dict) and "random" in v:
        sub = Section(node, sec.source, sec.key_path(key), RANDOM_SWEEP_SPEC)
        rs = sub.section("random", required=True)
        sub.done()
        n = int(rs.read("n"))
        seed = rs.read("seed")
        rng = np.random.default_rng(int(seed))
        if rs.has("choice"):
            choices = rs.value("choice")
            if not isinstance(choices, list) or not choices:
                raise rs.error("choice", "expected a non-empty list of values")
            idx = rng.integers(0, len(choices), n)
            rs.done()
            return Sweep(
                key,
                tuple(copy.deepcopy(choices[i]) for i in idx),
                "random",
                node.line,
                tuple(unique_values(choices)),
            )
        lo, hi, unit = _pair(rs, "low", "high")
        integer = rs.value("integer", False)
        if not isinstance(integer, bool):
            raise rs.error("integer", f"expected true or false, got {integer!r}")
        rs.done()
        draws = rng.uniform(lo, hi, n)
        if integer:
            draws = np.round(draws)
        vals = tuple(_fmt(x, unit, integer) for x in draws)
        return Sweep(
            key, vals, "random", node.line, (_fmt(lo, unit, integer), _fmt(hi, unit, integer))
        )
    if isinstance(v, dict) and ("from" in v or "to" in v or "steps" in v):
        rs = Section(node, sec.source, sec.key_path(key), RANGE_SPEC)
        lo, hi, unit = _pair(rs, "from", "to")
        steps = int(rs.read("steps"))
        spacing = rs.read("spacing")
        rs.done()
        if spacing == "log":
            if lo <= 0 or hi <= 0:
                raise rs.error("spacing", "log spacing needs positive from and to")
            grid = np.geomspace(lo, hi, steps)
        else:
            grid = np.linspace(lo, hi, steps)
        vals = tuple(_fmt(x, unit, False) for x in grid)
        return Sweep(key, vals, "range", node.line, (vals[0], vals[-1]))
    if isinstance(v, dict):
        raise InputError(
            "expected a list of values, {from, to, steps}, {random: {...}} or one value",
            source=sec.source,
            where=where,
        )
    return Sweep(key, (v,), "fixed", node.line, (v,))


def _pair(sec: Section, a: str, b: str):
    na, nb = sec.raw(a, required=True), sec.raw(b, required=True)
    xa, ua = _split(na.value, sec, a)
    xb, ub = _split(nb.value, sec, b)
    if ua != ub:
        raise sec.error(b, f"'{a}' and '{b}' must use the same unit ('{ua}' vs '{ub}')")
    if xb < xa:
        raise sec.error(b, f"'{b}' ({nb.value}) is below '{a}' ({na.value})")
    return xa, xb, ua


def _split(v, sec: Section, key: str):
    if isinstance(v, bool):
        raise sec.error(key, f"expected a number with a unit, got {v!r}")
    if isinstance(v, (int, float)):
        x, unit = float(v), ""
    else:
        m = _QTY.match(str(v)) if len(str(v)) <= 200 else None
        if not m:
            raise sec.error(key, f"cannot read '{str(v)[:60]}' as a number with a unit")
        x, unit = float(m.group(1)), m.group(2)
    if not math.isfinite(x) or abs(x) > 1e15:
        raise sec.error(key, f"'{v}' is not a finite number of sensible size")
    return x, unit


def _fmt(x: float, unit: str, integer: bool):
    num = int(round(float(x))) if integer else float(f"{float(x):.6g}")
    return num if not unit else f"{num:.6g} {unit}"


# ------------------------------------------------------------------------------------------- cases


__all__ = ["STUDY_SPEC", "load_study", "read_sweep"]
