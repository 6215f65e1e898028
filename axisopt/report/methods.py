"""Reports of ``axisopt evaluate --methods`` and ``--frf``: text table, JSON dicts, the FRF plot.

Vendor units (N/um, um/N, Hz, deg).  Nothing here prints.
"""

from __future__ import annotations

import math
import textwrap

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
    """Text table of :func:`axisopt.model.methods.stiffness_methods` rows in N/um, ``*`` on the used
    value."""
    lines = [
        "stiffness by method [N/um]   (* the value the model uses)",
        f"  {'component':<10}{'method':<34}{'value':>10}  note",
    ]
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
        head = f"{mark} {comp:<10}{r.method:<34}{shown:>10}  "
        lines += (
            textwrap.wrap(head + note, 100, subsequent_indent=" " * len(head))
            if note
            else [head.rstrip()]
        )
    return "\n".join(lines)


def methods_dict(rows) -> dict:
    """JSON-ready stiffness methods: values in N/um, None where an input is missing."""
    return {
        "unit": "N/um",
        "methods": [
            {
                "component": r.component,
                "method": r.method,
                "source": r.source,
                "value_N_per_um": None
                if r.value_N_per_m is None
                else _num(r.value_N_per_m / N_PER_UM),
                "used": bool(r.used),
                "missing": list(r.missing),
                "note": r.note,
            }
            for r in rows
        ],
    }


def _curves(result: dict) -> list:
    return [
        {
            "position_mm": float(q["position_mm"]),
            "modes_Hz": [_num(f) for f in q.get("modes_Hz", ())],
            "magnitude_um_per_N": [_num(v) for v in q["magnitude_um_per_N"]],
            "phase_deg": [_num(v) for v in q["phase_deg"]],
        }
        for q in result["positions"]
    ]


def frf_dict(result: dict, held: dict | None = None, closed: dict | None = None) -> dict:
    """JSON-ready dynamic compliance of :func:`axisopt.model.frf.frf` (um/N, deg, Hz); with ``held``
    (the same with the motor held, the headline first frequency's model) and ``closed`` (the
    closed-loop compliance at the tool with the tuned servo, :func:`closed_loop_frf`) on the same
    grid."""
    out = {
        "motor_held": bool(result["motor_held"]),
        "frequency_Hz": [float(f) for f in result["frequency_Hz"]],
        "positions": _curves(result),
    }
    if held is not None:
        out["motor_held_positions"] = _curves(held)
    if closed is not None:
        out["closed_loop"] = {"kv_per_s": float(closed["kv"]), "positions": _curves(closed)}
    return out


def closed_loop_frf(ev, freqs) -> dict:
    """The closed-loop compliance at the tool x_tool / F with the tuned servo
    (:mod:`axisopt.model.servo`) at stroke start, middle and end, in the layout of
    :func:`axisopt.model.frf.frf`."""
    from ..model.frf import frf_positions
    from ..model.servo import frequency_response, tune

    g = tune(ev)
    s = ev.x - ev.design.axis.start_offset
    pos = []
    for i, h in zip(frf_positions(ev), frequency_response(ev, freqs, g)):
        pos.append(
            {
                "index": i,
                "position_mm": float(s[i] * 1e3),
                "compliance_m_per_N": h,
                "magnitude_um_per_N": np.abs(h) * 1e6,
                "phase_deg": np.degrees(np.unwrap(np.angle(h))),
                "modes_Hz": (),
            }
        )
    return {
        "design": ev.design.name,
        "kv": g.kv,
        "frequency_Hz": np.asarray(freqs, float),
        "positions": pos,
    }


def plot_frf(
    result: dict, path: str | None = None, held: dict | None = None, closed: dict | None = None
):
    """Magnitude (log-log, um/N) and phase of the table compliance, one colour per nut position, the
    modes as vertical lines in the same colour.  With ``held`` and ``closed``: the motor-held curve
    (solid, its first mode the headline first frequency), the motor-free one (dashed) and the closed
    loop with the tuned servo (dotted), each labelled.  Returns the matplotlib Figure; written to
    ``path`` only when given."""
    from ..figure import Figure

    f = np.asarray(result["frequency_Hz"], dtype=float)
    fig = Figure(figsize=(7, 6.5 if held is not None else 6))
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    names = ("stroke start", "mid-stroke", "stroke end")
    own = "motor held" if result.get("motor_held") else "motor free"
    sets = [(result, "--" if held is not None else "-", own)]
    if held is not None:
        sets.insert(0, (held, "-", "motor held"))
    if closed is not None:
        sets.append((closed, ":", f"servo Kv {closed['kv']:.0f}/s"))
    for j in range(len(result["positions"])):
        color = f"C{j}"
        name = names[j] if j < len(names) and len(result["positions"]) == 3 else "nut"
        for res, style, what in sets:
            q = res["positions"][j]
            modes = [m for m in q.get("modes_Hz", ()) if m is not None and math.isfinite(m)]
            shown = f" (modes {', '.join(f'{m:.0f}' for m in modes)} Hz)" if modes else ""
            label = (
                f"{name} {q['position_mm']:.0f} mm, {what}{shown}"
                if len(sets) > 1
                else f"{name} {q['position_mm']:.0f} mm{shown}"
            )
            ax1.loglog(
                f,
                q["magnitude_um_per_N"],
                color=color,
                linestyle=style,
                label=label,
                linewidth=1.0 if style != "-" else 1.4,
            )
            ax2.semilogx(f, q["phase_deg"], color=color, linestyle=style, linewidth=1.0)
            if style in ("-", "--") and modes:
                for m in modes[:1] if style == "-" and len(sets) > 1 else modes:
                    if f[0] <= m <= f[-1]:
                        for ax in (ax1, ax2):
                            ax.axvline(m, color=color, linestyle=style, linewidth=0.7, alpha=0.5)
    title = (
        "table compliance X/F: motor held (-), free (--), with the servo (:)"
        if len(sets) > 1
        else f"table compliance X/F ({own})"
    )
    ax1.set_title(f"{result.get('design', '')}: {title}", fontsize=9)
    ax1.set_ylabel("compliance [um/N]")
    ax2.set_ylabel("phase [deg]")
    ax2.set_xlabel("frequency [Hz]")
    for ax in (ax1, ax2):
        ax.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=6 if len(sets) > 1 else 8, ncol=1)
    tidy_layout(fig)
    if path is not None:
        save_figure(fig, path)
    return fig
