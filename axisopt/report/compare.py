"""Designs side by side (:class:`~axisopt.study.compare.Compared` items): ``compare_table`` is the
text table ``axisopt compare`` prints, ``compare_dict`` / ``compare_rows`` the JSON and CSV forms,
:class:`Comparison` the notebook's result object (``axisopt.compare``).  The weakest link of each
design (the component with the lowest stiffness where the total is lowest) is marked.
"""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass

import numpy as np

from ..catalog.columns import DRIVE_SLOTS, MECH_SLOTS
from ..display import fmt, html_table, one_line
from ..model import CHECKS, Evaluation
from ..model.limits import CHECK_RECORDS
from ..search.reported import REPORTED
from ..units import N_PER_UM
from .checktext import allowed_list, judged_rows
from .evaluation import CHECK_SHORT, CHECK_UNITS, drive_dict, evaluation_dict
from .text import fmt_value


@dataclass(repr=False)
class Comparison:
    """Designs side by side (:func:`axisopt.compare`): ``items`` one
    :class:`~axisopt.study.compare.Compared` each, in argument order."""

    items: list

    def __len__(self) -> int:
        return len(self.items)

    def __iter__(self):
        return iter(self.items)

    def __getitem__(self, i):
        return self.items[i]

    def text(self) -> str:
        """The table ``axisopt compare`` prints."""
        return compare_table(self.items)

    def to_dict(self) -> dict:
        return compare_dict(self.items)

    def to_frame(self):
        """pandas DataFrame, one row per design (the CSV's columns: units in the names, e.g.
        ``min_stiffness [N/um]``, each check's margin, available and needed)."""
        import pandas as pd

        return pd.DataFrame(compare_rows(self.items))

    def __repr__(self) -> str:
        cells = []
        for c in self.items:
            e = c.evaluation
            if e is None:
                cells.append(f"{c.label}: {c.solve['status']}")
                continue
            cells.append(
                f"{c.label}: {fmt(e.minimum('k_total')[0] / N_PER_UM, 'N/um')}, "
                f"{fmt(e.minimum('f1')[0], 'Hz')}, {fmt(e['cost'], 'EUR')}"
            )
        return one_line("Comparison", f"{len(self.items)} designs", {"": " | ".join(cells)})

    def _repr_html_(self) -> str:
        col = COLUMN
        keys = (
            "label",
            "kind",
            "mounting",
            col["min_stiffness"],
            "weakest_link",
            col["min_frequency"],
            col["drag_torque"],
            col["total_mass"],
            col["cost"],
            "all_checks_pass",
        )
        return html_table(
            compare_rows(self.items), f"Comparison of {len(self.items)} designs", columns=keys
        )


TEXT_WIDTH = 100  # the terminal columns the table fits
# the reported values' columns (search.result.REPORTED)
COLUMN = {r.field: r.column for r in REPORTED}


def component_stiffness(ev: Evaluation) -> dict:
    """Screw, nut and bearing stiffness [N/m] where the total stiffness is lowest."""
    v = ev.values
    i = int(np.argmin(v["k_total"]))
    return {
        "screw": float(v["k_screw"][i]),
        "nut": float(v["k_nut"]),
        "bearings": float(v["k_bearing"]),
    }


def compare_table(items) -> str:
    """The text table: one column per design, the weakest link of each marked with '<'.  Within
    100 columns: when the designs do not fit side by side, the table is printed in blocks of as many
    designs as fit, one under the other."""
    if any(getattr(c, "drive", None) is not None for c in items):
        return drive_compare_table(items)
    w0 = 34
    width = max(22, *(min(30, len(c.label) + 2) for c in items))
    rows: list = []  # a text line, or (name, cells) of a table row

    def row(name, cells):
        rows.append((name, list(cells)))

    def num(x, nd=1):
        return (
            "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else f"{x:,.{nd}f}"
        )

    row("", [c.label for c in items])
    row("kind", [c.kind if c.ok else f"{c.kind}: {c.solve['status']}" for c in items])
    evs = [c.evaluation for c in items]

    def each(fn):
        return [fn(e) if e is not None else "-" for e in evs]

    row("mounting", each(lambda e: e.design.axis.mounting))
    row("stroke [mm]", each(lambda e: num(e.design.axis.stroke * 1e3, 0)))
    drives = [e for e in evs if e is not None and e.design.motor is not None]
    reds = [e for e in evs if e is not None and e.design.reduction is not None]
    for slot in (
        MECH_SLOTS + (DRIVE_SLOTS[:2] if drives else ()) + (DRIVE_SLOTS[2:] if reds else ())
    ):
        row(slot, each(lambda e, s=slot: e.design.part_ids().get(s, "-")))
    row("nut preload [N]", each(lambda e: num(e.design.preload, 0)))
    rows.append("")
    rows.append("stiffness [N/um]  (< weakest link)")
    comps = [component_stiffness(e) if e is not None else None for e in evs]
    for comp, label in (
        ("screw", "  screw (where total is min)"),
        ("nut", "  nut"),
        ("bearings", "  bearings"),
    ):
        cells = []
        for c in comps:
            if c is None:
                cells.append("-")
                continue
            mark = " <" if min(c, key=c.get) == comp else "  "
            cells.append(num(c[comp] / N_PER_UM) + mark)
        row(label, cells)
    row("  total minimum", each(lambda e: num(e.minimum("k_total")[0] / N_PER_UM) + "  "))
    row("  at [mm from stroke start]", each(lambda e: num(e.minimum("k_total")[1] * 1e3, 0) + "  "))
    row("  weakest link", each(lambda e: e.weakest + "  "))
    rows.append("")
    rows.append("frequency [Hz]")
    row("  1st natural, minimum", each(lambda e: num(e.minimum("f1")[0])))
    row("  at [mm from stroke start]", each(lambda e: num(e.minimum("f1")[1] * 1e3, 0)))
    row("  axial-torsional, minimum", each(lambda e: num(e.minimum("f_axial_torsional")[0])))
    row("  table on guides", each(lambda e: num(e["f_table"])))
    rows.append("")
    row("drag torque [N.m]", each(lambda e: num(e["drag_torque"], 3)))
    row(
        "  nut / bearings / guides",
        each(lambda e: f"{e['drag_nut']:.2f}/{e['drag_bearings']:.2f}/{e['drag_guides']:.2f}"),
    )
    row("moving mass [kg]", each(lambda e: num(e["moving_mass"])))
    row("total mass [kg]", each(lambda e: num(e["total_mass"])))
    row("cost [EUR]", each(lambda e: num(e["cost"], 0)))
    if drives:
        rows.append("")
        rows.append("drive (needed / available)")

        def motor(fn):
            return each(
                lambda e: fn(e, e.design.motor) if e.design.motor is not None else "no motor"
            )

        # the check's own needed / available values, in its vendor unit
        def pair(name, digits=".2f"):
            def cell(e, m):
                rec = CHECK_RECORDS[name]
                need = float(e.values[f"needed_{name}"]) * rec.factor
                have = float(e.values[f"available_{name}"]) * rec.factor
                return f"{need:{digits}} / {have:{'.3g' if digits != ',.0f' else digits}}"

            return motor(cell)

        # what the checks compare: the cycle's peak scaled to the motor's zone at its speed, the RMS
        # (or mean thrust) torque against the rule's allowed share of the rated torque
        row("  peak torque (zone-scaled) [N.m]", pair("motor_peak_torque"))
        row("  RMS torque / allowed [N.m]", pair("motor_rated_torque"))
        row("  motor speed [rpm]", pair("motor_speed", ",.0f"))
        row("  inertia ratio load/rotor", pair("inertia_ratio"))
        if any(e.design.axis.orientation == "vertical" for e in drives):
            row(
                "  holding torque x safety [N.m]",
                motor(
                    lambda e, m: (
                        "-"
                        if e.design.axis.orientation != "vertical"
                        else f"{e['holding_torque'] * e.design.axis.brake_safety:.2f} / "
                        f"{(m['brake_torque'] if math.isfinite(float(m['brake_torque'])) else 0.0):.3g}"  # noqa: E501
                    )
                ),
            )
    rows.append("")
    rows.append("checks: margin (available / needed), >= 1 passes, ! fails")
    # a solved problem's checks judged against its limits.margins (marked *)
    tables = [
        {r["check"]: r for r in judged_rows(e, c.margins)} if e is not None else None
        for c, e in zip(items, evs)
    ]
    for c in CHECKS:
        if not any(t is not None and c in t for t in tables):
            continue
        unit = CHECK_UNITS[c][0]

        def cell(t, c=c):
            if t is None or c not in t:
                return "-"
            r = t[c]
            if r["margin"] is None:  # the check does not apply to this design: no values compared
                return "n/a  "
            m = f"{r['margin']:.2f}"
            return (
                f"{m} ({fmt_value(r['available'])}/{fmt_value(r['needed'])})"
                + ("" if "allowed" not in r else "*")
                + ("  " if r["pass"] else " !")
            )

        row(f"  {CHECK_SHORT[c]}" + (f" [{unit}]" if unit else ""), [cell(t) for t in tables])
    # the checks that apply, as the rows above judge them (not every margin the model computes: a
    # horizontal axis's brake, an unloaded check)
    row(
        "all checks pass",
        [
            ("yes" if all(r["pass"] for r in t.values()) else "NO") if t is not None else "-"
            for t in tables
        ],
    )
    notes = [
        f"{c.label}: {allowed_list(t.values())}"
        for c, t in zip(items, tables)
        if t is not None and allowed_list(t.values())
    ]
    if notes:
        rows.append("* against the problem's least margin (limits.margins)")
        for n in notes:
            rows.extend(textwrap.wrap(n, TEXT_WIDTH, initial_indent="  ", subsequent_indent="    "))
    # the columns as wide as their widest cell (a check's 'margin (available/needed)' included), up
    # to 32: two designs side by side at least; a wider cell is cut with a mark and given in full
    # under the table
    longest = max(
        [len(str(c).rstrip()) for r in rows if not isinstance(r, str) for c in r[1]] + [0]
    )
    width = max(width, min(32, longest + 3))
    per = max(1, (TEXT_WIDTH - w0) // width)  # designs side by side
    cut: list = []

    # a cell wider than its column: cut with a '~' mark, given in full under the table
    def fit(text) -> str:
        text = str(text)
        if len(text.rstrip()) <= width - 1:
            return text if len(text) <= width - 1 else text.rstrip()
        if text not in cut:
            cut.append(text)
        return text[: width - 2] + "~"

    blocks = []
    for j in range(0, len(items), per):
        lines = [
            r
            if isinstance(r, str)
            else f"{r[0]:<{w0}}" + "".join(f"{fit(c):>{width}}" for c in r[1][j : j + per])
            for r in rows
        ]
        blocks.append("\n".join(ln.rstrip() for ln in lines))
    if cut:
        blocks.append(
            "\n".join(
                textwrap.wrap(
                    "~ cut to fit the column; in full: " + ", ".join(cut),
                    TEXT_WIDTH,
                    subsequent_indent="    ",
                )
            )
        )
    solved = [c for c in items if c.solve is not None]
    if solved:
        tail = ["solved problems"]
        for c in solved:
            s = c.solve
            val = (
                "-"
                if s["objective_value"] is None
                else f"{s['objective_value']:,.3f} {s['objective_unit']}"
            )
            tail.append(f"  {c.label}: {s['status']} ({s['method']}), {s['objective']} = {val}")
        blocks.append("\n".join(tail))
    return "\n\n".join(blocks)


def _common(c) -> dict | None:
    """What designs of every drive type share, in display units: the drive type, the parts, the
    least axial stiffness [N/um], the first frequency [Hz], the cost [EUR], the moving mass [kg] and
    the least margin with its check (None: no design)."""
    d = getattr(c, "drive", None)
    if d is not None:
        least = min(d.margins.items(), key=lambda kv: kv[1]) if d.margins else (None, None)
        return {
            "drive_type": d.drive_type,
            "parts": dict(d.parts),
            "stiffness": d.stiffness,
            "frequency": d.frequency,
            "cost": d.cost,
            "moving_mass": d.moving_mass,
            "least_margin": least,
        }
    e = c.evaluation
    if e is None:
        return None
    ed = evaluation_dict(e)
    margins = {k: v["margin"] for k, v in ed["checks"].items() if v["margin"] is not None}
    least = min(margins.items(), key=lambda kv: kv[1]) if margins else (None, None)
    return {
        "drive_type": "screw",
        "parts": {"mounting": ed["mounting"], **ed["parts"]},
        "stiffness": ed["min_axial_stiffness_N_per_um"],
        "frequency": ed["min_natural_frequency_Hz"],
        "cost": ed["cost"],
        "moving_mass": ed["moving_mass_kg"],
        "least_margin": least,
    }


def drive_compare_table(items) -> str:
    """The comparison when a rack-and-pinion or linear-motor design is among the designs: what every
    drive type has (the quantities of :func:`_common`), one block per design."""
    from .drivetype import LABELS as DRIVE_LABELS

    out = [
        "designs of several drive types: the quantities every type has (stiffness: the least axial "
        "stiffness at the table over the stroke)"
    ]
    for c in items:
        m = _common(c)
        out.append("")
        out.append(f"{c.label}  ({c.source})")
        if m is None:
            out.append(f"  no design (status {c.solve['status'] if c.solve else '-'})")
            continue
        out.append(f"  drive type        {DRIVE_LABELS[m['drive_type']]}")
        parts = ", ".join(f"{k} {v}" for k, v in m["parts"].items() if v is not None)
        out += textwrap.wrap(
            parts, 100, initial_indent="  parts             ", subsequent_indent=" " * 20
        )
        out.append(f"  stiffness         {m['stiffness']:,.1f} N/um")
        out.append(f"  first frequency   {m['frequency']:,.1f} Hz")
        out.append(f"  cost              {m['cost']:,.0f} EUR")
        out.append(f"  moving mass       {m['moving_mass']:,.1f} kg")
        k, v = m["least_margin"]
        if k is not None:
            out.append(f"  least margin      {v:.2f} ({k}){'' if v >= 1.0 else '  FAIL'}")
    return "\n".join(out)


def compare_dict(items) -> dict:
    out = []
    for c in items:
        d = {"label": c.label, "source": c.source, "kind": c.kind, "solve": c.solve}
        if c.evaluation is not None:
            ev = evaluation_dict(c.evaluation)
            comp = component_stiffness(c.evaluation)
            ev["component_stiffness_at_min_N_per_um"] = {k: v / N_PER_UM for k, v in comp.items()}
            fa, fapos = c.evaluation.minimum("f_axial_torsional")
            ev["min_axial_torsional_frequency_Hz"] = fa
            d["evaluation"] = ev
        if getattr(c, "drive", None) is not None:
            d["drive_design"] = c.drive.to_dict()
        out.append(d)
    return {"designs": out}


def compare_rows(items) -> list:
    """Flat rows (one per design) for the CSV."""
    rows = []
    for c in items:
        r = {
            "label": c.label,
            "source": c.source,
            "kind": c.kind,
            "status": c.solve["status"] if c.solve else "design",
        }
        e = c.evaluation
        dd = getattr(c, "drive", None)
        if dd is not None:
            r.update(
                {
                    "drive_type": dd.drive_type,
                    **dd.parts,
                    COLUMN["min_stiffness"]: dd.stiffness,
                    COLUMN["min_frequency"]: dd.frequency,
                    COLUMN["moving_mass"]: dd.moving_mass,
                    COLUMN["cost"]: dd.cost,
                    "all_checks_pass": all(v >= 1.0 for v in dd.margins.values()),
                    **{f"{k} margin": v for k, v in dd.margins.items()},
                }
            )
        if e is not None:
            d = evaluation_dict(e)
            comp = component_stiffness(e)
            r.update(
                {
                    "mounting": d["mounting"],
                    **d["parts"],
                    "nut_preload [N]": d["nut_preload_N"],
                    "stroke [mm]": e.design.axis.stroke * 1e3,
                    "screw_stiffness_at_min [N/um]": comp["screw"] / N_PER_UM,
                    "nut_stiffness [N/um]": comp["nut"] / N_PER_UM,
                    "bearing_stiffness [N/um]": comp["bearings"] / N_PER_UM,
                    COLUMN["min_stiffness"]: d["min_axial_stiffness_N_per_um"],
                    "min_stiffness_at [mm]": d["min_axial_stiffness_position_mm"],
                    "weakest_link": d["weakest_link"],
                    COLUMN["min_frequency"]: d["min_natural_frequency_Hz"],
                    "min_frequency_at [mm]": d["min_natural_frequency_position_mm"],
                    "table_mode [Hz]": d["table_mode_Hz"],
                    COLUMN["drag_torque"]: d["drag_torque_Nm"],
                    COLUMN["moving_mass"]: d["moving_mass_kg"],
                    COLUMN["total_mass"]: d["total_mass_kg"],
                    COLUMN["cost"]: d["cost"],
                    "all_checks_pass": d["all_checks_pass"],
                }
            )
            for k, v in (drive_dict(e) or {}).items():
                if k not in DRIVE_SLOTS:
                    r[f"drive_{k}"] = v
            for k, v in d["checks"].items():
                u = f" [{v['unit']}]" if v["unit"] else ""
                r[f"{k} margin"] = v["margin"]
                r[f"{k} available{u}"] = v["available"]
                r[f"{k} needed{u}"] = v["needed"]
        rows.append(r)
    return rows


def write_compare_csv(items, path) -> None:
    import pandas as pd

    from ..fileio import csv_safe, open_output

    with open_output(path, "w", what="CSV") as fh:  # text cells escaped against CSV injection
        csv_safe(pd.DataFrame(compare_rows(items))).to_csv(fh, index=False, float_format="%.10g")


__all__ = [
    "Comparison",
    "compare_table",
    "compare_dict",
    "compare_rows",
    "write_compare_csv",
    "component_stiffness",
]
