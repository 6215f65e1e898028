"""Machines side by side: each a machine solve's plain data
(:func:`axisopt.machine.record.result_dict`, as ``axisopt machine solve --json`` writes it), one
column per machine: the joint optimum, the stiffness at the tool per direction and its most
compliant link, the lowest frequency and what limits it, the moving masses, the sequential sizing,
and every axis's parts."""

from __future__ import annotations

from ..errors import InputError

_UNITS = {"cost": "EUR", "tool_stiffness": "N/um", "frequency": "Hz", "moving_mass": "kg"}
_OBJ_KEY = {"cost": "cost_eur", "frequency": "lowest_frequency_hz", "moving_mass": "moving_mass_kg"}
PARTS = ("screw", "nut", "bearing", "guide", "motor", "reduction")


def objective_value(design: dict, objective: str) -> float:
    if objective == "tool_stiffness":
        return min(design["k_tool_n_per_um"].values())
    return design[_OBJ_KEY[objective]]


def check_result(d, source: str) -> dict:
    """``d`` read from ``source`` must be a machine result (InputError naming the file
    otherwise)."""
    need = ("machine", "objective", "status", "best", "sequential")
    if not isinstance(d, dict) or any(k not in d for k in need) or d.get("objective") not in _UNITS:
        raise InputError(
            "not a machine result (write one with `axisopt machine solve MACHINE.yaml --json "
            "FILE`)",
            source=source,
        )
    for key in ("best", "sequential"):
        v = d[key]
        if v is not None and not (
            isinstance(v, dict)
            and isinstance(v.get("axes"), list)
            and isinstance(v.get("k_tool_n_per_um"), dict)
        ):
            raise InputError(
                f"not a machine result: '{key}' is not a machine design", source=source
            )
    return d


def compare_rows(results: list) -> tuple:
    """(head, rows): one column per result, a row per figure and per axis part."""
    head = [""] + [r["machine"] for r in results]
    rows = [
        ["status"] + [r["status"] for r in results],
        ["objective"] + [r["objective"] for r in results],
    ]

    def row(label, f):
        rows.append([label] + [f(r["best"], r) if r["best"] is not None else "-" for r in results])

    row(
        "joint optimum",
        lambda b, r: f"{objective_value(b, r['objective']):,.1f} {_UNITS[r['objective']]}",
    )
    row("cost [EUR]", lambda b, r: f"{b['cost_eur']:,.0f}")
    for d in "xyz":
        row(
            f"k_{d} at the tool [N/um]",
            lambda b, r, d=d: (
                f"{b['k_tool_n_per_um'][d]:,.1f} "
                f"({b['most_compliant'][d]['axis']} {b['most_compliant'][d]['part']})"
            ),
        )
    row(
        "lowest frequency [Hz]",
        lambda b, r: (
            f"{b['lowest_frequency_hz']:,.1f} ({b['lowest_mode']['direction']}, "
            f"{b['lowest_mode']['axis']} {b['lowest_mode']['link']})"
        ),
    )
    row("Dunkerley's bound [Hz]", lambda b, r: f"{b['dunkerley_hz']:,.1f}")
    row("moving masses [kg]", lambda b, r: f"{b['moving_mass_kg']:,.1f}")
    rows.append(
        ["sequential sizing"]
        + [
            "-"
            if r["sequential"] is None
            else f"{objective_value(r['sequential'], r['objective']):,.1f} {_UNITS[r['objective']]}"
            + ("" if r["sequential"]["feasible"] else " (misses)")
            for r in results
        ]
    )
    names = []
    for r in results:
        for a in (r["best"] or {}).get("axes", []):
            if a["name"] not in names:
                names.append(a["name"])
    for n in names:
        for part in PARTS:
            cells = []
            for r in results:
                a = next((a for a in (r["best"] or {}).get("axes", []) if a["name"] == n), None)
                cells.append("-" if a is None else (a.get(part) or "-"))
            if any(c != "-" for c in cells):
                rows.append([f"{n} {part}"] + cells)
    return head, rows


def format_compare(results: list) -> str:
    head, rows = compare_rows(results)
    w0 = max(len(r[0]) for r in rows)
    widths = [max(len(str(r[i])) for r in rows + [head]) for i in range(1, len(head))]
    lines = [
        (f"{head[0]:<{w0}}  " + "  ".join(f"{h:<{w}}" for h, w in zip(head[1:], widths))).rstrip()
    ]
    for r in rows:
        marks = "" if len(set(r[1:])) == 1 else " *"
        lines.append(
            (f"{r[0]:<{w0}}  " + "  ".join(f"{c:<{w}}" for c, w in zip(r[1:], widths))).rstrip()
            + marks
        )
    lines.append("* the machines differ in this row")
    return "\n".join(lines)


__all__ = ["compare_rows", "format_compare", "check_result", "objective_value"]
