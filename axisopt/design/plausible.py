"""Values far outside machine-tool practice: warned about, not refused (a test rig or a unit slip
both happen).

A feed axis of a machine tool accelerates at about 0.5-15 m/s^2 with a ball screw and up to about 50
m/s^2 with a linear motor, runs its rapids at 1-120 m/min, moves 1 kg (a laser head) to 50 t (a
boring-mill table), over strokes of about 50 mm to 20 m.  The ranges below are wider by a factor of
a few on each side (estimates from the shipped problems and the vendors' catalog ranges,
docs/assumptions.md): a value outside is most often a unit slip (mm/s^2 written for m/s^2, m/min for
mm/min), which the warning names.  One table, one declaration per key.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..display import fmt


@dataclass(frozen=True)
class Range:
    key: str  # axis key
    low: float  # [SI]
    high: float  # [SI]
    unit: str  # display unit
    factor: float  # SI -> display


# forces: a feed axis's cutting force is tens of N (a laser head) to about 100 kN (a heavy boring
# mill); lives: a machine is specified for about 5 000-50 000 h (THK A-704's examples; 20 000 h is
# the common one).  A force in MN, a life in s or min, an acceleration in mm/s^2 read as m/s^2 fall
# outside.
RANGES = (
    Range("acceleration", 0.1, 50.0, "m/s^2", 1.0),
    Range("max_speed", 0.5 / 60.0, 200.0 / 60.0, "m/min", 60.0),
    Range("mean_speed", 0.05 / 60.0, 200.0 / 60.0, "m/min", 60.0),
    Range("moving_mass", 0.5, 100e3, "kg", 1.0),
    Range("stroke", 5e-3, 30.0, "mm", 1e3),
    Range("axial_load", 0.0, 500e3, "N", 1.0),
    Range("mean_axial_load", 0.0, 500e3, "N", 1.0),
    Range("normal_load", 0.0, 500e3, "N", 1.0),
    Range("cross_load", 0.0, 500e3, "N", 1.0),
    Range("required_life", 100 * 3600.0, 300e3 * 3600.0, "h", 1 / 3600.0),
)
# a duty cycle's largest process force (the same range as axis.axial_load)
CYCLE_RANGES = (Range("duty_cycle", 0.0, 500e3, "N", 1.0),)
# the problem's limits with a typical unit slip (the same ranges where the quantity is the same)
LIMIT_RANGES = (
    Range("min_life", 100 * 3600.0, 300e3 * 3600.0, "h", 1 / 3600.0),
    Range("max_moving_mass", 0.5, 100e3, "kg", 1.0),
    Range("max_total_mass", 0.5, 200e3, "kg", 1.0),
    Range("min_stiffness", 0.5e6, 50e3 * 1e6, "N/um", 1e-6),
    Range("min_tool_stiffness", 0.5e6, 50e3 * 1e6, "N/um", 1e-6),
    Range("min_frequency", 1.0, 5e3, "Hz", 1.0),
    Range("max_cost", 50.0, 5e6, "EUR", 1.0),
)


def implausible(values: dict, ranges=RANGES) -> list:
    """(key, message) for each given value of ``values`` ({axis key: SI value}) outside
    :data:`RANGES` (0 and absent values are left to the readers: 0 means 'none' where a key allows
    it); ``ranges``: another table (:data:`LIMIT_RANGES`)."""
    out = []
    for r in ranges:
        v = values.get(r.key)
        if v is None or v == 0 or r.low <= v <= r.high:
            continue
        side = "below" if v < r.low else "above"
        out.append(
            (
                r.key,
                f"{fmt(v * r.factor, r.unit)} is far {side} machine-tool practice "
                f"({fmt(r.low * r.factor)}-{fmt(r.high * r.factor, r.unit)}): check the value and "
                "its unit",
            )
        )
    return out
