"""The parts list to order (issue 42 item 4): quantities, the rails' length, the nut preload
rounded."""

from pathlib import Path

from axisopt.design import load_design
from axisopt.report.partslist import parts_list, preload_step

P = Path(__file__).resolve().parents[2] / "problems"


def test_parts_list_of_the_vmc_axis():
    d = load_design(P / "vmc_x_design.yaml")
    rows = {r["part"]: r for r in parts_list(d)}
    assert set(rows) == {"screw", "nut", "bearing", "guide", "guide rail", "motor", "coupling"}
    assert (
        rows["guide"]["quantity"] == d.axis.guide_blocks
        and rows["guide rail"]["quantity"] == d.axis.rails
    )
    rail_mm = (d.axis.stroke + d.axis.table_length) * 1e3
    assert f"length {10 * -(-round(rail_mm) // 10):,} mm" in rows["guide rail"]["order"]
    preload = float(rows["nut"]["order"].split()[1].replace(",", ""))
    step = preload_step(d.preload)
    assert preload % step == 0 and abs(preload - d.preload) < step
    assert rows["bearing"]["quantity"] == (2 if d.axis.mounting == "fixed-fixed" else 1)
    assert (
        rows["screw"]["id"] == d.part_ids()["screw"]
        and f"{d.axis.span * 1e3:,.0f} mm" in rows["screw"]["order"]
    )


def test_a_design_without_a_drive_lists_no_motor():
    d = load_design(P / "teaching_design.yaml")
    parts = [r["part"] for r in parts_list(d)]
    assert ("motor" in parts) == (d.motor is not None) and "nut" in parts


def test_ordered_preload_stays_in_the_nuts_catalog_range():
    # a nut whose catalog range starts at 1534 N: 1534.5 N is nearest 1530 N, below the range, so it
    # goes up
    from dataclasses import replace

    from axisopt.catalog.parttable import Row
    from axisopt.report.partslist import order_preload

    d = load_design(P / "vmc_x_design.yaml")
    d = replace(d, nut=Row({**d.nut, "preload_min": 1534.0, "preload_max": 5126.0}, d.nut.name))
    low = order_preload(replace(d, nut_preload=1534.5))
    assert low.value == 1540.0 and low.nearest_breaks == ("the nut's preload range",)
    assert "1530 N would break the nut's preload range" in low.note()
    assert order_preload(replace(d, nut_preload=5125.5)).value == 5120.0
    # the nearest where nothing binds
    assert order_preload(replace(d, nut_preload=3183.3)).value == 3180.0


def test_ordered_preload_keeps_a_digit_more_when_both_round_neighbours_break():
    from dataclasses import replace

    from axisopt.catalog.parttable import Row
    from axisopt.report.partslist import order_preload, preload_step

    assert [preload_step(p) for p in (95.0, 245.0, 3183.3, 12345.0)] == [10.0, 10.0, 10.0, 100.0]
    d = load_design(P / "vmc_x_design.yaml")
    d = replace(d, nut=Row({**d.nut, "preload_min": 1534.3, "preload_max": 1537.8}, d.nut.name))
    o = order_preload(replace(d, nut_preload=1535.4))  # 1530 and 1540 N are both outside: 1 N steps
    assert (o.value, o.step, o.text) == (1535.0, 1.0, "1,535")
