"""Strict YAML reading: line numbers for every key, unknown keys are errors, units required.

``read_yaml(path)`` returns a :class:`Node` tree.  ``Section`` wraps a mapping node and hands out
typed values (``quantity``, ``choice``, ``integer``...) while recording which keys were used;
``Section.done()`` then rejects any key left over (a typo), naming the file, line and key path.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from .errors import InputError
from .units import parse_quantity


@dataclass
class Node:
    value: Any  # dict[str, Node] | list[Node] | scalar
    line: int


class _Loader(yaml.SafeLoader):
    pass


def _construct(loader, node):
    line = node.start_mark.line + 1
    if isinstance(node, yaml.MappingNode):
        out: dict[str, Node] = {}
        for k, v in node.value:
            key = loader.construct_object(k)
            if not isinstance(key, str):
                key = str(key)
            if key in out:
                raise InputError(f"duplicate key '{key}'", where=f"line {k.start_mark.line + 1}")
            out[key] = _construct(loader, v)
        return Node(out, line)
    if isinstance(node, yaml.SequenceNode):
        return Node([_construct(loader, v) for v in node.value], line)
    return Node(loader.construct_object(node), line)


def read_yaml(path) -> Node:
    path = Path(path)
    src = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        why = getattr(exc, "strerror", None) or exc  # a decoding error has no strerror
        raise InputError(f"cannot read file ({exc.__class__.__name__}: {why})", source=src) from None
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
        raise InputError(str(exc), source=src) from None
    if root is None:
        raise InputError("empty YAML file", source=src)
    try:
        return _construct(_Loader(""), root)
    except InputError as exc:
        raise InputError(str(exc).split(": ", 1)[-1], source=src, where=exc.where) from None
    except yaml.YAMLError as exc:  # e.g. an unknown tag such as !!python/object
        mark = getattr(exc, "problem_mark", None)
        where = f"line {mark.line + 1}" if mark else None
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise InputError(f"malformed YAML: {problem}", source=src, where=where) from None
    except RecursionError:
        raise InputError("malformed YAML: a self-referencing alias", source=src) from None


class Section:
    """Typed, strict access to one YAML mapping."""

    def __init__(self, node: Node, source: str, path: str = ""):
        if not isinstance(node.value, dict):
            raise InputError("expected a mapping of keys", source=source, where=self._loc(path, node.line))
        self.node = node
        self.source = source
        self.path = path
        self.used: set[str] = set()

    @staticmethod
    def _loc(path: str, line: int) -> str:
        return f"line {line}, key '{path}'" if path else f"line {line}"

    def key_path(self, key: str) -> str:
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
        self.used.add(key)
        if key not in self.node.value:
            if required:
                typo = difflib.get_close_matches(key, [k for k in self.node.value if k not in self.used], n=1)
                if typo:
                    raise self.error(typo[0], f"unknown key '{self.key_path(typo[0])}'; did you mean '{key}'?")
                raise InputError(f"missing required key '{self.key_path(key)}'", source=self.source,
                                 where=self._loc(self.path, self.node.line) if self.path else None)
            return default
        return self.node.value[key]

    def value(self, key: str, default=None, *, required: bool = False):
        n = self.raw(key, None, required=required)
        return default if n is None else _plain(n)

    def quantity(self, key: str, kind: str, default=None, *, required: bool = False, positive: bool = False,
                 non_negative: bool = False, maximum: tuple | None = None):
        """A quantity in SI; ``maximum`` = (SI value, text shown) bounds it from above."""
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        v = parse_quantity(n.value, kind, source=self.source, key=self.where(key))
        if positive and not v > 0:
            raise self.error(key, f"must be positive, got '{n.value}'")
        if non_negative and v < 0:
            raise self.error(key, f"must not be negative, got '{n.value}'")
        if maximum is not None and v > maximum[0]:
            raise self.error(key, f"must be at most {maximum[1]}, got '{n.value}'")
        return v

    def number(self, key: str, default=None, *, required: bool = False, integer: bool = False,
               minimum: float | None = None):
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        v = n.value
        if isinstance(v, bool) or not isinstance(v, (int, float)) or (integer and not isinstance(v, int)):
            raise self.error(key, f"expected a{'whole' if integer else ''} number, got {v!r}")
        if minimum is not None and v < minimum:
            raise self.error(key, f"must be at least {minimum}, got {v}")
        return v

    def choice(self, key: str, options, default=None, *, required: bool = False):
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        v = n.value
        if v not in options:
            near = difflib.get_close_matches(str(v), list(options), n=1)
            hint = f"; did you mean '{near[0]}'?" if near else ""
            raise self.error(key, f"'{v}' is not one of {', '.join(options)}{hint}")
        return v

    def string(self, key: str, default=None, *, required: bool = False):
        n = self.raw(key, None, required=required)
        if n is None:
            return default
        if not isinstance(n.value, str):
            raise self.error(key, f"expected text, got {n.value!r}")
        return n.value

    def string_list(self, key: str, default=None):
        n = self.raw(key, None)
        if n is None:
            return default
        items = n.value if isinstance(n.value, list) else [n]
        out = []
        for it in items:
            if not isinstance(it.value, (str, int, float)) or isinstance(it.value, bool):
                raise self.error(key, f"expected a list of names, got {_plain(n)!r}")
            out.append(str(it.value))
        return out

    def section(self, key: str, *, required: bool = False) -> Section | None:
        n = self.raw(key, None, required=required)
        if n is None:
            return None
        return Section(n, self.source, self.key_path(key))

    def done(self) -> None:
        extra = [k for k in self.node.value if k not in self.used]
        if extra:
            k = extra[0]
            near = difflib.get_close_matches(k, sorted(self.used), n=1)
            hint = f"; did you mean '{near[0]}'?" if near else ""
            raise self.error(k, f"unknown key '{self.key_path(k)}'{hint}")


def _plain(node: Node):
    v = node.value
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_plain(x) for x in v]
    return v
