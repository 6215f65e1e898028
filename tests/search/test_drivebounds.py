"""The per-drive least cost the screening and the explanation use (search.drivebounds.least_cost) is the least
over every guide and bearing combination, checked by enumeration."""

import numpy as np
import pytest

from axisopt.model.cost import cost
from axisopt.problem import load_problem
from axisopt.search.drivebounds import hull_ends
from axisopt.search.drivebounds import least_cost as drive_least_cost
from axisopt.search.parts import build_space

# A turning-centre Z at 500 EUR with the drive sized (the catalogs' cheapest combination costs about 1 500 EUR,
# the cheapest design meeting every other limit about 4 000 EUR)
LATHE = """name: lathe-z
description: >
  Turning-centre Z axis with its three cutting-force components: 1.5 m stroke, a 250 kg carriage and turret,
  40 m/min, 8 kN feed force when roughing.  Maximise the minimum axial stiffness over the stroke; the search
  chooses the mounting, parts and the drive (motor, coupling, a planetary gearbox or none).
axis:
  stroke: 1500 mm
  moving_mass: 250 kg
  mounting: fixed-fixed
  orientation: horizontal
  max_speed: 40 m/min
  acceleration: 4 m/s^2
  # Roughing steel (our assumption): feed force Ff 8 kN along Z, the tangential force Fc 12 kN pressing the
  # carriage onto its ways, the passive force Fp 4 kN across them (Ff : Fc : Fp near the rule of thumb
  # 0.5 : 1 : 0.25, Isakov, CTE 2013), at the tool tip 250 mm above the guides, 150 mm off the centre line.
  axial_load: 8 kN
  mean_axial_load: 2.5 kN
  normal_load: 12 kN
  cross_load: 4 kN
  tool_height: 250 mm
  tool_offset: 150 mm
  table_length: 600 mm
  duty_cycle:
    - {move: 200 mm}
    - {move: 1000 mm, speed: 0.3 m/min, force: 6 kN}
    - {move: -1000 mm}
    - {move: 1000 mm, speed: 0.2 m/min, force: 1.5 kN}
    - {move: -1200 mm}
    - {dwell: 10 s}
  required_life: 20000 h
objective: stiffness
limits:
  max_cost: 500 EUR
  min_life: 20000 h
  # a gearbox's backlash at the carriage within 10 um (compensated by the control)
  max_backlash: 10 um
  margins:
    critical_speed: 1.25
catalog:
  mountings: [fixed-supported, fixed-fixed]
  nut_types: [double]
  drive: yes
continuous:
  nut_preload: {min: 200 N, max: 20 kN}
"""


def _lathe(tmp_path, budget: str):
    text = LATHE.replace("max_cost: 500 EUR", f"max_cost: {budget}")
    assert text != LATHE or budget == "500 EUR"
    path = tmp_path / "lathe.yaml"
    path.write_text(text, encoding="utf-8")
    return load_problem(path)


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_least_cost_per_drive_is_the_least_over_guides_and_bearings(tmp_path):
    """The screening's and the explanation's per-drive cost bound (drivebounds.least_cost) is the least cost
    over the block's guides and each group's bearings, for every drive of the lathe's 4 531: every (guide,
    drive) combination evaluated."""
    sp = build_space(_lathe(tmp_path, "500 EUR"))
    B = sp.shape[2]
    for mounting in sp.mountings:
        nuts = np.array([0, sp.shape[1] // 2, sp.shape[1] - 1])
        _, group = hull_ends(sp, mounting, nuts, False)
        got = drive_least_cost(sp, mounting, nuts, group)
        for k in range(len(nuts)):
            every = np.asarray(cost(sp.params_drives(mounting, nuts[k : k + 1])), dtype=float)
            every = np.broadcast_to(every, (1, B) + every.shape[2:]).min(axis=2)[
                0
            ]  # (bearings, drives)
            for g in range(group.max() + 1):
                np.testing.assert_allclose(got[k, g], every[group == g].min(axis=0), rtol=1e-12)


def test_hull_rows_kept_on_the_space_bound_as_a_fresh_evaluation(tmp_path):
    """The per-nut rows drive_hull keeps on the space for the searches after the first (limit sensitivities,
    the cheaper design) are the fresh interval bounds rounded outward to float32: an upper end never below,
    a lower end never above, within float32's rounding; asked again (in another order, with another nut
    among them) they come from the store and are the same."""
    from axisopt.search.drivebounds import _drive_hull, _whole_hull, drive_hull
    from axisopt.search.task.constraints import build_constraints
    from axisopt.search.task.space import DRIVE_KEYS

    problem = _lathe(tmp_path, "20000 EUR")
    sp = build_space(problem)
    assert not _whole_hull(sp)  # the store is used on this space
    cons = [c for c in build_constraints(problem) if c.key in DRIVE_KEYS]
    assert any(c.sense == ">=" for c in cons) and any(c.sense == "<=" for c in cons)
    mounting = sp.mountings[-1]
    nuts = np.array([3, sp.shape[1] // 2])
    fresh, group = _drive_hull(sp, mounting, nuts, cons)
    kept, g1 = drive_hull(sp, mounting, nuts, cons)
    np.testing.assert_array_equal(group, g1)
    for c in cons:
        f, k = fresh[c.name], kept[c.name]
        fin = np.isfinite(f)
        np.testing.assert_array_equal(fin, np.isfinite(k))
        assert (k[fin] >= f[fin]).all() if c.sense == ">=" else (k[fin] <= f[fin]).all()
        np.testing.assert_allclose(k[fin], f[fin], rtol=2e-7, atol=1e-30)
    again, _ = drive_hull(sp, mounting, np.array([1, 3, sp.shape[1] // 2]), cons)
    for c in cons:
        np.testing.assert_array_equal(again[c.name][1:], kept[c.name])
    fresh1, _ = _drive_hull(sp, mounting, np.array([1]), cons)
    for c in cons:
        np.testing.assert_allclose(again[c.name][0], fresh1[c.name][0], rtol=2e-7)
