"""Axial stiffness of nut, support bearings and screw by every method the seed paper gives.

One row per (component, method): the value [N/m] where the parts' data allow it, else the names of
the inputs no catalog column supplies.  A missing input is a row that says so, never an error and
never an invented number.  The row the model uses is marked ``used``.  Pure functions, SI
throughout.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ..physics import bearings as pb
from ..physics import nut as pn
from ..physics import screw as ps
from .function import Evaluation, design_params
from .loads import bearing_set_stiffness

__all__ = ["MethodRow", "stiffness_methods", "bearing_c_type"]

EQ20_NOTE = (
    "eq. 20 read in mm, N, N/um as printed; 3.8x above Palmgren for a 7012C at 1 kN, "
    "units of the original unverified"
)


@dataclass(frozen=True)
class MethodRow:
    """Stiffness of one component by one method.

    component      : "nut", "bearings" or "screw"
    method         : short name with the seed equation numbers
    source         : where the formula and its inputs come from
    value_N_per_m  : the stiffness [N/m], or None where an input is missing
    used           : True for the value the axis model uses
    missing        : names of the inputs no catalog column gives (empty when value is set)
    note           : basis of the value (load, position, conversion)
    """

    component: str
    method: str
    source: str
    value_N_per_m: float | None
    used: bool = False
    missing: tuple = ()
    note: str = ""


def _col(row, name):
    """A finite number from a part row's column, or None when the row has no such column / an empty
    cell."""
    try:
        v = row[name]
    except (KeyError, IndexError, TypeError):
        return None
    try:
        v = float(v)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


_SERIES_RE = re.compile(r"(?<!\d)(719|70|72)\d{2}(AC|C)(?![A-Za-z])")


def bearing_c_type(series: str, contact_angle: float | None = None):
    """Seed Table 2 c_type for an angular-contact spindle series (70xx/72xx/719xx, C or AC), else
    None.

    series : the catalog ``series`` text (e.g. "7012C", "71912AC ...");  contact_angle [rad], when
        given, must match the suffix (C 15 deg, AC 25 deg) or no value is returned.
    """
    m = _SERIES_RE.search(str(series))
    if not m:
        return None
    prefix, suffix = m.group(1), m.group(2)
    if contact_angle is not None:
        expected = 15.0 if suffix == "C" else 25.0
        if abs(math.degrees(contact_angle) - expected) > 0.5:
            return None
    return pb.C_TYPE_TABLE2.get(prefix + suffix)


def _axial_from_radial(k_r, alpha):
    """Inverse of seed eq. 27: k_a = 2 k_r tan^2(alpha)."""
    return 2.0 * k_r * math.tan(alpha) ** 2


def _nut_rows(ev: Evaluation, p: dict) -> list:
    d = ev.design
    double = p["nut_double"] > 0.5
    k0 = float(ev["k_nut_unloaded"])
    if double:
        load = float(d.preload)
        basis = f"double nut at preload {load:.0f} N"
    else:
        load = max(float(ev["max_axial_force"]), 1e-6)
        basis = f"single nut at the largest axial load {load:.0f} N"
    rows = [
        MethodRow(
            "nut",
            "catalog eq. 9",
            "seed eq. 9 (THK/HIWIN): 0.8 k (P / 0.1 C)^(1/3), nut catalog rigidity",
            k0,
            used=True,
            note=f"{basis}; the chain uses {float(ev['k_nut']) / 1e6:.1f} N/um under the largest "
            "axial load",
        )
    ]

    n_balls = _col(d.nut, "n_balls")
    ball_d = _col(d.screw, "ball_diameter")
    pitch_d = _col(d.screw, "nominal_diameter")
    beta = _col(d.nut, "contact_angle")
    lead = _col(d.screw, "lead")
    inputs = {
        "n_balls": n_balls,
        "ball_diameter": ball_d,
        "nominal_diameter": pitch_d,
        "contact_angle": beta,
        "lead": lead,
    }
    missing = tuple(k for k, v in inputs.items() if v is None)
    value = None
    note = (
        "needs the loaded balls per nut half (no catalog column gives it); pitch diameter = "
        "nominal diameter"
    )
    if not missing:
        phi = float(ps.lead_angle(lead, pitch_d))
        k_half = float(pn.nut_stiffness_hertz(load, n_balls, ball_d, pitch_d, beta, phi))
        # both halves of a preloaded double nut carry the preload and act together at zero external
        # load
        value = 2.0 * k_half if double else k_half
        note = (
            f"{basis}; {n_balls:.0f} loaded balls per half (nut column n_balls); pitch diameter = "
            "nominal diameter; rigid nut body (eq. 9's 0.8 not applied)"
        )
    rows.append(
        MethodRow(
            "nut",
            "Hertz eq. 12-18",
            "seed eq. 12-18 (Hertz point contact, Hamrock-Brewe)",
            value,
            missing=missing,
            note=note,
        )
    )
    return rows


def _bearing_rows(ev: Evaluation, p: dict) -> list:
    d = ev.design
    row = d.bearing
    c_a = float(p["bearing_stiffness"])
    sets = int(round(float(p["bearing_sets"])))
    k_set = float(bearing_set_stiffness(p))
    alpha = _col(row, "contact_angle")
    n_rows = _col(row, "rows") or 1.0
    preload = _col(row, "preload")
    bore, outer = _col(row, "bore"), _col(row, "outer_diameter")
    rows = [
        MethodRow(
            "bearings",
            "catalog c_a",
            "bearing catalog axial rigidity of the set (seed sec. 3.3.2)",
            c_a,
            used=True,
            note=(
                f"one set; the model takes {sets} set(s), each in series with its housing "
                f"({k_set / 1e6:.1f} N/um per set): k_bearing {float(ev['k_bearing']) / 1e6:.1f} "
                "N/um"
            ),
        )
    ]

    load_note = (
        (
            f"per bearing at F_r = set preload {preload:.0f} N, x {n_rows:.0f} bearings of the "
            "set, axial by inverse eq. 27 (k_a = 2 k_r tan^2 alpha)"
        )
        if preload is not None
        else ""
    )

    # eq. 20 (empirical, c_type of Table 2)
    try:
        series = str(row["series"])
    except (KeyError, IndexError, TypeError):
        series = ""
    c_type = bearing_c_type(series, alpha)
    missing = tuple(
        n
        for n, v in (
            ("c_type", c_type),
            ("bore", bore),
            ("outer_diameter", outer),
            ("contact_angle", alpha),
            ("preload", preload),
        )
        if v is None
    )
    value = None
    if not missing:
        k_r = float(pb.radial_stiffness_eq20(bore, outer, preload, c_type))
        value = n_rows * _axial_from_radial(k_r, alpha)
    note = EQ20_NOTE + ("" if missing else f"; c_type {c_type}, {load_note}")
    if "c_type" in missing:
        note += "; Table 2 has c_type only for 70xx/72xx/719xx C (15 deg) and AC (25 deg) series"
    rows.append(
        MethodRow(
            "bearings",
            "eq. 20 (radial, as printed)",
            "seed eq. 20, Table 2 (after [1])",
            value,
            missing=missing,
            note=note,
        )
    )

    # Palmgren and Kraemer need the ball set of the bearing
    ball_d, n_balls = _col(row, "ball_diameter"), _col(row, "n_balls")
    geo = (
        ("ball_diameter", ball_d),
        ("n_balls", n_balls),
        ("contact_angle", alpha),
        ("preload", preload),
    )
    for method, source, fn in (
        (
            "Palmgren eq. 21-23",
            "seed eq. 21-23 (Palmgren, Stribeck load share)",
            lambda: pb.radial_stiffness_palmgren(preload, ball_d, n_balls, alpha),
        ),
        (
            "Kraemer eq. 25-26",
            "seed eq. 25-26 (Kraemer)",
            lambda: pb.radial_stiffness_kramer(preload, ball_d, n_balls),
        ),
    ):
        missing = tuple(n for n, v in geo if v is None)
        value = None if missing else n_rows * _axial_from_radial(float(fn()), alpha)
        note = (
            "the bearing catalog has no ball diameter / ball count columns"
            if missing
            else load_note
        )
        rows.append(MethodRow("bearings", method, source, value, missing=missing, note=note))

    # eq. 27: radial stiffness of the set from its catalog axial rigidity (informational, not axial)
    if alpha is None or alpha <= 0.0:
        rows.append(
            MethodRow(
                "bearings",
                "eq. 27 radial from axial",
                "seed eq. 27",
                None,
                missing=("contact_angle",),
                note="radial stiffness, not comparable to the axial rows",
            )
        )
    else:
        k_r = float(pb.radial_from_axial_eq27(c_a, alpha))
        rows.append(
            MethodRow(
                "bearings",
                "eq. 27 radial from axial",
                "seed eq. 27 (k_r = k_a cot^2(alpha) / 2)",
                k_r,
                note=(
                    f"RADIAL stiffness of one set from c_a at {math.degrees(alpha):.0f} deg; "
                    "informational, not comparable to the axial rows"
                ),
            )
        )
    return rows


def _screw_rows(ev: Evaluation, p: dict) -> list:
    d = ev.design
    k = np.asarray(ev["k_screw"], dtype=float)
    i = int(np.argmin(k))
    pos_mm = (ev.x[i] - d.axis.start_offset) * 1e3
    mounting = d.axis.mounting
    rows = [
        MethodRow(
            "screw",
            "eq. 3-5/10 over the stroke (min)",
            "seed eq. 3-5, 10 (E A / x; fixed-fixed E A L / (x (L - x)))",
            float(k[i]),
            used=True,
            note=f"{mounting}, minimum at {pos_mm:.0f} mm along the stroke (screw shaft only)",
        )
    ]
    k_cat = float(ps.screw_stiffness_catalog(p["root_diameter"], p["span"], mounting))
    c = ps.CATALOG_STIFFNESS_FACTOR[mounting]
    rows.append(
        MethodRow(
            "screw",
            "catalog eq. 7-8 worst case",
            "seed eq. 7-8 (c E pi d_r^2 / (4 L))",
            k_cat,
            note=f"c = {c:.0f}, L = bearing span {p['span'] * 1e3:.0f} mm",
        )
    )
    return rows


def stiffness_methods(ev: Evaluation) -> list[MethodRow]:
    """Rows for nut, bearings and screw: every seed method, with its value or the inputs it
    lacks."""
    p = design_params(ev.design)
    return _nut_rows(ev, p) + _bearing_rows(ev, p) + _screw_rows(ev, p)


# Names a user can ask for with ``evaluate --methods nut:hertz,bearings:palmgren``:
# component:keyword, the keyword matched against the start of the method's name (lower case).
METHOD_KEYS = {
    "nut:catalog": ("nut", "catalog"),
    "nut:hertz": ("nut", "hertz"),
    "bearings:catalog": ("bearings", "catalog"),
    "bearings:eq20": ("bearings", "eq. 20"),
    "bearings:palmgren": ("bearings", "palmgren"),
    "bearings:kraemer": ("bearings", "kraemer"),
    "bearings:eq27": ("bearings", "eq. 27"),
    "screw:eq3": ("screw", "eq. 3"),
    "screw:eq7": ("screw", "catalog"),
}


def select_methods(rows, names: str, design_name: str = "design") -> list:
    """The rows a user asked for by name ('all' or a comma list of :data:`METHOD_KEYS`).

    An unknown name, or a named method the design's parts lack data for, is an InputError (one
    line)."""
    from ..errors import InputError

    if names == "all":
        return list(rows)
    out = []
    for name in (n.strip() for n in names.split(",")):
        if name not in METHOD_KEYS:
            raise InputError(
                f"unknown stiffness method '{name}'; choose from {', '.join(METHOD_KEYS)} or all",
                where="--methods",
            )
        comp, key = METHOD_KEYS[name]
        row = next(r for r in rows if r.component == comp and r.method.lower().startswith(key))
        if row.value_N_per_m is None:
            raise InputError(
                f"method '{name}' needs {', '.join(row.missing)}, which the parts of "
                f"'{design_name}' do not give",
                where="--methods",
            )
        out.append(row)
    return out
