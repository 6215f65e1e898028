"""The estimated part values of one design (values not in the vendor's table) and what each moves:
the key outputs and the checks near their limit; and the counterbalance block (cylinder or weight
against the load).  Nothing here prints."""

from __future__ import annotations

import math
import textwrap

from ..model import CHECKS, Evaluation
from ..model.limits import check_name, margin_output
from ..model.loads import balance_summary
from ..model.params import axis_params
from .text import WIDTH


def _balance(ev: Evaluation) -> dict:
    d = ev.design
    p = axis_params(d.axis, d.screw, d.nut, d.bearing, d.guide, d.motor, d.coupling, d.reduction)
    return {k: float(x) for k, x in balance_summary(p, float(ev.values["moving_mass"])).items()}


def counterbalance_dict(ev: Evaluation) -> dict:
    """A counterbalance's kind and sizes and what it takes off the head [N] (JSON)."""
    cb = ev.design.axis.counterbalance
    b = _balance(ev)
    sizes = (
        {"mass_kg": cb.mass, "efficiency": cb.efficiency, "chain_mass_kg": cb.chain_mass}
        if cb.kind == "counterweight"
        else {
            "force_N": cb.force,
            "force_at_end_N": cb.force_end,
            "tolerance": cb.tolerance,
            "piston_mass_kg": cb.piston_mass,
        }
    )
    return {
        "kind": cb.kind,
        **sizes,
        "force_at_rest_N": b["rest"],
        "force_rising_N": b["rising"],
        "force_lowering_N": b["lowering"],
        "head_weight_N": b["weight"],
        "net_weight_on_screw_N": b["net"],
    }


def counterbalance_lines(ev: Evaluation) -> list:
    """``evaluate``'s counterbalance line: what it is and the weight it leaves on the screw."""
    cb = ev.design.axis.counterbalance
    if cb is None:
        return []
    b = _balance(ev)
    if cb.kind == "counterweight":
        what = (
            f"counterweight {cb.mass:,.0f} kg (chain efficiency {cb.efficiency:g}"
            + (f", chain {cb.chain_mass:g} kg" if cb.chain_mass else "")
            + f"): {b['rest']:,.0f} N up at rest, "
            f"{b['rising']:,.0f} N rising, {b['lowering']:,.0f} N lowering"
        )
    else:
        what = (
            f"cylinder {cb.force:,.0f}..{cb.force_end:,.0f} N over the stroke +/- "
            f"{cb.tolerance * 100:g} %: {b['rest']:,.0f} N taken (the end that loads the drive "
            "most)"
        )
    text = (
        f"counterbalance: {what}; the screw carries {b['net']:,.0f} N of the head's "
        f"{b['weight']:,.0f} N at rest"
    )
    return textwrap.wrap(text, WIDTH, initial_indent="  ", subsequent_indent="    ")


# outputs an evaluation names the estimates of (besides the checks near their limit)
_EST_OUTPUTS = (
    ("k_total", "min stiffness"),
    ("f1", "min frequency"),
    ("drag_torque", "drag torque"),
    ("life", "nut life"),
)


NEAR_LIMIT = 1.1  # a check with margin below this counts as near its limit


# defaults the life, torque and heat checks read, shown with their value: (axis attribute, display
# unit, SI per unit) (the temperature rise has its own line: the thermal block says where it comes
# from)
_DEFAULT_VALUES = {
    "mean_axial_load": ("mean_axial_load_eff", "N", 1.0),
    "mean_speed": ("mean_speed_eff", "m/min", 1 / 60),
    "required_life": ("required_life", "h", 3600.0),
    "load_factor": ("load_factor_eff", "", 1.0),
}


def default_shown(axis, key: str) -> str:
    """A defaulted axis key as the evaluation names it: with its value where the checks read it."""
    if key not in _DEFAULT_VALUES:
        return key
    attr, unit, factor = _DEFAULT_VALUES[key]
    value = getattr(axis, attr, None)
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        return key
    from ..model.estimates import axis_value_text

    return f"{key} {axis_value_text(value / factor, unit)}"


def estimates(ev: Evaluation) -> list:
    """[(Estimate, [what it moves])] for the design's estimated part values except prices (which
    move only the cost and are always illustrative): the key outputs and the checks within 10 % of
    their limit."""
    from ..model.estimates import design_estimates, resting_on

    est = [e for e in design_estimates(ev.design) if "price" not in e.column]
    if not est:
        return []
    near = [margin_output(c) for c in CHECKS if float(ev.values[margin_output(c)]) < NEAR_LIMIT]
    names = dict(_EST_OUTPUTS) | {m: f"check {check_name(m).replace('_', ' ')}" for m in near}
    moved = resting_on(ev.design, list(names), est)
    return [(e, [names[o] for o in names if any(x is e for x in moved.get(o, ()))]) for e in est]


def estimate_lines(ev: Evaluation) -> list:
    rows = [(e, w) for e, w in estimates(ev) if w]
    if not rows:
        return []
    out = [
        "",
        "estimated values (not in the vendor's table; catalogs/SOURCES.md) and what they move:",
    ]
    for e, what in rows:
        out.extend(
            textwrap.wrap(
                f"{e.text()} moves {', '.join(what)}",
                WIDTH,
                initial_indent="  ",
                subsequent_indent="      ",
            )
        )
    return out
