"""The life checks' load table of one design, as the vendors print it in their worked examples (THK
A-725 to A-730: the axial load and travel of each motion, the cubic-mean load, the mean speed, the
life): the rows :func:`axisopt.model.loads.life_rows` gives the nut and support-bearing checks, and
the equivalent loads those checks rate (:func:`axisopt.model.checks.nut_life_load`,
:func:`axisopt.model.checks.bearing_life_load`).  Floats only: for ``evaluate``; the search reads
the checks' margins."""

from __future__ import annotations

import math

from ..design import Design
from ..physics import life as pl
from .checks import bearing_life_load, nut_life_load
from .function import design_params
from .loads import life_rows
from .response import loaded


def life_table(design: Design) -> dict:
    """The load cases of the life checks and their equivalent loads (SI).

    Returns ``rows`` (:func:`axisopt.model.loads.life_rows`: load [N], travel [m], direction,
    acceleration [m/s^2], mass [kg], friction, process force, weight [N]), ``from_cycle`` (the rows
    come from the user's duty cycle, else from the mean axial load), ``cubic_mean`` the cubic-mean
    load of each direction [N] (+, -; THK A-706), ``nut_equivalent`` and ``bearing_equivalent`` the
    loads on the nut's and the set's ratings that give their L10 lives [N] and ``mean_speed`` [m/s].
    """
    preload = design.preload
    p, _, m, loads = loaded(design_params(design), preload)
    rows = life_rows(p, m["moving_mass"], loads["guide_friction"])
    forces, travels = [r["load"] for r in rows], [r["travel"] for r in rows]
    plus, minus = pl.directional_means(forces, travels)
    return {
        "rows": rows,
        "from_cycle": bool(getattr(p.get("duty", ()), "given", False)),
        "cubic_mean": (float(plus), float(minus)),
        "nut_equivalent": float(nut_life_load(p, preload, forces, travels)),
        "bearing_equivalent": float(
            bearing_life_load(p, forces, travels, loads["bearing_static_load"])
        ),
        "mean_speed": float(p["mean_speed"]),
    }


def table_rows_finite(table: dict) -> bool:
    """True when every number of a :func:`life_table` is finite (a guard for the printed table)."""
    nums = [v for r in table["rows"] for v in r.values()] + list(table["cubic_mean"])
    nums += [table["nut_equivalent"], table["bearing_equivalent"], table["mean_speed"]]
    return all(math.isfinite(float(v)) for v in nums)
