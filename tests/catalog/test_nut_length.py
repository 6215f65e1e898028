"""The nut length column (issue 53): the catalog's values against the vendors' printed nut tables,
the envelope estimate against the vendor rows, and bad input one line, exit 2."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import pytest

from axisopt.catalog.loading import default_catalog
from axisopt.physics.nut import NUT_LENGTH_FACTORS, nut_length_estimate

ROOT = Path(__file__).resolve().parents[2]


def _rows():
    with open(ROOT / "catalogs" / "nuts.csv", encoding="utf-8") as f:
        return {r["id"]: r for r in csv.DictReader(f)}


@pytest.mark.published
@pytest.mark.parametrize(
    ("nut", "mm", "source"),
    [
        ("HIWIN-R20-05K4-FSC", 40, "H-BS Table 6.4, L"),
        ("HIWIN-R40-10K5-FDC", 171, "H-BS Table 6.5, L"),
        ("HIWIN-R63-10T6-FDI", 205, "H-BS Table 6.7, L"),
        ("THK-BNFN1605-5", 106, "T-GC B-652/B-653, L1"),
        ("THK-BNF4016-5", 152, "T-GC B-702/B-703, L1"),
        ("THK-DIR3210-6", 131, "T-GC B-720, L1"),
        ("REXROTH-FEMES-32x10x3.969-5-P2-5", 77, "BR-BS p. 37, L"),
        ("REXROTH-FDMES-32x10x3.969-5-P7-10", 146, "BR-BS p. 45, L"),
    ],
)
def test_catalog_nut_length_is_the_vendors(nut, mm, source):
    row = default_catalog().rows("nuts").by_id([nut])
    assert float(row["length"][0]) == pytest.approx(mm * 1e-3), source


def test_envelope_is_never_shorter_than_a_vendor_nut():
    """The estimate for a nut with no listed length is the upper envelope of the vendor rows: never
    shorter (never a kinder band) than a catalog nut of the same lead, diameter and type; tight
    within 2 %."""
    nuts, screws = _rows(), {}
    with open(ROOT / "catalogs" / "screws.csv", encoding="utf-8") as f:
        screws = {r["id"]: r for r in csv.DictReader(f)}
    worst = {0.0: 0.0, 1.0: 0.0}
    for r in nuts.values():
        if not r["length [mm]"] or r["status"] != "vendor" or "length derived" in r["source"]:
            continue
        s = screws[r["screw_id"]]
        double = 1.0 if r["type"] == "double" else 0.0
        est = nut_length_estimate(float(s["lead [mm]"]), float(s["nominal_diameter [mm]"]), double)
        ratio = float(r["length [mm]"]) / est
        assert ratio <= 1.0, r["id"]
        worst[double] = max(worst[double], ratio)
    assert min(worst.values()) > 0.98, (worst, NUT_LENGTH_FACTORS)


def test_every_vendor_row_but_the_estimated_has_a_length():
    empty = [i for i, r in _rows().items() if not r["length [mm]"]]
    assert sorted(empty) == ["PAPER21-40x10-DN", "PAPER21-40x20-DN"]


@pytest.mark.parametrize("value", ["-90 mm", "0 mm", "long"])
def test_bad_inline_nut_length_is_one_line_exit_2(tmp_path, value):
    src = (ROOT / "problems" / "teaching_design.yaml").read_text(encoding="utf-8")
    nut = _rows()["HIWIN-R25-05K4-FDC"]
    inline = (
        "  nut:\n    id: MY-NUT\n    vendor: me\n    screw_id: HIWIN-G-25x5-b3p175\n    type: "
        "double\n"
        f"    stiffness: {nut['stiffness [N/um]']} N/um\n"
        f"    stiffness_preload: {nut['stiffness_preload [N]']} N\n"
        f"    preload_min: {nut['preload_min [N]']} N\n    preload_max: {nut['preload_max [N]']} "
        "N\n"
        f"    dynamic_load_rating: {nut['dynamic_load_rating [kN]']} kN\n"
        f"    static_load_rating: {nut['static_load_rating [kN]']} kN\n"
        "    contact_angle: 45 deg\n    axial_play: 0 mm\n    mass: 1 kg\n    price: 300 EUR\n"
        f"    length: {value}\n"
    )
    f = tmp_path / "d.yaml"
    f.write_text(src.replace("  nut: HIWIN-R25-05K4-FDC\n", inline), encoding="utf-8")
    r = subprocess.run(
        [sys.executable, "-m", "axisopt", "evaluate", str(f)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 2, r.stderr
    err = r.stderr.strip()
    assert len(err.splitlines()) == 1 and "length" in err and "Traceback" not in err
