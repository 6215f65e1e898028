"""The stiffness at the tool against the published closed forms, on the catalog's own rows read here
apart from the code: springs in series add their compliances (THK General Catalog, "Rigidity of the
feed screw system", formula (6): 1/K = 1/K_S + 1/K_N + 1/K_B + 1/K_H; the seed paper's eq. (6),
1/k_bs = 1/k_s + 1/k_n), and the blocks of a carriage carry a load across the rails in parallel
(their rigidities add)."""

import csv

import pytest

from axisopt.machine import load_machine, solve_machine

AXIS = """    problem:
      axis:
        stroke: 500 mm
        moving_mass: {mass} kg
        mounting: fixed-supported
        max_speed: 15 m/min
        axial_load: 1000 N
        acceleration: 2 m/s^2
        cross_load: 1000 N
        normal_load: 1000 N
      limits: {{min_life: 1000 h}}
      catalog:
        vendors: [HIWIN]
        nut_types: [double]
        drive: no
        require: {{screw: [HIWIN-G-40x20-b6p35], guide: [{guide}], bearing: [HIWIN-WBK30-DF]}}
"""
MACHINE = (
    "name: two-axes\naxes:\n  Y:\n    carried_by: frame\n    direction: y\n    normal: z\n"
    "    frame_stiffness: {x: 900 N/um, y: 1100 N/um, z: 1300 N/um}\n"
    + AXIS.format(mass=300, guide="HIWIN-HG30-ZA")
    + "  X:\n    carried_by: Y\n    direction: x\n    normal: z\n"
    "    frame_stiffness: estimate\n" + AXIS.format(mass=200, guide="HIWIN-HG25-ZA")
)


def _rigidity(guide: str) -> tuple:
    """(normal, tangential) rigidity of one block [N/um], read from catalogs/guides.csv (HIWIN H-LG
    rows)."""
    with open("catalogs/guides.csv", newline="") as f:
        row = next(r for r in csv.DictReader(f) if r["id"] == guide)
    return float(row["normal_rigidity [N/um]"]), float(row["tangential_rigidity [N/um]"])


@pytest.mark.published
def test_tool_stiffness_is_the_series_of_every_link_with_blocks_in_parallel(tmp_path):
    p = tmp_path / "m.yaml"
    p.write_text(MACHINE)
    res = solve_machine(load_machine(p))
    md = res.best
    assert md is not None
    by = {a.name: a for a in md.axes}
    assert (by["Y"].candidate.guide, by["X"].candidate.guide) == ("HIWIN-HG30-ZA", "HIWIN-HG25-ZA")
    ny, ty = _rigidity("HIWIN-HG30-ZA")
    nx, tx = _rigidity("HIWIN-HG25-ZA")
    blocks = 4  # the axis's default carriage: four blocks on two rails
    kfy = {"x": 900.0, "y": 1100.0, "z": 1300.0}
    # z: across both axes' rails (their blocks' normal rigidity), the bed under Y given, the frame
    # under X the stated estimate (as stiff as X's link: its compliance doubled)
    kz = 1.0 / (1 / (blocks * ny) + 1 / kfy["z"] + 2 / (blocks * nx))
    assert md.k_tool[2] * 1e-6 == pytest.approx(kz, rel=1e-9)
    # x: X's drive chain along its travel and Y's blocks across it (tangential)
    kax = by["X"].k_axis[0] * 1e-6
    kx = 1.0 / (1 / (blocks * ty) + 1 / kfy["x"] + 2 / kax)
    assert md.k_tool[0] * 1e-6 == pytest.approx(kx, rel=1e-9)
    # y: Y's drive chain and X's blocks across it (tangential)
    kay = by["Y"].k_axis[1] * 1e-6
    ky = 1.0 / (1 / kay + 1 / kfy["y"] + 2 / (blocks * tx))
    assert md.k_tool[1] * 1e-6 == pytest.approx(ky, rel=1e-9)
    # each drive chain: THK's formula (6) over its components at its softest point is the link the
    # machine reads
    import math

    from axisopt.model import evaluate

    for name, d in (("X", 0), ("Y", 1)):
        ev = evaluate(by[name].candidate.design)
        comps = [v for v in ev.components().values() if math.isfinite(v) and v > 0]
        assert len(comps) >= 3
        assert 1.0 / sum(1.0 / v for v in comps) == pytest.approx(by[name].k_axis[d], rel=1e-6)
