"""A twin-drive gantry's report entries (:mod:`axisopt.model.gantry`): the governing side's shares,
the gantry's modes, and each side's checks at the cross carriage's worst position.

The limits are checked on the governing side (the one nearest the cross carriage at the end of its
stroke); the far side at that moment carries 1 - r of the process force and less of the cross
carriage's mass.  The table :func:`side_rows` shows both, for the checks the share changes (the
loads, lives, lift-off, the torques), so the designer sees which side binds and what the other has
left.  Both sides have the same parts, and the cross carriage at the other end swaps them: each side
is in turn the governing one.
"""

from __future__ import annotations

import textwrap

import numpy as np

from ..model import Evaluation, evaluate
from ..model.function import check_rows
from ..model.gantry import gantry_params

# a check whose margins on the two sides differ by less than this (relative) is shared, not listed
# per side
SAME = 1e-3


def side_rows(ev: Evaluation) -> list:
    """Per check the share changes: ``check``, ``label``, ``unit``, ``needed`` on the governing and
    far side, ``available``, both margins and the governing side's pass (a twin drive only; [] for
    one drive)."""
    if ev.design.axis.twin_drive is None:
        return []
    far = evaluate(ev.design, len(ev.x), side="far")
    near_rows = {r["check"]: r for r in check_rows(ev)}
    out = []
    for r in check_rows(far):
        n = near_rows.get(r["check"])
        if n is None or n["margin"] is None or r["margin"] is None:
            continue
        if abs(n["margin"] - r["margin"]) <= SAME * max(abs(n["margin"]), 1e-12):
            continue
        out.append(
            {
                "check": r["check"],
                "label": r["label"],
                "unit": r["unit"],
                "available": n["available"],
                "needed_governing": n["needed"],
                "needed_far": r["needed"],
                "margin_governing": n["margin"],
                "margin_far": r["margin"],
                "pass": n["pass"],
            }
        )
    return out


def twin_dict(ev: Evaluation) -> dict:
    """A twin-drive gantry's entries (model.gantry): the governing side's shares, the gantry's modes
    and each side's checks (:func:`side_rows`); none for one drive."""
    tw = ev.design.axis.twin_drive
    if tw is None:
        return {}
    v = ev.values
    return {
        "twin_drive": {
            "span_mm": tw.span * 1e3,
            "cross_stroke_mm": tw.cross_stroke * 1e3,
            "cross_mass_kg": tw.cross_mass,
            "bridge_yaw_inertia_kgm2": gantry_params(ev.design.axis)["bridge_yaw_inertia"],
            "bridge_yaw_inertia_estimated": tw.bridge_yaw_inertia is None,
            "governing_side_force_share": tw.force_share,
            "governing_side_moving_mass_kg": v["moving_mass"],
            "gantry_moving_mass_kg": v["gantry_moving_mass"],
            "min_gantry_frequency_Hz": float(np.min(v["f_gantry"])),
            "racking_frequency_Hz": np.asarray(v["f_racking"]).tolist(),
            "min_racking_stiffness_Nm_per_urad": float(np.min(v["k_racking"])) * 1e-6,
            "sides": side_rows(ev),
        }
    }


WIDTH = 100  # terminal columns the text fits


def twin_lines(ev: Evaluation) -> list:
    """The text lines of :func:`twin_dict` (none for one drive)."""
    d = twin_dict(ev).get("twin_drive")
    if d is None:
        return []
    tw = ev.design.axis.twin_drive
    est = (
        (
            " (uprights estimated: half the bridge at the drives)"
            if tw.upright_mass is None
            else " (beam + uprights at the drives)"
        )
        if d["bridge_yaw_inertia_estimated"]
        else ""
    )
    L = [
        f"twin drive: 2 drives {d['span_mm']:.0f} mm apart, cross carriage "
        f"{d['cross_mass_kg']:.0f} kg over {d['cross_stroke_mm']:.0f} mm; governing side at the "
        f"stroke end: {d['governing_side_force_share'] * 100:.1f} % of the process force, "
        f"{d['governing_side_moving_mass_kg']:.1f} of {d['gantry_moving_mass_kg']:.1f} kg",
        "  gantry modes (2-DOF translation + yaw, both chains): lowest "
        f"{d['min_gantry_frequency_Hz']:.1f} Hz; racking {min(d['racking_frequency_Hz']):.1f} Hz "
        f"at its lowest, yaw stiffness {d['min_racking_stiffness_Nm_per_urad']:.1f} N.m/urad{est}; "
        "the guides-only yaw mode is not in the 1st frequency",
    ]
    rows = d["sides"]
    if rows:
        share = d["governing_side_force_share"]
        L.append(
            "  each side with the cross carriage at the end of its stroke (governing side "
            f"{share * 100:.1f} %,"
            f" far side {(1 - share) * 100:.1f} % of the process force; the limits are checked on "
            "the governing side, and the sides swap when the carriage crosses):"
        )
        # a longer label is wrapped above its numbers
        w = min(WIDTH - 30, max(len(r["label"]) for r in rows))
        L.append(f"    {'margin (available / needed)':<{w}}  {'governing':>9}  {'far':>9}")
        for r in rows:
            label = textwrap.wrap(r["label"], w) or [""]
            L.extend(f"    {x}" for x in label[:-1])
            L.append(
                f"    {label[-1]:<{w}}  {r['margin_governing']:>9.3g}  {r['margin_far']:>9.3g}"
                + ("" if r["pass"] else "  FAIL")
            )
    # the sentences wrapped at the text width (the table rows above fit it)
    out = []
    for line in L:
        if len(line) <= WIDTH:
            out.append(line)
            continue
        lead = len(line) - len(line.lstrip())
        out.extend(
            textwrap.wrap(
                line, WIDTH, initial_indent=" " * lead, subsequent_indent=" " * (lead + 2)
            )
        )
    return out
