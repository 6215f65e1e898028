"""The life checks' load table of ``evaluate`` (text and JSON), in the units of the vendors' worked
examples (THK A-725 to A-730: N, mm, m/min)."""

from __future__ import annotations

from ..model import Evaluation
from ..model.lifetable import life_table, table_rows_finite

_COLUMNS = (
    ("direction", "dir", 4, ""),
    ("acceleration", "acc m/s2", 9, ".2f"),
    ("mass", "mass kg", 9, ".1f"),
    ("process", "process N", 10, ",.0f"),
    ("friction", "friction N", 11, ",.0f"),
    ("weight", "weight N", 9, ",.0f"),
    ("load", "load N", 9, ",.0f"),
    ("travel", "travel", 12, ""),
)


def life_lines(ev: Evaluation) -> list:
    """The load cases the nut and support-bearing lives are computed from, one per duty-cycle phase
    group that travels (or the mean axial load each way), with the cubic-mean loads, the equivalent
    loads on the ratings and the mean speed."""
    t = life_table(ev.design)
    if not table_rows_finite(t):
        return ["life loads: not finite (check the duty cycle and the loads)"]
    src = (
        "the duty cycle's phases"
        if t["from_cycle"]
        else "the mean axial load each way (no duty cycle)"
    )
    lines = [f"life loads from {src} (THK A-725)"]
    lines.append("  " + "".join(f"{head:>{w}}" for _, head, w, _ in _COLUMNS))
    for r in t["rows"]:
        cells = []
        for key, _, w, fmt in _COLUMNS:
            v = r[key]
            if key == "direction":
                cells.append(f"{'+' if v > 0 else '-':>{w}}")
            # the cycle's travel, or the share of it the default load cases take
            elif key == "travel":
                cells.append(
                    f"{v * 1e3:>{w - 3},.1f} mm" if t["from_cycle"] else f"{v * 100:>{w - 2}.0f} %"
                )
            else:
                cells.append(f"{v:>{w}{fmt}}")
        lines.append("  " + "".join(cells))
    plus, minus = t["cubic_mean"]
    lines.append(
        f"  cubic-mean load {plus:,.0f} N (+), {minus:,.0f} N (-); mean speed "
        f"{t['mean_speed'] * 60:.1f} m/min"
    )
    lines.append(
        f"  equivalent load on the nut's rating {t['nut_equivalent']:,.0f} N, on the bearing set's "
        f"{t['bearing_equivalent']:,.0f} N"
    )
    return lines


def life_dict(ev: Evaluation) -> dict:
    """The same table for JSON (SI with units in the keys)."""
    t = life_table(ev.design)
    return {
        "from_duty_cycle": t["from_cycle"],
        "phases": [
            {
                "direction": int(r["direction"]),
                "acceleration_m_per_s2": r["acceleration"],
                "moving_mass_kg": r["mass"],
                "process_force_N": r["process"],
                "guide_friction_N": r["friction"],
                "weight_N": r["weight"],
                "axial_load_N": r["load"],
            }
            | (
                {"travel_mm": r["travel"] * 1e3}
                if t["from_cycle"]
                else {"travel_share": r["travel"]}
            )
            for r in t["rows"]
        ],
        "cubic_mean_load_N": {"positive": t["cubic_mean"][0], "negative": t["cubic_mean"][1]},
        "nut_equivalent_load_N": t["nut_equivalent"],
        "bearing_equivalent_load_N": t["bearing_equivalent"],
        "mean_speed_m_per_min": t["mean_speed"] * 60.0,
    }
