"""``axis_response``: the sub-assemblies of the axis model put together, one pure function.

``axis_response(p, x, mounting, preload, request)`` takes ``p`` (the names in :data:`PARAM_NAMES`
mapped to floats, numpy arrays that broadcast against the positions ``x``, or CasADi symbols), so
the same function

* evaluates one design on floats,
* screens millions of catalog combinations at once on numpy arrays (``search``), and
* builds the symbolic CasADi Function of :class:`axisopt.model.AxisModel` that IPOPT differentiates,

and ``identify`` builds its plant from it.  Sub-assemblies: :mod:`.loads` (masses and axial loads),
:mod:`.chain` (stiffness chain), :mod:`.modes` (frequencies and damping), :mod:`.drag`, :mod:`.cost`
and :mod:`.checks`.  Which of them it evaluates is the caller's :class:`~.request.Request` (default
:data:`~.request.FULL`: all).
"""

from __future__ import annotations

from ..physics.servo import kv_rule
from .accuracy import positioning_budget
from .carriage import carriage_loads, rocking, tool_stiffness
from .chain import stiffness_chain
from .checks import checks
from .cost import cost
from .drag import drag_torque
from .drive import drive, lost_motion
from .heat import heat_balance, with_temperature
from .loads import axial_loads, masses
from .modes import axial_modes, damping, drive_train_modes
from .request import FULL, Request


def loaded(p: dict, preload) -> tuple:
    """The first steps every evaluation of the axis shares: the heat balance (:mod:`.heat`), the
    parameters at the temperature rise it sets, the masses and the axial loads (:mod:`.loads`).
    Returns (p at that rise, the heat balance, the masses, the axial loads); float, numpy or CasADi
    like :func:`axis_response`."""
    heat = heat_balance(p, preload)
    p = with_temperature(p, heat)
    m = masses(p)
    return p, heat, m, axial_loads(p, m["moving_mass"], m["gantry_moving_mass"])


def axis_response(p: dict, x, mounting: str, preload, request: Request = FULL) -> dict:
    """Evaluate the axis model.

    p        : dict of :data:`PARAM_NAMES` -> float / ndarray / CasADi
    x        : nut positions, fixed bearing to nut [m]
    mounting : 'fixed-free' | 'fixed-supported' | 'fixed-fixed'
    preload  : nut preload [N] (float / ndarray / CasADi)
    request  : the sub-assemblies to evaluate (:class:`~.request.Request`); the searches ask for
               less: :data:`~.request.SCREEN`, :data:`~.request.MECHANICS` when each drive is
               screened apart (:func:`drive_response`), no chain where only the lowest preload's
               limits are checked
    Returns a dict: per-position arrays (``k_total``, ``k_screw``, ``f_axial``, ``f1``, ...),
    per-design scalars (``k_nut``, ``k_bearing``, ``f_table``, ``drag_torque``, masses, ``cost``,
    loads) and ``margin_<check>`` for each of :data:`CHECKS` (>= 1 passes); the outputs of the
    sub-assemblies the request leaves out are absent.
    """
    p, heat, m, loads = loaded(p, preload)
    loads.update(carriage_loads(p, m["gantry_moving_mass"]))
    out = {}
    out.update(heat)
    out.update(m)
    # per-phase lists: no outputs
    out.update({k: v for k, v in loads.items() if not isinstance(v, list)})
    if request.chain or request.extras:
        chained, k, rock, modes = _chain(p, x, mounting, preload, m, loads)
        out.update(chained)
        # the positioning-error budget (model.accuracy): its rows at the stroke's softest points
        if request.budget:
            out.update(
                positioning_budget(
                    p, mounting, preload, loads["max_axial_force"], loads["mean_axial_force"], rock
                )
            )
    out.update(drag_torque(p, preload, loads))
    out["cost"] = cost(p)
    out["backlash"] = lost_motion(p)
    out.update(checks(p, mounting, preload, loads))
    if request.drive:
        out.update(
            drive(
                p,
                m["moving_mass"],
                out["drag_torque"],
                loads["guide_friction_static"],
                request.regen,
            )
        )
    if request.extras:
        out.update(drive_train_modes(p, k, modes["m_eff"]))
        out.update(damping(p, k, modes["m_eff"]))
    return out


def _chain(p, x, mounting, preload, m, loads) -> tuple:
    """The stiffness chain, the table's rocking, the stiffness at the tool, the axial modes and the
    achievable
    Kv: (their outputs, the chain, the rocking, the modes)."""
    k = stiffness_chain(
        p, x, mounting, preload, loads["max_axial_force"], loads["mean_axial_force"]
    )
    rock = rocking(p)
    modes = axial_modes(
        p, x, mounting, k, m["moving_mass"], m["screw_mass"], rock, m["gantry_moving_mass"]
    )
    out = dict(k)
    out.update(rock)
    out.update(tool_stiffness(p, k["k_total"], rock))
    out.update(modes)
    out["kv"] = kv_rule(modes["f_axial"])  # achievable position-loop gain [1/s] (model.servo)
    return out, k, rock, modes


def chain_response(p: dict, x, mounting: str, preload, coupling_stiffnesses=None):
    """The outputs of :func:`axis_response` that the coupling's torsional stiffness changes (the
    stiffness chain, the stiffness at the tool, the axial modes and the achievable Kv), from the
    same sub-assemblies without the guides' loads, the checks, the drag, the cost and the
    positioning budget: what the infeasibility explanation evaluates once per distinct coupling
    stiffness (search.infeasible.explain).
    ``coupling_stiffnesses``: a list of values of ``p["coupling_stiffness"]`` [N m/rad]: a list of
    outputs, one per value, sharing the heat balance and the loads (which the coupling does not
    change)."""
    q, _, m, loads = loaded(p, preload)
    if coupling_stiffnesses is None:
        return _chain(q, x, mounting, preload, m, loads)[0]
    return [
        _chain(dict(q, coupling_stiffness=k), x, mounting, preload, m, loads)[0]
        for k in coupling_stiffnesses
    ]


def drive_inputs(p: dict, preload) -> tuple:
    """What the drive block takes from the mechanics of a combination: the moving mass [kg], the
    drag torques by source [N m] (:func:`axisopt.model.drag.drag_torque`) and the guide friction at
    standstill [N] (credited to the holding torque).  The guide enters the drive only through these
    three, so the searches can bound the drive over a range of guides from their ranges."""
    p, _, m, loads = loaded(p, preload)
    return m["moving_mass"], drag_torque(p, preload, loads), loads["guide_friction_static"]


def drive_response(p: dict, preload, request: Request = FULL) -> dict:
    """The outputs of :func:`axis_response` that the motor, coupling and reduction change (the drive
    block, the cost and the lost motion), from the same sub-assemblies without the stiffness chain
    and the modes: for the searches, which screen the mechanics once per combination of screw, nut,
    bearing and guide and then each drive against it, and solve the preload against the motor-torque
    limits (which depend on it through the nut's drag only).  Of the ``request`` only ``regen``
    applies (the regenerated energy and power)."""
    moving, out, hold_friction = drive_inputs(p, preload)
    out = dict(out)
    out.update(drive(p, moving, out["drag_torque"], hold_friction, request.regen))
    out["cost"] = cost(p)
    out["backlash"] = lost_motion(p)
    return out
