"""The parts list to order (issue 42 item 4): quantities, the rails' length, the nut preload rounded."""

from pathlib import Path

from axisopt.design import load_design
from axisopt.report.partslist import parts_list, preload_step

P = Path(__file__).resolve().parents[2] / "problems"


def test_parts_list_of_the_vmc_axis():
    d = load_design(P / "vmc_x_design.yaml")
    rows = {r["part"]: r for r in parts_list(d)}
    assert set(rows) == {"screw", "nut", "bearing", "guide", "guide rail", "motor", "coupling"}
    assert rows["guide"]["quantity"] == d.axis.guide_blocks and rows["guide rail"]["quantity"] == d.axis.rails
    rail_mm = (d.axis.stroke + d.axis.table_length) * 1e3
    assert f"length {10 * -(-round(rail_mm) // 10):,} mm" in rows["guide rail"]["order"]
    preload = float(rows["nut"]["order"].split()[1].replace(",", ""))
    step = preload_step(d.preload)
    assert preload % step == 0 and abs(preload - d.preload) < step
    assert rows["bearing"]["quantity"] == (2 if d.axis.mounting == "fixed-fixed" else 1)
    assert rows["screw"]["id"] == d.part_ids()["screw"] and f"{d.axis.span * 1e3:,.0f} mm" in rows["screw"]["order"]


def test_a_design_without_a_drive_lists_no_motor():
    d = load_design(P / "teaching_design.yaml")
    parts = [r["part"] for r in parts_list(d)]
    assert ("motor" in parts) == (d.motor is not None) and "nut" in parts
