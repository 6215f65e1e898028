"""Which part values of a design are estimates (not the vendor's table) and which results rest on
them.

The optimizer goes wherever the model is optimistic, so a value the vendor does not list must never
read better than the vendor values it stands in for, and a result that depends on one must say so.
Where a value is estimated is declared once with the part columns
(:data:`axisopt.catalog.columns.COLUMNS`: ``estimate`` for an optional column left empty,
``estimated_when`` for the row statuses whose value is derived or illustrative,
catalogs/SOURCES.md); :func:`design_estimates` lists them for one design and :func:`resting_on`
finds, by perturbing each estimated parameter, the outputs (a binding limit, a check at its limit,
the objective) that move with it.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from ..catalog.columns import COLUMNS, SLOT_TABLES, USER_STATUS
from ..units import DISPLAY_UNITS, unit_factor
from .paramnames import PART_PARAMS, RULE_PARAMS
from .params import axis_params, positions
from .response import axis_response

_STEP = 0.05  # relative perturbation of an estimated parameter
_MOVES = 1e-7  # relative change of an output that counts as "rests on it"


@dataclass(frozen=True)
class Estimate:
    """A part value the model uses that is not in the vendor's table.

    slot, part : the design slot ('bearing') and the part id;  column : the catalog column
    param      : the model parameter it feeds;  value : what the model uses (SI)
    how        : how it was estimated (the column's declaration, catalogs/SOURCES.md)
    """

    slot: str
    part: str
    column: str
    param: str
    value: float
    how: str
    unit: str = ""  # display unit of ``shown``
    shown: float = math.nan  # value in the display unit
    probe: float = math.nan  # the value :func:`resting_on` tries (default: the value raised by 5 %)

    def to_dict(self) -> dict:
        d = asdict(self)
        d["value"] = _finite(self.value)
        d["shown"] = _finite(self.shown)
        d.pop("probe")
        return d

    def text(self) -> str:
        return estimate_text(self.to_dict())


def estimate_text(e: dict) -> str:
    """One estimate (:meth:`Estimate.to_dict`) as text: 'guide HG15 normal_rigidity 177 N/um (how)',
    or for an axis value left out 'axis.bearing_housing_stiffness 27,000 N/um (how)'."""
    shown = e["shown"]
    if e["slot"] == "axis":
        if shown is None:  # a part left out: rigid
            return f"axis.{e['column']} rigid ({e['how']})"
        return f"axis.{e['column']} {axis_value_text(shown, e['unit'])} ({e['how']})"
    num = "-" if shown is None else f"{shown:.4g}"
    return f"{e['slot']} {e['part']} {e['column']} {num} {e['unit']} ({e['how']})"


def axis_value_text(value: float, unit: str = "") -> str:
    """An axis value as the outputs name it: '1,333 N', '666.7 N', '1.2' (separators from 1000 up,
    else four significant digits)."""
    num = f"{value:,.0f}" if abs(value) >= 1000 else f"{value:.4g}"
    return f"{num} {unit}" if unit else num


# Axis values a design may leave out that the model then estimates (model.params.mount_compliances):
# (YAML key, compliance parameter, how).  No vendor publishes them for the machine's own parts
# (THK's axial rigidity of the feed screw system has a term K_H for the nut and bearing mounting,
# "as high as possible"), so a result that moves with them names the estimate.
ASSUMED_MOUNTS = (
    (
        "bearing_housing_stiffness",
        "housing_compliance",
        "estimate: 26 x the bearing set, IBC TI-I-5010.2 units against their bare sets",
    ),
    (
        "nut_bracket_stiffness",
        "bracket_compliance",
        "estimate: 4 x the nut, THK A-709's 80 % nut-mounting allowance once more",
    ),
)
# Axis values a design may leave to a default that the life, torque and thermal checks read: (YAML
# key, parameter, display unit, SI per unit, how, whether the axis left it to the default).
ASSUMED_DEFAULTS = (
    (
        "mean_axial_load",
        "mean_axial_load",
        "N",
        1.0,
        "default: a third of axial_load",
        lambda a: a.mean_axial_load is None,
    ),
    (
        "mean_speed",
        "mean_speed",
        "m/min",
        1 / 60,
        "default: half of max_speed",
        lambda a: a.mean_speed is None and not a.duty_cycle,
    ),
    (
        "temperature_rise",
        "temperature_rise",
        "K",
        1.0,
        "default without a duty cycle; THK plans for 2-5 degC",
        lambda a: a.temperature_rise is None and not a.rise_from_balance,
    ),
    (
        "pretension_rise",
        "pretension_rise",
        "K",
        1.0,
        "default design rise of the auto pretension; THK plans for 2-5 degC",
        lambda a: (
            a.pretension_rise is None and a.pretension is None and a.mounting == "fixed-fixed"
        ),
    ),
    (
        "load_factor",
        "load_factor",
        "",
        1.0,
        "default: THK A-704 Table 19 by max speed, the upper end of the row",
        lambda a: a.load_factor is None,
    ),
    (
        "nut_lift_off_safety",
        "nut_lift_off_safety",
        "",
        1.0,
        "default: lift-off at 2.83 x preload, THK A-687, HIWIN F 3.6",
        lambda a: a.nut_lift_off_safety == 1.0,
    ),
)
# Parameters the model holds as the reciprocal of their column (RULE_PARAMS): an estimate shows the
# column's value (a reduction's torsional stiffness, not the compliance the model sums)
RECIPROCAL = frozenset({"reduction_compliance"})
# Part columns whose estimate an axis value replaces: (table, column) -> axis attribute.
OVERRIDDEN_BY_AXIS = {("bearings", "static_safety"): "bearing_static_safety"}


def _param_of(table: str, column: str) -> str | None:
    return dict(PART_PARAMS[table]).get(column) or RULE_PARAMS.get((table, column))


def design_estimates(design) -> list:
    """The estimated values of a design's parts, in slot order (:class:`Estimate`)."""
    p = axis_params(
        design.axis,
        design.screw,
        design.nut,
        design.bearing,
        design.guide,
        design.motor,
        design.coupling,
        design.reduction,
    )
    out = []
    for slot, table in SLOT_TABLES:
        row = getattr(design, slot, None)
        if row is None:
            continue
        status = str(row.get("status", USER_STATUS)) if hasattr(row, "get") else USER_STATUS
        pid = str(row["id"])
        for col in COLUMNS[table]:
            if col.kind in ("str", "int"):
                continue
            param = _param_of(table, col.name)
            if param is None or param not in p:
                continue
            val = row.get(col.name, math.nan) if hasattr(row, "get") else math.nan
            empty = val is None or (isinstance(val, float) and math.isnan(val))
            if col.applies and (row.get(col.applies) if hasattr(row, "get") else None) != 1:
                continue  # a rotating-nut unit's column on a nut that does not turn
            if (
                getattr(design.axis, OVERRIDDEN_BY_AXIS.get((table, col.name), "_none_"), None)
                is not None
            ):
                continue
            how = (
                col.estimate
                if (empty and col.estimate)
                else col.estimated_in(status, row.get("source", ""))
            )
            if how:
                v = float(np.ravel(p[param])[0])
                unit = DISPLAY_UNITS.get(col.kind, "")
                cv = (1.0 / v if v else math.inf) if param in RECIPROCAL else v
                shown = cv / unit_factor(unit, col.kind) if unit else cv
                out.append(Estimate(slot, pid, col.name, param, v, how, unit, shown))
    for key, param, how in ASSUMED_MOUNTS:
        if getattr(design.axis, key) is None:
            c = float(np.ravel(p[param])[0])
            out.append(Estimate("axis", "", key, param, c, how, "N/um", 1e-6 / c))
    for key, param, unit, factor, how, defaulted in ASSUMED_DEFAULTS:
        if defaulted(design.axis):
            v = float(np.ravel(p[param])[0])
            out.append(Estimate("axis", "", key, param, v, how, unit, v / factor))
    return out


def _scalar(v) -> float:
    return float(np.min(np.asarray(v, dtype=float)))


def resting_on(design, outputs, estimates=None) -> dict:
    """{output: [Estimate, ...]} for each of ``outputs`` (model output names; a profile output as
    its minimum over the stroke) that changes when one estimated parameter of the design is raised
    by 5 %."""
    estimates = design_estimates(design) if estimates is None else estimates
    outputs = [o for o in dict.fromkeys(outputs)]
    if not estimates or not outputs:
        return {}
    x = positions(design.axis)
    p = axis_params(
        design.axis,
        design.screw,
        design.nut,
        design.bearing,
        design.guide,
        design.motor,
        design.coupling,
        design.reduction,
    )
    # the design and each estimate raised by 5 %, one row each, in one evaluation of the model
    k = len(estimates) + 1

    def column(v):
        numeric = (
            not isinstance(v, (bool, str, tuple, list))
            and np.ndim(v) == 0
            and np.asarray(v).dtype.kind in "fiu"
        )
        return np.full((k, 1), float(v)) if numeric else v

    q = {n: column(v) for n, v in p.items()}
    for i, est in enumerate(estimates, start=1):
        v = float(p[est.param])
        q[est.param][i, 0] = (
            est.probe if math.isfinite(est.probe) else (v * (1.0 + _STEP) if v != 0 else _STEP)
        )

    def row(v, i):
        a = np.asarray(v, dtype=float)
        return float(np.min(a[i] if a.ndim and a.shape[0] == k else a))

    with np.errstate(divide="ignore", invalid="ignore"):
        out = axis_response(q, x, design.axis.mounting, design.preload)
    ref = {o: row(out[o], 0) for o in outputs if o in out}
    found: dict = {}
    for i, est in enumerate(estimates, start=1):
        for o, v0 in ref.items():
            v1 = row(out[o], i)
            if (
                math.isfinite(v0)
                and math.isfinite(v1)
                and abs(v1 - v0) > _MOVES * max(abs(v0), 1e-12)
            ):
                found.setdefault(o, []).append(est)
    return found


def _finite(v):
    return v if isinstance(v, float) and math.isfinite(v) else None


@dataclass(frozen=True)
class Resting:
    """A result of a design that moves with estimated part values.

    what      : 'objective', a limit key (``max_drag_torque``) or ``check <name>``
    output    : the model output (``drag_torque``, ``margin_nut_life``)
    estimates : the :class:`Estimate` values it moves with
    """

    what: str
    output: str
    estimates: tuple

    def to_dict(self) -> dict:
        return {
            "what": self.what,
            "output": self.output,
            "estimates": [e.to_dict() for e in self.estimates],
        }

    def text(self) -> str:
        vals = "; ".join(e.text() for e in self.estimates)
        return f"{self.what} rests on estimated {vals}"


# a limit or check within this of its bound is active (the search holds limits exactly)
ACTIVE_RTOL = 1e-4


def binding_estimates(design, limits=(), objective_outputs=(), checks: bool = True) -> list:
    """The objective and the active limits and checks of ``design`` that rest on estimated part
    values.

    limits            : ((key, SI value), ...) of :data:`axisopt.model.limits.LIMITS` keys
    objective_outputs : model outputs the objective is made of (``k_total``)
    checks            : also the vendor checks at their limit (margin within :data:`ACTIVE_RTOL`
                        of 1)
    Returns [:class:`Resting`] (empty: every active value is a vendor value)."""
    from .limits import CHECK_TABLE, LIMITS

    x = positions(design.axis)
    p = axis_params(
        design.axis,
        design.screw,
        design.nut,
        design.bearing,
        design.guide,
        design.motor,
        design.coupling,
        design.reduction,
    )
    with np.errstate(divide="ignore", invalid="ignore"):
        out = axis_response(p, x, design.axis.mounting, design.preload)
    wanted = [("objective", o) for o in objective_outputs]
    for key, value in limits:
        lim = LIMITS[key]
        if lim.output not in out or value == 0.0:
            continue
        at = _scalar(out[lim.output])
        if abs(at - value) <= ACTIVE_RTOL * abs(value):
            wanted.append((key, lim.output))
    if checks:
        for c in CHECK_TABLE:
            m = out.get(c.output)
            if m is not None and _scalar(m) <= 1.0 + ACTIVE_RTOL:
                wanted.append((f"check {c.name}", c.output))
    found = resting_on(design, [o for _, o in wanted])
    return [Resting(what, o, tuple(found[o])) for what, o in wanted if found.get(o)]
