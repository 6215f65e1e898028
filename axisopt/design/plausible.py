"""Values far outside machine-tool practice: warned about, not refused (a test rig or a unit slip both happen).

A feed axis of a machine tool accelerates at about 0.5-15 m/s^2 with a ball screw and up to about 50 m/s^2 with a
linear motor, runs its rapids at 1-120 m/min, moves 1 kg (a laser head) to 50 t (a boring-mill table), over strokes
of about 50 mm to 20 m.  The ranges below are wider by a factor of a few on each side (estimates from the shipped
problems and the vendors' catalog ranges, docs/assumptions.md): a value outside is most often a unit slip (mm/s^2
written for m/s^2, m/min for mm/min), which the warning names.  One table, one declaration per key.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Range:
    key: str  # axis key
    low: float  # [SI]
    high: float  # [SI]
    unit: str  # display unit
    factor: float  # SI -> display


RANGES = (
    Range("acceleration", 0.1, 50.0, "m/s^2", 1.0),
    Range("max_speed", 0.5 / 60.0, 200.0 / 60.0, "m/min", 60.0),
    Range("moving_mass", 0.5, 100e3, "kg", 1.0),
    Range("stroke", 5e-3, 30.0, "mm", 1e3),
)


def implausible(values: dict) -> list:
    """(key, message) for each given value of ``values`` ({axis key: SI value}) outside :data:`RANGES` (0 and
    absent values are left to the readers: 0 means 'none' where a key allows it)."""
    out = []
    for r in RANGES:
        v = values.get(r.key)
        if v is None or v == 0 or r.low <= v <= r.high:
            continue
        side = "below" if v < r.low else "above"
        out.append((r.key, f"{v * r.factor:.4g} {r.unit} is far {side} machine-tool practice "
                           f"({r.low * r.factor:g}-{r.high * r.factor:g} {r.unit}): check the value and its unit"))
    return out
