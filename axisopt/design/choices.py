"""A problem's ``search:`` section: the counterbalance and the twin drive as search choices.

``search: {counterbalance: [none, {kind: counterweight, mass: 200 kg}, ...], twin_drive: [none,
{span: ...}]}`` lists the options; each one is read exactly as the single ``axis.counterbalance`` /
``axis.twin_drive`` key (:func:`.reader.read_counterbalance`, :func:`.reader.read_twin_drive`), an
error naming the option's index.
:func:`read_arrangements` returns every arrangement (the product of the lists) as ``(label, Axis)``;
the search solves each one and keeps the best (:mod:`axisopt.search.arrangements`).  A design keeps
one value."""

from __future__ import annotations

from dataclasses import replace

from ..errors import InputError
from ..yamlio import Key, Node, Section, Spec
from .drivechoice import DRIVE_KEYS
from .keys import AXIS_SPEC
from .reader import read_counterbalance, read_twin_drive
from .sectionkeys import COUNTERBALANCE_SPEC, TWIN_SPEC

MAX_OPTIONS = 12  # options per list (each arrangement is one full solve)
SEARCH_SPEC = Spec(
    "search",
    "axis arrangements the search chooses among (a problem only): each arrangement "
    "(the product of the lists) is solved and the best design wins",
    {
        "counterbalance": Key(
            "list",
            "vertical axes: counterbalance options, each 'none' or as axis.counterbalance",
            minimum=1,
            maximum=MAX_OPTIONS,
            items=Key(
                "one_of",
                options=(
                    Key("choice", "no counterbalance", choices=("none",)),
                    Key("section", spec=COUNTERBALANCE_SPEC),
                ),
            ),
        ),
        "twin_drive": Key(
            "list",
            "horizontal axes: twin-drive options, each 'none' (one drive) or as axis.twin_drive",
            minimum=1,
            maximum=MAX_OPTIONS,
            items=Key(
                "one_of",
                options=(
                    Key("choice", "one drive", choices=("none",)),
                    Key("section", spec=TWIN_SPEC),
                ),
            ),
        ),
        **DRIVE_KEYS,
    },
)


def _options(sec: Section, key: str, axis, reader) -> list:
    """The options of ``search.<key>``: None ('none') or what ``reader`` reads from the option."""
    node = sec.raw(key)
    if node is None:
        return [getattr(axis, key)]
    if not isinstance(node.value, list) or not node.value:
        raise sec.error(key, f"expected a list of options (e.g. [none, ...]), got {node!r}"[:200])
    if len(node.value) > MAX_OPTIONS:
        raise sec.error(
            key, f"{len(node.value)} options; at most {MAX_OPTIONS} (each arrangement is one solve)"
        )
    kw = {"orientation": axis.orientation, "moving_mass": axis.moving_mass}
    out = []
    for i, item in enumerate(node.value):
        if item.value == "none" or item.value is None:
            out.append(None)
            continue
        if not isinstance(item.value, dict):
            raise sec.error(
                key, f"option {i}: expected 'none' or a mapping of keys, got {item!r}"[:200]
            )
        holder = Section(
            Node({key: item}, item.line),
            sec.source,
            sec.path,
            spec=Spec(key, "", {key: AXIS_SPEC.keys[key]}),
        )
        try:
            out.append(reader(holder, kw))
        except InputError as e:
            raise InputError(f"option {i}: {e.message}", source=e.source, where=e.where) from None
    if len(set(map(repr, out))) < len(out):
        raise sec.error(key, "the same option is listed twice")
    return out


def _label(cb, tw) -> str:
    parts = []
    if cb is not None:
        parts.append(
            f"counterweight {cb.mass:g} kg"
            if cb.kind == "counterweight"
            else f"cylinder {cb.force:g} N"
        )
    if tw is not None:
        parts.append(f"twin drive {tw.span * 1e3:g} mm apart, cross carriage {tw.cross_mass:g} kg")
    return ", ".join(parts) or "none"


def read_arrangements(sec: Section | None, asec: Section, axis) -> tuple:
    """``((label, Axis), ...)`` of ``search:`` (empty without one); ``asec``: the axis section (an
    option list beside a single axis key is refused)."""
    if sec is None:
        return ()
    # drive types only (design.drivechoice)
    if not (sec.has("counterbalance") or sec.has("twin_drive")):
        sec.done()
        return ()
    for key in ("counterbalance", "twin_drive"):
        if sec.has(key) and asec.has(key):
            raise sec.error(
                key,
                f"axis.{key} and search.{key} both given: list the options in search.{key} only",
            )
    cbs = _options(sec, "counterbalance", axis, read_counterbalance)
    tws = _options(sec, "twin_drive", axis, read_twin_drive)
    sec.done()
    return tuple(
        (_label(cb, tw), replace(axis, counterbalance=cb, twin_drive=tw))
        for cb in cbs
        for tw in tws
    )


__all__ = ["SEARCH_SPEC", "read_arrangements"]
