"""Issue 26: the motor's intermittent (peak) zone by speed and the RMS margin."""

import shutil

import pytest

from axisopt.catalog.columns import SHIPPED_DIR
from axisopt.catalog.loading import load_catalogs
from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.physics.drive import PEAK_CORNER_FRACTION, peak_torque_available

RPM = 60.0 / (2.0 * 3.141592653589793)


def test_zone_is_flat_to_the_corner_then_linear_to_max_speed():
    # SGM7G-20A (YSK-S7 sec. 7.2.2: rated 11.5 N.m at 1500 rpm, peak 28.7 N.m, max 3000 rpm),
    # estimated zone: corner min(1500, 3000 / 2) = 1500 rpm, peak falling to the rated torque at
    # 3000 rpm
    args = dict(
        peak_torque=28.7, corner_speed=1500 / RPM, peak_at_max_speed=11.5, max_speed=3000 / RPM
    )
    assert peak_torque_available(1000 / RPM, **args) == pytest.approx(28.7)
    assert peak_torque_available(1500 / RPM, **args) == pytest.approx(28.7)
    assert peak_torque_available(2250 / RPM, **args) == pytest.approx(0.5 * (28.7 + 11.5))
    assert peak_torque_available(3000 / RPM, **args) == pytest.approx(11.5)
    # above max: the speed check refuses
    assert peak_torque_available(3500 / RPM, **args) == pytest.approx(11.5)
    # Mitsubishi MDS-D-SVJ3 sec. 7-1 (2): "less than half of the max speed"
    assert PEAK_CORNER_FRACTION == 0.5


# Yaskawa Sigma (E-S series Product Manual sec. 2.4.1 p. 2-13, capacity selection example):
# SGMSL-A3C, rated 0.0955 N.m, instantaneous max 0.286 N.m; the cycle needs T_P = 0.186 N.m at 3000
# rpm, the rated speed, where the intermittent zone is still flat (3000 <= the corner): 0.286 >
# 0.186, the example's verdict.
def test_yaskawa_selection_example_peak_within_the_zone():
    avail = peak_torque_available(
        3000 / RPM,
        peak_torque=0.286,
        corner_speed=3000 / RPM,
        peak_at_max_speed=0.0955,
        max_speed=5000 / RPM,
    )
    assert avail == pytest.approx(0.286)
    assert avail / 0.186 == pytest.approx(1.54, abs=0.005)


@pytest.mark.parametrize(
    "column, value, message",
    [
        ("peak_torque_at_max_speed [N.m]", "99", "peak_torque is below peak_torque_at_max_speed"),
        ("peak_corner_speed [rpm]", "99999", "max_speed is below peak_corner_speed"),
    ],
)
def test_non_monotonic_curve_points_are_one_line_errors(tmp_path, capsys, column, value, message):
    src = (SHIPPED_DIR / "motors.csv").read_text(encoding="utf-8").splitlines()
    head = src[0].split(",")
    row = src[1].split(",")
    for c in ("peak_corner_speed [rpm]", "peak_torque_at_max_speed [N.m]"):
        if c not in head:
            head.insert(len(head) - 2, c)
            row.insert(len(row) - 2, "")
    row[0] = "USER-MOTOR"
    row[head.index(column)] = value
    d = tmp_path / "cat"
    d.mkdir()
    (d / "motors.csv").write_text(",".join(head) + "\n" + ",".join(row) + "\n", encoding="utf-8")
    with pytest.raises(InputError) as exc:
        load_catalogs([d])
    assert message in str(exc.value) and "\n" not in str(exc.value)
    design = tmp_path / "d.yaml"
    shutil.copy(SHIPPED_DIR.parent / "problems" / "teaching_design.yaml", design)
    text = design.read_text(encoding="utf-8")
    design.write_text(f"catalogs: [cat]\n{text}", encoding="utf-8")
    assert main(["evaluate", str(design)]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and len(err.splitlines()) == 1
