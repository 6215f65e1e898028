"""The checks of one evaluation as text: each check judged against its limit (the user's allowed
margins included), the rows that list them, and the notes on the motor rule and the DN rules.
Nothing here prints."""

from __future__ import annotations

import textwrap

from ..model import Evaluation
from ..model.checks import DN_RULE_OTHER, DN_RULES
from ..model.function import check_rows
from .text import WIDTH, fmt_value


def judged_rows(ev: Evaluation, margins: dict | None = None) -> list:
    """:func:`check_rows`, each judged against the least margin a problem sets for it (``margins``:
    check -> margin, the problem's ``limits.margins``; 0 switches a check off): where that is not 1,
    ``pass`` reads the margin against it and ``allowed`` holds it (a table must not say FAIL for a
    margin the problem allowed)."""
    from ..model.checks import MARGIN_RTOL

    out = []
    for r in check_rows(ev):
        m = (margins or {}).get(r["check"], 1.0)
        if m != 1.0:
            r = {
                **r,
                "allowed": m,
                "pass": m == 0
                or r["margin"] is None
                and r["pass"]
                or r["margin"] is not None
                and r["margin"] >= m * (1.0 - MARGIN_RTOL),
            }
        out.append(r)
    return out


def allowed_list(rows) -> str:
    """'bearing life 0.5, critical speed 1.2': the rows :func:`judged_rows` judged on another margin
    than 1, with that margin ('off' for 0); '' when none."""
    return ", ".join(
        f"{r['check'].replace('_', ' ')} " + ("off" if r["allowed"] == 0 else f"{r['allowed']:g}")
        for r in rows
        if "allowed" in r
    )


def allowed_note(rows) -> str:
    """'* against the problem's least margin (limits.margins): ...' (:func:`allowed_list`; '' when
    none)."""
    judged = allowed_list(rows)
    return f"* against the problem's least margin (limits.margins): {judged}" if judged else ""


# checks whose needed value means nothing when the check does not apply (a rotating nut's screw
# stands still)
NOT_LOADED = ("critical_speed", "dn_limit", "bearing_speed", "coupling_speed")


def check_lines(ev: Evaluation, margins: dict | None = None) -> list:
    """The checks block of ``evaluate``: available, needed and margin with units (fits 100 columns);
    with a problem's ``margins`` (check -> least margin), pass or FAIL against them
    (:func:`judged_rows`)."""
    lines = [
        f"{'checks (margin = available / needed, >= 1 passes)':<50}{'available':>15}{'needed':>15}"
        f"{'margin':>8}"
    ]
    rows = judged_rows(ev, margins)
    for r in rows:
        unit = f" {r['unit']}" if r["unit"] else ""
        if r["check"] == "bearing_fit":
            have = f"{fmt_value(r['available_min'])}-{fmt_value(r['available'])}{unit}"
            label = "bearing bore / bores the screw end takes"
        else:
            have = fmt_value(r["available"]) + unit if r["available"] is not None else "n/a"
            label = r["label"]
        need = fmt_value(r["needed"]) + unit if r["needed"] else "none"
        margin = "n/a" if r["margin"] is None else f"{r['margin']:.2f}"
        verdict = "pass" if r["pass"] else "FAIL"
        # the check does not apply (a standing screw's critical speed, a single nut's
        if r["margin"] is None:
            # preload): no values compared, no verdict
            have, verdict = "n/a", "does not apply"
            need = "-" if r["check"] in NOT_LOADED else need
        lines.append(
            f"  {label:<48}{have:>15}{need:>15}{margin:>8}  {verdict}"
            + ("*" if "allowed" in r else "")
        )
    lines.extend(
        textwrap.wrap("  rules: " + "; ".join(rule_notes(ev)), WIDTH, subsequent_indent="    ")
    )
    note = allowed_note(rows)
    if note:
        lines.extend(textwrap.wrap(note, WIDTH, initial_indent="  ", subsequent_indent="    "))
    return lines


def rule_notes(ev: Evaluation) -> list:
    """Whose rule each vendor-dependent check applies: the DN by the screw's vendor, the nut
    lift-off's load cases (model.loads.lift_off_load)."""
    d = ev.design
    out = [
        "DN " + DN_RULES.get(str(d.screw["vendor"]), DN_RULE_OTHER),
        "buckling with the nut a "
        + (
            "fixed end (THK A-726)"
            if d.axis.buckling_nut_end == "fixed"
            else "supported end (MiSUMi Selection of Ball Screws 2)"
        ),
    ]
    if d.nut["type"] == "double":
        out.append(
            "lift-off: the cut and the inertia at once (axis.cut_while_accelerating)"
            if d.axis.cut_while_accelerating
            else "lift-off: each load case its own load (THK A-725: the cut at feed speed, the "
            "inertia in the " + ("duty cycle's phases)" if d.axis.duty_cycle else "rapid)")
        )
    return out
