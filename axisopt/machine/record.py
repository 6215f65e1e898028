"""A machine solve as plain data (for JSON, a study's case records and the reports): every axis's
parts, the stiffness chain at the tool (each link per direction: the axis part, the frame under it,
the two in series), the lumped chain's frequencies, Dunkerley's bound, the misses; the sequential
sizing beside the joint optimum.
"""

from __future__ import annotations

from .spec import DIRECTIONS


def design_dict(md) -> dict:
    """One machine design (:class:`.model.MachineDesign`) in display units (N/um, Hz, kg, EUR,
    mm)."""
    return {
        "feasible": md.feasible,
        "cost_eur": md.cost,
        "moving_mass_kg": md.moving_mass,
        "k_tool_n_per_um": dict(zip(DIRECTIONS, (k * 1e-6 for k in md.k_tool))),
        "lowest_frequency_hz": md.f_lowest,
        "dunkerley_hz": md.f_dunkerley,
        "lowest_mode": {
            "direction": md.lowest_at[0],
            "axis": md.lowest_at[1],
            "link": md.lowest_at[2],
        },
        "frequencies_hz": {
            f"{'/'.join(md.branches[b])}:{d}": list(f) for (b, d), f in md.frequencies.items()
        },
        "misses": [{"limit": k, "value": v, "bound": b} for k, v, b in md.misses],
        "tool_point_mm": {n: v * 1e3 for n, v in md.tool_point.items()},
        "k_tool_at_point_n_per_um": dict(zip(DIRECTIONS, (k * 1e-6 for k in md.k_tool_at_point))),
        "most_compliant": {
            d: dict(zip(("axis", "part"), md.weakest(i))) for i, d in enumerate(DIRECTIONS)
        },
        "axes": [
            {
                "name": a.name,
                **a.candidate.parts(),
                "nut_preload_n": a.candidate.nut_preload,
                "arrangement": a.candidate.arrangement,
                "carried_kg": a.carried,
                "lumped_mass_kg": a.lumped,
                "cost_eur": a.cost,
                "parts_mass_kg": a.parts_mass,
                "counterweight_kg": a.counterweight,
                "link_n_per_um": {
                    d: {
                        "role": a.roles[i],
                        "axis": a.k_axis[i] * 1e-6,
                        "frame": a.k_frame[i] * 1e-6,
                        "frame_estimated": a.frame_estimated,
                        "link": a.k_link[i] * 1e-6,
                    }
                    for i, d in enumerate(DIRECTIONS)
                },
            }
            for a in md.axes
        ],
    }


def result_dict(res) -> dict:
    """A :class:`.joint.MachineResult`: the joint optimum, the sequential sizing and how the search
    went."""
    m = res.machine
    return {
        "machine": m.name,
        "objective": m.objective,
        "method": res.method,
        "status": res.status,
        "nominal_combinations": res.nominal_combinations,
        "axis_solves": res.axis_solves,
        "offers_kept": dict(res.offers),
        "time_s": res.time,
        "notes": list(res.notes),
        "best": None if res.best is None else design_dict(res.best),
        "sequential": None if res.sequential is None else design_dict(res.sequential),
        "gain": res.gain,
    }


__all__ = ["design_dict", "result_dict"]
