"""Reports of ``axisopt evaluate --methods`` and ``--frf``: text table, JSON dicts, the FRF plot.

Vendor units (N/um, um/N, Hz, deg).  Nothing here prints.
"""

from __future__ import annotations

import math

import numpy as np

from ..fileio import save_figure, tidy_layout
from ..units import N_PER_UM


def _num(v):
    """A finite float for JSON, else None."""
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def methods_table(rows) -> str:
    """Text table of :func:`axisopt.model.methods.stiffness_methods` rows in N/um, ``*`` on the used value."""
    lines = ["stiffness by method [N/um]   (* the value the model uses)",
             f"  {'component':<10}{'method':<34}{'value':>10}  note"]
    last = None
    for r in rows:
        comp = r.component if r.component != last else ""
        last = r.component
        mark = "*" if r.used else " "
        if r.value_N_per_m is None:
            shown = "-"
            note = f"missing: {', '.join(r.missing)}" + (f"; {r.note}" if r.note else "")
        else:
            shown = f"{r.value_N_per_m / N_PER_UM:,.1f}"
            note = r.note
        lines.append(f"{mark} {comp:<10}{r.method:<34}{shown:>10}  {note}".rstrip())
    return "\n".join(lines)


def methods_dict(rows) -> dict:
    """JSON-ready stiffness methods: values in N/um, None where an input is missing."""
    return {
        "unit": "N/um",
        "methods": [{
            "component": r.component,
            "method": r.method,
            "source": r.source,
            "value_N_per_um": None if r.value_N_per_m is None else _num(r.value_N_per_m / N_PER_UM),
            "used": bool(r.used),
            "missing": list(r.missing),
            "note": r.note,
        } for r in rows],
    }


def frf_dict(result: dict) -> dict:
    """JSON-ready dynamic compliance of :func:`axisopt.model.frf.frf` (um/N, deg, Hz)."""
    return {
        "motor_held": bool(result["motor_held"]),
        "frequency_Hz": [float(f) for f in result["frequency_Hz"]],
        "positions": [{
            "position_mm": float(q["position_mm"]),
            "modes_Hz": [_num(f) for f in q["modes_Hz"]],
            "magnitude_um_per_N": [_num(v) for v in q["magnitude_um_per_N"]],
            "phase_deg": [_num(v) for v in q["phase_deg"]],
        } for q in result["positions"]],
    }


def plot_frf(result: dict, path: str | None = None):
    """Magnitude (log-log, um/N) and phase of the table compliance, one line per nut position, the modes
    as dashed vertical lines in the same colour.  Returns the matplotlib Figure; written to ``path`` only
    when given."""
    from matplotlib.figure import Figure

    f = np.asarray(result["frequency_Hz"], dtype=float)
    fig = Figure(figsize=(7, 6))
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    names = ("stroke start", "mid-stroke", "stroke end")
    for j, q in enumerate(result["positions"]):
        color = f"C{j}"
        name = names[j] if j < len(names) and len(result["positions"]) == 3 else "nut"
        modes = [m for m in q["modes_Hz"] if m is not None and math.isfinite(m)]
        label = f"{name} {q['position_mm']:.0f} mm (modes " + ", ".join(f"{m:.0f}" for m in modes) + " Hz)"
        ax1.loglog(f, q["magnitude_um_per_N"], color=color, label=label)
        ax2.semilogx(f, q["phase_deg"], color=color)
        for m in modes:
            if f[0] <= m <= f[-1]:
                for ax in (ax1, ax2):
                    ax.axvline(m, color=color, linestyle="--", linewidth=0.8, alpha=0.7)
    held = "motor held" if result.get("motor_held") else "motor free"
    ax1.set_title(f"{result.get('design', '')}: table compliance X/F ({held})", fontsize=10)
    ax1.set_ylabel("compliance [um/N]")
    ax2.set_ylabel("phase [deg]")
    ax2.set_xlabel("frequency [Hz]")
    for ax in (ax1, ax2):
        ax.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=8)
    tidy_layout(fig)
    if path is not None:
        save_figure(fig, path)
    return fig
