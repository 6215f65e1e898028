"""A machine solve (:class:`axisopt.machine.joint.MachineResult`) as text and as a dict for JSON."""

from __future__ import annotations

import textwrap

from ..machine.spec import DIRECTIONS

WIDTH = 100

_UNIT = {
    "cost": ("EUR", 1.0),
    "tool_stiffness": ("N/um", 1e-6),
    "frequency": ("Hz", 1.0),
    "moving_mass": ("kg", 1.0),
}
_LIMIT_UNIT = {
    "min_tool_stiffness": ("N/um", 1e-6),
    "min_frequency": ("Hz", 1.0),
    "max_cost": ("EUR", 1.0),
    "max_moving_mass": ("kg", 1.0),
}


def _val(objective: str, v: float) -> str:
    unit, f = _UNIT[objective]
    return f"{v * f:,.1f} {unit}"


def _design_lines(md, objective: str) -> list:
    L = []
    for a in md.axes:
        c = a.candidate
        arr = f", {c.arrangement}" if c.arrangement else ""
        L.append(f"  {a.name:<5} screw {c.screw}, nut {c.nut}, preload {c.nut_preload:,.0f} N")
        L.append(f"  {'':<5} bearing {c.bearing}, guide {c.guide}{arr}")
        L.append(
            f"  {'':<5} motor {c.motor or '-'}, coupling {c.coupling or '-'}, reduction "
            f"{c.reduction or '-'}"
        )
        L.append(
            f"  {'':<5} carries {a.carried:,.1f} kg, moves {a.lumped:,.1f} kg, cost {a.cost:,.0f} "
            "EUR"
        )
    L.append(
        "  stiffness at the tool, each link in N/um (axis part, frame under it; * an estimate):"
    )
    L.append(f"  {'axis':<5} " + " ".join(f"{d + ' (' + 'role' + ')':>24}" for d in DIRECTIONS))
    for a in md.axes:
        cells = []
        for i, _d in enumerate(DIRECTIONS):
            mark = "*" if a.frame_estimated else ""
            cells.append(
                f"{a.roles[i][:3]} {a.k_axis[i] * 1e-6:7.1f} | frm {a.k_frame[i] * 1e-6:6.0f}{mark}"
            )
        L.append(f"  {a.name:<5} " + " ".join(f"{c:>24}" for c in cells))
    L.append(f"  {'tool':<5} " + " ".join(f"{k * 1e-6:>24.1f}" for k in md.k_tool))
    for i, d in enumerate(DIRECTIONS):
        who, part = md.weakest(i)
        L.append(f"  k_{d} {md.k_tool[i] * 1e-6:.1f} N/um: most compliant link {who} ({part})")
    if md.k_tool_at_point:
        pts = ", ".join(f"{n} {s * 1e3:g} mm" for n, s in md.tool_point.items())
        L.append(
            f"  at the tool point ({pts}): "
            + ", ".join(f"k_{d} {k * 1e-6:.1f}" for d, k in zip(DIRECTIONS, md.k_tool_at_point))
            + " N/um"
        )
    d, who, role = md.lowest_at
    L.append(
        f"  lowest natural frequency {md.f_lowest:.1f} Hz ({d}-direction mode, most strain energy "
        f"in {who}'s {role} link); Dunkerley's bound {md.f_dunkerley:.1f} Hz"
    )
    L.append(f"  cost {md.cost:,.0f} EUR, moving masses {md.moving_mass:,.1f} kg")
    for key, v, lim in md.misses:
        unit, f = _LIMIT_UNIT[key.split(".")[0]]
        L.append(f"  misses {key}: {v * f:,.1f} against {lim * f:,.1f} {unit}")
    return L


def format_machine(res) -> str:
    """The joint optimum, the sequential sizing beside it and what the joint search gained."""
    m = res.machine
    L = [
        f"machine {m.name}: {len(m.axes)} axes "
        f"({', '.join(' <- '.join(a.name for a in ch) for ch in m.branches())}"
        f" on the frame), objective {m.objective}, method {res.method}"
    ]
    nominal = (
        f"{res.nominal_combinations:.3g} nominal joint combinations"
        if res.nominal_combinations > 0
        else "nominal joint combinations not counted (the search ended before every axis)"
    )
    kept = ", ".join(f"{k} {v}" for k, v in res.offers.items()) or "none"
    L.append(f"status {res.status}: {nominal}, {res.axis_solves} axis solves, offers kept {kept}")
    L.append(f"time {res.time:.1f} s")
    if res.best is None:
        L.append("no combination of the axes' designs meets every machine and axis limit")
    else:
        L.append("")
        L.append(f"joint optimum: {_val(m.objective, res.best.value(m.objective))}")
        L += _design_lines(res.best, m.objective)
    L.append("")
    if res.sequential is None:
        L.append(
            "sequential sizing (top axis first): an axis has no feasible design at the mass "
            "carried to it"
        )
    else:
        seq = res.sequential
        L.append(
            "sequential sizing (top axis first, each alone at its best, its mass carried down): "
            f"{_val(m.objective, seq.value(m.objective))}"
            f"{'' if seq.feasible else ', misses the machine limits'}"
        )
        L += _design_lines(seq, m.objective)
        if res.best is not None:
            L.append("")
            if not seq.feasible:
                L.append(
                    "the joint search gained: a machine that meets every limit (the sequential one "
                    "does not)"
                )
            elif abs(res.gain) <= 1e-9 * max(1.0, abs(res.best.value(m.objective))):
                L.append("the joint search gained: the same")
            else:
                L.append(
                    f"the joint search gained: {_val(m.objective, abs(res.gain))} "
                    f"({'less' if m.objective in ('cost', 'moving_mass') else 'more'})"
                )
    for n in res.notes:
        L.append(f"note: {n}")
    return "\n".join(
        w
        for line in L
        for w in (
            textwrap.wrap(line, WIDTH, subsequent_indent="    ") if len(line) > WIDTH else [line]
        )
    )


def format_evaluation(ev) -> str:
    """A machine of chosen parts (:class:`axisopt.machine.evaluate.MachineEvaluation`): every axis,
    the stiffness chain at the tool with each link, the frequencies and the machine limits it
    misses."""
    m = ev.machine
    L = [
        f"machine {m.name}: {len(m.axes)} axes "
        f"({', '.join(' <- '.join(a.name for a in ch) for ch in m.branches())}"
        " on the frame), its parts as chosen"
    ]
    if ev.design is None:
        for name, load in ev.failed:
            L.append(
                f"axis {name}: its parts miss its own limits carrying {load:,.1f} kg (evaluate it "
                "alone with `axisopt solve`, whose answer says which limit)"
            )
    else:
        L += _design_lines(ev.design, m.objective)
        L.append(
            "meets every machine limit" if ev.design.feasible else "misses a machine limit (above)"
        )
    return "\n".join(
        w
        for line in L
        for w in (
            textwrap.wrap(line, WIDTH, subsequent_indent="    ") if len(line) > WIDTH else [line]
        )
    )


def machine_dict(res) -> dict:
    """The result as plain data for JSON (:func:`axisopt.machine.record.result_dict`)."""
    from ..machine.record import result_dict

    return result_dict(res)
