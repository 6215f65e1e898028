"""The positioning-error budget of the axis: one row per cause THK lists ("Studying the Positioning
Accuracy", General Catalog A-712..A-716; :mod:`axisopt.physics.accuracy`), each the largest
deviation over the stroke [m]:

* ``lead_error``: the screw's lead error over the stroke by its grade (a parameter:
  :mod:`axisopt.catalog.grades`);
* ``thermal_error``: the thermal growth at the nut over the stroke (:mod:`.chain`) at the
  temperature rise of the heat balance with the nut at its highest catalog preload (the hottest
  it runs: conservative; a stated ``axis.temperature_rise`` instead where the axis gives one), so
  that the row does not rise with the preload and the search's one-sided preload solve stays exact
  (model.limits.OUTPUT_PRELOAD);
* ``elastic_error``: the deflection at the tool under the process force (``axis.axial_load``) at the
  softest point of the stroke (:func:`softest_compliance`): the stiffness chain in series with the
  table's rocking (:func:`.carriage.tool_stiffness`);
* ``abbe_error``: the guides' running pitch times the tool's height above the screw axis plus their
  yaw times the tool's offset across it (THK A-716 eq. 39; ``axis.guide_pitch`` /
  ``axis.guide_yaw``, default 0);
* ``lost_motion``: the nut's axial play (0 for a preloaded nut) and a reduction's backlash
  (:func:`.drive.lost_motion`).

``positioning_error`` adds them arithmetically (worst case:
:func:`axisopt.physics.accuracy.worst_case_total`); it does not rise with the nut preload (the
elastic row falls, the others stay), as model.limits declares.  ``repeatability`` is ISO 230-2's
scatter (:func:`axisopt.physics.accuracy.repeatability_iso`): the reversal (lost motion) and the
noise band (a scale's read head; a motor encoder's counts, negligible); the thermal drift is its own
row, not repeatability.
"""

from __future__ import annotations

from .. import mathx as mx
from ..physics import accuracy as pa
from ..physics import thermal as pt
from .carriage import tool_stiffness
from .chain import stiffness_chain
from .drive import lost_motion
from .heat import heat_balance
from .loads import bearing_set_stiffness

BUDGET_ROWS = ("lead_error", "thermal_error", "elastic_error", "abbe_error", "lost_motion")
BUDGET_OUTPUTS = BUDGET_ROWS + ("positioning_error", "repeatability")


def softest_compliance(p, mounting: str, preload, axial_force, mean_force, rock):
    """The largest compliance at the tool over the stroke [m/N]: the chain's, each
    position-dependent term at its worst, plus the table's rocking.  The screw's torsion softens
    with the distance from the fixed bearing (worst at the stroke's far end); the screw with its
    bearings is softest there too, except on a fixed-fixed screw, where it is softest at mid-span
    (within the stroke).  Exact for fixed-free and fixed-supported; for fixed-fixed the two worst
    terms come from two positions, a slight overestimate (conservative)."""
    end = p["start_offset"] + p["stroke"]
    k_end = stiffness_chain(p, end, mounting, preload, axial_force, mean_force)
    c = 1.0 / k_end["k_total"]
    if mounting == "fixed-fixed":
        mid = mx.fmin(mx.fmax(0.5 * p["span"], p["start_offset"]), end)
        k_mid = stiffness_chain(p, mid, mounting, preload, axial_force, mean_force)
        c = c + mx.fmax(1.0 / k_mid["k_screw_bearings"] - 1.0 / k_end["k_screw_bearings"], 0.0)
    return 1.0 / tool_stiffness(p, 1.0 / c, rock)["k_tool"]


def thermal_growth_at(p, rise):
    """Largest thermal growth at the nut over the stroke [m] at a temperature rise [K] (as
    :mod:`.chain`)."""
    k_set = bearing_set_stiffness(p)
    ends = [
        mx.fabs(
            pt.thermal_displacement(
                xe, p["span"], p["root_diameter"], rise, k_set, p["bearing_sets"] - 1.0
            )
        )
        for xe in (p["start_offset"], p["start_offset"] + p["stroke"])
    ]
    return mx.fmax(ends[0], ends[1])


def positioning_budget(p, mounting: str, preload, axial_force, mean_force, rock) -> dict:
    """The budget's rows, total and repeatability [m] (module docstring).  ``p`` at the model's
    temperature rise (:func:`.response.loaded`), ``axial_force`` and ``mean_force`` as the stiffness
    chain takes them, ``rock`` the table's rocking (:func:`.carriage.rocking`).  Floats, numpy
    arrays or CasADi like the model."""
    # the rise the model uses where no heat balance sets it (a stated rise, or no duty cycle:
    # Python-level flag, as model.heat), else the balance at the nut's highest preload
    flag = getattr(p.get("duty", ()), "heat", None)
    hot = (
        p["temperature_rise"]
        if flag is False
        else heat_balance(p, p["nut_preload_max"])["temperature_rise"]
    )
    thermal = thermal_growth_at(p, hot)
    k_soft = 1.0 / softest_compliance(p, mounting, preload, axial_force, mean_force, rock)
    elastic = pa.stiffness_positioning_error(p["axial_load"], k_soft)
    abbe = pa.abbe_error(p["tool_height"], p["guide_pitch"]) + pa.abbe_error(
        p["tool_offset"], p["guide_yaw"]
    )
    lost = lost_motion(p)
    # a linear scale on the table (p["scale_feedback"] 1): its error in place of the lead row, and
    # the screw's thermal growth out of the loop (the scale measures the table, not the screw)
    scale = p.get("scale_feedback", 0.0)
    lead = (1.0 - scale) * p["lead_error"] + scale * p.get("scale_error", 0.0) + 0.0 * elastic
    thermal = (1.0 - scale) * thermal
    noise = scale * p.get("scale_repeatability", 0.0) + 0.0 * elastic
    return {
        "lead_error": lead,
        "thermal_error": thermal,
        "elastic_error": elastic,
        "abbe_error": abbe + 0.0 * elastic,
        "lost_motion": lost + 0.0 * elastic,
        "positioning_error": pa.worst_case_total(lead, thermal, elastic, abbe, lost),
        "repeatability": pa.repeatability_iso(lost, noise),
    }
