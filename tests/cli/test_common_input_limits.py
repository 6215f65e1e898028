"""Hardening of the one YAML reader and the one quantity parser: every hostile input below ends in
one line on stderr and exit 2, quickly (each case would hang, crash with a traceback, or be accepted
as nonsense without the limits in ``yamlio`` and ``units``)."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
DESIGN = (ROOT / "problems" / "vmc_x_design.yaml").read_text()
PROBLEM = (ROOT / "problems" / "teaching_problem.yaml").read_text()
LEXICOGRAPHIC = (ROOT / "problems" / "highspeed_problem.yaml").read_text()

BOMB = "".join(
    f"{a}: &{a} [" + ",".join([f"*{p}"] * 9 if p else ['"x"'] * 9) + "]\n"
    for a, p in zip("abcdefghi", [None, *"abcdefgh"])
)


def _run(tmp_path, capsys, text, command="evaluate", encoding="utf-8"):
    f = tmp_path / "in.yaml"
    f.write_bytes(text.encode(encoding) if isinstance(text, str) else text)
    t = time.perf_counter()
    rc = main([command, str(f)])
    dt = time.perf_counter() - t
    err = capsys.readouterr().err.strip()
    return rc, err, dt


@pytest.mark.parametrize(
    "name, text, words",
    [
        ("deep nesting", "a: " + "[" * 1000 + "]" * 1000 + "\n", "nested deeper than"),
        ("alias bomb", BOMB, "aliases are expanded"),
        ("nan factor", DESIGN.replace("load_factor: 1.2", "load_factor: .nan"), "finite"),
        ("inf factor", DESIGN.replace("load_factor: 1.2", "load_factor: .inf"), "finite"),
        ("huge count", DESIGN.replace("guide_blocks: 4", "guide_blocks: 100000000000"), "at most"),
        ("huge length", DESIGN.replace("stroke: 800 mm", "stroke: 1e308 mm"), "out of range"),
        ("tiny length", DESIGN.replace("stroke: 800 mm", "stroke: 1e-300 mm"), "too small"),
        (
            "huge time",
            DESIGN.replace("required_life: 20000 h", "required_life: 1e300 h"),
            "out of range",
        ),
        ("micro alone", DESIGN.replace("moving_mass: 450 kg", "moving_mass: 450 µ"), "prefix"),
        ("u alone", DESIGN.replace("moving_mass: 450 kg", "moving_mass: 450 u"), "prefix"),
        (
            "long unit",
            DESIGN.replace("stroke: 800 mm", "stroke: 800 " + "m" * 100_000),
            "characters",
        ),
        (
            "long name",
            DESIGN.replace("name: VMC X axis", "name: " + "x" * 100_000),
            "text too long",
        ),
        ("long key", DESIGN.replace("  rails: 2", "  " + "r" * 1000 + ": 2"), "unknown key"),
        (
            "latin-1",
            DESIGN.replace("description:", "description: Tisch für Werkstück,"),
            "UnicodeDecodeError",
        ),
    ],
)
def test_hostile_design_is_one_line_exit_2(tmp_path, capsys, name, text, words):
    rc, err, dt = _run(tmp_path, capsys, text, encoding="latin-1" if name == "latin-1" else "utf-8")
    assert rc == 2, (name, err)
    assert err.startswith("error: ") and "\n" not in err and words in err, err
    assert len(err) < 400 and dt < 5.0


@pytest.mark.parametrize(
    "text, old, new, words",
    [
        (PROBLEM, "max_cost: 3500 EUR", "max_cost: .nan EUR", "read"),
        (LEXICOGRAPHIC, "tolerance: 0.02", "tolerance: .nan", "finite"),
    ],
)
def test_hostile_problem_is_one_line_exit_2(tmp_path, capsys, text, old, new, words):
    assert old in text
    rc, err, _ = _run(tmp_path, capsys, text.replace(old, new), command="solve")
    assert rc == 2 and "\n" not in err and words in err, err


CUSTOM = (ROOT / "problems" / "custom_parts_design.yaml").read_text()


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("root_diameter: 72.5 mm", "root_diameter: 0 mm", "root_diameter must be positive"),
        ("stiffness: 2200 N/um", "stiffness: 0 N/um", "stiffness must be positive"),
        ("lead: 20 mm", "lead: 0 mm", "lead must be positive"),
        ("type: double", "type: triple", "'triple' is not one of"),
        ("preload_min: 5 kN", "preload_min: 25 kN", "preload_max is below preload_min"),
    ],
)
def test_inline_parts_follow_the_catalog_rules(tmp_path, capsys, old, new, words):
    """The same row rules as catalog CSVs (catalog.row_problem), named by the design's key."""
    assert old in CUSTOM
    rc, err, _ = _run(tmp_path, capsys, CUSTOM.replace(old, new, 1))
    assert rc == 2 and "\n" not in err and words in err and "parts." in err, err


@pytest.mark.parametrize(
    "table, column, cell, words",
    [
        ("guides", "rail_mass_per_length [kg/m]", "-3", "must not be negative"),
        ("nuts", "mass [kg]", "1e30", "out of range"),
        ("screws", "id", "x" * 200_000, "malformed CSV"),
    ],
)
def test_catalog_cells_follow_the_row_rules(tmp_path, capsys, table, column, cell, words):
    import csv
    import shutil

    from axisopt.catalog.columns import SHIPPED_DIR

    d = tmp_path / "cat"
    shutil.copytree(SHIPPED_DIR, d)
    path = d / f"{table}.csv"
    with path.open(newline="", encoding="utf-8-sig") as fh:
        rows = list(csv.reader(fh))
    rows[1][rows[0].index(column)] = cell
    with path.open("w", newline="", encoding="utf-8") as fh:
        csv.writer(fh).writerows(rows)
    design = tmp_path / "d.yaml"
    design.write_text(DESIGN.replace("parts:", f"catalogs: [{d}]\nparts:", 1))
    rc = main(["evaluate", str(design)])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and "\n" not in err and words in err and f"{table}.csv" in err, err


def test_diagnose_data_out_of_range_is_one_line(tmp_path, capsys):
    """A force of 1e300 N in a test table used to run the fit for minutes with overflow warnings."""
    data = ROOT / "problems" / "data"
    text = (data / "table_x_stiffness.csv").read_text().splitlines()
    cells = text[1].split(",")
    cells[1] = "1e300"
    f = tmp_path / "d.csv"
    f.write_text("\n".join([text[0], ",".join(cells), *text[2:]]) + "\n")
    rc = main(["diagnose", str(f), "--design", str(data / "table_x.yaml")])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and "\n" not in err and "out of range" in err and "line 2" in err, err


@pytest.mark.parametrize("value", ["nan", "inf", "-1"])
def test_time_limit_must_be_finite_positive(capsys, value):
    rc = main(["solve", str(ROOT / "problems" / "teaching_problem.yaml"), "--time-limit", value])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and "\n" not in err and "--time-limit" in err, err


def test_json_never_holds_nan(tmp_path):
    """write_json writes null for a value the model could not compute, never NaN (invalid JSON)."""
    import json
    import math

    import numpy as np

    from axisopt.cli.common import write_json

    f = tmp_path / "x.json"
    write_json(
        {"a": math.nan, "b": [1.0, math.inf, np.float64("nan")], "c": np.array([1.0, np.nan])},
        str(f),
    )
    assert json.loads(f.read_text()) == {"a": None, "b": [1.0, None, None], "c": [1.0, None]}


def test_choice_with_boolean_options_is_one_line(tmp_path, capsys):
    """catalog.drive takes yes/no/true/false: another value was a TypeError in the 'did you mean'
    lookup."""
    text = PROBLEM.replace("catalog:", "catalog:\n  drive: maybe", 1)
    rc, err, _ = _run(tmp_path, capsys, text, command="solve")
    assert rc == 2 and "\n" not in err and "'maybe' is not one of" in err, err


def test_non_regular_files_and_huge_position_grids(tmp_path, capsys):
    """A FIFO hung forever and /dev/zero read until MemoryError; positions: 1e9 allocated
    gigabytes."""
    import os

    fifo = tmp_path / "fifo.yaml"
    os.mkfifo(fifo)
    for path in (fifo, Path("/dev/zero")):
        assert main(["evaluate", str(path)]) == 2
        err = capsys.readouterr().err.strip()
        assert "not a regular file" in err and "\n" not in err
    rc, err, _ = _run(
        tmp_path, capsys, DESIGN.replace("  rails: 2", "  rails: 2\n  positions: 1000000000")
    )
    assert rc == 2 and "at most 2001" in err


def test_brake_yes_no_as_yaml_booleans(tmp_path, capsys):
    """The README's 'brake: yes' is a YAML boolean: read as the mode, not refused."""
    from axisopt.design import load_design

    for word, mode in (("yes", "yes"), ("no", "no")):
        f = tmp_path / f"{word}.yaml"
        f.write_text(DESIGN.replace("  rails: 2", f"  rails: 2\n  brake: {word}"))
        assert load_design(f).axis.brake == mode


def test_empty_pareto_front_prints(tmp_path, capsys):
    """An infeasible Pareto problem printed a TypeError traceback from the empty design table."""
    text = PROBLEM.replace(
        "objective: stiffness", "objective: {mode: pareto, pareto: [stiffness, cost]}"
    )
    rc, err, _ = _run(
        tmp_path, capsys, text.replace("max_cost: 3500 EUR", "max_cost: 100 EUR"), command="solve"
    )
    assert rc == 1 and "Traceback" not in err
