"""Sizing problems: YAML <-> frozen dataclasses.

A problem YAML names the axis (the same ``axis:`` section as a design YAML), the objective, the
limits, the catalog restrictions and the bounds of the continuous variables.  Every value with a
dimension carries its unit; unknown keys, bare numbers that need a unit and unknown part ids are
:class:`~axisopt.errors.InputError` naming the file and key.

.. code-block:: yaml

    name: vmc-x
    description: free text
    catalogs: [../my_catalog]          # optional extra catalog directories (relative to this file)
    axis: {...}                        # as in a design YAML (axis.mounting is the default mounting)
    objective:
      mode: stiffness                  # stiffness | frequency | weighted | lexicographic | pareto | kv
      weights: {stiffness: 1, frequency: 1}           # weighted: sum w_i * value_i / scale_i
      scale: {stiffness: 100 N/um, frequency: 100 Hz}  # weighted
      order: [frequency, stiffness]    # lexicographic
      tolerance: 0.01                  # lexicographic: keep designs within 1 % of the best primary
      pareto: [stiffness, frequency, cost, total_mass]  # pareto (two or more)
    limits:
      max_moving_mass: 450 kg
      max_total_mass: 700 kg
      max_cost: 6000 EUR
      max_drag_torque: 1.2 N.m
      min_life: 20000 h                # nut L10 life; the life checks' need unless axis.required_life
      min_stiffness: 150 N/um          # minimum over the stroke
      min_frequency: 60 Hz             # minimum over the stroke
      max_backlash: 0 um               # axial play of the nut (default 0: preloaded nuts only)
      margins: {critical_speed: 1.25, buckling: 2.0}   # per model.CHECKS; default 1.0, 0 disables
    catalog:
      mountings: [fixed-supported, fixed-fixed]         # default: [axis.mounting]
      vendors: [HIWIN, THK]
      nut_types: [double]
      bearing_arrangements: [DB, DBD]
      bearing_preload: [medium, heavy]                # bearing preload classes
      guide_types: [ball, roller]
      guide_preload: [medium, heavy]                  # guide preload levels or vendor classes (ZA, Z0, ...)
      status: [vendor, stiffness-derived]             # row provenance (catalogs/SOURCES.md); the default also
                                                      # allows user rows; add derived or paper to search those
      require: {screw: [id, ...], nut: id, bearing: [...], guide: [...], motor: [...], coupling: [...]}
      exclude: {guide: [id, ...]}
      drive: yes                       # motor, coupling and reduction are search choices (default: yes when
                                       # the catalogs have motors and the axis an acceleration or duty cycle;
                                       # 'no' keeps the axis's motor_inertia and coupling values, skips the
                                       # drive checks, and every answer says so)
      motor_vendors: [Yaskawa]         # the drive parts' own vendor and series filters ('vendors' is for
      motor_series: [Sigma-7 SGM7G]    # the mechanical parts)
      coupling_series: [...]
      reductions: yes                  # a searched drive also chooses a reduction (catalogs' reductions.csv) or
                                       # none (default yes when the table has rows; 'no': direct drive, or the
                                       # axis's reduction_ratio, only)
      max_motor_flange: 130 mm         # the motor must fit the machine: flange (square) size at most this
    continuous:
      nut_preload: {min: 0 N, max: 5 kN}  # intersected with each nut's preload_min..preload_max
"""  # noqa: E501

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType

from .catalog.loading import Catalog
from .design import AXIS_SPEC, CATALOGS_KEY, DESCRIPTION_KEY, NAME_KEY, Axis, catalog_for, read_axis
from .design.choices import SEARCH_SPEC, read_arrangements
from .design.drivechoice import DRIVE_DESIGN_SPEC, read_drive_choice, read_drive_design
from .display import fmt, one_line
from .errors import InputError
from .model import CHECKS
from .model.goals import (
    OBJECTIVE_MODES,
    PARETO_ALIASES,
    PARETO_KEYS,
    PERFORMANCE,
    WEIGHTED,
    Objective,
)
from .model.limits import LIMITS
from .restrictions import (  # noqa: F401  (the slot names are the problem's vocabulary too)
    DRIVE_SLOTS,
    MECH_SLOTS,
    RESTRICTIONS_SPEC,
    SLOT_TABLE,
    SLOTS,
    Restrictions,
    read_restrictions,
)
from .yamlio import Key, Section, Spec, close_matches, read_yaml, require_kind

# limit key -> model.limits.Limit (output, sense, kind, display unit, doc, default): declared once
# there
DEFAULT_LIMITS = MappingProxyType(
    {k: lim.default for k, lim in LIMITS.items() if lim.default is not None}
)


@dataclass(frozen=True)
class Problem:
    """A sizing problem (SI).  ``limits`` maps :data:`LIMITS` keys to SI values; ``margins`` maps
    each of :data:`axisopt.model.CHECKS` to the smallest accepted margin (0 disables the check)."""

    axis: Axis
    catalog: Catalog = field(repr=False, compare=False)
    objective: Objective = Objective()
    limits: tuple = ()  # ((key, value_SI), ...)
    margins: tuple = tuple((c, 1.0) for c in CHECKS)
    restrictions: Restrictions = Restrictions()
    preload_min: float = 0.0
    preload_max: float = float("inf")
    name: str = "problem"
    source: str = ""
    assumed: tuple = ()
    # the checks' required life (axis.required_life) follows limits.min_life: the YAML set min_life,
    # not required_life (one life requirement, not a stricter hidden default beside the user's
    # limit)
    life_from_limit: bool = False
    # search.counterbalance / search.twin_drive: ((label, Axis), ...) the search chooses among
    # (empty: the axis)
    arrangements: tuple = field(default=(), repr=False)
    # search.drive_types (design.drivechoice.DriveChoice): rack and pinion, linear motors beside the
    # screw; None: the screw drive alone
    drives: object = field(default=None, repr=False, compare=False)
    # drive_design: one rack-and-pinion or linear-motor design ({slot: id}, design.drivechoice), or
    # None
    drive_design: dict | None = field(default=None, repr=False, compare=False)

    @property
    def limit_map(self) -> dict:
        return dict(self.limits)

    @property
    def margin_map(self) -> dict:
        return dict(self.margins)

    @property
    def mountings(self) -> tuple:
        return self.restrictions.mountings or (self.axis.mounting,)

    def axis_for(self, mounting: str) -> Axis:
        return replace(self.axis, mounting=mounting)

    def with_limit(self, key: str, value: float | None) -> Problem:
        lim = self.limit_map
        if value is None:
            lim.pop(key, None)
        else:
            lim[key] = float(value)
        if key == "min_life" and self.life_from_limit and value is not None:
            return replace(
                self,
                limits=tuple(sorted(lim.items())),
                axis=replace(self.axis, required_life=float(value)),
            )
        return replace(self, limits=tuple(sorted(lim.items())))

    def with_objective(self, objective: Objective) -> Problem:
        return replace(self, objective=objective)

    def __repr__(self) -> str:
        a = self.axis
        lims = ", ".join(f"{k} {fmt(v / LIMITS[k].factor, LIMITS[k].unit)}" for k, v in self.limits)
        margins = ", ".join(f"{c} {m:g}" for c, m in self.margins if m != 1.0)
        return one_line(
            "Problem",
            repr(self.name),
            {
                "objective": self.objective.label,
                "limits": lims,
                "margins": margins,
                "axis": f"{', '.join(self.mountings)}, stroke {fmt(a.stroke * 1e3, 'mm')}, moving "
                f"mass {fmt(a.moving_mass, 'kg')}, {fmt(a.max_speed * 60, 'm/min')}",
            },
        )


# ------------------------------------------------------------------------------ the YAML keys (one table)  # noqa: E501
# The one declaration of a problem file's keys: the readers below read them by it (Section.read) and
# `axisopt schema problem` writes it out.  What a Key cannot say (a weight's scale follows its
# weight, catalog names are checked against the catalogs loaded) stays in the readers.

MARGINS_SPEC = Spec(
    "margins",
    "smallest accepted margin per check (default 1.0; 0 disables the check)",
    {
        c: Key("number", f"smallest accepted {c.replace('_', ' ')} margin", minimum=0.0)
        for c in CHECKS
    },
)
LIMITS_SPEC = Spec(
    "limits",
    "limits on the model's outputs (each with its unit)",
    {
        **{
            key: Key(
                "quantity",
                lim.doc,
                kind=lim.kind,
                positive=not lim.zero_ok,
                non_negative=lim.zero_ok,
            )
            for key, lim in LIMITS.items()
        },
        "margins": Key("section", spec=MARGINS_SPEC),
    },
)
WEIGHTS_SPEC = Spec(
    "weights",
    "weighted objective: weight per performance value",
    {k: Key("number", f"weight of the {k}", minimum=0.0) for k in WEIGHTED},
)
SCALE_SPEC = Spec(
    "scale",
    "weighted objective: the scale of each weighted value (one per weight)",
    {
        "stiffness": Key(
            "quantity", "stiffness scale", kind="stiffness", positive=True, example="100 N/um"
        ),
        "frequency": Key(
            "quantity", "frequency scale", kind="frequency", positive=True, example="100 Hz"
        ),
    },
)
OBJECTIVE_SPEC = Spec(
    "objective",
    "what to maximise",
    {
        "mode": Key("choice", "objective mode", required=True, choices=OBJECTIVE_MODES),
        "weights": Key("section", "weighted: sum of weight * value / scale", spec=WEIGHTS_SPEC),
        "scale": Key("section", "weighted: the scale of each weighted value", spec=SCALE_SPEC),
        "order": Key(
            "names",
            "lexicographic: two of the goals (stiffness, frequency, cost, moving_mass) in any "
            "order, first the primary",
            choices=PERFORMANCE,
            minimum=2,
            maximum=2,
        ),
        "tolerance": Key(
            "number",
            "lexicographic: keep designs within this fraction of the best primary (below 1; "
            "above it for a least cost or mass)",
            minimum=0.0,
            default=0.0,
        ),
        "pareto": Key("names", "pareto: two or more objectives", choices=PARETO_KEYS, minimum=2),
    },
)
PRELOAD_RANGE_SPEC = Spec(
    "nut_preload",
    "nut preload range (intersected with each nut's preload range)",
    {
        "min": Key("quantity", "lowest preload", kind="force", non_negative=True, default=0.0),
        "max": Key(
            "quantity",
            "highest preload",
            kind="force",
            positive=True,
            default=float("inf"),
            example="5 kN",
        ),
    },
)
CONTINUOUS_SPEC = Spec(
    "continuous",
    "bounds of the continuous variables",
    {"nut_preload": Key("section", spec=PRELOAD_RANGE_SPEC)},
)
PROBLEM_SPEC = Spec(
    "problem",
    "a sizing problem: the axis, the objective, limits and catalog restrictions",
    {
        "name": NAME_KEY,
        "description": DESCRIPTION_KEY,
        "catalogs": CATALOGS_KEY,
        "axis": Key(
            "section",
            "as in a design (axis.mounting is the default mounting)",
            required=True,
            spec=AXIS_SPEC,
        ),
        "objective": Key(
            "one_of",
            "what to maximise (default: stiffness)",
            options=(
                Key("choice", "a mode without options", choices=PERFORMANCE + ("tool_stiffness",)),
                Key("section", spec=OBJECTIVE_SPEC),
            ),
        ),
        "limits": Key("section", spec=LIMITS_SPEC),
        "catalog": Key("section", spec=RESTRICTIONS_SPEC),
        "continuous": Key("section", spec=CONTINUOUS_SPEC),
        "search": Key("section", spec=SEARCH_SPEC),
        "drive_design": Key("section", spec=DRIVE_DESIGN_SPEC),
    },
)


# ----------------------------------------------------------------------------------------- reading


def load_problem(path, catalog: Catalog | None = None) -> Problem:
    """Read a problem YAML; every error names the file and key (InputError)."""
    path = Path(path)
    root = Section(
        require_kind(read_yaml(path), str(path), "problem"), str(path), spec=PROBLEM_SPEC
    )
    cat = catalog if catalog is not None else catalog_for(root, path.parent)
    return read_problem(root, cat, name=path.stem)


def read_problem(root: Section, catalog: Catalog, name: str = "problem") -> Problem:
    root = root.declared(PROBLEM_SPEC)
    name = root.read("name", name)
    root.read("description")
    asec = root.read("axis")
    axis, assumed = read_axis(asec)
    objective = _read_objective(root)
    lsec = root.read("limits")
    limits, margins = _read_limits(lsec)
    for key in ("max_moving_mass", "max_total_mass"):  # the table alone already weighs more
        cap = dict(limits).get(key)
        if (
            lsec is not None
            and cap is not None
            and lsec.has(key)
            and cap < axis.moving_mass * (1 - 1e-9)
        ):
            raise lsec.error(
                key,
                f"{cap:g} kg is below axis.moving_mass ({axis.moving_mass:g} kg, the table alone, "
                "before nut and blocks): no design can meet it",
            )
    restr = read_restrictions(root.read("catalog"), catalog, axis)
    if (
        restr.drive and axis.acceleration <= 0 and not axis.duty_cycle
    ):  # as a design with a motor: no default
        raise asec.error(
            "acceleration",
            "sizing a motor (the search chooses the drive) needs axis.acceleration "
            "> 0 or an axis.duty_cycle: without one the drive would carry no inertia torque",
        )
    pmin, pmax = _read_continuous(root.read("continuous"))
    ssec = root.read("search")
    drives = read_drive_choice(
        ssec, axis, root.string_list("catalogs", []), base=Path(root.source).parent
    )
    dsec = root.read("drive_design")
    drive_design = read_drive_design(dsec)
    if drive_design is not None and (drives is None or drive_design["type"] not in drives.types):
        raise dsec.error(
            "type",
            f"a {drive_design['type']} design needs search.drive_types to list "
            f"{drive_design['type']}",
        )
    root.done()
    min_life = dict(limits).get("min_life")
    follows = min_life is not None and "required_life" in assumed
    if follows:  # the user's life limit is the life the nut, bearing and guide checks need
        axis = replace(axis, required_life=min_life)
        assumed = tuple(k for k in assumed if k != "required_life")
    return Problem(
        axis=axis,
        catalog=catalog,
        objective=objective,
        limits=limits,
        margins=margins,
        restrictions=restr,
        preload_min=pmin,
        preload_max=pmax,
        name=name,
        source=root.source,
        assumed=assumed,
        life_from_limit=follows,
        arrangements=read_arrangements(ssec, asec, axis),
        drives=None if drives is None or drives.screw_only else drives,
        drive_design=drive_design,
    )


def _read_objective(root: Section) -> Objective:
    node = root.raw("objective")
    if node is None:
        return Objective()
    if isinstance(
        node.value, str
    ):  # all modes, so that the options-taking ones get a helpful message
        mode = root.choice("objective", OBJECTIVE_MODES)
        if mode in ("weighted", "lexicographic", "pareto"):
            raise root.error("objective", f"mode '{mode}' needs a mapping (see the problem format)")
        return Objective(mode=mode)
    sec = root.section("objective")
    mode = sec.read("mode")
    kw: dict = {"mode": mode}
    if mode == "weighted":
        wsec = sec.section("weights", required=True)  # required in this mode only
        weights = []
        for k in wsec.keys():
            if k not in WEIGHTED:
                raise wsec.error(
                    k,
                    f"unknown objective '{k}'; use {', '.join(WEIGHTED)} (a least cost or mass: "
                    "mode cost or moving_mass, or a lexicographic order)",
                )
            w = wsec.read(k)
            weights.append((k, float(w)))
        wsec.done()
        ssec = sec.section("scale", required=True)
        scale = []
        for k, _ in weights:
            scale.append(
                (k, ssec.quantity(k, SCALE_SPEC.keys[k].kind, required=True, positive=True))
            )
        ssec.done()
        if not weights or sum(w for _, w in weights) <= 0:
            raise sec.error("weights", "at least one weight must be positive")
        kw.update(weights=tuple(weights), scale=tuple(scale))
    elif mode == "lexicographic":
        order = sec.read("order")
        if (
            not order
            or len(order) != 2
            or len(set(order)) != 2
            or not set(order) <= set(PERFORMANCE)
        ):
            raise sec.error(
                "order",
                f"lexicographic order must list two different goals of "
                f"{', '.join(PERFORMANCE)}, e.g. [frequency, stiffness] or [stiffness, cost]",
            )
        tol = sec.read("tolerance")
        if tol >= 1:
            raise sec.error("tolerance", f"relative tolerance must be below 1, got {tol}")
        kw.update(order=tuple(order), tolerance=float(tol))
    elif mode == "pareto":
        keys = sec.read("pareto")
        if not keys or len(keys) < 2:
            raise sec.error("pareto", f"list two or more of {', '.join(PARETO_KEYS)}")
        for k in keys:
            if k not in PARETO_KEYS:
                raise sec.error(
                    "pareto", f"unknown Pareto objective '{k}'; use {', '.join(PARETO_KEYS)}"
                )
        keys = [PARETO_ALIASES.get(k, k) for k in keys]
        if len(set(keys)) != len(keys):
            raise sec.error("pareto", "Pareto objectives repeat")
        kw.update(pareto=tuple(keys))
    sec.done()
    return Objective(**kw)


def _read_limits(sec: Section | None):
    margins = {c: 1.0 for c in CHECKS}
    limits = dict(DEFAULT_LIMITS)
    if sec is None:
        return tuple(sorted(limits.items())), tuple(margins.items())
    given = {}
    for key in LIMITS:
        v = sec.read(key)
        if v is not None:
            limits[key] = given[key] = v
    import warnings

    from .design.plausible import LIMIT_RANGES, implausible
    from .errors import ImplausibleInput

    for key, message in implausible(given, LIMIT_RANGES):
        warnings.warn(
            str(InputError(message, source=sec.source, where=sec.where(key))),
            ImplausibleInput,
            stacklevel=2,
        )
    msec = sec.read("margins")
    if msec is not None:
        for k in msec.keys():
            if k not in CHECKS:
                near = close_matches(k, CHECKS)
                hint = f"; did you mean '{near[0]}'?" if near else ""
                raise msec.error(k, f"unknown check '{k}'{hint} (checks: {', '.join(CHECKS)})")
            margins[k] = float(msec.read(k))
        msec.done()
    sec.done()
    return tuple(sorted(limits.items())), tuple(margins.items())


def _read_continuous(sec: Section | None):
    if sec is None:
        return 0.0, float("inf")
    pre = sec.read("nut_preload")
    lo, hi = 0.0, float("inf")
    if pre is not None:
        lo = pre.read("min")
        hi = pre.read("max")
        if lo > hi:
            raise pre.error("max", f"nut_preload max {hi:.0f} N is below min {lo:.0f} N")
        pre.done()
    sec.done()
    return lo, hi


__all__ = [
    "Problem",
    "Objective",
    "Restrictions",
    "LIMITS",
    "PROBLEM_SPEC",
    "load_problem",
    "read_problem",
    "InputError",
]
