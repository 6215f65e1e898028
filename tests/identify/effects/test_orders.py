"""Lines in motor and screw orders (:mod:`axisopt.identify.effects.orders`): a force periodic in
the table's position at an integer order of the motor turn (cogging), at the tooth order of a belt
stage (tooth mesh) or at the nut's non-integer ball-pass order, hidden in records simulated by the
tests' own cascade (``sim_cascade``: a P-PI loop, AR(1) force noise, position noise before the
quantiser), alone and beside a Stribeck rise, over seeds, noise colours, position jitter and
parameter values; each must be named with its order and amplitude (within 10 %).  Null records with
coloured noise and decoys (a force periodic in time, a lead ripple) name none of them."""

import math

import pytest
from identify_helpers import DESIGN
from sim_cascade import Axis, Loop, simulate, write

from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.records.idim import diagnose_time_files
from axisopt.report.timediag import time_diagnosis_text

LEAD = 0.01  # table_x.yaml's lead [m]
ORDER_EFFECTS = {"motor_cogging", "belt_mesh", "ball_pass"}
BELT = "  reduction: ELATECH-ATL5-50-32x48\n"  # 32 teeth on the motor pulley, 48 on the screw's


def _design(tmp_path, ratio=None, parts=""):
    text = DESIGN.read_text()
    if ratio is not None:
        text = text.replace(
            "  end_margin: 150 mm\n", f"  end_margin: 150 mm\n  reduction_ratio: {ratio}\n"
        )
    text = text.replace("  guide: HIWIN-HG35-ZB\n", "  guide: HIWIN-HG35-ZB\n" + parts)
    path = tmp_path / "design.yaml"
    path.write_text(text)
    return plant_from_design(load_design(path))


def _diagnose(tmp_path, plant, ax, loop, seed, est_s=8.0, val_s=5.0):
    runs = [
        write(tmp_path / "e.csv", simulate(ax, loop, est_s, seed), ()),
        write(tmp_path / "v.csv", simulate(ax, loop, val_s, seed + 500), ()),
    ]
    return diagnose_time_files(runs, plant=plant)


def _amp(diag, s, c):
    return math.hypot(diag.final.value(s), diag.final.value(c))


@pytest.mark.parametrize(
    "seed, ratio, order, amp, rho, jitter",
    [
        (11, 2, 6, 40.0, 0.0, 0.0),
        pytest.param(12, 1.5, 8, 25.0, 0.8, 5e-7, marks=pytest.mark.slow),
        pytest.param(13, 3, 4, 60.0, 0.5, 1e-6, marks=pytest.mark.slow),
    ],
)
def test_motor_cogging_is_named_with_its_order_and_amplitude(
    tmp_path, seed, ratio, order, amp, rho, jitter
):
    plant = _design(tmp_path, ratio)
    ax = Axis(lines=((amp, LEAD / ratio / order, 0.7 * seed),))
    diag = _diagnose(tmp_path, plant, ax, Loop(fs=1000.0, rho=rho, pos_jitter=jitter), seed)
    assert diag.verdict == ["motor_cogging"]
    assert diag.final.shape["cog_order"] == order
    assert _amp(diag, "gs", "gc") == pytest.approx(amp, rel=0.10)
    text = " ".join(time_diagnosis_text(diag).split())
    assert f"order {order} of the motor turn" in text


@pytest.mark.parametrize(
    "seed, amp, rho, jitter",
    [(21, 30.0, 0.0, 0.0), pytest.param(22, 20.0, 0.7, 5e-7, marks=pytest.mark.slow)],
)
def test_a_belts_tooth_mesh_is_named_at_the_motor_pulleys_teeth(tmp_path, seed, amp, rho, jitter):
    plant = _design(tmp_path, parts=BELT)
    assert (plant.belt_teeth, plant.reduction) == (32, 1.5)
    ax = Axis(lines=((amp, LEAD / 1.5 / 32, 0.3),), vmax=0.06)
    diag = _diagnose(tmp_path, plant, ax, Loop(fs=2000.0, rho=rho, pos_jitter=jitter), seed)
    assert diag.verdict == ["belt_mesh"]
    assert _amp(diag, "bs", "bc") == pytest.approx(amp, rel=0.10)


@pytest.mark.parametrize(
    "seed, order, amp, rho",
    [(31, 11.3, 35.0, 0.0), pytest.param(32, 10.6, 25.0, 0.8, marks=pytest.mark.slow)],
)
def test_the_nuts_ball_pass_is_named_at_its_order(tmp_path, seed, order, amp, rho):
    plant = _design(tmp_path)
    # the test's own estimate of table_x's nut: 32 mm, balls 3.969 mm, 45 deg: 11.55 per turn
    z = math.pi * 32.0 / 3.969
    assert plant.ball_order == pytest.approx(0.5 * z * (1 - 3.969 * math.cos(math.pi / 4) / 32.0))
    ax = Axis(lines=((amp, LEAD / order, 1.1),))
    diag = _diagnose(tmp_path, plant, ax, Loop(fs=1000.0, rho=rho), seed)
    assert diag.verdict == ["ball_pass"]
    assert diag.final.shape["ball_order"] == pytest.approx(order, rel=0.01)
    assert _amp(diag, "ns", "nc") == pytest.approx(amp, rel=0.10)


@pytest.mark.slow
def test_cogging_beside_a_stribeck_rise(tmp_path):
    plant = _design(tmp_path, 2)
    ax = Axis(lines=((40.0, LEAD / 2 / 5, 0.0),), fs_excess=150.0, vs=0.005)
    diag = _diagnose(tmp_path, plant, ax, Loop(fs=1000.0, rho=0.5), 41, est_s=10.0)
    assert set(diag.verdict) == {"motor_cogging", "stribeck"}
    assert diag.final.shape["cog_order"] == 5
    assert _amp(diag, "gs", "gc") == pytest.approx(40.0, rel=0.10)


@pytest.mark.parametrize(
    "seed, parts, rho",
    [(51, BELT, 0.8), pytest.param(52, "", 0.5, marks=pytest.mark.slow)],
)
def test_a_null_record_with_coloured_noise_names_no_order_line(tmp_path, seed, parts, rho):
    plant = _design(tmp_path, parts=parts)
    diag = _diagnose(tmp_path, plant, Axis(vmax=0.1), Loop(fs=2000.0, rho=rho), seed)
    assert diag.verdict == []
    assert not [p.kind for p in diag.unexplained.remaining]


@pytest.mark.slow
def test_a_lead_ripple_decoy_is_not_named_a_motor_order(tmp_path):
    # a force once per screw turn (run-out), reduction 2: order 0.5 of the motor turn
    plant = _design(tmp_path, 2)
    ax = Axis(lines=((50.0, LEAD, 0.4),))
    diag = _diagnose(tmp_path, plant, ax, Loop(fs=1000.0, rho=0.5), 61)
    assert diag.verdict == ["lead_ripple"]
    text = " ".join(time_diagnosis_text(diag).split())
    assert "order 1 of the screw turn, order 0.5 of the motor turn" in text


@pytest.mark.slow
def test_a_pump_decoy_is_not_named_a_motor_order(tmp_path):
    # a force periodic in time (23 Hz), not in position: no order of any turn
    plant = _design(tmp_path, 2)
    diag = _diagnose(tmp_path, plant, Axis(tone=(40.0, 23.0)), Loop(fs=1000.0, rho=0.5), 71)
    assert diag.verdict == ["time_periodic"]
