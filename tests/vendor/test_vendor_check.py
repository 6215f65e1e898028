"""Every shipped optimum (and the shipped designs) by the part vendors' own procedures (issue 38,
done-when 2).

tools/vendor_check.py solves each problem with axisopt as a program, then recomputes every check
from the design YAML and the catalog rows by the vendors' printed procedures
(tools/vendor_procedures.py, tested against the worked examples in
test_vendor_procedures.py).  Here:

* the vendor's criterion: every margin >= 1 by the checker's own computation on every shipped
  optimum (the teaching design, a lesson, fails exactly where axisopt's checks fail it);
* agreement with axisopt where both use the same method: within TOLERANCE (2 %), or the wider
  tolerance stated below where the vendor constants or an input convention differ by a known amount
  (docs/validation.md).
"""

from __future__ import annotations

import ast
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
TOLERANCE = 0.02
# (file, check) -> (tolerance, why).  `None` as file: every file.
WIDER = {
    (None, "buckling"): (
        0.035,
        "HIWIN's F 3.25 constant 0.5 x 4.072e5 = 2.036e5 against THK's 2e5 (A-694 eq. 6), "
        "which axisopt applies to every screw: +1.8 %; and axisopt's viscous guide friction "
        "in the load",
    ),
    ("lathe_z_problem", "tensile/compressive load"): (
        0.03,
        "the pretension: the checker takes THK's 12e-6/K "
        "(A-715) for the Rexroth shaft, axisopt HIWIN's "
        "11.6e-6/K for every screw (3.4 % on the pretension)",
    ),
    ("lathe_z_problem", "support bearing static"): (
        0.03,
        "the same pretension difference on the set's load",
    ),
    ("lathe_z_problem", "thermal pretension"): (
        0.04,
        "THK's 12e-6/K (checker) against HIWIN's 11.6e-6/K (axisopt) for the Rexroth shaft: 3.4 %",
    ),
    ("lathe_z_belt_problem", "tensile/compressive load"): (
        0.03,
        "as lathe_z_problem: 12e-6/K against 11.6e-6/K on the Rexroth shaft's pretension",
    ),
    ("lathe_z_belt_problem", "thermal pretension"): (0.04, "as lathe_z_problem"),
    ("boring_table_problem", "buckling"): (
        1.0,
        "axisopt's compression adds what the heat balance's rise (3.7 K) "
        "beyond the pretension's design rise (2 K) pushes into the screw; "
        "the checker takes the feed force: both margins above 7",
    ),
    ("boring_table_problem", "thermal pretension"): (
        0.04,
        "THK's 12e-6/K against HIWIN's 11.6e-6/K",
    ),
    (None, "support bearing L10 life"): (
        0.05,
        "an NSK set by NSK's rule on both sides (its printed split for as many rows each way, the "
        "Hertz split for 3 against 1); the rest: the inputs' rounding and the friction terms",
    ),
    ("lathe_z_problem", "support bearing L10 life"): (
        0.06,
        "NSK's rule on both sides; the pretension on the set: THK's 12e-6/K (checker) against "
        "HIWIN's 11.6e-6/K (axisopt) for the Rexroth shaft, as its thermal pretension row",
    ),
    ("lathe_z_belt_problem", "support bearing L10 life"): (
        0.09,
        "NSK's rule on both sides; the static set load differs as on the boring table (axisopt "
        "adds the heat balance's rise beyond the pretension's design rise) and by the alpha",
    ),
    ("boring_table_problem", "support bearing L10 life"): (
        0.2,
        "NSK's rule on both sides; axisopt's static set load adds the thermal force of the heat "
        "balance's rise (3.7 K) beyond the pretension's design rise (2 K): with the rise stated "
        "at 2 K axisopt gives 27,639 h against the checker's 27,679 h",
    ),
    ("vmc_x_problem", "nut L10 life"): (
        0.05,
        "axisopt adds the roller blocks' viscous friction at rapid speed "
        "(39 N.s/m x 4 blocks) to the life loads; THK's f is constant",
    ),
    ("vertical_counterweight_problem", "buckling"): (
        0.06,
        "as every file's buckling row, and axisopt prints a "
        "margin above 1000 as 1000 (the checker's is 1057)",
    ),
    ("precision_problem", "buckling"): (
        0.6,
        "axisopt prints a margin above 1000 as 1000 (the checker's 1581 on the 500 mm "
        "grinder axis)",
    ),
    ("highspeed_problem", "guide L10 travel"): (
        0.08,
        "the most loaded block's mean load differs by 2 % (the "
        "checker's rigid-table statics with the screw at the rail "
        "plane against axisopt's carriage model)",
    ),
}
# where the vendor's criterion fails (checker's computation), the checks that fail: the teaching
# design is a lesson, not an optimum, and axisopt's own checks fail it on the same two lives (and
# its bearing bore, which this checker does not compute)
KNOWN_FAILS = {
    "teaching_design": {"nut L10 life", "support bearing L10 life"},
    # issue 53: an NSK 3-against-1 set (the boring table's and the twin gantry's 50TAC100B-DFT) is
    # judged by NSK's own group rating with the Hertz split (NSK-SP pp. 110-111), which both pass;
    # IBC's per-bearing reading (15 300 h and 7 534 h) is printed beside it, not judged
}
# shipped optima whose drive is not a screw: the drive checker's rows (tools/vendor_check_drives.py)
DRIVE_FILES = {"laser_problem", "router_rack_problem", "laser_lm_problem"}
FILES = [
    "teaching_problem",
    "highspeed_problem",
    "gantry_problem",
    "vertical_problem",
    "vmc_x_problem",
    "duty_cycle_problem",
    "teaching_design",
    "vmc_x_design",
    "boring_mill_problem",
    "laser_problem",
    "lathe_z_problem",
    "vertical_counterweight_problem",
    "gantry_twin_problem",
    "vertical_z600_problem",
    "lathe_z_belt_problem",
    "boring_table_problem",
]
# the other shipped optima (not in the results table, which is wide enough): the precision grinder
# axis, the router's rack and pinion, the laser axis solved for a linear motor
MORE_OPTIMA = ["precision_problem", "router_rack_problem", "laser_lm_problem"]
_CACHE: dict = {}


def rows(name: str, tmp_path_factory) -> list[dict]:
    """The checker's rows for problems/<name>.yaml (run once per session)."""
    if name not in _CACHE:
        out = tmp_path_factory.mktemp("vendor") / f"{name}.json"
        env = dict(os.environ, PYTHONPATH=str(ROOT))
        subprocess.run(
            [
                sys.executable,
                str(ROOT / "tools" / "vendor_check.py"),
                f"problems/{name}.yaml",
                "--json",
                str(out),
            ],
            cwd=ROOT,
            env=env,
            check=True,
            capture_output=True,
            text=True,
        )
        _CACHE[name] = json.loads(out.read_text(encoding="utf-8"))
    return _CACHE[name]


def _compared(r: dict) -> tuple[float, float] | None:
    """The two numbers the checker compared for a same-method row (its same-basis value, else the
    margins, else the values)."""
    if r["kind"] in ("CONV", "INFO"):
        return None
    if r["same_basis"] is not None:
        return r["same_basis"], r["axisopt"]
    if r["margin"] is not None and r["axis_margin"] is not None:
        return r["margin"], r["axis_margin"]
    return r["vendor"], r["axisopt"]


@pytest.mark.parametrize("name", FILES + MORE_OPTIMA)
def test_vendor_criterion(name, tmp_path_factory):
    failed = {r["check"] for r in rows(name, tmp_path_factory) if not r["passes"]}
    assert failed == KNOWN_FAILS.get(name, set()), (
        f"{name}: the vendor's procedure fails {sorted(failed)}"
    )


@pytest.mark.parametrize("name", FILES + MORE_OPTIMA)
def test_agrees_with_axisopt_where_same_method(name, tmp_path_factory):
    checked = 0
    for r in rows(name, tmp_path_factory):
        pair = _compared(r)
        if pair is None:
            continue
        tol = WIDER.get((name, r["check"]), WIDER.get((None, r["check"]), (TOLERANCE, "")))[0]
        assert pair[0] == pytest.approx(pair[1], rel=tol), f"{name}: {r['check']} {pair}"
        checked += 1
    # the checks of screw, nut, guides and drive that both compute the same way (a linear motor:
    # peak and effective force, the peak's duration, the guides)
    assert checked >= (4 if name in DRIVE_FILES else 8)


def test_fixed_fixed_pretension_and_tension(tmp_path):
    # no shipped optimum is fixed-fixed: the VMC design mounted fixed-fixed exercises the pretension
    # path
    design = tmp_path / "ff.yaml"
    design.write_text(
        (ROOT / "problems" / "vmc_x_design.yaml")
        .read_text(encoding="utf-8")
        .replace("mounting: fixed-supported", "mounting: fixed-fixed"),
        encoding="utf-8",
    )
    out = tmp_path / "ff.json"
    subprocess.run(
        [sys.executable, str(ROOT / "tools" / "vendor_check.py"), str(design), "--json", str(out)],
        cwd=ROOT,
        env=dict(os.environ, PYTHONPATH=str(ROOT)),
        check=True,
        capture_output=True,
    )
    by = {r["check"]: r for r in json.loads(out.read_text(encoding="utf-8"))}
    pre = by["thermal pretension"]
    # 3 K (THK A-715: 2-5 K) on the root section, alpha 11.6e-6/K for a HIWIN shaft (H-BS F 3.36)
    assert pre["vendor"] == pytest.approx(pre["axisopt"], rel=TOLERANCE)
    # the pretension counts in tension
    assert by["tensile/compressive load"]["limit"] > by["buckling"]["limit"]


def test_teaching_optimum_every_check_present(tmp_path_factory):
    names = {r["check"] for r in rows("teaching_problem", tmp_path_factory)}
    assert {
        "critical speed",
        "DN value",
        "buckling",
        "tensile/compressive load",
        "nut L10 life",
        "support bearing L10 life",
        "support bearing static",
        "guide L10 travel",
        "nut static safety C0a/Famax",
        "guide static safety C0/P",
        "axial rigidity (screw, nut, bearing, K_H)",
        "inertia ratio load/rotor",
        "RMS torque",
    } <= names


def test_checker_imports_nothing_of_axisopt():
    for path in (ROOT / "tools" / "vendor_check.py", ROOT / "tools" / "vendor_procedures.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        names = [a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names]
        names += [n.module or "" for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)]
        assert not [m for m in names if m.split(".")[0] == "axisopt"], path


COLUMNS = {
    "teaching_problem": "teaching",
    "highspeed_problem": "highspeed",
    "gantry_problem": "gantry",
    "vertical_problem": "vertical",
    "vmc_x_problem": "vmc_x",
    "duty_cycle_problem": "duty_cycle",
    "teaching_design": "teaching design",
    "vmc_x_design": "vmc_x design",
    "boring_mill_problem": "boring mill",
    "laser_problem": "laser",
    "lathe_z_problem": "lathe Z",
    "vertical_counterweight_problem": "vertical counterweight",
    "gantry_twin_problem": "twin gantry",
    "vertical_z600_problem": "Z 600 kg",
    "lathe_z_belt_problem": "lathe Z belt",
    "boring_table_problem": "boring table",
}


def test_docs_results_table_is_what_the_checker_prints(tmp_path_factory):
    """docs/validation.md's results table, cell by cell, from the checker's rows on every shipped
    file."""
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        from vendor_check import summary_table
    finally:
        sys.path.pop(0)
    want = summary_table({COLUMNS[n]: rows(n, tmp_path_factory) for n in FILES})
    text = (ROOT / "docs" / "validation.md").read_text(encoding="utf-8")
    assert want in text, "docs/validation.md results table differs; the checker prints:\n" + want


# the shipped optima's column names in docs/validation.md's sign-off table
SIGNOFF = {
    **{n: COLUMNS[n] for n in FILES if n.endswith("_problem")},
    "precision_problem": "precision",
    "router_rack_problem": "router (rack)",
    "laser_lm_problem": "laser (linear motor)",
}


def test_docs_signoff_table_is_what_the_checker_prints(tmp_path_factory):
    """docs/validation.md's sign-off of every shipped optimum: its lowest vendor margin, the check
    and the vendor rule as the checker prints them, and a reason to sign in the last cell."""
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        from vendor_check import signoff_cells
    finally:
        sys.path.pop(0)
    text = (ROOT / "docs" / "validation.md").read_text(encoding="utf-8")
    for name, label in SIGNOFF.items():
        want = signoff_cells(label, rows(name, tmp_path_factory))
        line = next((x for x in text.splitlines() if x.startswith(want)), None)
        assert line is not None, (
            f"docs/validation.md sign-off row differs; the checker prints:\n{want}"
        )
        why = line[len(want) :].strip().rstrip("|").strip()
        assert len(why) > 40, f"{name}: no reason to sign in the row"
