"""What a table diagnosis cannot tell apart or leaves unexplained: the parameters the data do not
identify, the other explanations that fit as well, and the residual signatures no effect explains
(as JSON-ready dicts).  Nothing here prints."""

from __future__ import annotations

import math

from ..identify.tables.diagnose import plausibility
from ..identify.tables.unexplained import display_value, table_signature


def unexplained_dicts(diag) -> list:
    """Per dataset: is structure left in the final residual, and its signatures in words."""
    out = []
    for u in diag.unexplained:
        sigs = []
        for p in u.remaining:
            what, causes, measure = table_signature(p, display_value)
            sigs.append(
                {
                    "factor": p.kind,
                    "share": p.share,
                    "log10_p": p.log10_p,
                    "signature": what,
                    "causes": causes,
                    "to_separate": measure,
                }
            )
        out.append(
            {
                "file": u.source,
                "test": u.kind,
                "rms_over_noise": u.rms,
                "remaining": bool(sigs),
                "signatures": sigs,
            }
        )
    return out


def why_none(d) -> str:
    first = [c for c in d["not_accepted"] if c["round"] == 1][:3]
    if not first:
        return "no candidate effect applies to these data"
    return "; ".join(f"{c['effect']}: {c['reason']}" for c in first)


def plausibility_flags(res):
    return plausibility(res, []) + unidentifiable(res)


def unidentifiable(res, names=None) -> list:
    """Parameters the data do not fix (infinite variance: a zero or dependent Jacobian column)."""
    return [
        f"{p.name} is not identifiable from these data: the fit does not change with it (it is "
        "reported at the value the search stopped at, without an uncertainty)"
        for p, s in zip(res.params, res.sigma)
        if not math.isfinite(s) and (names is None or p.name in names)
    ]


def undetermined_notes(res, names) -> list:
    """Parameters whose standard deviation exceeds their value: the data do not fix them."""
    out = []
    for p, v, s in zip(res.params, res.theta, res.sigma):
        if p.name in names and math.isfinite(s) and v != 0 and s > abs(v):
            out.append(
                f"{p.name} not determined by these data (+-{p.show(s):.3g} on {p.show(v):.4g} "
                f"{p.unit})"
            )
    return out


def other_explanations(diag) -> list:
    """What else the fit points to: a screw modulus outside steel's range means the chain is softer
    (or stiffer) than the model, which a component off its catalog value explains as well; name each
    component and the stiffness it would need to carry the same compliance at mid-stroke."""
    out = []
    vals = diag.final.values()
    E = vals.get("screw_modulus")
    pl = diag.plant
    if E is None or 0.9 * pl.youngs_modulus <= E <= 1.1 * pl.youngs_modulus:
        return out
    x = pl.start_offset + 0.5 * pl.stroke
    # extra compliance the modulus absorbs [m/N]
    dc = x / (E * pl.area) - x / (pl.youngs_modulus * pl.area)
    side = "softer" if dc > 0 else "stiffer"
    text = (
        f"the screw modulus fitted at {E / 1e9:.0f} GPa (steel {pl.youngs_modulus / 1e9:.0f} GPa) "
        f"makes the chain {abs(dc) * 1e9:.2f} um/kN {side} at mid-stroke; the same would follow "
        "from"
    )
    alts = []
    for name, k in (("the support bearing set", pl.k_bearing), ("the nut", pl.k_nut)):
        c_new = 1.0 / k + dc
        if c_new > 0:
            alts.append(
                f"{name} at {1.0 / c_new / 1e6:,.0f} N/um instead of its catalog {k / 1e6:,.0f} "
                "N/um"
            )
    alts.append(
        "an unlisted compliance (housing, nut bracket, coupling) of "
        f"{1.0 / abs(dc) / 1e6:,.0f} N/um in series"
        if dc > 0
        else "a stiffer structure than modelled"
    )
    out.append(text + " " + "; or ".join(alts) + " (test: --effects compliance_offset)")
    return out
