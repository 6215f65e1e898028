"""The servo vendors' motor selection rules (model.motorrule) against their published manuals, and
how a motor's RMS check names its limit."""

from __future__ import annotations

import pytest

from axisopt.model.motorrule import DEFAULT_RULE, MOTOR_RULES, rule_text


# Yaskawa Sigma-7 product manual 11.2.1: Trms and TL within the rated torque; Mitsubishi MDS-D-
# SVJ3/SPJ3 Specifications Manual 7-1 eqs. 7-10 and 7-12: Trms <= 0.8 Tst, unbalanced TL <= 0.6 Tst;
# FANUC B-65262EN/03 3.1: condition 5 at 0.9 Ts, gravity-holding torque within 60 % of stall;
# Siemens 1FT7 PFT7S 2.4.3: within S1
@pytest.mark.published
@pytest.mark.parametrize(
    "vendor, rms, unbalance",
    [
        ("Yaskawa", 1.0, 1.0),
        ("Mitsubishi Electric", 0.8, 0.6),
        ("FANUC", 0.9, 0.6),
        ("Siemens", 1.0, 1.0),
    ],
)
def test_published_rules(vendor, rms, unbalance):
    rule = MOTOR_RULES[vendor]
    assert (rule.rms, rule.unbalance) == (rms, unbalance)
    assert rule_text(vendor, rms, unbalance) == rule.source


def test_no_rule_is_the_harshest():
    assert DEFAULT_RULE.rms == min(r.rms for r in MOTOR_RULES.values())
    assert DEFAULT_RULE.unbalance == min(r.unbalance for r in MOTOR_RULES.values())


def test_rule_text_of_a_ratio_asked_or_not_the_vendors():
    assert rule_text("Yaskawa", 1.0, 1.0, asked=0.7) == "axis.rms_torque_ratio 0.7 x rated"
    assert rule_text("Yaskawa", 0.8, 0.6) == "0.8 x rated (RMS), 0.6 x rated (unbalanced load)"
    assert (
        rule_text("Unknown vendor", 0.8, 0.6) == "0.8 x rated (RMS), 0.6 x rated (unbalanced load)"
    )
