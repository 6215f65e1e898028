"""A study expanded into its cases: the sweeps' rows (product or zip), each case's overrides applied
to the base problem's YAML tree, the problem built from it, and the base problem checked before any
case runs (the error naming the sweep that caused it); and the data they are: :class:`Study`,
:class:`Sweep`, :class:`Case`."""

from __future__ import annotations

import copy
import hashlib
import itertools
import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

from ..design import catalog_for
from ..errors import InputError
from ..problem import read_problem
from ..yamlio import Node, Section, plain


@dataclass(frozen=True)
class Sweep:
    """One swept key: its dotted path, the values (as YAML would hold them) and how they were
    made."""

    key: str
    values: tuple
    kind: str  # 'list' | 'range' | 'random' | 'fixed'
    line: int = 0
    checked: tuple = ()  # the values validated against the base problem when the study is read


@dataclass(frozen=True)
class Case:
    """One solve: the case id, its position in the study and the values it writes into the base."""

    case_id: str
    index: int
    overrides: tuple  # ((dotted key, plain value), ...)

    def inputs(self) -> dict:
        return dict(self.overrides)


@dataclass(frozen=True)
class Study:
    name: str
    description: str
    source: str
    base: Node = field(repr=False)  # the base problem's YAML tree
    base_source: str = ""  # file the base tree came from (for error messages)
    base_dir: str = "."  # directory that relative catalog paths in the base refer to
    method: str = "default"
    combine: str = "product"
    sweeps: tuple = ()
    cases: tuple = ()
    # [s] of each case's solve (the command's --time-limit; not in the fingerprint)
    time_limit: float = 100.0

    @property
    def keys(self) -> tuple:
        return tuple(s.key for s in self.sweeps)

    def fingerprint(self) -> str:
        return _digest({"base": plain(self.base), "method": self.method})

    def context(self) -> dict:
        """What a worker needs besides the cases: small, picklable, no catalog or solver objects."""
        return {
            "base": self.base,
            "base_source": self.base_source,
            "base_dir": self.base_dir,
            "method": self.method,
            "name": self.name,
            "time_limit": self.time_limit,
        }


MAX_CASES = 1_000_000  # cases of one study


def unique_values(values):
    seen, out = set(), []
    for v in values:
        k = json.dumps(v, sort_keys=True, default=str)
        if k not in seen:
            seen.add(k)
            out.append(v)
    return out


def _digest(obj) -> str:
    return hashlib.sha1(json.dumps(obj, sort_keys=True, default=str).encode()).hexdigest()


def expand(study: Study, sweep_sec: Section | None = None) -> tuple:
    """The study's cases in order; ids combine the position with a hash of the base and the inputs,
    so a changed study never reuses a stale result and identical inputs at two positions stay
    apart."""
    rows = _rows(study, sweep_sec)
    base = study.fingerprint()
    width = max(4, len(str(len(rows) - 1)))
    out = []
    for i, row in enumerate(rows):
        ov = tuple((s.key, v) for s, v in zip(study.sweeps, row))
        h = _digest({"base": base, "inputs": [list(x) for x in ov]})[:10]
        out.append(Case(f"{i:0{width}d}-{h}", i, ov))
    return tuple(out)


def _rows(study: Study, sweep_sec: Section | None = None) -> list:
    sweeps = study.sweeps
    if study.combine == "product":
        total = math.prod(len(s.values) for s in sweeps)
        if total > MAX_CASES:
            raise InputError(
                f"the sweep makes {total:,} cases (at most {MAX_CASES:,}); split the study",
                source=study.source,
                where="key 'sweep'",
            )
        return list(itertools.product(*(s.values for s in sweeps)))
    lengths = {s.key: len(s.values) for s in sweeps if s.kind != "fixed"}
    n = max(lengths.values(), default=1)
    for k, m in lengths.items():
        if m != n:
            raise InputError(
                f"combine: zip needs the same number of values for every key; "
                f"'{k}' has {m}, another has {n}",
                source=study.source,
                where=sweep_sec.where(k) if sweep_sec else None,
            )
    return [
        tuple(s.values[0] if s.kind == "fixed" else s.values[i] for s in sweeps) for i in range(n)
    ]


def apply_overrides(base: Node, overrides, line: int = 0) -> Node:
    """A copy of the base YAML tree with each dotted key set to its value (missing mappings
    created)."""
    tree = copy.deepcopy(base)
    for key, value in overrides:
        parts = key.split(".")
        node = tree
        for j, p in enumerate(parts[:-1]):
            if not isinstance(node.value, dict):
                raise InputError(
                    f"cannot set '{key}': '{'.'.join(parts[:j])}' is not a mapping in the base "
                    f"problem; sweep '{'.'.join(parts[:j])}' itself instead"
                )
            nxt = node.value.get(p)
            if nxt is None:
                nxt = Node({}, line)
                node.value[p] = nxt
            node = nxt
        if not isinstance(node.value, dict):
            where = ".".join(parts[:-1])
            raise InputError(
                f"cannot set '{key}': '{where}' is a single value in the base problem, not a "
                f"mapping; sweep '{where}' itself instead"
            )
        node.value[parts[-1]] = _to_node(value, line)
    return tree


def _to_node(v, line: int) -> Node:
    if isinstance(v, dict):
        return Node({str(k): _to_node(x, line) for k, x in v.items()}, line)
    if isinstance(v, list):
        return Node([_to_node(x, line) for x in v], line)
    return Node(v, line)


def build_problem(context: dict, case: Case):
    """The case's :class:`~axisopt.problem.Problem` (InputError if the combination is invalid)."""
    tree = apply_overrides(context["base"], case.overrides)
    root = Section(tree, context["base_source"])
    catalog = catalog_for(root, Path(context["base_dir"]))  # cached per process
    return read_problem(root, catalog, name=f"{context['name']}[{case.case_id}]")


def check_base(study: Study, root: Section) -> None:
    """Read the base alone, then each distinct swept value against it, so that a typo or a bad value
    is reported at once, naming the study key, instead of failing every case."""
    ctx = study.context()
    try:
        build_problem(ctx, Case("base", -1, ()))
    except InputError as exc:
        raise InputError(
            f"base problem: {exc}", source=study.source, where=root.where("base")
        ) from None
    # every key with its first value, then each further distinct value on its own; with zip, the
    # cases where a listed value first appears (the user paired those values explicitly)
    first = tuple((s.key, s.checked[0]) for s in study.sweeps)
    trials = [(None, first)]
    if study.combine == "zip":
        rows = _rows(study)
        seen: set = set()
        for row in rows:
            for s, v in zip(study.sweeps, row):
                k = (s.key, json.dumps(v, sort_keys=True, default=str))
                if s.kind == "list" and k not in seen:
                    seen.add(k)
                    trials.append((s, tuple((x.key, y) for x, y in zip(study.sweeps, row))))
        first = tuple((x.key, y) for x, y in zip(study.sweeps, rows[0]))
    for i, s in enumerate(study.sweeps):
        if study.combine == "zip" and s.kind == "list":
            continue
        for v in s.checked[1:] if study.combine != "zip" else s.checked:
            trials.append((s, first[:i] + ((s.key, v),) + first[i + 1 :]))
    for s, ov in trials:
        try:
            build_problem(ctx, Case("check", -1, ov))
        except InputError as exc:
            culprit = _culprit(ctx, [s] if s is not None else study.sweeps, ov)
            # each value is valid on its own: only the combination is invalid, which
            if culprit is None:
                # is that case's result (recorded as input_error), not a fault of the study file
                continue
            value = dict(ov)[culprit.key]
            raise InputError(
                f"sweep '{culprit.key}' value {json.dumps(value, default=str)}: "
                f"{short_message(exc)}",
                source=study.source,
                where=f"line {culprit.line}",
            ) from None


def _culprit(ctx, sweeps, overrides) -> Sweep | None:
    """The first of ``sweeps`` whose value in ``overrides`` fails on its own against the base, or
    None when every one is valid alone (the combination is what is invalid)."""
    values = dict(overrides)
    for s in sweeps:
        try:
            build_problem(ctx, Case("check", -1, ((s.key, values[s.key]),)))
        except InputError:
            return s
    return None


def short_message(exc: InputError) -> str:
    """The message without the base file name and the made-up location of a swept value."""
    msg = str(exc)
    if exc.source and msg.startswith(exc.source + ": "):
        msg = msg[len(exc.source) + 2 :]
    return re.sub(r"^line 0, (key '[^']*'): ", r"\1: ", msg)
