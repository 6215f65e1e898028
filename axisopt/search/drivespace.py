"""The search spaces of the rack-and-pinion and linear-motor drive types: every combination of their
parts (rack set x reduction x motor x twin pinion x guide; linear motor x forcers x guide) as
broadcast numpy arrays of the model's parameters (:mod:`axisopt.model.rackdrive`,
:mod:`axisopt.model.lmdrive`), the axis's values per drive side, and the evaluation of a whole space
(``evaluate_space``) or of one combination in floats (``evaluate_one``, the exhaustive method's
ground truth).  Prices of the parts: the catalogs'."""

from __future__ import annotations

from dataclasses import dataclass
from math import prod

import numpy as np

from ..model.lmdrive import lm_response
from ..model.motorrule import DEFAULT_RULE
from ..model.rackdrive import guide_response, rack_response
from ..physics import rack as pr

MOTOR_MASS_BASE = (
    2.0  # [kg] a servo motor without a catalog mass: 2 kg + 0.7 kg per N m rated (an estimate)
)
MOTOR_MASS_PER_NM = 0.7


@dataclass(frozen=True)
class Side:
    """The axis as one drive side sees it (SI)."""

    sides: int  # 1, or 2 for a twin-drive gantry
    m_axis: float  # this side's moving mass without drive parts and blocks
    normal: float
    vertical: float
    cycle: dict  # physics.rack.cycle_gram of the phases (process force already this side's share)
    v_max: float
    t_acc: float  # longest acceleration run [s]
    life_needed: float  # travel [m]
    fw: float
    static_safety: float
    rms_ratio: float | None  # None: each motor's vendor rule
    max_inertia_ratio: float
    thrust: float  # steady feed force of this side at feed [N] (axis.axial_load x share)
    mean_thrust: float  # ... at the mean axial load [N]
    blocks: float  # per side
    rails: float  # per side
    rail_length: float
    stroke: float


def side_of(axis) -> Side:
    """The per-side values of ``axis`` (a twin drive: the governing side, as the screw model checks
    it)."""
    tw = axis.twin_drive
    sides = 2 if tw is not None else 1
    share = tw.force_share if tw is not None else 1.0
    m_axis = axis.moving_mass / sides + (share * tw.cross_mass if tw is not None else 0.0)
    phases = tuple(axis.phases)
    v_max = max((ph.speed for ph in phases), default=axis.max_speed)
    run, t_acc = 0.0, 0.0
    for ph in phases:  # contiguous phases accelerating the same way
        if ph.a0 != 0.0 or ph.a1 != 0.0:
            run += ph.duration
            t_acc = max(t_acc, run)
        else:
            run = 0.0
    mean = axis.mean_speed_eff
    return Side(
        sides=sides,
        m_axis=m_axis,
        normal=axis.normal_load * share,
        vertical=float(axis.orientation == "vertical"),
        cycle=pr.cycle_gram(phases),
        v_max=v_max,
        t_acc=max(t_acc, 1e-3),
        life_needed=axis.required_life * mean,
        fw=axis.load_factor_eff,
        static_safety=axis.guide_static_safety,
        rms_ratio=axis.rms_torque_ratio,
        max_inertia_ratio=axis.max_inertia_ratio,
        thrust=axis.axial_load * share,
        mean_thrust=axis.mean_axial_load_eff * share,
        blocks=axis.guide_blocks / sides,
        rails=axis.rails / sides,
        rail_length=axis.stroke + axis.table_length,
        stroke=axis.stroke,
    )


def _guides(table, side: Side) -> dict:
    roller = np.array([t == "roller" for t in table["type"]], dtype=float)
    return {
        "mu": table["friction_coefficient"],
        "f_seal": table["friction_force"] * side.blocks,
        "m_blocks": table["block_mass"] * side.blocks,
        "k_n": table["normal_rigidity"],
        "c_block": table["dynamic_load_rating"],
        "c0_block": table["static_load_rating"],
        "roller": roller,
        "rating_distance": table["rating_distance"],
        "guide_cost": side.sides
        * (
            table["block_price"] * side.blocks
            + table["rail_price_per_length"] * side.rails * side.rail_length
        ),
    }


@dataclass
class DriveSpace:
    """One drive type's combinations: ``axes`` names the broadcast axes and their part ids, ``p``
    the model's parameters broadcast over them, ``cost`` the parts' price of the whole axis (both
    sides)."""

    kind: str  # 'rack_pinion' | 'linear_motor'
    axes: tuple  # ((slot, ids), ...) in broadcast order
    p: dict
    side: Side
    guide_cost: object = 0.0  # the guides' share of the cost (broadcast over the guide axis)
    drive_cost: object = 0.0  # the rest (a size-1 guide axis)

    @property
    def cost(self):
        """The parts' price of every combination (a full array: the exhaustive method's)."""
        return self.drive_cost + self.guide_cost

    def cost_of(self, idx):
        """The price at the multi-index ``idx`` (arrays of indices per axis)."""
        return take(self.drive_cost, idx) + take(self.guide_cost, idx)

    @property
    def shape(self) -> tuple:
        return tuple(len(ids) for _, ids in self.axes)

    @property
    def size(self) -> int:
        return prod(self.shape)

    def parts(self, flat: int) -> dict:
        idx = np.unravel_index(flat, self.shape)
        return {slot: ids[i] for (slot, ids), i in zip(self.axes, idx)}

    def at(self, flat: int) -> dict:
        """The parameters of one combination, floats."""
        idx = np.unravel_index(flat, self.shape)
        return {
            k: float(np.broadcast_to(v, self.shape)[idx]) if isinstance(v, np.ndarray) else float(v)
            for k, v in self.p.items()
        }

    def cost_at(self, flat: int) -> float:
        return float(self.cost_of(np.unravel_index(flat, self.shape)))


def take(v, idx):
    """The entries of a broadcastable array at the multi-index ``idx`` (a size-1 axis stays at
    0)."""
    if not isinstance(v, np.ndarray) or v.ndim == 0:
        return v
    return v[tuple(ix if v.shape[d] != 1 else 0 for d, ix in enumerate(idx))]


def _shape(values, axis: int, ndim: int) -> np.ndarray:
    a = np.asarray(values, dtype=float)
    return a.reshape([-1 if i == axis else 1 for i in range(ndim)])


def rack_space(racks, reductions, motors, guides, side: Side, choice) -> DriveSpace:
    """rack set x reduction x motor x twin pinion x guide."""
    nd = 5
    R = lambda col: _shape([r[col] for r in racks], 0, nd)  # noqa: E731
    red = lambda col: _shape(reductions[col], 1, nd)  # noqa: E731
    mot = lambda col: _shape(motors[col], 2, nd)  # noqa: E731
    # each motor by its vendor's rule (model.motorrule; a row without one: the harshest), unless the
    # problem asks one RMS ratio of every motor (axis.rms_torque_ratio)
    mot_rule = lambda col, default: _shape(  # noqa: E731
        np.where(np.isfinite(np.asarray(motors[col], float)), motors[col], default)
        if col in motors
        else np.full(len(motors["rated_torque"]), default),
        2,
        nd,
    )
    twin = _shape(choice.twin_pinion, 3, nd)
    g = {k: _shape(v, 4, nd) for k, v in _guides(guides, side).items()}
    m_motor = np.where(
        np.isfinite(motors["mass"]),
        motors["mass"],
        MOTOR_MASS_BASE + MOTOR_MASS_PER_NM * motors["rated_torque"],
    )
    pinions = 1.0 + twin
    m_parts = pinions * (_shape(m_motor, 2, nd) + red("mass"))
    p = {
        "m_axis": side.m_axis,
        "m_parts": m_parts,
        "m_blocks": g["m_blocks"],
        "mu": g["mu"],
        "f_seal": g["f_seal"],
        "normal": side.normal,
        "vertical": side.vertical,
        "d": R("pitch_diameter"),
        "perm": R("permissible_force"),
        "k_o": choice.overload_factor,
        "face": R("face_width"),
        "err": R("pitch_error"),
        "stroke": side.stroke,
        "ratio": red("ratio"),
        "eta": red("efficiency"),
        "j_motor": mot("rotor_inertia"),
        "j_red": red("inertia"),
        "t_rated": mot("rated_torque"),
        "t_peak": mot("peak_torque"),
        "n_max": mot("max_speed"),
        "t2b": red("accel_torque"),
        "t2n": red("rated_torque"),
        "n1max": red("max_input_speed"),
        "backlash": red("backlash"),
        "kt_red": red("torsional_stiffness"),
        "twin": twin,
        "bias": choice.preload_bias,
        "rms_ratio": side.rms_ratio
        if side.rms_ratio is not None
        else mot_rule("rms_ratio", DEFAULT_RULE.rms),
        "max_inertia_ratio": side.max_inertia_ratio,
        "k_n": g["k_n"],
        "blocks": side.blocks,
        "v_max": side.v_max,
        "thrust": side.thrust,
        "mean_thrust": side.mean_thrust,
        **_guide_params(g, side),
    }
    rack_len = side.sides * side.rail_length
    drive_cost = side.sides * pinions * (
        R("pinion_price") + red("price") + mot("price")
    ) + rack_len * R("rack_price_per_length")
    axes = (
        ("rack", tuple(r["id"] for r in racks)),
        ("reduction", tuple(reductions["id"])),
        ("motor", tuple(motors["id"])),
        ("twin_pinion", tuple("yes" if t else "no" for t in choice.twin_pinion)),
        ("guide", tuple(guides["id"])),
    )
    return DriveSpace("rack_pinion", axes, p, side, g["guide_cost"], drive_cost)


def lm_space(lms, guides, side: Side, choice) -> DriveSpace:
    """linear motor x forcers x guide."""
    nd = 3
    L = lambda col: _shape([0.0 if r[col] is None else r[col] for r in lms], 0, nd)  # noqa: E731
    forcers = _shape(np.arange(1, choice.max_forcers + 1), 1, nd)
    g = {k: _shape(v, 2, nd) for k, v in _guides(guides, side).items()}
    p = {
        "m_axis": side.m_axis,
        "m_blocks": g["m_blocks"],
        "mu": g["mu"],
        "f_seal": g["f_seal"],
        "normal": side.normal,
        "vertical": side.vertical,
        "forcers": forcers,
        "fc": L("continuous_force"),
        "fp": L("peak_force"),
        "kf": L("force_constant"),
        "m_forcer": L("forcer_mass"),
        "fa": L("attraction_force"),
        "accuracy": L("accuracy"),
        "t_acc": side.t_acc,
        "bandwidth": choice.servo_bandwidth,
        "k_n": g["k_n"],
        "blocks": side.blocks,
        "thrust": side.thrust,
        "mean_thrust": side.mean_thrust,
        **_guide_params(g, side),
    }
    drive_cost = side.sides * (
        forcers * L("forcer_price") + side.rail_length * L("track_price_per_length")
    )
    axes = (
        ("linear_motor", tuple(r["id"] for r in lms)),
        ("forcers", tuple(str(i) for i in range(1, choice.max_forcers + 1))),
        ("guide", tuple(guides["id"])),
    )
    return DriveSpace("linear_motor", axes, p, side, g["guide_cost"], drive_cost)


def _guide_params(g, side: Side) -> dict:
    return {
        "c_block": g["c_block"],
        "c0_block": g["c0_block"],
        "roller": g["roller"],
        "rating_distance": g["rating_distance"],
        "fw": side.fw,
        "life_needed": side.life_needed,
        "static_safety": side.static_safety,
    }


def respond(space: DriveSpace, p: dict) -> dict:
    """The model on ``p`` (arrays or floats): {'outputs', 'margins'} merged with the guide
    checks."""
    if space.kind == "rack_pinion":
        res = rack_response(p, space.side.cycle)
        attraction = 0.0
    else:
        res = lm_response(p, space.side.cycle)
        attraction = res["outputs"]["attraction_force"]
    gr = guide_response(p, res["outputs"]["moving_mass"], attraction)
    return {
        "outputs": {**res["outputs"], **gr["outputs"]},
        "margins": {**res["margins"], **gr["margins"]},
    }


def evaluate_space(space: DriveSpace) -> dict:
    """Every combination at once: outputs and margins as arrays of ``space.shape``."""
    res = respond(space, space.p)
    shape = space.shape
    res["outputs"] = {
        k: np.broadcast_to(np.asarray(v, dtype=float), shape) for k, v in res["outputs"].items()
    }
    res["margins"] = {
        k: np.broadcast_to(np.asarray(v, dtype=float), shape) for k, v in res["margins"].items()
    }
    res["cost"] = np.broadcast_to(np.asarray(space.cost, dtype=float), shape)
    return res


def evaluate_one(space: DriveSpace, flat: int) -> dict:
    """One combination in floats (the exhaustive method)."""
    res = respond(space, space.at(flat))
    return {
        "outputs": {k: float(v) for k, v in res["outputs"].items()},
        "margins": {k: float(v) for k, v in res["margins"].items()},
        "cost": space.cost_at(flat),
    }
