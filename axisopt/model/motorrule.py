"""The servo vendors' motor selection rules, each as its vendor publishes it (the motors table's
``rms_ratio`` and ``unbalance_ratio`` columns carry the numbers per row; this table says where each
comes from, for the check rows).

* Yaskawa (Sigma-7 product manual 11.2.1; E-S product manual 2.4.1): the effective (RMS) torque
  within the rated torque, the load torque TL within the rated torque: 1 and 1.
* Mitsubishi Electric (MDS-D-SVJ3/SPJ3 Specifications Manual 7-1 (3)): Trms <= 0.8 Tst (eq. 7-10);
  an unbalanced axis's load torque TL <= 0.6 Tst (eq. 7-12).  Tst is the stall torque; the tables
  here list the rated torque, at most the stall torque, so the rule applied to it is at least as
  strict.
* FANUC (B-65262EN/03 alpha-i 3.1): Trms within the stall torque, the worked example of condition 5
  at 0.9 Ts; the gravity-holding torque of a vertical axis within 60 % of stall: 0.9 and 0.6.
* Siemens (1FT7 Configuration Manual PFT7S 2.4.3; 1FK2/1FT2: "the average value of the output torque
  must lie below the S1 characteristic"): the RMS torque within S1, read at the rated torque (S1 at
  the rated speed): 1 and 1.
A row without a rule: Mitsubishi's, the harshest (catalog.COLUMNS estimate).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType


@dataclass(frozen=True)
class MotorRule:
    """One vendor's selection rule: RMS torque <= ``rms`` x rated; on an unbalanced (vertical) axis
    the steady load torque (friction and the weight less a counterbalance) <= ``unbalance`` x
    rated."""

    rms: float
    unbalance: float
    source: str


MOTOR_RULES = MappingProxyType(
    {
        "Yaskawa": MotorRule(1.0, 1.0, "Yaskawa Sigma-7 11.2.1: Trms <= rated"),
        "Mitsubishi Electric": MotorRule(
            0.8, 0.6, "Mitsubishi MDS-D-SVJ3 7-1: Trms <= 0.8 Tst, TL <= 0.6 Tst"
        ),
        "FANUC": MotorRule(0.9, 0.6, "FANUC B-65262EN 3.1: Trms <= 0.9 Ts, gravity <= 0.6 Ts"),
        "Siemens": MotorRule(1.0, 1.0, "Siemens 1FT7 PFT7S 2.4.3: Trms within S1"),
    }
)
# where a motor row names no rule (catalog estimate): Mitsubishi's, the harshest
DEFAULT_RULE = MotorRule(0.8, 0.6, "no vendor rule: Mitsubishi's 0.8 / 0.6, the harshest")


def rule_text(vendor: str, rms: float, unbalance: float, asked: float | None = None) -> str:
    """How a motor's RMS check reads its limit: the vendor's published rule, or the problem's
    ratio."""
    if asked is not None:
        return f"axis.rms_torque_ratio {asked:g} x rated"
    rule = MOTOR_RULES.get(vendor)
    if (
        rule is not None
        and math.isclose(rule.rms, rms, rel_tol=1e-9)
        and math.isclose(rule.unbalance, unbalance, rel_tol=1e-9)
    ):
        return rule.source
    return f"{rms:g} x rated (RMS), {unbalance:g} x rated (unbalanced load)"
