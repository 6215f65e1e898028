"""Cost of the axis parts (catalog prices; the shipped ones are illustrative)."""

from __future__ import annotations

from .gantry import pair_cost


def cost(p):
    """Screw by length plus end machining (times its lead accuracy grade's price factor,
    axisopt.catalog.grades), nut, bearing sets, guide blocks, rails, motor, coupling and reduction
    [EUR]; a twin drive: the second drive's parts too (:func:`axisopt.model.gantry.pair_cost`)."""
    return (
        (p["screw_price_per_length"] * p["span"] + p["screw_price_fixed"]) * p["grade_price_factor"]
        + p["nut_price"]
        + p["bearing_sets"] * p["bearing_price"]
        + p["guide_blocks"] * p["guide_block_price"]
        + p["rails"] * p["rail_length"] * p["guide_rail_price_per_length"]
        + p["motor_price"]
        + p["coupling_price"]
        + p["reduction_price"]
    ) + pair_cost(p)
