"""Machine files: YAML <-> frozen dataclasses (the same unit and error rules as a problem file).

.. code-block:: yaml

    name: vmc
    machine:
      objective: cost                  # cost | tool_stiffness | frequency | moving_mass
      limits:
        min_tool_stiffness: {x: 20 N/um, y: 20 N/um, z: 30 N/um}   # or one value for every direction
        min_frequency: 40 Hz           # the machine's lowest natural frequency (lumped chain)
        max_cost: 40000 EUR            # every axis's parts
        max_moving_mass: 2500 kg       # every moving mass of the machine
      tool_point: {X: 400 mm, Y: 250 mm, Z: 200 mm}   # nut positions the stiffness chain is shown at
    axes:
      Y:
        carried_by: frame              # the frame or another axis's name
        direction: y                   # travel
        normal: z                      # normal of the guides' mounting plane
        frame_stiffness: {x: 900 N/um, y: 900 N/um, z: 1500 N/um}   # or 'estimate' (stated, conservative)
        carried_at: {height: 250 mm, offset: 0 mm}   # where this axis and all it carries act on its carrier
        nut_preload: 3000 N            # machine evaluate: the pinned nut's preload (default: the top)
        problem: {axis: {...}, limits: {...}, catalog: {...}}       # as a problem file
"""  # noqa: E501

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

from ..design import CATALOGS_KEY, DESCRIPTION_KEY, NAME_KEY, catalog_for
from ..errors import InputError
from ..problem import PROBLEM_SPEC, Problem, read_problem
from ..yamlio import Key, Section, Spec, read_yaml

DIRECTIONS = ("x", "y", "z")
FRAME = "frame"
OBJECTIVES = ("cost", "tool_stiffness", "frequency", "moving_mass")
# what an axis's problem section may not say: the machine decides it
NOT_IN_AXIS_PROBLEM = ("name", "description", "catalogs", "objective")

XYZ_STIFFNESS = Spec(
    "stiffness per direction",
    "a stiffness in each of x, y and z",
    {
        d: Key(
            "quantity",
            f"in {d}",
            required=True,
            kind="stiffness",
            positive=True,
            example="500 N/um",
        )
        for d in DIRECTIONS
    },
)
LIMITS_SPEC = Spec(
    "machine limits",
    "limits on the machine's outputs",
    {
        "min_tool_stiffness": Key(
            "one_of",
            "least static stiffness at the tool, one value or per direction",
            options=(
                Key("quantity", kind="stiffness", positive=True, example="20 N/um"),
                Key("section", spec=XYZ_STIFFNESS),
            ),
        ),
        "min_frequency": Key(
            "quantity",
            "least lowest natural frequency of the machine's lumped chain",
            kind="frequency",
            positive=True,
            example="40 Hz",
        ),
        "max_cost": Key(
            "quantity",
            "most cost of every axis's parts",
            kind="money",
            positive=True,
            example="40000 EUR",
        ),
        "max_moving_mass": Key(
            "quantity",
            "most sum of the machine's moving masses",
            kind="mass",
            positive=True,
            example="2500 kg",
        ),
    },
)
MACHINE_SPEC = Spec(
    "machine",
    "the machine's objective and limits",
    {
        "objective": Key(
            "choice",
            "what the joint search optimises (default cost)",
            choices=OBJECTIVES,
            default="cost",
        ),
        "limits": Key("section", spec=LIMITS_SPEC),
        "tool_point": Key(
            "section",
            "the nut position on each axis's stroke the stiffness chain is shown at "
            "(default: mid-stroke); the limits read the worst over the strokes",
            spec=Spec(
                "tool_point",
                "nut position per axis name",
                extra=Key("quantity", kind="length", non_negative=True, example="400 mm"),
                extra_doc="an axis name",
            ),
        ),
    },
)
CARRIED_AT = Spec(
    "carried_at",
    "where this axis, with all it carries, acts on its carrier",
    {
        "height": Key(
            "quantity",
            "above the carrier's guide mounting plane",
            kind="length",
            non_negative=True,
            default=0.0,
            example="250 mm",
        ),
        "offset": Key(
            "quantity",
            "across the carrier's rails from its carriage centre",
            kind="length",
            default=0.0,
            example="0 mm",
        ),
    },
)
AXIS_NODE_SPEC = Spec(
    "machine axis",
    "one axis of the machine",
    {
        "carried_by": Key(
            "string",
            "'frame' or the name of the axis whose carriage carries this axis",
            required=True,
        ),
        "direction": Key("choice", "direction of travel", required=True, choices=DIRECTIONS),
        "normal": Key(
            "choice",
            "normal of the guides' mounting plane (the blocks' normal rigidity acts along it)",
            required=True,
            choices=DIRECTIONS,
        ),
        "frame_stiffness": Key(
            "one_of",
            "the frame's (structure's) stiffness under this axis's guides, or "
            "'estimate': as stiff as the axis link itself in each direction (doubles its "
            "compliance; conservative, stated in every result)",
            required=True,
            options=(Key("choice", choices=("estimate",)), Key("section", spec=XYZ_STIFFNESS)),
        ),
        "carried_at": Key("section", spec=CARRIED_AT),
        "nut_preload": Key(
            "quantity",
            "for `axisopt machine evaluate`: the pinned nut's preload, within the nut's catalog "
            "range (and, a preloaded nut, the vendors' ceiling of 10 % of its Ca); default: the "
            "top of its feasible preload interval.  `machine solve` chooses every preload and "
            "refuses it",
            kind="force",
            positive=True,
            example="3000 N",
        ),
        "problem": Key(
            "section",
            "the axis's problem: axis, limits, catalog, continuous, search sections as in a "
            "problem file; axis.moving_mass is the axis's own moving structure (what it carries is "
            "added)",
            required=True,
            spec=PROBLEM_SPEC,
        ),
    },
)
MACHINE_FILE_SPEC = Spec(
    "machine file",
    "a machine: a tree of feed axes sized together",
    {
        "name": NAME_KEY,
        "description": DESCRIPTION_KEY,
        "catalogs": CATALOGS_KEY,
        "machine": Key("section", spec=MACHINE_SPEC),
        "axes": Key(
            "section",
            "the axes by name",
            required=True,
            spec=Spec(
                "axes",
                "axis name -> axis",
                extra=Key("section", spec=AXIS_NODE_SPEC),
                extra_doc="an axis name",
            ),
        ),
    },
)


@dataclass(frozen=True)
class MachineAxis:
    """One axis of a machine (SI).  ``problem.axis.moving_mass`` is the axis's own moving
    structure."""

    name: str
    carried_by: str  # FRAME or an axis name
    direction: str  # 'x' | 'y' | 'z'
    normal: str  # the guides' normal
    problem: Problem
    frame_stiffness: tuple | None  # (kx, ky, kz) [N/m]; None: the stated estimate
    carried_at: tuple = (0.0, 0.0)  # (height, offset) on the carrier [m]
    nut_preload: float | None = None  # [N]; machine evaluate's (None: the feasible top)

    @property
    def lateral(self) -> str:
        return next(d for d in DIRECTIONS if d not in (self.direction, self.normal))

    def link_role(self, d: str) -> str:
        """What of the axis acts in direction ``d``: 'axial' (its drive chain) or 'normal' /
        'lateral' (its guides across it)."""
        return "axial" if d == self.direction else ("normal" if d == self.normal else "lateral")


@dataclass(frozen=True)
class Machine:
    """A machine: its axes (carriers before what they carry), objective and limits (SI)."""

    name: str
    axes: tuple  # MachineAxis, a carrier before the axes it carries
    objective: str = "cost"
    min_tool_stiffness: tuple = (0.0, 0.0, 0.0)  # [N/m] per direction
    min_frequency: float = 0.0  # [Hz]
    max_cost: float = float("inf")  # [EUR]
    max_moving_mass: float = float("inf")  # [kg]
    tool_point: tuple = ()  # ((axis name, nut position [m]), ...)
    source: str = ""
    description: str = ""

    @property
    def by_name(self) -> dict:
        return {a.name: a for a in self.axes}

    def children(self, name: str) -> list:
        return [a for a in self.axes if a.carried_by == name]

    def branches(self) -> list:
        """The chains from the frame: each a list of axes, the one on the frame first."""
        out = []
        for root in self.children(FRAME):
            chain, a = [root], root
            while self.children(a.name):
                a = self.children(a.name)[0]
                chain.append(a)
            out.append(chain)
        return out

    @property
    def estimated_frames(self) -> tuple:
        return tuple(a.name for a in self.axes if a.frame_stiffness is None)


def load_machine(path) -> Machine:
    """Read a machine YAML; every error names the file and key (InputError)."""
    path = Path(path)
    root = Section(read_yaml(path), str(path), spec=MACHINE_FILE_SPEC)
    if root.has("axis") and not root.has("axes"):
        raise InputError(
            "an axis's problem or design, not a machine (it has 'axis', no 'axes'): size it with "
            "`axisopt solve`",
            source=str(path),
        )
    return read_machine(root, path)


def is_machine_file(path) -> bool:
    """A YAML file with a top-level ``axes:`` key (a machine, not an axis problem)."""
    node = read_yaml(Path(path))
    return isinstance(node.value, dict) and "axes" in node.value


def read_machine(root: Section, path: Path) -> Machine:
    catalog = catalog_for(root, path.parent)
    name = root.read("name", path.stem)
    description = root.read("description") or ""
    msec = root.read("machine")
    asec = root.read("axes")
    root.done()
    axes = {}
    for an in asec.keys():
        axes[an] = _read_axis(asec.section(an), str(an), catalog)
    asec.done()
    if not axes:
        raise asec.error("axes", "a machine needs at least one axis")
    ordered = _order(axes, asec)
    kw = _read_machine_section(msec, axes)
    return Machine(name=name, axes=ordered, source=str(path), description=description, **kw)


def _read_axis(sec: Section, name: str, catalog) -> MachineAxis:
    carried_by = sec.read("carried_by")
    if carried_by == name:
        raise sec.error("carried_by", f"axis '{name}' is carried by itself")
    direction, normal = sec.read("direction"), sec.read("normal")
    if normal == direction:
        raise sec.error(
            "normal",
            f"the guides' normal ({normal}) is the direction of travel: it must be across it",
        )
    fnode = sec.raw("frame_stiffness", required=True)
    if isinstance(fnode.value, str):
        sec.choice("frame_stiffness", ("estimate",))
        frame = None
    else:
        fs = sec.section("frame_stiffness")
        frame = tuple(fs.read(d) for d in DIRECTIONS)
        fs.done()
    at = sec.read("carried_at")
    carried_at = (0.0, 0.0)
    if at is not None:
        carried_at = (at.read("height"), at.read("offset"))
        at.done()
    pre = sec.read("nut_preload")
    psec = sec.read("problem")
    for k in NOT_IN_AXIS_PROBLEM:
        if psec.has(k):
            raise psec.error(
                k, f"'{k}' is the machine's, not an axis problem's: remove it from axis '{name}'"
            )
    problem = read_problem(psec, catalog, name=name)
    if problem.drives is not None:
        # the machine's offers are screw designs (machine.offers): a listed rack or linear motor
        # would be left out without a word
        raise psec.section("search").error(
            "drive_types",
            f"axis '{name}': a machine sizes its axes as screw drives; rack-and-pinion and "
            "linear-motor axes are not joined in a machine yet (size this axis alone with "
            "`axisopt solve`)",
        )
    sec.done()
    return MachineAxis(name, carried_by, direction, normal, problem, frame, carried_at, pre)


def _order(axes: dict, asec: Section) -> tuple:
    """The axes with every carrier before what it carries; an unknown carrier, a cycle, an axis
    carrying two axes or more than two chains on the frame are errors."""
    for a in axes.values():
        if a.carried_by != FRAME and a.carried_by not in axes:
            raise asec.section(a.name).error(
                "carried_by",
                f"axis '{a.name}' is carried by '{a.carried_by}', "
                f"which is neither 'frame' nor an axis ({', '.join(axes)})",
            )
    for a in axes.values():  # follow the carriers down: a cycle never reaches the frame
        seen, b = [a.name], a
        while b.carried_by != FRAME:
            b = axes[b.carried_by]
            if b.name in seen:
                cycle = " -> ".join(seen[seen.index(b.name) :] + [b.name])
                raise asec.section(a.name).error(
                    "carried_by",
                    f"the axes carry each other in a cycle: {cycle} "
                    "(every chain of carriers ends on the frame)",
                )
            seen.append(b.name)
    for a in axes.values():
        carried = [b.name for b in axes.values() if b.carried_by == a.name]
        if len(carried) > 1:
            raise asec.section(carried[1]).error(
                "carried_by",
                f"axis '{a.name}' carries {', '.join(carried)}: "
                "an axis carries at most one axis here",
            )
    roots = [a.name for a in axes.values() if a.carried_by == FRAME]
    if len(roots) > 2:
        raise asec.section(roots[2]).error(
            "carried_by",
            f"{len(roots)} chains on the frame ({', '.join(roots)}): "
            "at most two (the tool's and the workpiece's side)",
        )
    out, placed = [], {FRAME}
    while len(out) < len(axes):
        for a in axes.values():
            if a.name not in placed and a.carried_by in placed:
                out.append(a)
                placed.add(a.name)
    return tuple(out)


def _read_machine_section(msec: Section | None, axes: dict) -> dict:
    if msec is None:
        return {}
    kw: dict = {"objective": msec.read("objective")}
    lsec = msec.read("limits")
    if lsec is not None:
        node = lsec.raw("min_tool_stiffness")
        if node is not None and isinstance(node.value, dict):
            ks = lsec.section("min_tool_stiffness")
            kw["min_tool_stiffness"] = tuple(ks.read(d) for d in DIRECTIONS)
            ks.done()
        elif node is not None:
            k = lsec.quantity("min_tool_stiffness", "stiffness", positive=True)
            kw["min_tool_stiffness"] = (k, k, k)
        for key in ("min_frequency", "max_cost", "max_moving_mass"):
            v = lsec.read(key)
            if v is not None:
                kw[key] = v
        lsec.done()
    tsec = msec.read("tool_point")
    if tsec is not None:
        pts = []
        for an in tsec.keys():
            if an not in axes:
                raise tsec.error(an, f"no axis '{an}' in the machine ({', '.join(axes)})")
            v = tsec.quantity(an, "length", required=True, non_negative=True)
            stroke = axes[an].problem.axis.stroke
            if v > stroke:
                raise tsec.error(
                    an,
                    f"the tool point is outside axis {an}'s stroke: {v * 1e3:g} mm beyond "
                    f"{stroke * 1e3:g} mm",
                )
            pts.append((str(an), v))
        tsec.done()
        kw["tool_point"] = tuple(pts)
    msec.done()
    return kw


def at_carried_load(a, mass: float, height: float, offset: float):
    """The axis ``a`` (an :class:`axisopt.design.Axis`) with ``mass`` [kg] carried at
    ``height``/``offset`` on its carriage (SI): the mass joins the moving mass (a twin drive's: its
    cross carriage, ``cross_mass``) and moves the centre of gravity."""
    if mass <= 0:
        return a
    if a.twin_drive is not None:
        return replace(
            a, twin_drive=replace(a.twin_drive, cross_mass=a.twin_drive.cross_mass + mass)
        )
    own = a.moving_mass
    total = own + mass
    cg = (own * a.cg_height_eff + mass * height) / total
    cgo = (own * a.cg_offset + mass * offset) / total
    return replace(a, moving_mass=total, cg_height=cg, cg_offset=cgo)


__all__ = [
    "Machine",
    "MachineAxis",
    "load_machine",
    "read_machine",
    "is_machine_file",
    "at_carried_load",
    "DIRECTIONS",
    "FRAME",
    "OBJECTIVES",
    "MACHINE_FILE_SPEC",
    "InputError",
]
