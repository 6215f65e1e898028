"""The strict design-YAML reader: :func:`load_design` and the section readers the problem and study
readers share (:func:`read_axis`, :func:`read_parts`, :func:`catalog_for`).  Every error names the
file and key.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import fields
from pathlib import Path

from ..catalog.columns import SCHEMA, row_problem
from ..catalog.grades import grade_table
from ..catalog.loading import Catalog, default_catalog
from ..catalog.parttable import Row
from ..errors import ImplausibleInput, InputError
from ..physics import motion
from ..physics.nut import nut_length_estimate
from ..yamlio import Section, close_matches, file_kind, read_yaml, require_kind
from .axis import BRAKE_MODES, Axis, Counterbalance, Design, TwinDrive
from .keys import AXIS_KINDS, AXIS_NUMBERS, AXIS_SPEC, DESIGN_SPEC
from .partkeys import PART_SPECS
from .plausible import CYCLE_RANGES, implausible
from .sectionkeys import COUNTERBALANCE_KEYS, DWELL_SPEC, MOVE_SPEC, SEGMENT_LIMIT, TWIN_SPEC


def read_axis(sec: Section) -> tuple[Axis, tuple]:
    """Read an ``axis:`` section.  Returns the Axis and the names of keys left at their defaults."""
    sec = sec.declared(AXIS_SPEC)
    kw = {}
    for name in AXIS_KINDS:
        v = sec.read(name)
        if v is not None:
            kw[name] = v
    kw["mounting"] = sec.read("mounting")
    if sec.has("pretension"):
        node = sec.raw("pretension")
        if node.value != "auto":
            kw["pretension"] = sec.quantity("pretension", "force", non_negative=True)
    kw["orientation"] = sec.read("orientation")
    # YAML reads a bare yes/no as a boolean
    if sec.has("brake") and isinstance(sec.raw("brake").value, bool):
        kw["brake"] = "yes" if sec.raw("brake").value else "no"
    else:
        kw["brake"] = sec.choice("brake", BRAKE_MODES, AXIS_SPEC.keys["brake"].default)
    for name in AXIS_NUMBERS:
        v = sec.read(name)
        if v is not None:
            kw[name] = float(v)
    if sec.has("duty_cycle"):
        kw["duty_cycle"] = read_duty_cycle(sec, kw)
    for name in ("guide_blocks", "rails", "positions"):
        v = sec.read(name)
        if v is not None:
            kw[name] = int(v)
    v = sec.read("load_factor")
    if v is not None:
        kw["load_factor"] = float(v)
    kw["buckling_nut_end"] = sec.choice("buckling_nut_end", ("fixed", "supported"), "fixed")
    kw["rise_without_cycle"] = sec.choice("rise_without_cycle", ("practice", "balance"), "practice")
    kw["feedback"] = sec.choice("feedback", ("motor_encoder", "linear_scale"), "motor_encoder")
    if sec.has("scale_grade"):
        if kw["feedback"] != "linear_scale":
            raise sec.error("scale_grade", "a scale grade needs axis.feedback: linear_scale")
        kw["scale_grade"] = sec.read("scale_grade")
    elif kw["feedback"] == "linear_scale":
        raise sec.error(
            "feedback",
            "a linear scale needs its accuracy grade: axis.scale_grade (one of "
            "AMO-LMB-3, AMO-LMB-5, HIWIN-PMS)",
        )
    if sec.has("controller"):
        kw["controller"] = sec.choice("controller", ("pd", "p_pi_cascade"), None)
    if sec.has("pitch_compensation"):
        kw["pitch_compensation"] = sec.read("pitch_compensation") is True
    if sec.has("cut_while_accelerating"):
        kw["cut_while_accelerating"] = sec.read("cut_while_accelerating") is True
    _check_carriage(sec, kw)
    _check_pairs(sec, kw)
    if sec.has("counterbalance"):
        cb = read_counterbalance(sec, kw)
        if cb is not None:
            kw["counterbalance"] = cb
    if sec.has("twin_drive"):
        kw["twin_drive"] = read_twin_drive(sec, kw)
    sec.done()
    cycle_force = max(
        [abs(s.force) for s in kw.get("duty_cycle", ()) if s.force is not None] + [0.0]
    )
    for key, message in implausible(kw) + implausible({"duty_cycle": cycle_force}, CYCLE_RANGES):
        warnings.warn(
            str(InputError(message, source=sec.source, where=sec.where(key))),
            ImplausibleInput,
            stacklevel=2,
        )
    # a counterbalance or twin drive left out is no assumption of a value: the axis has none (one
    # drive)
    assumed = tuple(
        f.name
        for f in fields(Axis)
        if f.name not in kw and f.name not in ("counterbalance", "twin_drive", "controller")
    )
    return Axis(**kw), assumed


def read_counterbalance(sec: Section, kw: dict) -> Counterbalance | None:
    """``counterbalance``: ``{kind: counterweight, mass:, efficiency:, chain_mass:}`` or
    ``{kind: cylinder, force:, force_at_end:, tolerance:, piston_mass:}`` (``{kind: none}``: None).
    Only on a vertical axis; a counterweight at most the head (axis.moving_mass: an overbalanced
    head would rise with the brake released); a key of the other kind is refused."""
    s = sec.read("counterbalance")
    kind = s.read("kind")
    for key in s.keys():  # a typo first, before a missing key of the kind is asked for
        if key not in s.spec.keys:
            near = close_matches(key, COUNTERBALANCE_KEYS[kind], n=1)
            hint = f"; did you mean '{near[0]}'?" if near else ""
            raise s.error(key, f"unknown key '{s.key_path(key)}'{hint}")
    if kind != "none" and kw.get("orientation") != "vertical":
        raise sec.error(
            "counterbalance",
            f"a counterbalance takes the weight of a vertical axis; this axis is "
            f"{kw.get('orientation')} (axis.orientation: vertical)",
        )
    for key in s.keys():
        if key in COUNTERBALANCE_KEYS[kind]:
            continue
        if key in s.spec.keys:
            raise s.error(
                key,
                f"'{key}' does not apply to a {kind} counterbalance (its keys: "
                f"{', '.join(COUNTERBALANCE_KEYS[kind])})",
            )
    if kind == "none":
        s.done()
        return None
    if kind == "counterweight":
        mass = s.read("mass")
        if mass is None:
            raise s.error("kind", f"a counterweight needs its mass ('{s.key_path('mass')}')")
        head = kw.get("moving_mass")
        if head is not None and mass > head * (1 + 1e-9):
            raise s.error(
                "mass",
                f"{mass:g} kg is heavier than the head (axis.moving_mass {head:g} kg): the head "
                "would rise with the brake released",
            )
        out = Counterbalance(
            kind,
            mass=mass,
            efficiency=float(s.read("efficiency", Counterbalance.efficiency)),
            chain_mass=s.read("chain_mass", 0.0),
        )
    else:
        force = s.read("force")
        if force is None:
            raise s.error("kind", f"a balance cylinder needs its force ('{s.key_path('force')}')")
        out = Counterbalance(
            kind,
            force=force,
            force_at_end=s.read("force_at_end"),
            tolerance=s.read("tolerance", 0.0),
            piston_mass=s.read("piston_mass", 0.0),
        )
    s.done()
    return out


def read_twin_drive(sec: Section, kw: dict) -> TwinDrive:
    """``twin_drive: {span, cross_stroke, cross_mass, bridge_yaw_inertia}`` (:class:`TwinDrive`).  A
    horizontal axis only: on a vertical axis the drives would carry the weight and a wall-mounted
    bridge hangs across its rails, neither in the model (:mod:`axisopt.model.gantry`); the cross
    stroke stays between the drives."""
    sub = sec.read("twin_drive")
    tw = {name: sub.read(name) for name in TWIN_SPEC.keys}
    sub.done()
    orientation = kw.get("orientation", "horizontal")
    if orientation != "horizontal":
        raise sec.error(
            "twin_drive",
            f"a twin drive is a horizontal gantry's; this axis is {orientation} (the "
            "model has no share of the weight per drive)",
        )
    if tw["cross_stroke"] > tw["span"] * (1 + 1e-9):
        raise sub.error(
            "cross_stroke",
            f"{tw['cross_stroke'] * 1e3:g} mm is more than the span between the drives "
            f"({tw['span'] * 1e3:g} mm): the cross carriage would leave the bridge",
        )
    if tw.get("upright_mass") is not None and tw["upright_mass"] > kw.get(
        "moving_mass", float("inf")
    ) * (1 + 1e-9):
        raise sub.error(
            "upright_mass",
            f"{tw['upright_mass']:g} kg is more than the bridge's axis.moving_mass "
            f"({kw['moving_mass']:g} kg) it is part of",
        )
    return TwinDrive(**{k: v for k, v in tw.items() if v is not None})


def _check_carriage(sec: Section, kw: dict) -> None:
    """The block pattern fits the table; at least two blocks on every rail (the table's rocking
    stiffness comes from the block spacing: no vendor text gives one block's moment rigidity)."""
    length = kw.get("table_length", Axis.table_length)
    width = kw.get("table_width", length)
    if kw.get("block_spacing", 0.0) > length * (1 + 1e-9):
        raise sec.error(
            "block_spacing",
            f"{kw['block_spacing'] * 1e3:g} mm is larger than the table "
            f"(table_length {length * 1e3:g} mm)",
        )
    if kw.get("rail_spacing", 0.0) > width * (1 + 1e-9):
        raise sec.error(
            "rail_spacing",
            f"{kw['rail_spacing'] * 1e3:g} mm is larger than the table "
            f"(table_width {width * 1e3:g} mm)",
        )
    blocks, rails = kw.get("guide_blocks", Axis.guide_blocks), kw.get("rails", Axis.rails)
    if blocks % rails or blocks < 2 * rails:
        key = "guide_blocks" if sec.has("guide_blocks") else "rails"
        raise sec.error(
            key,
            f"{blocks} blocks on {rails} rail(s): give every rail the same number of blocks, "
            "at least two",
        )


def _check_pairs(sec: Section, kw: dict) -> None:
    """Values that bound one another: a mean speed at most the top speed, a mean axial load at most
    the largest (the axial load, or a duty cycle's largest force)."""
    top, mean = kw.get("max_speed"), kw.get("mean_speed")
    if top is not None and mean is not None and mean > top * (1 + 1e-9):
        raise sec.error(
            "mean_speed",
            f"{mean * 60:g} m/min is faster than axis.max_speed ({top * 60:g} m/min): "
            "the mean speed over the machine's hours cannot exceed the rapid speed",
        )
    load, mean = kw.get("axial_load"), kw.get("mean_axial_load")
    if load is not None and mean is not None:
        largest = max(
            [load] + [abs(s.force) for s in kw.get("duty_cycle", ()) if s.force is not None]
        )
        if mean > largest * (1 + 1e-9):
            raise sec.error(
                "mean_axial_load",
                f"{mean:g} N is more than the largest axial load ({largest:g} N, "
                "axis.axial_load or the duty cycle's largest force): a mean cannot exceed it",
            )


def read_duty_cycle(sec: Section, kw: dict) -> tuple:
    """``duty_cycle``: a list of moves ``{move: 400 mm, speed: 24 m/min, acceleration:, jerk:,
    force:, moving_mass:}`` (speed defaults to the axis max_speed, acceleration and jerk to the
    axis's) and dwells ``{dwell: 2 s, force:, moving_mass:}``.  An entry's ``moving_mass`` (a
    workpiece loaded or unloaded) is at most the axis's: ``axis.moving_mass`` is the heaviest the
    table carries (the largest inertia force, the modes, the guides' static load and the brake are
    taken with it)."""
    node = sec.raw("duty_cycle")
    where = sec.key_path("duty_cycle")
    if not isinstance(node.value, list) or not node.value:
        raise sec.error("duty_cycle", "expected a list of moves and dwells")
    if len(node.value) > SEGMENT_LIMIT:
        raise sec.error("duty_cycle", f"has {len(node.value)} entries; at most {SEGMENT_LIMIT}")
    out = []
    for i, item in enumerate(node.value):
        s = Section(item, sec.source, f"{where}[{i}]")
        if s.has("dwell") == s.has("move"):
            raise InputError(
                "each entry is a 'move' or a 'dwell'",
                source=sec.source,
                where=Section._loc(f"{where}[{i}]", item.line),
            )
        s = Section(item, sec.source, f"{where}[{i}]", DWELL_SPEC if s.has("dwell") else MOVE_SPEC)
        force = s.read("force")
        mass = s.read("moving_mass")
        heaviest = kw.get("moving_mass")
        if mass is not None and heaviest is not None and mass > heaviest * (1 + 1e-9):
            raise s.error(
                "moving_mass",
                f"{mass:g} kg is heavier than axis.moving_mass ({heaviest:g} kg); give the axis "
                "the heaviest mass the table carries (the largest inertia force, the modes, the "
                "guides' static load and the brake are taken with it)",
            )
        if s.has("dwell"):
            out.append(
                motion.Segment("dwell", duration=s.read("dwell"), force=force, moving_mass=mass)
            )
        else:
            dist = s.read("move")
            if dist == 0:
                raise s.error("move", "a move needs a distance (signed: + forward, - back)")
            if abs(dist) > kw.get("stroke", math.inf) * (1 + 1e-9):
                raise s.error("move", f"{abs(dist) * 1e3:g} mm is longer than the stroke")
            speed = s.read("speed", kw.get("max_speed"))
            top = kw.get("max_speed")
            # the speed checks are taken at max_speed
            if top is not None and speed > top * (1 + 1e-9):
                raise s.error(
                    "speed",
                    f"{speed * 60:g} m/min is faster than axis.max_speed ({top * 60:g} m/min); "
                    "raise max_speed to the fastest move (critical speed, DN and bearing speed are "
                    "checked at it)",
                )
            acc = s.read("acceleration", kw.get("acceleration", 0.0))
            if not acc:
                raise s.error("move", "needs an acceleration (here or in axis.acceleration)")
            jerk = s.read("jerk", kw.get("jerk"))
            out.append(
                motion.Segment(
                    "move",
                    distance=dist,
                    speed=speed,
                    acceleration=acc,
                    jerk=jerk,
                    force=force,
                    moving_mass=mass,
                )
            )
        s.done()
    return tuple(out)


def read_part(sec: Section, key: str, table: str, catalog: Catalog):
    """A part slot: a catalog id, or an inline mapping with the catalog's columns (values with
    units)."""
    node = sec.raw(key, required=True)
    if isinstance(node.value, (str, int)) and not isinstance(node.value, bool):
        return catalog.part(table, str(node.value), source=sec.source, key=sec.where(key))
    if not isinstance(node.value, dict):
        raise sec.error(key, f"expected a catalog id or a mapping of {table[:-1]} properties")
    return inline_part(Section(node, sec.source, sec.key_path(key), PART_SPECS[table]), table)


def inline_part(sec: Section, table: str):
    sec = sec.declared(PART_SPECS[table])
    rec = {}
    for col, kind in SCHEMA[table].items():
        v = sec.read(col)
        if kind == "int":
            v = math.nan if v is None else int(v)
        elif kind != "str" and v is None:
            v = math.nan
        rec[col] = float(v) if kind == "dimensionless" else v
    sec.done()
    # the catalog loader's rules: positive geometry, choices, ordered pairs
    bad = row_problem(table, rec)
    if bad is not None:
        col, msg = bad
        raise sec.error(col, msg if msg.startswith(col) else f"{col} {msg}")
    rec["_source"] = f"{sec.source}:{sec.node.line}"
    return Row(rec, rec["id"])


def read_parts(sec: Section, catalog: Catalog) -> dict:
    parts = {
        "screw": read_part(sec, "screw", "screws", catalog),
        "nut": read_part(sec, "nut", "nuts", catalog),
        "bearing": read_part(sec, "bearing", "bearings", catalog),
        "guide": read_part(sec, "guide", "guides", catalog),
    }
    for slot, table in (
        ("motor", "motors"),
        ("coupling", "couplings"),
        ("reduction", "reductions"),
    ):
        if sec.has(slot):
            parts[slot] = read_part(sec, slot, table, catalog)
    pre = sec.read("nut_preload")
    grade = sec.read("screw_grade")
    sec.done()
    nut, screw = parts["nut"], parts["screw"]
    if nut["screw_id"] != screw["id"]:
        raise sec.error(
            "nut",
            f"nut '{nut['id']}' fits screw '{nut['screw_id']}', not '{screw['id']}'; "
            + fitting_nuts(catalog, screw["id"]),
        )
    if pre is not None and not (nut["preload_min"] - 1e-9 <= pre <= nut["preload_max"] + 1e-9):
        raise sec.error(
            "nut_preload",
            f"{pre:.0f} N is outside nut '{nut['id']}' range "
            f"{nut['preload_min']:.0f}..{nut['preload_max']:.0f} N",
        )
    parts["nut_preload"] = pre
    if grade is not None:
        t = grade_table()
        if grade not in t.names:
            raise sec.error(
                "screw_grade", f"unknown grade '{grade}' (JIS B 1192: {', '.join(t.names)})"
            )
        made = t.orderable(str(screw["vendor"]), str(screw["series"]))
        if grade not in made:
            raise sec.error(
                "screw_grade",
                f"screw '{screw['id']}' is not made in grade {grade} (its series: "
                f"{' '.join(made)}; catalogs/screw_grades.csv)",
            )
    parts["screw_grade"] = grade
    return parts


def rotating_nut(nut) -> bool:
    """True for a driven rotating-nut unit (the nut row's ``rotating`` flag is 1; empty or absent:
    0)."""
    try:
        v = float(nut["rotating"])
    except (KeyError, TypeError, ValueError):
        return False
    return v == 1.0


def fitting_nuts(catalog: Catalog, screw_id: str, shown: int = 6) -> str:
    """'nuts for it: A, B (+3 more; axisopt parts nuts --fits ID)' -- what a refused nut could be
    instead."""
    nuts = catalog.rows("nuts")
    ids = [str(i) for i in nuts.ids[nuts["screw_id"] == screw_id]]
    if not ids:
        return f"the catalogs have no nut for '{screw_id}'"
    more = f" (+{len(ids) - shown} more)" if len(ids) > shown else ""
    return f"nuts for it: {', '.join(ids[:shown])}{more} (axisopt parts nuts --fits {screw_id})"


def catalog_for(root: Section, base_dir: Path) -> Catalog:
    dirs = root.string_list("catalogs", [])
    resolved = []
    for d in dirs:
        p = (base_dir / d).resolve()
        if not p.is_dir():
            raise root.error("catalogs", f"catalog directory '{d}' not found")
        resolved.append(p)
    return default_catalog(tuple(resolved))


# top-level keys of a problem file (axisopt.problem)
PROBLEM_KEYS = ("objective", "limits", "continuous")


def load_design(path) -> Design:
    """Read a design YAML file into a :class:`Design`; every error names the file and key."""
    path = Path(path)
    node = read_yaml(path)
    if file_kind(node) == "study" or not isinstance(node.value, dict):
        require_kind(node, str(path), "design")
    root = Section(node, str(path), spec=DESIGN_SPEC)
    problem_key = next((k for k in PROBLEM_KEYS if root.has(k)), None)
    # a problem file given where a design is read
    if problem_key is not None and not root.has("parts"):
        raise InputError(
            f"a problem file, not a design (it has '{problem_key}', no 'parts'): size it with "
            "`axisopt solve`",
            source=str(path),
        )
    catalog = catalog_for(root, path.parent)
    name = root.read("name", path.stem)
    root.read("description")
    axis, assumed = read_axis(root.read("axis"))
    psec = root.read("parts")
    parts = read_parts(psec, catalog)
    root.done()
    given = [
        k
        for k in ("reduction_ratio", "reduction_efficiency", "reduction_inertia")
        if k not in assumed
    ]
    if parts.get("reduction") is not None and given:
        raise psec.error(
            "reduction",
            f"the reduction part sets the ratio, efficiency and inertia: leave "
            f"axis.{given[0]} out (it applies only without a reduction part)",
        )
    if rotating_nut(parts["nut"]) and axis.mounting != "fixed-fixed":
        raise psec.error(
            "nut",
            f"nut '{parts['nut']['id']}' is a driven rotating-nut unit: it runs on a stationary "
            f"screw fixed at both ends (axis.mounting: fixed-fixed), not {axis.mounting}",
        )
    if rotating_nut(parts["nut"]) and axis.feedback == "linear_scale":
        raise psec.error(
            "nut",
            f"nut '{parts['nut']['id']}' is a driven rotating-nut unit: axis.feedback: "
            "linear_scale is not supported on it (its standing screw's positioning rows are the "
            "unit's; use the motor encoder)",
        )
    grade = parts.get("screw_grade")
    travel = axis.stroke + _nut_length(parts)
    if grade is not None and not math.isfinite(grade_table().lead_error(grade, travel)):
        raise psec.error(
            "screw_grade",
            f"grade {grade} has no lead tolerance over a {travel * 1e3:.0f} mm "
            "travelled thread (stroke + nut length; THK A-678 Table 1)",
        )
    if parts.get("motor") is not None and axis.acceleration <= 0 and not axis.duty_cycle:
        raise psec.error("motor", "sizing a motor needs axis.acceleration (or an axis.duty_cycle)")
    return Design(axis=axis, name=name, source=str(path), assumed=assumed, **parts)


def _nut_length(parts) -> float:
    """The design's nut length [m]: its row's ``length``, else the catalog envelope (physics.nut;
    what model.params.nut_length takes)."""
    nut, screw = parts.get("nut"), parts.get("screw")
    if nut is None or screw is None:
        return 0.0
    v = nut.get("length") if hasattr(nut, "get") else None
    if v is not None and math.isfinite(float(v)):
        return float(v)
    double = 1.0 if str(nut.get("type")) == "double" else 0.0
    return float(nut_length_estimate(screw["lead"], screw["nominal_diameter"], double))


__all__ = [
    "load_design",
    "read_axis",
    "read_counterbalance",
    "read_duty_cycle",
    "read_parts",
    "read_part",
    "inline_part",
    "fitting_nuts",
    "catalog_for",
]
