"""The positioning-error budget of an evaluated design as text rows (um), each with its source
(:mod:`axisopt.model.accuracy`)."""

from __future__ import annotations

import math

from ..catalog.grades import SCALE_GRADES, grade_table
from ..model import nut_length
from ..physics.nut import NUT_LENGTH_FACTORS

ARCSEC = math.pi / 180.0 / 3600.0


def lead_source(grade: str, stroke: float, nut_length: float = 0.0) -> str:
    """How the lead row is read from the grade tables (THK A-678) over the thread the nut travels,
    stroke + nut length (ISO 3408-3's useful travel)."""
    g = grade_table().grade(grade)
    over = f"{stroke * 1e3:.0f}"
    over += f" + {nut_length * 1e3:.0f} mm nut" if nut_length > 0 else " mm"
    if math.isfinite(g.travel_error_300):
        return f"+-{g.travel_error_300 * 1e6:.0f} um/300 mm over {over}, THK A-678"
    return f"e_p+v_u over {over}, THK A-678"


def reduction_lost_motion(design) -> float:
    """A reduction part's torsional backlash through the lead at the table [m]
    (model.drive.lost_motion's second term; 0 without a reduction part)."""
    r = design.reduction
    if r is None:
        return 0.0
    return float(r["backlash"]) * float(design.screw["lead"]) / (2.0 * math.pi)


def budget_rows(ev) -> list:
    """(label, value [m], source) of each row, the total and the repeatability."""
    d, v = ev.design, ev.values
    a = d.axis
    rise = f"heat balance, preload {d.preload:.0f} N" if a.rise_from_balance else "the rise used"
    pitch, yaw = a.guide_pitch / ARCSEC, a.guide_yaw / ARCSEC
    red = reduction_lost_motion(d)
    if a.feedback == "linear_scale":
        g = SCALE_GRADES[a.scale_grade]
        lead_row = (
            f"linear scale {a.scale_grade}",
            float(v["lead_error"]),
            f"{g.source} per m, at least 1 m",
        )
        thermal_row = (
            "thermal growth at the nut (outside the loop)",
            float(v["thermal_error"]),
            "the scale measures the table",
        )
    else:
        if a.pitch_compensation:
            lead_row = (
                f"lead error, grade {d.grade}, compensated",
                float(v["lead_error"]),
                "what compensation leaves: v_u, THK A-677",
            )
        else:
            lead_row = (
                f"lead error, grade {d.grade}",
                float(v["lead_error"]),
                lead_source(d.grade, a.stroke, float(nut_length(d.screw, d.nut))),
            )
        # the design's own growth (model.chain at its preload), not the budget's bound at the nut's
        # top preload
        thermal_row = ("thermal drift at the nut", float(v["thermal_growth"]), f"{rise}; THK A-715")
    noise = "scale head" if a.feedback == "linear_scale" else "encoder: negligible"
    rows = [
        lead_row,
        thermal_row,
        (
            f"deflection at the tool under {a.axial_load:.0f} N",
            float(v["elastic_error"]),
            "softest point, chain + rocking; THK A-713",
        ),
        (
            f'Abbe: pitch {pitch:.3g}" x {a.tool_height_eff * 1e3:.0f} mm, yaw {yaw:.3g}" x '
            f"{a.tool_offset * 1e3:.0f} mm",
            float(v["abbe_error"]),
            "THK A-716 eq. 39",
        ),
        ("lost motion, nut play", float(v["lost_motion"]) - red, "0: preloaded nut; THK A-712"),
        *(
            [
                (
                    f"lost motion, reduction {d.reduction['id']}",
                    red,
                    f"backlash {float(d.reduction['backlash']) * 10800 / math.pi:g} arcmin x lead "
                    "/ 2 pi",
                )
            ]
            if d.reduction is not None
            else []
        ),
    ]
    rows.append(
        ("total, arithmetic worst case", sum(r[1] for r in rows), "every row at its worst at once")
    )
    bound = float(v["positioning_error"])
    if not math.isclose(bound, rows[-1][1], rel_tol=1e-9, abs_tol=1e-12):
        # limits.max_positioning_error holds the model's total, whose thermal row is at the nut's
        # top preload (model.accuracy: the search's one-sided preload solve rests on it)
        rows.append(
            (
                "total the limit holds (thermal at top preload)",
                bound,
                "model.accuracy: conservative bound",
            )
        )
    rows.append(
        ("repeatability (ISO 230-2)", float(v["repeatability"]), f"reversal + noise, {noise}")
    )
    return rows


def nut_length_estimate_note(design) -> str | None:
    """The line saying the lead row rests on the nut-length estimate (the nut's vendor lists no
    length: physics.nut.nut_length_estimate), or None (a listed length; a scale, whose row does not
    read the screw's lead)."""
    if design.axis.feedback == "linear_scale":
        return None
    try:
        listed = math.isfinite(float(design.nut["length"]))
    except (KeyError, TypeError, ValueError):
        listed = False
    if listed:
        return None
    double = str(design.nut.get("type", "")) == "double"
    factor = NUT_LENGTH_FACTORS[1 if double else 0]
    length = float(nut_length(design.screw, design.nut)) * 1e3
    return (
        f"  the lead row rests on an estimate: nut length {length:.0f} mm = {factor:g} (P + d) "
        "(its vendor lists none)"
    )


def budget_lines(ev) -> list:
    """The budget as the text lines ``axisopt evaluate`` prints (and, where the nut's length is
    the estimate, a line saying the lead row rests on it)."""
    lines = [
        f"positioning error budget over the {ev.design.axis.stroke * 1e3:.0f} mm stroke (um, "
        "largest deviation; THK A-712)"
    ]
    for label, value, source in budget_rows(ev):
        lines.append(f"  {label:<44}{value * 1e6:>8.1f}  ({source})")
    note = nut_length_estimate_note(ev.design)
    if note:
        lines.append(note)
    return lines


def budget_dict(ev) -> dict:
    """The budget for the JSON report: each row in um, the grade."""
    rows = {label: round(value * 1e6, 3) for label, value, _ in budget_rows(ev)}
    return {"grade": ev.design.grade, "rows_um": rows}
