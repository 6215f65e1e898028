"""Strict YAML reading: line numbers for every key, unknown keys are errors, units required.

``read_yaml(path)`` returns a :class:`Node` tree.  ``Section`` wraps a mapping node and hands out
typed values (``quantity``, ``choice``, ``integer``...) while recording which keys were used;
``Section.done()`` then rejects any key left over (a typo), naming the file, line and key path.

Each kind of file declares its keys once, as :class:`Spec` tables of :class:`Key` entries (name,
type, unit kind, required, choices, one-line description).  A Section given a Spec reads a declared
key with :meth:`Section.read`, refuses to read an undeclared one (a bug, :class:`UndeclaredKey`) and
hands the nested Spec to its sub-sections; :mod:`axisopt.schema` writes the same tables out as a
JSON Schema.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

import yaml

from .errors import InputError
from .units import parse_quantity


@dataclass
class Node:
    value: Any  # dict[str, Node] | list[Node] | scalar
    line: int

    # as the user wrote it: error messages never show Node(value=..., line=...)
    def __repr__(self) -> str:
        return repr(plain(self))

    def __str__(self) -> str:
        v = plain(self)
        return v if isinstance(v, str) else repr(v)


MAX_DEPTH = 64  # nesting of mappings and lists; the deepest axisopt input nests 5 levels
MAX_VALUES = 200_000  # values after expanding aliases (a YAML "billion laughs" expands to 10^9)
MAX_BYTES = 20_000_000  # file size (fileio.INPUT_LIMITS["yaml"])


# a mapping or list without an explicit tag
_PLAIN_TAGS = ("tag:yaml.org,2002:map", "tag:yaml.org,2002:seq")


class _Loader(yaml.SafeLoader):
    # PyYAML composes recursively: bound the depth before Python does
    def compose_node(self, parent, index):
        depth = getattr(self, "_depth", 0) + 1
        if depth > MAX_DEPTH:
            raise InputError(
                f"malformed YAML: nested deeper than {MAX_DEPTH} levels",
                where=f"line {self.peek_event().start_mark.line + 1}",
            )
        self._depth = depth
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth = depth - 1


def _construct(loader, node, count=None):
    count = [0] if count is None else count
    count[0] += 1
    if count[0] > MAX_VALUES:
        raise InputError(
            f"YAML too large: more than {MAX_VALUES:,} values once its aliases are expanded",
            where=f"line {node.start_mark.line + 1}",
        )
    line = node.start_mark.line + 1
    if isinstance(node, (yaml.MappingNode, yaml.SequenceNode)) and node.tag not in _PLAIN_TAGS:
        raise InputError(
            f"YAML tag '{node.tag}' is not supported here (write a plain mapping or list)",
            where=f"line {line}",
        )
    if isinstance(node, yaml.MappingNode):
        out: dict[str, Node] = {}
        for k, v in node.value:
            key = loader.construct_object(k)
            if not isinstance(key, str):
                key = str(key)
            if key in out:
                raise InputError(f"duplicate key '{key}'", where=f"line {k.start_mark.line + 1}")
            out[key] = _construct(loader, v, count)
        return Node(out, line)
    if isinstance(node, yaml.SequenceNode):
        return Node([_construct(loader, v, count) for v in node.value], line)
    return Node(loader.construct_object(node), line)


def read_yaml(path) -> Node:
    path = Path(path)
    src = str(path)
    from .fileio import (
        read_input,  # regular files only (a FIFO or device is never opened), size cap
    )

    text = read_input(path, "yaml", what="file")
    return parse_yaml_text(text, src)


def parse_yaml_text(text: str, src: str) -> Node:
    try:
        loader = _Loader(text)
        try:
            root = loader.get_single_node()
        finally:
            loader.dispose()
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f"line {mark.line + 1}" if mark else None
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise InputError(f"malformed YAML: {problem}", source=src, where=where) from None
    except InputError as exc:
        raise InputError(exc.message, source=src, where=exc.where) from None
    except RecursionError:
        raise InputError(
            f"malformed YAML: nested deeper than {MAX_DEPTH} levels", source=src
        ) from None
    if root is None:
        raise InputError("empty YAML file", source=src)
    try:
        return _construct(_Loader(""), root)
    except InputError as exc:
        raise InputError(exc.message, source=src, where=exc.where) from None
    except yaml.YAMLError as exc:  # e.g. an unknown tag such as !!python/object
        mark = getattr(exc, "problem_mark", None)
        where = f"line {mark.line + 1}" if mark else None
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise InputError(f"malformed YAML: {problem}", source=src, where=where) from None
    except RecursionError:
        raise InputError("malformed YAML: a self-referencing alias", source=src) from None


def close_matches(word: str, options, n: int = 1) -> list:
    """difflib's close matches, skipped for long texts (its cost grows with the square of the
    length)."""
    word = str(word)
    if len(word) > 64:
        return []
    return difflib.get_close_matches(word, [str(o) for o in options if len(str(o)) <= 64], n=n)


MAX_TEXT = 10_000  # characters of any text value (names, descriptions)

# Key types: what a key's value is in the YAML file.
#   quantity  a number with its unit ('800 mm'), of units.KINDS kind ``kind``; a bare number if
#   dimensionless
#   number    a plain number (``integer``: a whole one) within [minimum, maximum]
#   choice    one of ``choices``
#   string    text
#   names     a list of names (one name alone is a list of one); ``choices``: the allowed names
#   section   a mapping, described by ``spec``
#   list      a list of ``items``
#   one_of    one of the forms in ``options`` (each a Key)
#   any       anything (informational keys the reader skips)
KEY_TYPES = ("quantity", "number", "choice", "string", "names", "section", "list", "one_of", "any")


@dataclass(frozen=True)
class Key:
    """What one YAML key accepts.  The one declaration of the key: :meth:`Section.read` reads it by
    these rules, and :mod:`axisopt.schema` writes them into the JSON Schema."""

    type: str
    doc: str = ""
    required: bool = False
    kind: str | None = None  # quantity: the units.KINDS kind
    positive: bool = False  # quantity, number
    non_negative: bool = False  # quantity
    minimum: float | None = None  # number; list: fewest items
    # number: a float (default 1e9); quantity: (SI value, text shown); list: most items
    maximum: Any = None
    integer: bool = False  # number
    choices: tuple | None = None  # choice; names: the allowed names (None: any)
    default: Any = None  # returned by Section.read when the key is absent (SI for a quantity)
    spec: Spec | None = None  # section
    items: Key | None = None  # list
    options: tuple = ()  # one_of
    example: Any = None  # a value as written in YAML, for the schema

    def __post_init__(self):
        if self.type not in KEY_TYPES:
            raise ValueError(f"unknown key type {self.type!r}")

    def specs(self) -> tuple:
        """The mapping forms this key accepts (its own spec, or its options' specs)."""
        if self.type == "section" and self.spec is not None:
            return (self.spec,)
        return tuple(s for o in self.options for s in o.specs())


@dataclass(frozen=True)
class Spec:
    """The keys of one YAML mapping.  ``extra``: the form of any other key (a mapping whose key
    names are the user's, e.g. sweep paths), ``extra_doc`` describes those names; without it other
    keys are errors."""

    name: str
    doc: str
    keys: Any = field(default_factory=dict)  # {name: Key}, kept read-only
    extra: Key | None = None
    extra_doc: str = ""
    extra_pattern: str | None = None  # a regular expression every other key name matches

    def __post_init__(self):
        object.__setattr__(self, "keys", MappingProxyType(dict(self.keys)))

    def key(self, name: str) -> Key:
        k = self.keys.get(name)
        if k is None:
            if self.extra is None:
                raise UndeclaredKey(
                    f"the reader of '{self.name}' reads key '{name}', which its Spec does not "
                    "declare: add it to the table"
                )
            return self.extra
        return k

    def merged(self, other: Spec) -> Spec:
        return Spec(self.name, self.doc, {**self.keys, **other.keys}, self.extra or other.extra)


class UndeclaredKey(LookupError):
    """A reader read a key its :class:`Spec` does not declare: a bug in axisopt, not in the
    input."""


def nested_spec(key: Key) -> Spec | None:
    """The Spec a sub-section of ``key`` is read with (the union of the mapping forms it
    accepts)."""
    specs = key.specs()
    if not specs:
        return None
    out = specs[0]
    for s in specs[1:]:
        out = out.merged(s)
    return out


class Section:
    """Typed, strict access to one YAML mapping; ``spec`` (optional) declares its keys."""

    def __init__(self, node: Node, source: str, path: str = "", spec: Spec | None = None):
        if not isinstance(node.value, dict):
            raise InputError(
                "expected a mapping of keys", source=source, where=self._loc(path, node.line)
            )
        self.node = node
        self.source = source
        self.path = path
        self.spec = spec
        self.used: set[str] = set()

    def declared(self, spec: Spec) -> Section:
        """This section, read by ``spec`` unless it already has one (a Section made without a
        Spec)."""
        if self.spec is None:
            self.spec = spec
        return self

    @staticmethod
    def _loc(path: str, line: int) -> str:
        return f"line {line}, key '{path}'" if path else f"line {line}"

    def key_path(self, key: str) -> str:
        key = (
            str(key)
            if len(str(key)) <= 60
            else str(key)[:40] + f"...({len(str(key)):,} characters)"
        )
        return f"{self.path}.{key}" if self.path else key

    def where(self, key: str) -> str:
        n = self.node.value.get(key)
        return self._loc(self.key_path(key), n.line if n else self.node.line)

    def error(self, key: str, message: str) -> InputError:
        return InputError(message, source=self.source, where=self.where(key))

    def has(self, key: str) -> bool:
        return key in self.node.value

    def keys(self):
        return list(self.node.value)

    def raw(self, key: str, default=None, *, required: bool = False):
        if self.spec is not None:
            self.spec.key(key)  # a key the table does not declare is a bug in the reader
        self.used.add(key)
        if key not in self.node.value:
            if required:
                typo = close_matches(key, [k for k in self.node.value if k not in self.used], n=1)
                if typo:
                    raise self.error(
                        typo[0], f"unknown key '{self.key_path(typo[0])}'; did you mean '{key}'?"
                    )
                raise InputError(
                    f"missing required key '{self.key_path(key)}'",
                    source=self.source,
                    where=self._loc(self.path, self.node.line) if self.path else None,
                )
            return default
        return self.node.value[key]

    def value(self, key: str, default=None, *, required: bool = False):
        n = self.raw(key, None, required=required)
        return default if n is None else plain(n)

    def quantity(
        self,
        key: str,
        kind: str,
        default=None,
        *,
        required: bool = False,
        positive: bool = False,
        non_negative: bool = False,
        maximum: tuple | None = None,
    ):
        """A quantity in SI; ``maximum`` = (SI value, text shown) bounds it from above."""
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        v = parse_quantity(plain(n), kind, source=self.source, key=self.where(key))
        if positive and not v > 0:
            raise self.error(key, f"must be positive, got '{n.value}'")
        if non_negative and v < 0:
            raise self.error(key, f"must not be negative, got '{n.value}'")
        if maximum is not None and v > maximum[0]:
            raise self.error(key, f"must be at most {maximum[1]}, got '{n.value}'")
        return v

    def number(
        self,
        key: str,
        default=None,
        *,
        required: bool = False,
        integer: bool = False,
        minimum: float | None = None,
        maximum: float | None = None,
    ):
        """A plain number: finite, within [minimum, maximum] (``maximum`` defaults to 1e9, which no
        count or factor of an axis input reaches)."""
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        v = n.value
        if (
            isinstance(v, bool)
            or not isinstance(v, (int, float))
            or (integer and not isinstance(v, int))
        ):
            shown = repr(v) if len(repr(v)) <= 60 else repr(v)[:60] + "..."
            raise self.error(key, f"expected a {'whole ' if integer else ''}number, got {shown}")
        if not math.isfinite(v):
            raise self.error(key, f"must be a finite number, got {v}")
        if minimum is not None and v < minimum:
            raise self.error(key, f"must be at least {minimum}, got {v}")
        top = 1e9 if maximum is None else maximum
        if v > top:
            raise self.error(key, f"must be at most {top:g}, got {v:g}")
        return v

    def choice(self, key: str, options, default=None, *, required: bool = False):
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        v = n.value
        if v not in options:
            near = close_matches(str(v), list(options), n=1)
            hint = f"; did you mean '{near[0]}'?" if near else ""
            shown = str(v) if len(str(v)) <= 60 else str(v)[:60] + "..."
            raise self.error(key, f"'{shown}' is not one of {', '.join(map(str, options))}{hint}")
        return v

    def string(self, key: str, default=None, *, required: bool = False):
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        if not isinstance(n.value, str):
            raise self.error(key, f"expected text, got {str(n.value)[:60]!r}")
        if len(n.value) > MAX_TEXT:
            raise self.error(
                key, f"text too long ({len(n.value):,} characters; at most {MAX_TEXT:,})"
            )
        return n.value

    def string_list(self, key: str, default=None):
        n = self.raw(key, None)
        if n is None:
            return default
        items = n.value if isinstance(n.value, list) else [n]
        out = []
        for it in items:
            if not isinstance(it.value, (str, int, float)) or isinstance(it.value, bool):
                raise self.error(key, f"expected a list of names, got {plain(n)!r}")
            out.append(str(it.value))
        return out

    def section(self, key: str, *, required: bool = False) -> Section | None:
        n = self.raw(key, None, required=required)
        if n is None:
            return None
        spec = nested_spec(self.spec.key(key)) if self.spec is not None else None
        return Section(n, self.source, self.key_path(key), spec)

    def read(self, key: str, default=None):
        """Read a declared key by its :class:`Key` (type, unit kind, required, bounds, choices);
        ``default`` (else the Key's) when it is absent."""
        k = self.spec.key(key) if self.spec is not None else None
        if k is None:
            raise UndeclaredKey(f"Section.read('{key}') needs a Spec")
        default = k.default if default is None else default
        if k.type == "quantity":
            return self.quantity(
                key,
                k.kind,
                default,
                required=k.required,
                positive=k.positive,
                non_negative=k.non_negative,
                maximum=k.maximum,
            )
        if k.type == "number":
            v = self.number(
                key,
                default,
                required=k.required,
                integer=k.integer,
                minimum=k.minimum,
                maximum=k.maximum,
            )
            if k.positive and v is not None and not v > 0:
                raise self.error(key, f"must be a positive finite number, got {v}")
            return v
        if k.type == "choice":
            return self.choice(key, k.choices, default, required=k.required)
        if k.type == "string":
            return self.string(key, default, required=k.required)
        if k.type == "names":
            return self.string_list(key, default)
        if k.type == "section":
            return self.section(key, required=k.required)
        raise TypeError(f"Section.read cannot read a '{k.type}' key ('{key}'); read it with raw()")

    def done(self) -> None:
        extra = [k for k in self.node.value if k not in self.used]
        if extra:
            k = extra[0]
            # the keys read, and those the table declares (a section whose reader asks a key only
            # when another is there: search.counterbalance beside search.drive_types)
            known = set(self.used) | (set(self.spec.keys) if self.spec is not None else set())
            near = close_matches(k, sorted(known - set(extra)), n=1)
            hint = f"; did you mean '{near[0]}'?" if near else ""
            raise self.error(k, f"unknown key '{self.key_path(k)}'{hint}")


def plain(node: Node):
    v = node.value
    if isinstance(v, dict):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, list):
        return [plain(x) for x in v]
    return v


# ------------------------------------------------------------------------------ which kind of file
# The top-level keys that tell the YAML files apart, and the command that reads each: a file given
# to the wrong command is named as what it is, with the command to use (not "unknown key 'parts'").
KIND_COMMANDS = {
    "design": "axisopt evaluate {file}",
    "problem": "axisopt solve {file}",
    "study": "axisopt study {file}",
}


def file_kind(node: Node) -> str | None:
    """'design', 'problem' or 'study' by the top-level keys of a YAML tree (None: none of them)."""
    if not isinstance(node.value, dict):
        return None
    keys = set(node.value)
    if keys & {"base", "sweep"}:
        return "study"
    if "parts" in keys:
        return "design"
    if keys & {"objective", "limits", "continuous", "search", "catalog"}:
        return "problem"
    return None


def require_kind(node: Node, src: str, wanted: str) -> Node:
    """``node`` unchanged when it can be a ``wanted`` file; else a one-line InputError naming what
    it is and the command that reads it (a CSV, e.g. measured data, given where a YAML file is read,
    too)."""
    if not isinstance(node.value, dict) and str(src).lower().endswith((".csv", ".txt", ".tsv")):
        raise InputError(
            f"a CSV file, not a {wanted} YAML: measured data go to `axisopt diagnose {src} "
            "--design DESIGN.yaml`, catalog tables to --catalogs DIR",
            source=src,
        )
    kind = file_kind(node)
    if kind is None or kind == wanted:
        return node
    return_cmd = KIND_COMMANDS[kind].format(file=src)
    raise InputError(f"a {kind} file, not a {wanted}: use `{return_cmd}`", source=src)
