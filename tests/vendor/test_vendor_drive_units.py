"""The vendor checker on a design with a gearbox (Beckhoff AG2400) and on one with a driven
rotating-nut unit (THK DIR): the new rows are printed, computed by the vendors' procedures, and
agree with axisopt where both use the same method (tools/vendor_check.py,
tools/vendor_procedures.py)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import vendor_procedures as vp  # noqa: E402
from vendor_check import TOLERANCE  # noqa: E402

sys.path.pop(0)
DATA = Path(__file__).parent / "data"
# (check) -> (tolerance, why) where a vendor constant differs from axisopt's by a known amount
WIDER = {
    "thermal pretension": (
        0.04,
        "THK's alpha 12e-6/K for its DIR shaft (A-715 eq. 38) against the 11.6e-6/K "
        "axisopt applies (H-BS F 3.36): +3.4 %",
    )
}
_CACHE: dict = {}


def rows(name: str, tmp_path_factory) -> dict:
    if name not in _CACHE:
        out = tmp_path_factory.mktemp("vendor") / f"{name}.json"
        proc = subprocess.run(
            [
                sys.executable,
                str(ROOT / "tools" / "vendor_check.py"),
                str(DATA / f"{name}.yaml"),
                "--json",
                str(out),
            ],
            cwd=ROOT,
            env=dict(os.environ, PYTHONPATH=str(ROOT)),
            check=True,
            capture_output=True,
            text=True,
        )
        _CACHE[name] = (
            {r["check"]: r for r in json.loads(out.read_text(encoding="utf-8"))},
            proc.stdout,
        )
    return _CACHE[name]


def test_beckhoff_commissioning_worked_example():
    # Beckhoff AG2300 manual, "Commissioning"
    # (infosys.beckhoff.com/content/1033/ag2300_ba/8712251019.html): M_pmax 5 N.m, T2B 20 N.m, i 10
    # -> peak current limited to 40 %; M0 1 N.m, T2N 8 N.m, i 10 -> 80 %
    peak, rated = vp.gearbox_current_limits(5.0, 1.0, 10.0, 20.0, 8.0)
    assert peak == pytest.approx(0.40)
    assert rated == pytest.approx(0.80)
    # within T2B, T2N: no limit
    assert vp.gearbox_current_limits(5.0, 1.0, 2.0, 20.0, 8.0) == (1.0, 1.0)


def test_catalog_units_of_the_reduction_rows():
    # the AG2400 TP010 row: 97 % efficiency, 3 arcmin backlash, 33 N.m/arcmin
    # (catalogs/reductions.csv headers)
    assert vp.quantity("97 %") == pytest.approx(0.97)
    assert vp.quantity("60 arcmin") == pytest.approx(1.0 * 3.141592653589793 / 180)


def _agree(by, checks):
    for name in checks:
        r = by[name]
        assert r["kind"] != "DIFF" or name in WIDER, (name, r)
        if r["kind"] in ("CONV", "INFO"):
            continue
        pair = (
            (r["same_basis"], r["axisopt"])
            if r["same_basis"] is not None
            else (r["margin"], r["axis_margin"])
            if r["axis_margin"] is not None
            else (r["vendor"], r["axisopt"])
        )
        assert pair[0] == pytest.approx(pair[1], rel=WIDER.get(name, (TOLERANCE,))[0]), (name, pair)


def test_reduction_design(tmp_path_factory):
    by, out = rows("reduction_design", tmp_path_factory)
    new = [
        "reduction T2B / peak output torque",
        "reduction T2N / RMS output torque",
        "reduction n1Max / motor speed",
        "reduction commissioning current limits",
        "screw sag (own weight)",
    ]
    for name in new:
        assert name in out
    # Beckhoff TP010 MF i 5: T2B 172, T2N 81 N.m, n1Max 7500 rpm; 24 m/min on a 20 mm lead x 5 =
    # 6000 rpm
    assert by["reduction T2B / peak output torque"]["vendor"] == pytest.approx(172.0)
    assert by["reduction n1Max / motor speed"]["limit"] == pytest.approx(6000.0)
    assert by["reduction commissioning current limits"]["kind"] == "INFO"
    assert by["reduction T2B / peak output torque"]["kind"] == "AGREE"
    _agree(
        by,
        [
            "reduction T2B / peak output torque",
            "reduction n1Max / motor speed",
            "inertia ratio load/rotor",
            "nut L10 life",
            "critical speed",
            "tensile/compressive load",
        ],
    )


def test_rotating_nut_design(tmp_path_factory):
    by, out = rows("rotating_nut_design", tmp_path_factory)
    # a standing screw: no critical speed, no screw DN, no end-bearing life (T-GC A-772..A-774)
    assert (
        "critical speed" not in by and "DN value" not in by and "support bearing L10 life" not in by
    )
    nut = by["rotating nut permissible speed"]
    # THK DIR4010-6, B-720: dp 41.75 mm -> DN 70 000 (A-697) / 41.75 = 1677 rpm
    assert nut["vendor"] == pytest.approx(70000 / 41.75, rel=1e-3)
    assert nut["kind"] == "AGREE"
    unit = by["unit support bearing L10 life"]
    assert unit["kind"] == "CONV" and "preload" in unit["note"]
    # the unit's printed inertia 20.6 kg.cm^2 (B-721) in the inertia ratio: agrees with axisopt's
    assert "20.6 kg.cm^2" in by["inertia ratio load/rotor"]["note"]
    _agree(
        by,
        [
            "rotating nut permissible speed",
            "buckling",
            "nut L10 life",
            "nut lift-off",
            "inertia ratio load/rotor",
            "thermal pretension",
            "guide L10 travel",
        ],
    )


def test_unit_bearing_life_formula():
    # T-GC A-704 life on the table's Ca: Ca 21.5 kN (DIR4010-6, B-721), 2150 N at fw 1 -> 10^3 x
    # 10^6 rev; at a constant 500 rpm that is 10^9 / 30 000 = 33 333 h
    ph = [vp.Phase(1.0, 1.0, 1.0, 0.0, 1, 0.0, 2150.0)]
    assert vp.unit_bearing_life_h(21500.0, ph, 1.0, 500.0) == pytest.approx(1e9 / 30000)


def test_sag_matches_axisopt_and_aisc_ratios():
    # AISC Table 3-23: case 15 (both ends fixed) wL^4/384EI is 1/5 of case 1 (simple) 5wL^4/384EI;
    # no published screw figure: the checker's own beam formula and axisopt's
    # physics.screw.screw_sag must agree
    from axisopt.physics.screw import screw_sag

    ss = vp.screw_sag(8.22, 0.0347, 1.1, "supported-supported")
    assert vp.screw_sag(8.22, 0.0347, 1.1, "fixed-fixed") == pytest.approx(ss / 5)
    for m in ("fixed-free", "fixed-supported", "fixed-fixed"):
        assert vp.screw_sag(8.22, 0.0347, 1.1, m) == pytest.approx(
            screw_sag(8.22, 0.0347, 1.1, m), rel=1e-9
        )
