"""Write the 3-against-1 (DFT) rows of the NSK TAC B support sets into catalogs/bearings.csv.

    python tools/bearing_sets.py [--check]

From each NSK TAC B DF pair row (NSK-SP p. 168: preload, rigidity, starting torque; pp. 110-111:
ratings) the DFT set of the same bearings: its dynamic rating and limiting axial load are NSK's
printed three-row values (pp. 110-111, "3 rows loaded: DTD, DFT, DBT"), its preload, rigidity,
lift-off loads and starting torque follow from the pair's by Hertz's contact law
(axisopt.physics.bearingsets, which reproduces IBC TI-I-5010.2/E Table 2.2 and NSK's printed triplex
and quadruplex ratios).  ``--check`` exits 1 when the catalog lacks a row or holds another value.
"""

from __future__ import annotations

import csv
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from axisopt.physics.bearingsets import set_lift_off, set_preload_ratio, set_rigidity_ratio  # noqa: E402

CSV = ROOT / "catalogs" / "bearings.csv"
# NSK-SP p. 111: three rows loaded (DTD, DFT, DBT): Ca [kN], limiting axial load [kN], by bearing
THREE_ROWS = {
    "15TAC47B": (47.5, 79.5),
    "17TAC47B": (47.5, 79.5),
    "20TAC47B": (47.5, 79.5),
    "25TAC62B": (61.5, 122),
    "30TAC62B": (63.0, 129),
    "35TAC72B": (67.0, 150),
    "40TAC72B": (68.5, 157),
    "40TAC90B": (127, 269),
    "45TAC75B": (71.0, 170),
    "45TAC100B": (133, 298),
    "50TAC100B": (136, 310),
    "55TAC100B": (136, 310),
    "55TAC120B": (145, 370),
    "60TAC120B": (145, 370),
}
SOURCE = (
    "NSK-SP pp. 110-111 (three-row Ca and limiting load), 168 (the DF pair); preload, rigidity, "
    "lift-off and torque derived from the pair (Hertz, physics.bearingsets; IBC Table 2.2)"
)


def _fmt(x: float, digits: int = 4) -> str:
    return f"{float(f'{x:.{digits}g}'):g}"


def dft_rows(rows: list[dict]) -> list[dict]:
    """The DFT rows derived from the NSK TAC B DF rows of ``rows``."""
    out = []
    k_pre, k_rig = set_preload_ratio(3.0, 1.0), set_rigidity_ratio(3.0, 1.0)
    for r in rows:
        name = r["id"].removeprefix("NSK-").split("-")[0]
        # the standard preload (C10) only: a 3-against-1 set is there to carry a pretension or one
        # heavy direction, which the light preload's lift-off load gives away
        if not (
            r["id"].startswith("NSK-")
            and r["arrangement"] == "DF"
            and name in THREE_ROWS
            and r["id"].endswith("-C10")
        ):
            continue
        ca, c0 = THREE_ROWS[name]
        pre = float(r["preload [N]"]) * k_pre
        new = dict(r)
        new.update(
            {
                "id": r["id"].replace("-DF-", "-DFT-"),
                "arrangement": "DFT",
                "rows": "4",
                "preload [N]": _fmt(pre),
                "axial_rigidity [N/um]": _fmt(float(r["axial_rigidity [N/um]"]) * k_rig),
                "lift_off_load [N]": _fmt(set_lift_off(pre, 1.0, 3.0)),
                "lift_off_load_strong [N]": _fmt(set_lift_off(pre, 3.0, 1.0)),
                "dynamic_load_rating [kN]": _fmt(ca),
                "static_load_rating [kN]": _fmt(c0),
                "starting_torque [N.m]": _fmt(float(r["starting_torque [N.m]"]) * k_pre, 2),
                "mass [kg]": _fmt(2.0 * float(r["mass [kg]"])),
                "price [EUR]": _fmt(2.0 * float(r["price [EUR]"])),
                "status": "stiffness-derived",
                "source": SOURCE,
            }
        )
        out.append(new)
    return out


def main(argv: list[str]) -> int:
    with open(CSV, newline="") as f:
        reader = csv.DictReader(f)
        header = list(reader.fieldnames)
        rows = list(reader)
    if "lift_off_load_strong [N]" not in header:
        header.insert(header.index("lift_off_load [N]") + 1, "lift_off_load_strong [N]")
    new = dft_rows(rows)
    have = {r["id"]: r for r in rows}
    if "--check" in argv:
        bad = [n["id"] for n in new if {k: have.get(n["id"], {}).get(k) for k in n} != n]
        print("catalog current" if not bad else f"rows missing or different: {', '.join(bad)}")
        return 1 if bad else 0
    rows = [r for r in rows if r["arrangement"] != "DFT" or r["id"] in {n["id"] for n in new}]
    rows = [r for r in rows if r["id"] not in {n["id"] for n in new}]
    at = {r["id"]: i for i, r in enumerate(rows)}
    for n in new:  # after the DFF row of the same bearing and class
        i = (
            at[n["id"].replace("-DFT-", "-DFF-")]
            if n["id"].replace("-DFT-", "-DFF-") in at
            else len(rows) - 1
        )
        rows.insert(i + 1, n)
        at = {r["id"]: i for i, r in enumerate(rows)}
    with open(CSV, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=header, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k) or "" for k in header})
    print(f"{len(new)} DFT rows written to {CSV.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
