"""The parts list of a design, as one would order it: each part's id, vendor, quantity and what to tell the
vendor (the screw's bearing span, the nut's preload rounded to 10 N, the rails' length).  Nothing here prints.

The rail length is the model's own (``stroke + table_length``, :func:`axisopt.model.params.design_params`),
rounded up to a whole 10 mm: an estimate, not the vendor's cut length (which follows the rail's hole pitch and
end distances in the vendor's catalog; see docs/assumptions.md).
"""

from __future__ import annotations

import math

PRELOAD_STEP = 10.0  # [N] the nut preload is ordered rounded to this


def _up(length_m: float, step_mm: float = 10.0) -> float:
    """A length [m] in mm rounded up to a whole ``step_mm``."""
    return step_mm * math.ceil(round(length_m * 1e3 / step_mm, 9))


def parts_list(design) -> list[dict]:
    """One row per part to order: ``part``, ``id``, ``vendor``, ``quantity`` and ``order`` (the values the
    order needs: lengths in mm, the preload in N)."""
    a = design.axis
    drives = 2 if getattr(a, "twin_drive", None) is not None else 1  # a twin-drive gantry orders two of each
    rows = []

    def add(slot: str, qty: int, note: str) -> None:
        part = getattr(design, slot)
        if part is not None:
            rows.append({"part": slot, "id": str(part["id"]), "vendor": str(part.get("vendor", "")),
                         "quantity": qty, "order": note})

    add("screw", drives, f"bearing span {_up(a.span):,.0f} mm (stroke {a.stroke * 1e3:,.0f} mm); end journals "
                         "machined to the support bearings")
    add("nut", drives, f"preload {PRELOAD_STEP * round(design.preload / PRELOAD_STEP):,.0f} N")
    sets = 2 if a.mounting == "fixed-fixed" else 1
    add("bearing", drives * sets, f"{a.mounting}: {sets} set{'s' if sets > 1 else ''} per screw"
        + ("" if a.mounting == "fixed-fixed" else " (the free or supported end's bearing is not sized here)"))
    if design.guide is not None:
        add("guide", a.guide_blocks, "blocks")
        rows.append({"part": "guide rail", "id": str(design.guide["id"]), "vendor": str(design.guide.get("vendor", "")),
                     "quantity": a.rails, "order": f"length {_up(a.stroke + a.table_length):,.0f} mm (estimate: "
                                                   "stroke + table length; cut to the vendor's hole pitch)"})
    add("motor", drives, "")
    add("coupling", drives, "")
    add("reduction", drives, "")
    return rows


__all__ = ["parts_list", "PRELOAD_STEP"]
