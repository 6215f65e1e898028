"""A rack-and-pinion or linear-motor design as a file: the problem's own YAML with a
``drive_design:`` section naming the parts (:func:`drive_design_yaml`, written by
``axisopt solve --save-design``), and its evaluation (:func:`evaluate_drive_design`,
``axisopt evaluate``): the one combination of the problem's drive-type space those parts make,
evaluated by the same model as the search's (:func:`.drivespace.evaluate_one`), so that a saved
design evaluates to the numbers its solve printed."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import yaml

from ..errors import InputError
from .drivedesigns import DriveDesign, design_of, objective_of, spaces
from .drivespace import evaluate_one


def evaluate_drive_design(problem) -> DriveDesign:
    """The design ``problem.drive_design`` names, evaluated: objective, cost, outputs, the checks'
    margins and the problem's limits as margins (>= 1 met).  A part the problem's catalogs and
    filters do not offer is a one-line error naming its key."""
    dd = problem.drive_design
    if dd is None:
        raise InputError("no drive_design section", source=problem.source, where="drive_design")
    _, spec = objective_of(problem)
    space = next((s for s in spaces(problem) if s.kind == dd["type"]), None)
    if space is None:
        raise InputError(
            f"the problem's catalogs and filters offer no {dd['type']} parts",
            source=problem.source,
            where="drive_design.type",
        )
    idx = []
    for slot, ids in space.axes:
        if dd[slot] not in ids:
            raise InputError(
                f"'{dd[slot]}' is not a {slot} the problem's catalogs and filters offer "
                f"({len(ids)} do)",
                source=problem.source,
                where=f"drive_design.{slot}",
            )
        idx.append(ids.index(dd[slot]))
    flat = int(np.ravel_multi_index(tuple(idx), space.shape))
    one = evaluate_one(space, flat)
    return design_of(space, flat, one, spec, problem)


KIND_NAMES = {"rack_pinion": "rack and pinion", "linear_motor": "linear motor", "screw": "screw"}


def _line(text: str) -> str:
    """``text`` on one line (a file name in a YAML comment injects nothing)."""
    return " ".join(str(text).split())


def drive_design_yaml(problem_path, design: DriveDesign, rank: int = 1) -> str:
    """The text of a saved rack-and-pinion or linear-motor ``design``: the problem file
    ``problem_path`` with its search narrowed to the design's drive type and a ``drive_design:``
    section naming the parts; catalog directories the problem names relative to itself made absolute
    (the file may be written elsewhere)."""
    path = Path(problem_path)
    data = yaml.safe_load(path.read_text(encoding="utf-8"))
    if data.get("catalogs"):
        dirs = data["catalogs"]
        dirs = [dirs] if isinstance(dirs, str) else dirs
        data["catalogs"] = [str((path.parent / str(d)).resolve()) for d in dirs]
    data.setdefault("search", {})["drive_types"] = [design.drive_type]
    data.pop("drive_design", None)
    parts = {"type": design.drive_type}
    for slot, v in design.parts.items():
        parts[slot] = int(v) if slot == "forcers" else v
    data["drive_design"] = parts
    head = (
        f"# design {rank} of `axisopt solve {_line(path.name)}`: {KIND_NAMES[design.drive_type]}, "
        f"objective {design.objective:.6g}, cost {design.cost:,.0f} EUR\n"
        "# `axisopt evaluate` of this file evaluates the drive_design below on the problem's axis, "
        "limits and catalogs\n"
    )
    return head + yaml.safe_dump(data, sort_keys=False, allow_unicode=True, width=100)
