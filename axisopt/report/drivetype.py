"""The text of a solve over drive types (:func:`axisopt.search.drivetype.solve_drive_types`)."""

from __future__ import annotations

import textwrap

WIDTH = 100  # the text fits 100 columns (tests/cli/test_solve_text_width.py)


def _wrap(line: str) -> list:
    """A long line broken at spaces within WIDTH, the continuation indented two more than the
    line."""
    indent = " " * (len(line) - len(line.lstrip()) + 2)
    return textwrap.wrap(line, WIDTH, subsequent_indent=indent, break_on_hyphens=False) or [line]


LABELS = {"screw": "screw", "rack_pinion": "rack and pinion", "linear_motor": "linear motor"}
MARGIN_LABELS = {
    "pinion_tooth": "pinion tooth (THK A-241)",
    "motor_peak": "motor peak",
    "motor_rms": "motor RMS",
    "motor_speed": "motor speed",
    "gearbox_peak": "gearbox T2B",
    "gearbox_rated": "gearbox T2N",
    "gearbox_speed": "gearbox n1Max",
    "inertia_ratio": "inertia ratio",
    "guide_life": "guide life",
    "guide_static": "guide static",
    "peak_time": "peak-force time (HIWIN 1 s)",
}


def _design(d, unit: str) -> list:
    lines = [
        f"  {LABELS[d.drive_type]}: " + ", ".join(f"{k} {v}" for k, v in d.parts.items()),
        f"    objective {d.objective:.6g} {unit}; cost {d.cost:,.0f} EUR, moving mass "
        f"{d.moving_mass:.1f} kg"
        f" (a side), stiffness {d.stiffness:.1f} N/um, first frequency {d.frequency:.1f} Hz, "
        f"positioning error {d.positioning_error:.1f} um",
    ]
    if d.margins:
        lines.append(
            "    margins: "
            + ", ".join(
                f"{MARGIN_LABELS.get(k, k)} {v:.2f}"
                for k, v in sorted(d.margins.items(), key=lambda kv: kv[1])
            )
        )
    return lines


def format_drive_result(res, top: int = 5) -> str:
    out = [
        f"status: {res.status} ({res.method} over drive types: "
        + ", ".join(LABELS[t.drive_type] for t in res.types)
        + f"), {res.time:.2f} s",
        f"objective: {res.objective_label} [{res.objective_unit}]",
    ]
    for t in res.types:
        best = "" if t.best is None else f", best {t.best:.6g} {res.objective_unit}"
        feas = "" if t.feasible is None else f", {t.feasible:,} feasible"
        out.append(
            f"  {LABELS[t.drive_type]:16s} {t.status}: {t.combinations:,} combinations{feas}{best}"
        )
    if res.best is not None:
        out.append("best design:")
        out += _design(res.best, res.objective_unit)
        for i, d in enumerate(res.runners_up[: max(top - 1, 0)], start=2):
            out.append(f"#{i}")
            out += _design(d, res.objective_unit)
    else:
        out.append("no design meets every check and limit; the closest (checks missed):")
        for d in res.closest:
            out += _design(d, res.objective_unit)
        if res.change:
            out.append(f"design change: {res.change}")
    out += [f"note: {n}" for n in res.notes]
    return "\n".join(w for line in out for w in _wrap(line))


def format_drive_design(d, problem) -> str:
    """The text of one evaluated rack-and-pinion or linear-motor design (``axisopt evaluate``): its
    parts, objective, cost and outputs, and every check and limit margin with PASS or FAIL."""
    from ..search.drivedesigns import objective_of

    _, (name, _, unit, _) = objective_of(problem)
    out = [f"design {problem.name}: {LABELS[d.drive_type]} ({name.replace('_', ' ')} in {unit})"]
    out += _design(d, unit)
    out.append("checks and limits (available / needed):")
    for k, v in sorted(d.margins.items(), key=lambda kv: kv[1]):
        out.append(f"  {MARGIN_LABELS.get(k, k):34s} {v:8.3f}  {'PASS' if v >= 1.0 else 'FAIL'}")
    return "\n".join(w for line in out for w in _wrap(line))
