"""The nut life over a duty cycle, through the whole model, against THK's vertical conveyance
example.

THK General Catalog, "Examples of Selecting a Ball Screw", vertical conveyance system (A-736 to
A-742): m1 + m2 = 50 kg lifted vertically, guide resistance f = 20 N, 0.3 m/s with 0.2 s ramps over
a 600 mm stroke, 5 cycles per minute; BLK1510-5.6 (lead 10 mm, Ca 9.8 kN), fW 1.5.  THK: phase loads
585 / 510 / 435 N up and 395 / 470 / 545 N down, Fm = 492 N, L = 2.34e9 rev, Nm = 600 min^-1, Lh =
65 000 h.
"""

from pathlib import Path

import pytest

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.physics import life

DESIGN = """
name: THK vertical conveyance (A-736)
axis:
  stroke: 600 mm
  moving_mass: 50 kg
  orientation: vertical
  mounting: fixed-supported
  max_speed: 18 m/min
  axial_load: 0 N
  acceleration: 1.5 m/s^2
  load_factor: 1.5
  guide_blocks: 2
  rails: 1
  duty_cycle:
    - {move: 600 mm}
    - {dwell: 3.8 s}
    - {move: -600 mm}
    - {dwell: 3.8 s}
parts:
  screw:
    id: THK-BLK1510-shaft
    vendor: THK
    nominal_diameter: 15 mm
    lead: 10 mm
    root_diameter: 12.5 mm
    max_length: 1000 mm
    mass_per_length: 1.2 kg/m
    dn_limit: 70000 mm.rpm
    support_bore_min: 10 mm
    support_bore_max: 15 mm
    price_per_length: 100 EUR/m
    price_fixed: 50 EUR
  nut:
    id: THK-BLK1510-5.6
    screw_id: THK-BLK1510-shaft
    type: single
    stiffness: 300 N/um
    stiffness_preload: 2940 N
    preload_min: 0 N
    preload_max: 0 N
    dynamic_load_rating: 9.8 kN
    static_load_rating: 25.2 kN
    contact_angle: 45 deg
    axial_play: 0.01 mm
    mass: 0 kg
    price: 100 EUR
  bearing: HIWIN-7002A-DB-M
  guide:
    id: GUIDE-f10
    vendor: example
    series: blocks with 10 N seal resistance each (THK's f = 20 N for the pair)
    type: ball
    size: 15 mm
    preload_class: none
    preload_level: medium
    preload: 100 N
    normal_rigidity: 100 N/um
    tangential_rigidity: 70 N/um
    dynamic_load_rating: 10 kN
    static_load_rating: 15 kN
    rating_distance: 50 km
    friction_force: 10 N
    friction_coefficient: 0.003
    friction_viscous: 0 N.s/m
    damping: 1000 N.s/m
    block_mass: 0 kg
    rail_mass_per_length: 1 kg/m
    block_price: 10 EUR
    rail_price_per_length: 10 EUR/m
    moment_roll: 100 N.m
    moment_pitch: 100 N.m
    moment_yaw: 100 N.m
"""


@pytest.mark.published
def test_thk_vertical_conveyance_nut_life(tmp_path: Path):
    path = tmp_path / "thk_vertical.yaml"
    path.write_text(DESIGN, encoding="utf-8")
    d = load_design(path)
    # 1.2 m per 12 s cycle: Nm = 600 rpm at lead 10
    assert d.axis.mean_speed_eff * 60 == pytest.approx(6.0)
    ev = evaluate(d, use_casadi=False)
    moving = float(ev.values["moving_mass"])
    # THK counts the table and work (m1 + m2); the nut is given no mass
    assert moving == pytest.approx(50.0)
    hours = float(ev.values["life"]) / 3600.0
    # THK's Lh with its Fm (492 N) and Nm (600 rpm)
    assert hours == pytest.approx(65_000, rel=0.005)
    # and exactly the cubic mean of the phase loads written out here from THK's formulas
    g, f, a, m = 9.80665, 20.0, 1.5, moving
    loads = [
        m * g + f + m * a,
        m * g + f,
        m * g + f - m * a,
        m * g - f - m * a,
        m * g - f,
        m * g - f + m * a,
    ]
    travels = [0.03, 0.54, 0.03] * 2
    fm = life.cubic_mean(loads, travels)
    assert hours == pytest.approx((9800.0 / (1.5 * fm)) ** 3 * 1e6 / (600 * 60), rel=1e-9)
