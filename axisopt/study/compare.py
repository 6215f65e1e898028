"""Designs to compare side by side (design YAMLs, or problem YAMLs solved to their best design).

``load_compared(paths)`` returns one :class:`Compared` per file, ``compare_designs`` one per file or
:class:`~axisopt.design.Design`: each holds the design's evaluation (or, for a problem without a
design, its solve status).  The table, JSON and CSV forms are made in :mod:`axisopt.report.compare`.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from ..model import Evaluation, evaluate
from ..yamlio import read_yaml

LOG = logging.getLogger("axisopt")
# [s] a comparison running longer reports each file done to the "axisopt" logger (a terminal)
PROGRESS = 2.0


@dataclass
class Compared:
    label: str
    source: str
    kind: str  # 'design' | 'problem'
    evaluation: Evaluation | None
    solve: dict | None = None  # for a problem: status, objective, certificate
    # for a problem: its least check margins (limits.margins), what its checks meet
    margins: dict | None = None
    # a rack-and-pinion or linear-motor design (search.drivedesigns.DriveDesign): no screw
    # evaluation
    drive: object = None

    @property
    def ok(self) -> bool:
        return self.evaluation is not None or self.drive is not None


def compare_designs(files, method: str = "default", time_limit: float = 100.0) -> list:
    """Designs to compare, one :class:`Compared` each in argument order: each of ``files`` a design
    or problem YAML path (a problem is solved to its best design with ``method``) or a
    :class:`axisopt.design.Design` (:class:`axisopt.report.compare.Comparison` shows them side by
    side)."""
    from ..design import Design

    items, paths = [], []
    for f in files:
        if isinstance(f, Design):
            items.append(Compared(f.name, "<Design>", "design", evaluate(f)))
        else:
            items.append(None)
            paths.append(f)
    loaded = iter(load_compared(paths, method, time_limit) if paths else [])
    items = [c if c is not None else next(loaded) for c in items]
    labels = [c.label for c in items]
    for i, c in enumerate(items):  # two with one name: number them
        if labels.count(c.label) > 1:
            c.label = f"{c.label} [{i + 1}]"
    return items


def file_kind(path) -> str:
    """'design' when the YAML names its parts, else 'problem'."""
    from ..yamlio import file_kind as kind_of
    from ..yamlio import require_kind

    root = read_yaml(path)
    if kind_of(root) == "study" or not isinstance(root.value, dict):
        require_kind(root, str(path), "design or problem")
    if not isinstance(root.value, dict):
        raise InputError("expected a design or problem mapping", source=str(path))
    if "drive_design" in root.value:
        return "drive design"
    return "design" if "parts" in root.value else "problem"


def load_compared(paths, method: str = "default", time_limit: float = 100.0) -> list:
    """Each file of ``paths`` evaluated (a design) or solved and its best design evaluated (a
    problem), as :class:`Compared`; once the comparison has run :data:`PROGRESS` seconds, each file
    done is reported to the "axisopt" logger."""
    from ..design import load_design

    out = []
    t0 = time.perf_counter()
    for i, p in enumerate(paths):
        if i and time.perf_counter() - t0 > PROGRESS:
            LOG.info(
                f"  compare: {i} of {len(paths)} files done, {time.perf_counter() - t0:.0f} s; "
                f"next {p}"
            )
        kind = file_kind(p)
        if kind == "drive design":
            from ..problem import load_problem
            from ..search.drivefile import evaluate_drive_design

            prob = load_problem(p)
            out.append(Compared(prob.name, str(p), kind, None, drive=evaluate_drive_design(prob)))
            continue
        if kind == "design":
            d = load_design(p)
            out.append(Compared(d.name, str(p), kind, evaluate(d)))
            continue
        from ..problem import load_problem
        from ..search import solve

        prob = load_problem(p)
        if prob.drives is not None:  # search.drive_types: the best of the types
            out.append(_drive_types(prob, p, method, time_limit))
            continue
        res = solve(prob, method, top=1, sensitivities=False, time_limit=time_limit)
        info = {
            "status": res.status,
            "method": res.method,
            "objective": res.objective_label,
            "objective_value": None if res.best is None else res.best.objective,
            "objective_unit": res.objective_unit,
            "proven": bool(res.certificate.proven),
            "message": res.message,
        }
        if res.best is None or res.best.design is None:
            out.append(Compared(f"{prob.name} (solved)", str(p), kind, None, info))
            continue
        d = res.best.design
        out.append(
            Compared(f"{prob.name} (solved)", str(p), kind, evaluate(d), info, prob.margin_map)
        )
    labels = [c.label for c in out]
    for c in out:  # two files with one name: tell them apart by file name
        if labels.count(c.label) > 1:
            c.label = f"{c.label} [{Path(c.source).name}]"
    return out


def _drive_types(prob, path, method: str, time_limit: float) -> Compared:
    """A problem with search.drive_types solved over its types: its best design (a screw design
    evaluated as a design is, a rack-and-pinion or linear-motor design as its own)."""
    from ..search.drivetype import solve_drive_types

    res = solve_drive_types(prob, method, top=1, time_limit=time_limit)
    best = res.best
    info = {
        "status": res.status,
        "method": res.method,
        "objective": res.objective_label,
        "objective_value": None if best is None else best.objective,
        "objective_unit": res.objective_unit,
        "proven": res.status == "optimal",
        "message": "; ".join(res.notes),
    }
    label = f"{prob.name} (solved)"
    if best is None:
        return Compared(label, str(path), "problem", None, info)
    if best.drive_type == "screw":
        return Compared(
            label, str(path), "problem", evaluate(best.candidate.design), info, prob.margin_map
        )
    return Compared(label, str(path), "problem", None, info, drive=best)


__all__ = ["Compared", "compare_designs", "file_kind", "load_compared"]
