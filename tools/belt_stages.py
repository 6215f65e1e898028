"""Write the timing-belt reduction stages (kind ``belt``) into catalogs/reductions.csv.

    python tools/belt_stages.py [--check]

Each stage is an ELATECH ATL5 (type M, steel cords) belt on two AT5 pulleys with BRECOflex's zero
tooth gap ("0" pulleys, no play between belt and pulley), ``z1`` teeth on the motor, ``i z1`` on the
screw, centre distance the sum of the pitch diameters (rounded to the belt's whole teeth).  Its
ratings and stiffness follow from the vendor's belt data through axisopt.physics.belt
(catalogs/SOURCES.md, "Timing-belt stages"):

* rated and acceleration torque at the output: the permissible effective pull at the stage's top
  input speed (tooth shear FUspez z_e b with z_e whole teeth in mesh, at most 12; the cords' F_Tzul
  with the pretension F_TV = F_U) times the output pulley's pitch radius;
* torsional stiffness: both spans (Cspez / span) on the output pulley;
* inertia at the input: both pulleys as steel discs of tip diameter and width b + 10 mm
  (an estimate: no vendor inertia table), the output one through i^2, and the belt's mass at the
  pitch line.

``--check`` exits 1 when the catalog lacks a row or holds another value.
"""

from __future__ import annotations

import csv
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from axisopt.physics import belt  # noqa: E402

CSV = ROOT / "catalogs" / "reductions.csv"
PITCH = 5e-3  # AT5 / ATL5 [m]
# pitch diameter - tip diameter of an AT5 pulley, 2 x the 0.75 mm pitch-line offset [m]
TIP_OFFSET = 1.5e-3
STEEL = 7850.0
TOP_SPEED = 3000.0  # [rpm] the stage's rated top input speed
FU_SPEZ_TOP = 19.85  # ATL5 tooth shear strength at 3000 min^-1 [N/cm] (ELATECH cat. p. 20)
# ATL5 type M (ELATECH cat. p. 20): width [mm] -> (F_Tzul [N], Cspez [N], weight [kg/m])
ATL5 = {
    25: (2530, 632500, 0.10),
    32: (3080, 770000, 0.12),
    50: (5060, 1265000, 0.19),
    75: (7590, 1897500, 0.29),
    100: (10120, 2530000, 0.38),
}
# 50 and 100 mm wide, 1.5:1 to 3:1 (a 1:1 stage is a direct drive with more inertia and
# less stiffness: the search would never choose it; folding the motor beside the screw is no value
# the model weighs)
STAGES = [(w, z1, i) for w in (50, 100) for z1 in (32,) for i in (1.5, 2.0, 3.0)]
EFFICIENCY = 98  # [%] an estimate (Siegling ref. 202: synchronous belt drives up to 98 %)
SOURCE = (
    "ELATECH PU belts cat. p. 20 (ATL5: FTzul, Cspez, weight, FUspez at 3000 rpm), 52-54 (F_U = "
    "FUspez z_e b, z_e <= 12); BRECOflex zero-gap AT5 pulleys (backlash); torque by the vendor's "
    "rule; stiffness and inertia derived (physics.belt, steel pulleys); efficiency estimate; price "
    "illustrative"
)


def _fmt(x: float, digits: int = 4) -> str:
    return f"{float(f'{x:.{digits}g}'):g}"


def stage(width_mm: int, z1: int, ratio: float) -> dict:
    """One stage's catalog row."""
    f_tzul, c_spez, kg_m = ATL5[width_mm]
    b = width_mm * 1e-3
    z2 = round(ratio * z1)
    d1, d2 = belt.pitch_diameter(PITCH, z1), belt.pitch_diameter(PITCH, z2)
    teeth = math.ceil(belt.belt_length(d1, d2, d1 + d2) / PITCH)  # the belt's whole teeth
    length = teeth * PITCH
    bb = 4.0 * length - 2.0 * math.pi * (d1 + d2)  # Gates' centre distance for a given belt length
    centre = (bb + math.sqrt(bb**2 - 32.0 * (d2 - d1) ** 2)) / 16.0
    ze = math.floor(belt.teeth_in_mesh(z1, d1, d2, centre))
    pull = belt.effective_pull(FU_SPEZ_TOP * 100.0, ze, b, f_tzul)
    torque = pull * 0.5 * d2
    kt = belt.stage_torsional_stiffness(c_spez, belt.span_length(d1, d2, centre), d2)
    jp = [belt.pulley_inertia(d - TIP_OFFSET, b + 0.01, STEEL) for d in (d1, d2)]
    j_in = belt.stage_input_inertia(jp[0], jp[1], kg_m * length, d1, z2 / z1)
    mass = (
        sum(((d - TIP_OFFSET) ** 2 * math.pi / 4.0 * (b + 0.01) * STEEL) for d in (d1, d2))
        + kg_m * length
    )
    return {
        "id": f"ELATECH-ATL5-{width_mm}-{z1}x{z2}",
        "vendor": "ELATECH",
        "series": f"ATL5 belt stage on AT5 zero-gap pulleys (belt {teeth} teeth; centre "
        f"{centre * 1e3:.1f} mm)",
        "kind": "belt",
        "ratio [-]": _fmt(z2 / z1),
        "efficiency [%]": str(EFFICIENCY),
        "inertia [kg.cm^2]": _fmt(j_in * 1e4),
        "rated_torque [N.m]": _fmt(torque),
        "accel_torque [N.m]": _fmt(torque),
        "torsional_stiffness [N.m/arcmin]": _fmt(kt * math.pi / (180 * 60)),
        "backlash [arcmin]": "0",
        "max_input_speed [rpm]": _fmt(TOP_SPEED),
        "mass [kg]": _fmt(mass, 3),
        "price [EUR]": _fmt(60 + 2.0 * width_mm + 0.8 * (z1 + z2), 3),
        "status": "stiffness-derived",
        "source": SOURCE,
    }


def main(argv: list[str]) -> int:
    with open(CSV, newline="") as f:
        reader = csv.DictReader(f)
        header = list(reader.fieldnames)
        rows = list(reader)
    new = [stage(*s) for s in STAGES]
    have = {r["id"]: r for r in rows}
    if "--check" in argv:
        bad = [n["id"] for n in new if {k: have.get(n["id"], {}).get(k) for k in n} != n]
        print("catalog current" if not bad else f"rows missing or different: {', '.join(bad)}")
        return 1 if bad else 0
    ids = {n["id"] for n in new}
    rows = [r for r in rows if r["id"] not in ids] + new
    with open(CSV, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=header, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k) or "" for k in header})
    print(f"{len(new)} belt stages written to {CSV.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
