"""The machine at its tool point and its lumped chain, against published formulas with the catalog
rows read here apart from the code.

- The stiffness at the tool point: moving an axis's nut along its stroke changes only the screw
  shaft between the fixed bearing and the nut, so the axis's compliance at the tool grows by the
  shaft's axial compliance dL / (E A) (THK General Catalog, "Axial rigidity of the feed screw
  system": K_S = A E / (1000 L) for fixed-supported screws, A = pi d1^2 / 4, E = 2.06e5 N/mm^2) and
  by its torsional wind-up between the motor and the nut seen through the lead, (P_h / 2 pi)^2 dL /
  (G J) (a round bar, J = pi d1^4 / 32; the screw's torsion term of THK's and HIWIN's feed-system
  rigidity).  At the far end of both strokes the tool point is the machine's least stiffness over
  the strokes.
- The lumped chain: the carried axis is one mass (its own structure, its nut and guide blocks), the
  carrier another (its structure, its nut and blocks, the carried axis's stationary parts), each on
  its link: the two natural frequencies are the roots of the two-mass chain's characteristic
  equation m1 m2 w^4 - (m1 k2 + m2 (k1 + k2)) w^2 + k1 k2 = 0 (S. S. Rao, Mechanical Vibrations,
  ch. 5; W. T. Thomson, Theory of Vibration with Applications, ch. 5).
"""

import csv
import math
import re

import pytest
from test_tool_stiffness_published import MACHINE

from axisopt.machine import load_machine, solve_machine

E = 2.06e11  # [Pa] THK's E for the screw shaft (2.06e5 N/mm^2)
G = E / (2 * (1 + 0.3))  # [Pa] steel, Poisson's ratio 0.3
BLOCKS = 4  # the axis's default carriage: four blocks on two rails


def _row(table: str, part: str) -> dict:
    with open(f"catalogs/{table}.csv", newline="") as f:
        return next(r for r in csv.DictReader(f) if r["id"] == part)


def _solve(tmp_path, points: str):
    """The two-axis machine (Y on the bed carrying X) with its tool point at ``points``."""
    text = MACHINE.replace(
        "name: two-axes\n", f"name: two-axes\nmachine:\n  tool_point: {points}\n"
    )
    p = tmp_path / (re.sub(r"\W", "", points) + ".yaml")
    p.write_text(text)
    res = solve_machine(load_machine(p))
    assert res.best is not None
    return res.best


def _shaft_compliance(screw: str, dl: float) -> float:
    """The compliance [m/N] a fixed-supported screw's nut gains moving ``dl`` m away from the fixed
    bearing: the shaft's stretch and its twist through the lead."""
    row = _row("screws", screw)
    d1 = float(row["root_diameter [mm]"]) * 1e-3
    lead = float(row["lead [mm]"]) * 1e-3
    a = math.pi * d1**2 / 4
    j = math.pi * d1**4 / 32
    return dl / (E * a) + (lead / (2 * math.pi)) ** 2 * dl / (G * j)


@pytest.mark.published
def test_the_stiffness_at_the_tool_point_follows_the_screw_shaft(tmp_path):
    near = _solve(tmp_path, "{Y: 50 mm, X: 100 mm}")
    far_y = _solve(tmp_path, "{Y: 450 mm, X: 100 mm}")
    both_far = _solve(tmp_path, "{Y: 500 mm, X: 500 mm}")
    by = {a.name: a for a in near.axes}
    # the same parts at every tool point (it is where the chain is shown, not what is chosen)
    for md in (far_y, both_far):
        assert [(a.candidate.screw, a.candidate.nut) for a in md.axes] == [
            (a.candidate.screw, a.candidate.nut) for a in near.axes
        ]
    assert by["Y"].candidate.design.axis.mounting == "fixed-supported"
    # Y's nut 400 mm further from its fixed bearing: Y's axial link gains the shaft's compliance
    grown = 1 / far_y.k_axial_at_point["Y"] - 1 / near.k_axial_at_point["Y"]
    assert grown == pytest.approx(_shaft_compliance(by["Y"].candidate.screw, 0.4), rel=1e-3)
    # ... and so does the stiffness at the tool in y (Y's travel), the frame under Y given
    grown_tool = 1 / far_y.k_tool_at_point[1] - 1 / near.k_tool_at_point[1]
    assert grown_tool == pytest.approx(grown, rel=1e-9)
    # X did not move: x and z at the tool are unchanged
    assert far_y.k_tool_at_point[0] == pytest.approx(near.k_tool_at_point[0], rel=1e-12)
    assert far_y.k_tool_at_point[2] == pytest.approx(near.k_tool_at_point[2], rel=1e-12)
    # the tool point's chain by hand: Y's axial link at the point, the bed under it, X's blocks
    # across y (tangential rigidity, four in parallel) with the frame under X the stated estimate
    # (X's link doubled)
    tx = float(_row("guides", by["X"].candidate.guide)["tangential_rigidity [N/um]"]) * 1e6
    ky = 1 / (1 / near.k_axial_at_point["Y"] + 1 / 1100e6 + 2 / (BLOCKS * tx))
    assert near.k_tool_at_point[1] == pytest.approx(ky, rel=1e-9)
    # both nuts at the far end of their strokes: the least over the strokes, the machine's k_tool
    assert both_far.k_tool_at_point == pytest.approx(both_far.k_tool, rel=1e-6)
    assert all(n > f for n, f in zip(near.k_tool_at_point[:2], both_far.k_tool_at_point[:2]))


@pytest.mark.published
def test_the_lumped_chain_is_the_two_mass_closed_form_on_the_catalog_masses(tmp_path):
    md = _solve(tmp_path, "{Y: 250 mm, X: 250 mm}")
    by = {a.name: a for a in md.axes}
    moving = {}
    for name in ("X", "Y"):
        nut = float(_row("nuts", by[name].candidate.nut)["mass [kg]"])
        block = float(_row("guides", by[name].candidate.guide)["block_mass [kg]"])
        moving[name] = nut + BLOCKS * block
    # X: its 200 kg structure, its nut and blocks; Y: its 300 kg, its nut and blocks, and what of X
    # stays on Y's carriage (X's parts but its nut and blocks)
    m_x = 200.0 + moving["X"]
    m_y = 300.0 + moving["Y"] + (by["X"].parts_mass - moving["X"])
    assert by["X"].lumped == pytest.approx(m_x, rel=1e-9)
    assert by["Y"].lumped == pytest.approx(m_y, rel=1e-9)
    assert by["Y"].carried == pytest.approx(200.0 + by["X"].parts_mass, rel=1e-9)
    lowest = math.inf
    for d, dname in enumerate("xyz"):
        k1, k2 = by["Y"].k_link[d], by["X"].k_link[d]
        a, b, c = m_y * m_x, -(m_y * k2 + m_x * (k1 + k2)), k1 * k2
        w2 = sorted(
            [
                (-b - math.sqrt(b * b - 4 * a * c)) / (2 * a),
                (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a),
            ]
        )
        f = [math.sqrt(v) / (2 * math.pi) for v in w2]
        assert md.frequencies[(0, dname)] == pytest.approx(f, rel=1e-9)
        lowest = min(lowest, f[0])
    assert md.f_lowest == pytest.approx(lowest, rel=1e-9)
    # Dunkerley's bound from the same masses and springs, by hand
    fd = min(
        1
        / math.sqrt(m_y / by["Y"].k_link[d] + m_x * (1 / by["Y"].k_link[d] + 1 / by["X"].k_link[d]))
        / (2 * math.pi)
        for d in range(3)
    )
    assert md.f_dunkerley == pytest.approx(fd, rel=1e-9)
    assert md.f_dunkerley <= md.f_lowest


def test_the_carried_axis_hangs_its_motor_coupling_and_reduction_on_its_carrier(tmp_path):
    """An axis's drive stays on the axis below with its screw, bearings and rails: the carrier
    carries the carried axis's structure, its axis parts and its drive, each part's mass read from
    its catalog row (a motor row without one: 2 kg + 0.7 kg per N m rated, the stated estimate)."""
    from axisopt.model import evaluate

    head, sep, x_part = MACHINE.partition("  X:\n")
    x_part = x_part.replace(
        "drive: no\n        require: {screw:",
        "motor_series: [Sigma-7 SGM7G]\n"
        "        require: {coupling: [RINGFEDER-GWB-AKN-150], screw:",
    )
    assert "motor_series" in x_part
    p = tmp_path / "driven.yaml"
    p.write_text(head + sep + x_part)
    md = solve_machine(load_machine(p)).best
    assert md is not None
    x = {a.name: a for a in md.axes}["X"]
    c = x.candidate
    assert c.motor and c.coupling
    motor = _row("motors", c.motor)
    m_motor = (
        float(motor["mass [kg]"])
        if motor["mass [kg]"]
        else 2.0 + 0.7 * float(motor["rated_torque [N.m]"])
    )
    m_drive = m_motor + float(_row("couplings", c.coupling)["mass [kg]"])
    if c.reduction:
        m_drive += float(_row("reductions", c.reduction)["mass [kg]"])
    # the axis parts the axis model counts (screw, nut, bearings, rails, blocks) and the drive
    axis_parts = float(evaluate(c.design)["total_mass"]) - 200.0
    assert x.parts_mass == pytest.approx(axis_parts + m_drive, rel=1e-9)
    assert {a.name: a for a in md.axes}["Y"].carried == pytest.approx(
        200.0 + axis_parts + m_drive, rel=1e-9
    )
