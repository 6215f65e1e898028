"""The turning-centre Z at an impossible 500 EUR budget that tests/search/test_drivebounds.py and
tests/search/infeasible/test_budget.py share: the shipped lathe Z (problems/lathe_z_problem.yaml) as
it was when these tests were written, with a max_cost limit."""

from axisopt.problem import load_problem

# A turning-centre Z at 500 EUR with the drive sized (the catalogs' cheapest combination costs about
# 1 500 EUR, the cheapest design meeting every other limit about 4 000 EUR)
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
"""  # noqa: E501


def lathe(tmp_path, budget: str):
    text = LATHE.replace("max_cost: 500 EUR", f"max_cost: {budget}")
    assert text != LATHE or budget == "500 EUR"
    path = tmp_path / "lathe.yaml"
    path.write_text(text, encoding="utf-8")
    return load_problem(path)
