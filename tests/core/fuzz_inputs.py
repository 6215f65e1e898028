"""Mutated CLI inputs for the fuzz test (tests/core/test_fuzz.py) and the long fuzz run
(bench/bench_fuzz.py).

A *case* is a command line plus the files it reads, all relative to an empty working directory: the
shipped designs, problems, studies (with a tiny sweep), a saved calibration, the diagnose data CSV
and a user catalog directory, with one mutation applied (a key deleted or misspelt, a value replaced
by NaN, infinity, a huge or tiny number, a wrong unit or type, a re-encoded, truncated, empty or
hostile file, odd command-line flags).

Choices are drawn from a ``Chooser`` (``choice``, ``randint``, ``random``), so the same generator
serves a seeded ``random.Random`` (the bench) and hypothesis' ``data.draw`` (the test, which then
shrinks).

:func:`classify` checks one outcome against the CLI contract:

* exit 0 with finite output (with ``--json``: no NaN/Infinity, no negative mass, stiffness, length
  or frequency), no traceback and no warning on stderr;
* exit 1 (proven negative) or 3 (unproven) with an explanation (stdout or stderr not empty), no
  traceback;
* exit 2 with exactly one line on stderr starting with ``error: ``.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import threading
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"
CATALOGS = ROOT / "catalogs"

# --------------------------------------------------------------------------------------------------
# ------------
# the shipped inputs

DESIGNS = (
    "vmc_x_design.yaml",
    "teaching_design.yaml",
    "custom_parts_design.yaml",
    "paper_3_1_3_d40.yaml",
    "data/table_x.yaml",
)
FAST_PROBLEMS = ("teaching_problem.yaml", "duty_cycle_problem.yaml", "vertical_problem.yaml")
ALL_PROBLEMS = FAST_PROBLEMS + (
    "vmc_x_problem.yaml",
    "highspeed_problem.yaml",
    "gantry_problem.yaml",
    "pareto_problem.yaml",
    "infeasible_problem.yaml",
    "infeasible_drive_problem.yaml",
)
STUDIES = (
    "teaching_random.yaml",
    "vmc_stroke_mounting.yaml",
    "gantry_weights.yaml",
    "pareto_stroke.yaml",
    "vmc_random_1000.yaml",
)
DATA_CSV = "data/table_x_stiffness.csv"
DATA_DESIGN = "data/table_x.yaml"
TABLES = ("screws", "nuts", "bearings", "guides", "motors", "couplings")
EFFECTS = (
    "support_condition",
    "hertz_contact",
    "backlash",
    "friction_hysteresis",
    "thermal_drift",
    "compliance_offset",
    "added_mass",
    "stribeck",
    "viscous",
    "load_dependent_friction",
    "direction_asymmetry",
    "preload_loss",
    "extra_mode",
)

KINDS = (
    "design",
    "problem",
    "study",
    "calibration",
    "data",
    "catalog",
    "flags",
    "compare",
    "hardening",
)


def shipped(rel: str) -> bytes:
    return (PROBLEMS / rel).read_bytes()


# --------------------------------------------------------------------------------------------------
# ------------
# choosers


class RandomChooser:
    """``random.Random`` as a chooser."""

    def __init__(self, rnd):
        self.rnd = rnd

    def choice(self, seq):
        seq = list(seq)
        return seq[self.rnd.randrange(len(seq))]

    def randint(self, lo, hi):
        return self.rnd.randint(lo, hi)

    def random(self):
        return self.rnd.random()


class DrawChooser:
    """hypothesis' ``data`` object as a chooser (so failing cases shrink)."""

    def __init__(self, data):
        from hypothesis import strategies as st

        self.data, self.st = data, st

    def choice(self, seq):
        seq = list(seq)
        return seq[self.data.draw(self.st.integers(0, len(seq) - 1))]

    def randint(self, lo, hi):
        return self.data.draw(self.st.integers(lo, hi))

    def random(self):
        return self.data.draw(self.st.integers(0, 999)) / 1000.0


# --------------------------------------------------------------------------------------------------
# ------------
# values that replace a YAML value

HUGE = "x" * 100_000
DEEP_TOKEN = "__FUZZ_DEEP__"
BOMB_TOKEN = "__FUZZ_BOMB__"
DEEP = "[" * 1000 + "]" * 1000
DEEP_MAP = "{a: " * 1000 + "1" + "}" * 1000
BOMB = (
    "["
    + ", ".join(
        [f"&a0 [{', '.join(['lol'] * 9)}]"]
        + [f"&a{i} [{', '.join([f'*a{i - 1}'] * 9)}]" for i in range(1, 9)]
    )
    + "]"
)

SPECIAL_VALUES = (
    ("nan", math.nan),
    ("inf", math.inf),
    ("-inf", -math.inf),
    ("-1", -1),
    ("0", 0),
    ("1e300", 1e300),
    ("1e-300", 1e-300),
    ("huge string", HUGE),
    ("list", [1, 2]),
    ("mapping", {"a": 1}),
    ("empty list", []),
    ("empty mapping", {}),
    ("null", None),
    ("true", True),
    ("empty string", ""),
    ("'450 u'", "450 u"),
    ("'450 µ'", "450 µ"),
    ("'3 furlong'", "3 furlong"),
    ("'-1 mm'", "-1 mm"),
    ("'1e300 mm'", "1e300 mm"),
    ("'nan mm'", "nan mm"),
    ("'0 kg'", "0 kg"),
    ("'450 kg/m'", "450 kg/m"),
    ("'1 1 mm'", "1 1 mm"),
    ("2**70", 2**70),
    ("1.5", 1.5),
    ("'yes'", "yes"),
    ("deep list", DEEP_TOKEN),
    ("alias bomb", BOMB_TOKEN),
)
NUMBERS = (
    ("-1", -1.0),
    ("0", 0.0),
    ("1e300", 1e300),
    ("1e-300", 1e-300),
    ("nan", math.nan),
    ("inf", math.inf),
    ("-inf", -math.inf),
    ("1e20", 1e20),
    ("1e-20", 1e-20),
    ("-0.0", -0.0),
    ("1e6", 1e6),
    ("0.001", 1e-3),
)
SCALES = (1e3, 1e6, 1e9, 1e12, 1e-3, 1e-6, 1e-9, 1e-12, 10.0, 0.1, 0.5, 2.0, -1.0, 1.0001, 0.9999)
_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*)$")
UNIT_SWAPS = (
    "u",
    "µ",
    "furlong",
    "mm",
    "kg",
    "N/um",
    "Hz",
    "s",
    "",
    "m/s^2",
    "K",
    "degC",
    "rad",
    "%",
    "N.m/rad",
    "mm mm",
    "1/0",
    "m**1000",
    "m^-1",
    "um/N",
)


def _fmt_num(v: float) -> str:
    if math.isnan(v):
        return "nan"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return repr(v)


def value_mutation(ch, old):
    """(description, new value) for a YAML value ``old``."""
    r = ch.random()
    m = _QTY.match(old) if isinstance(old, str) else None
    if m and r < 0.7:  # keep the unit, change the number (reaches the range checks), or the reverse
        num, unit = m.groups()
        r2 = ch.random()
        if r2 < 0.4:
            desc, v = ch.choice(NUMBERS)
            return f"number {num} -> {desc} (unit kept)", f"{_fmt_num(v)} {unit}"
        if r2 < 0.75:  # inside the plausible range but far from the shipped value
            f = ch.choice(SCALES)
            return f"number {num} scaled by {f:g} (unit kept)", f"{_fmt_num(float(num) * f)} {unit}"
        u = ch.choice(UNIT_SWAPS)
        return f"unit {unit!r} -> {u!r}", f"{num} {u}".strip()
    if isinstance(old, (int, float)) and not isinstance(old, bool) and r < 0.3:
        f = ch.choice(SCALES)
        v = old * f
        if isinstance(old, int) and float(v).is_integer() and abs(v) < 1e18:
            v = int(v)
        return f"number {old!r} scaled by {f:g}", v
    if isinstance(old, (int, float)) and not isinstance(old, bool) and r < 0.55:
        desc, v = ch.choice(
            NUMBERS + (("10**9", 10**9), ("10**18", 10**18), ("2", 2), ("1.5", 1.5))
        )
        return f"number {old!r} -> {desc}", v
    desc, v = ch.choice(SPECIAL_VALUES)
    return f"value -> {desc}", v


def typo(ch, key: str) -> str:
    key = str(key)
    if not key:
        return "x"
    i = ch.randint(0, len(key) - 1)
    op = ch.choice(("drop", "double", "swap", "upper", "suffix", "space"))
    if op == "drop":
        out = key[:i] + key[i + 1 :]
    elif op == "double":
        out = key[:i] + key[i] + key[i:]
    elif op == "swap" and len(key) > 1:
        i = min(i, len(key) - 2)
        out = key[:i] + key[i + 1] + key[i] + key[i + 2 :]
    elif op == "upper":
        out = key.upper()
    elif op == "space":
        out = key + " "
    else:
        out = key + "_"
    return out if out != key else key + "x"


# --------------------------------------------------------------------------------------------------
# ------------
# YAML mutations


def _paths(tree, prefix=()):
    if prefix:
        yield prefix
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from _paths(v, prefix + (k,))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from _paths(v, prefix + (i,))


def _get(tree, path):
    for p in path:
        tree = tree[p]
    return tree


def _show(path) -> str:
    return ".".join(str(p) for p in path) or "<root>"


def dump_yaml(tree) -> bytes:
    text = yaml.safe_dump(
        tree, sort_keys=False, allow_unicode=True, default_flow_style=None, width=10**9
    )
    text = text.replace(DEEP_TOKEN, DEEP).replace(BOMB_TOKEN, BOMB)
    return text.encode("utf-8")


def mutate_tree(ch, tree, where=None):
    """Mutate a parsed YAML tree in place at a random path (restricted to ``where`` prefixes if
    given).  Returns a description."""
    paths = list(_paths(tree))
    if where:
        sel = [p for p in paths if any(p[: len(w)] == w for w in where)]
        paths = sel or paths
    if not paths:
        return "no path"
    path = ch.choice(paths)
    parent = _get(tree, path[:-1])
    last = path[-1]
    op = ch.choice(
        (
            "delete",
            "rename",
            "value",
            "value",
            "value",
            "value",
            "value",
            "value",
            "wrap",
            "add_key",
        )
    )
    if op == "delete":
        del parent[last]
        return f"delete {_show(path)}"
    if op == "rename" and isinstance(parent, dict):
        new = typo(ch, last)
        items = [(new if k == last else k, v) for k, v in parent.items()]
        parent.clear()
        parent.update(items)
        return f"rename {_show(path)} -> {new!r}"
    if op == "wrap":
        old = parent[last]
        how = ch.choice(("list", "mapping"))
        parent[last] = [old] if how == "list" else {"value": old}
        return f"wrap {_show(path)} in a {how}"
    if op == "add_key":
        target = _get(tree, path) if isinstance(_get(tree, path), dict) else parent
        if isinstance(target, dict):
            desc, v = value_mutation(ch, "1 mm")
            target[typo(ch, "extra_key")] = v
            return f"add unknown key under {_show(path if target is not parent else path[:-1])}"
    old = parent[last]
    desc, new = value_mutation(ch, old)
    parent[last] = new
    return f"{_show(path)}: {desc}"


def _inject_non_ascii(text: str) -> str:
    """A non-ASCII character in a comment and in a unit, so that a re-encoding changes bytes."""
    text = "# Entwurf für Prüfstand, µm, °C\n" + text
    return text.replace(" um", " µm", 1).replace(" mm", " µm", 1) if "mm" in text else text


def mutate_text(ch, data: bytes, kind: str = "yaml"):
    """A whole-file mutation: (description, new bytes)."""
    text = data.decode("utf-8")
    ops = [
        "empty",
        "whitespace",
        "truncate",
        "random bytes",
        "random file",
        "nul",
        "latin-1",
        "utf-16",
        "utf-8 bom",
        "utf-32",
        "crlf",
        "cr only",
        "duplicate line",
    ]
    if kind == "yaml":
        ops += [
            "deep list",
            "deep mapping",
            "alias bomb",
            "self alias",
            "scalar doc",
            "list doc",
            "two docs",
            "python tag",
            "tab indent",
            "null doc",
            "complex key",
            "huge key",
            "dup top key",
            "merge key",
        ]
    op = ch.choice(ops)
    if op == "empty":
        return op, b""
    if op == "whitespace":
        return op, b"  \n\n\t\n"
    if op == "truncate":
        n = ch.randint(0, max(0, len(data) - 1))
        return f"truncate to {n} bytes", data[:n]
    if op == "random bytes":
        b = bytearray(data)
        k = ch.randint(1, 8)
        for _ in range(k):
            i = ch.randint(0, len(b) - 1)
            b[i] = ch.randint(0, 255)
        return f"{k} random bytes", bytes(b)
    if op == "random file":
        n = ch.randint(1, 400)
        seed = ch.randint(0, 2**31)
        import random

        return f"{n} random bytes (seed {seed})", random.Random(seed).randbytes(n)
    if op == "nul":
        i = ch.randint(0, len(data))
        return f"NUL at byte {i}", data[:i] + b"\x00" + data[i:]
    if op == "latin-1":
        return "Latin-1 encoded (non-ASCII µ, ü, °)", _inject_non_ascii(text).encode("latin-1")
    if op == "utf-16":
        return "UTF-16 encoded", text.encode("utf-16")
    if op == "utf-32":
        return "UTF-32 encoded", text.encode("utf-32")
    if op == "utf-8 bom":
        return "UTF-8 with BOM", b"\xef\xbb\xbf" + data
    if op == "crlf":
        return "CRLF line ends", text.replace("\n", "\r\n").encode()
    if op == "cr only":
        return "CR line ends", text.replace("\n", "\r").encode()
    if op == "duplicate line":
        lines = text.splitlines(keepends=True)
        i = ch.randint(0, len(lines) - 1)
        return f"line {i + 1} duplicated", "".join(lines[: i + 1] + lines[i:]).encode()
    if op == "deep list":
        return "1000-deep [[[...]]] document", DEEP.encode()
    if op == "deep mapping":
        return "1000-deep {a: {a: ...}} document", DEEP_MAP.encode()
    if op == "alias bomb":
        return "billion-laughs alias bomb as a value", (
            text.rstrip("\n") + "\nbomb: " + BOMB + "\n"
        ).encode()
    if op == "self alias":
        return "self-referencing alias", (text + "\nloop: &l [*l]\n").encode()
    if op == "scalar doc":
        return "document is a scalar", b"42\n"
    if op == "list doc":
        return "document is a list", b"- a\n- b\n"
    if op == "null doc":
        return "document is null", b"~\n"
    if op == "two docs":
        return "two YAML documents", (text + "\n---\n" + text).encode()
    if op == "python tag":
        return "!!python/object tag", (text + "\nx: !!python/object/apply:os.getcwd []\n").encode()
    if op == "tab indent":
        return "tab indentation", text.replace("  ", "\t").encode()
    if op == "complex key":
        return "non-string keys", (text + "\n? [1, 2]\n: 3\n1: 2\nnull: 1\n").encode()
    if op == "huge key":
        return "10^5-character key", (text + "\n" + "k" * 100_000 + ": 1\n").encode()
    if op == "dup top key":
        first = next((ln for ln in text.splitlines() if re.match(r"^[A-Za-z_]+:", ln)), "name: x")
        return f"duplicated top-level key ({first.split(':')[0]})", (
            text + "\n" + first + "\n"
        ).encode()
    if op == "merge key":
        return "YAML merge key <<", (text + "\nm: &m {a: 1}\nn: {<<: *m}\n").encode()
    raise AssertionError(op)


# Optional keys the shipped files leave at their defaults (README "Design YAML" / "Problem YAML"),
# with an example value: the "optional" mutation writes one in, its value often mutated too.
AXIS_OPTIONAL = {
    "start_offset": "130 mm",
    "end_margin": "170 mm",
    "mean_speed": "8 m/min",
    "mean_axial_load": "800 N",
    "acceleration": "3 m/s^2",
    "required_life": "20000 h",
    "load_factor": 1.2,
    "guide_blocks": 4,
    "rails": 2,
    "table_length": "600 mm",
    "orientation": "vertical",
    "normal_load": "500 N",
    "lubricant_viscosity": "32 mm^2/s",
    "motor_inertia": "0.001 kg.m^2",
    "coupling_stiffness": "75000 N.m/rad",
    "coupling_inertia": "0.29e-3 kg.m^2",
    "bearing_housing_stiffness": "2000 N/um",
    "nut_bracket_stiffness": "1500 N/um",
    "temperature_rise": "3 K",
    "pretension": "auto",
    "positions": 41,
    "jerk": "100 m/s^3",
    "reduction_ratio": 2,
    "reduction_efficiency": 0.95,
    "reduction_inertia": "0.4e-4 kg.m^2",
    "max_inertia_ratio": 5,
    "brake": "yes",
    "brake_safety": 2,
    "bearing_static_safety": 4,
    "nut_lift_off_safety": 1.2,
    "duty_cycle": [
        {"move": "300 mm"},
        {"move": "350 mm", "speed": "2 m/min", "force": "2500 N"},
        {"dwell": "1 s"},
        {"move": "-650 mm", "acceleration": "4 m/s^2", "jerk": "80 m/s^3"},
    ],
}
PROBLEM_OPTIONAL = {
    ("limits", "max_cost"): "5000 EUR",
    ("limits", "max_total_mass"): "600 kg",
    ("limits", "max_moving_mass"): "600 kg",
    ("limits", "max_drag_torque"): "2.5 N.m",
    ("limits", "min_life"): "20000 h",
    ("limits", "min_stiffness"): "150 N/um",
    ("limits", "min_frequency"): "50 Hz",
    ("limits", "max_backlash"): "30 um",
    ("limits", "margins"): {"critical_speed": 1.25, "buckling": 2.0, "dn": 0},
    ("catalog", "bearing_arrangements"): ["DF", "DFD", "DB"],
    ("catalog", "bearing_preload"): ["medium", "heavy"],
    ("catalog", "guide_types"): ["ball"],
    ("catalog", "guide_preload"): ["heavy", "super-heavy"],
    ("catalog", "max_motor_flange"): "130 mm",
    ("catalog", "drive"): "no",
    ("catalog", "vendors"): ["HIWIN"],
    ("catalog", "exclude"): {"guide": ["HIWIN-HG15-ZA"]},
    ("catalog", "motor_vendors"): ["Yaskawa"],
    ("continuous", "nut_preload"): {"min": "200 N", "max": "20 kN"},
    ("objective",): {
        "mode": "weighted",
        "weights": {"stiffness": 1, "frequency": 1},
        "scale": {"stiffness": "100 N/um", "frequency": "50 Hz"},
    },
}
OBJECTIVES = (
    PROBLEM_OPTIONAL[("objective",)],
    {"mode": "pareto", "pareto": ["stiffness", "cost"]},
    {"mode": "pareto", "pareto": ["stiffness", "frequency", "cost", "total_mass"]},
    {"mode": "lexicographic", "order": ["frequency", "stiffness"], "tolerance": 0.02},
    "frequency",
)
EXTREME_COUNTS = (10**9, 10**6, 10**5, 3, 0, -1, 2**63)


def add_optional(ch, tree) -> str | None:
    """Write one optional key the file leaves out (its value kept, pushed to an extreme or
    mutated)."""
    if not isinstance(tree, dict):
        return None
    cands = []
    if isinstance(tree.get("axis"), dict):
        cands += [(("axis", k), v) for k, v in AXIS_OPTIONAL.items()]
        if isinstance(tree.get("parts"), dict):
            cands.append((("parts", "nut_preload"), "3000 N"))
    if "objective" in tree:
        cands += list(PROBLEM_OPTIONAL.items())
    if not cands:
        return None
    path, value = ch.choice(cands)
    if path == ("objective",):
        value = ch.choice(OBJECTIVES)
    import copy

    value = copy.deepcopy(value)
    how = "example value"
    r = ch.random()
    if isinstance(value, int) and not isinstance(value, bool) and r < 0.5:
        value = ch.choice(EXTREME_COUNTS)
        how = f"value {value}"
    elif r < 0.75:
        how, value = value_mutation(ch, value)
    node = tree
    for p in path[:-1]:
        if not isinstance(node.get(p), dict):
            node[p] = {}
        node = node[p]
    node[path[-1]] = value
    return f"add optional {'.'.join(path)} ({how})"


def mutate_yaml(ch, data: bytes, where=None, text_share: float = 0.2):
    """Either a structured mutation (parse, change one path, dump) or a whole-file one."""
    if ch.random() < text_share:
        return mutate_text(ch, data, "yaml")
    tree = yaml.safe_load(data)
    descs = []
    for _ in range(ch.choice((1, 1, 1, 2, 3))):
        d = add_optional(ch, tree) if where is None and ch.random() < 0.3 else None
        descs.append(d or mutate_tree(ch, tree, where))
    return "; ".join(descs), dump_yaml(tree)


# --------------------------------------------------------------------------------------------------
# ------------
# CSV mutations

CSV_VALUES = (
    "",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "-1",
    "0",
    "1e300",
    "1e-300",
    "-1e300",
    "abc",
    HUGE,
    '"',
    "1,2",
    "1e400",
    "0x10",
    "1_000",
    " 5 ",
    "5 mm",
    "true",
    "\u00b5",
    "2",
    "-0",
)
HEADER_UNITS = (
    "[mm]",
    "[um]",
    "[µm]",
    "[u]",
    "[furlong]",
    "",
    "[]",
    "[-]",
    "[N]",
    "[kN]",
    "[N/um]",
    "[m]",
    "[s]",
    "[1/0]",
    "[mm",
    "[mm][mm]",
)


def read_csv_rows(data: bytes):
    return list(csv.reader(io.StringIO(data.decode("utf-8-sig"))))


def write_csv_rows(rows) -> bytes:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerows(rows)
    return buf.getvalue().encode("utf-8")


def mutate_csv(ch, data: bytes, rows_of_interest=None, text_share: float = 0.2):
    """(description, new bytes) for a CSV file; ``rows_of_interest`` (indices) get most cell
    mutations."""
    if ch.random() < text_share:
        return mutate_text(ch, data, "csv")
    rows = read_csv_rows(data)
    head, body = rows[0], rows[1:]
    op = ch.choice(
        (
            "cell",
            "cell",
            "cell",
            "cell",
            "column",
            "column scale",
            "header",
            "header unit",
            "delete rows",
            "keep rows",
            "delete column",
            "add column",
            "short row",
            "long row",
            "duplicate rows",
            "shuffle",
        )
    )
    if op == "cell" and body:
        if rows_of_interest and ch.random() < 0.7:
            i = ch.choice(rows_of_interest)
        else:
            i = ch.randint(0, len(body) - 1)
        j = ch.randint(0, len(head) - 1)
        v = ch.choice(CSV_VALUES)
        old = body[i][j] if j < len(body[i]) else None
        if j < len(body[i]):
            body[i][j] = v
        desc = (
            f"cell line {i + 2} column '{head[j]}' {old!r} -> "
            f"{v[:20]!r}{'...' if len(v) > 20 else ''}"
        )
    elif op == "column" and body:
        j = ch.randint(0, len(head) - 1)
        v = ch.choice(CSV_VALUES[:10])
        for r in body:
            if j < len(r):
                r[j] = v
        desc = f"every cell of column '{head[j]}' -> {v[:20]!r}"
    elif op == "column scale" and body:
        j = ch.randint(0, len(head) - 1)
        f = ch.choice((1e300, 1e-300, -1.0, 0.0, 1e6, 1e-6))
        for r in body:
            if j < len(r):
                try:
                    r[j] = repr(float(r[j]) * f)
                except ValueError:
                    pass
        desc = f"column '{head[j]}' scaled by {f!r}"
    elif op == "header":
        j = ch.randint(0, len(head) - 1)
        new = ch.choice(
            (typo(ch, head[j]), head[(j + 1) % len(head)], "", HUGE[:5000], head[j].upper())
        )
        desc = f"header '{head[j]}' -> {new[:30]!r}"
        head[j] = new
    elif op == "header unit":
        j = ch.randint(0, len(head) - 1)
        name = head[j].split("[")[0].strip()
        u = ch.choice(HEADER_UNITS)
        desc = f"header '{head[j]}' unit -> {u!r}"
        head[j] = f"{name} {u}".strip()
    elif op == "delete rows":
        k = ch.randint(1, max(1, len(body)))
        desc = f"delete {k} of {len(body)} data rows"
        body = body[k:]
    elif op == "keep rows":
        k = ch.choice((0, 1, 2, 3, 5))
        desc = f"keep only the first {k} data rows"
        body = body[:k]
    elif op == "delete column":
        j = ch.randint(0, len(head) - 1)
        desc = f"delete column '{head[j]}'"
        head = head[:j] + head[j + 1 :]
        body = [r[:j] + r[j + 1 :] for r in body]
    elif op == "add column":
        name = ch.choice(("extra [mm]", "status", "id", head[0], "exclude", "mass [kg]"))
        desc = f"add column {name!r}"
        head = head + [name]
        body = [r + ["1"] for r in body]
    elif op == "short row" and body:
        i = ch.randint(0, len(body) - 1)
        body[i] = body[i][:-1]
        desc = f"line {i + 2} one cell short"
    elif op == "long row" and body:
        i = ch.randint(0, len(body) - 1)
        body[i] = body[i] + ["1"]
        desc = f"line {i + 2} one cell too many"
    elif op == "duplicate rows" and body:
        desc = "every data row twice"
        body = body + body
    else:
        body = body[::-1]
        desc = "rows reversed"
    return desc, write_csv_rows([head] + body)


# --------------------------------------------------------------------------------------------------
# ------------
# cases


@dataclass
class Case:
    kind: str
    mutation: str
    argv: list
    files: dict = field(default_factory=dict)  # relative path -> bytes
    dirs: tuple = ()  # relative directories to create
    # ';'-separated: 'fifo:<rel path>' makes a named pipe nobody writes or reads; 'drain:<rel path>'
    # makes one that a thread of the runner reads to its end (as `cat fifo` would), for output paths
    special: str = ""
    # rel path -> _Drain (while running)
    drains: dict = field(default_factory=dict, repr=False, compare=False)

    def command(self) -> str:
        return "axisopt " + " ".join(_q(a) for a in self.argv)

    def materialize(self, workdir: Path) -> None:
        for d in self.dirs:
            (workdir / d).mkdir(parents=True, exist_ok=True)
        for rel, data in self.files.items():
            p = workdir / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_bytes(data)
        for spec in filter(None, self.special.split(";")):
            how, _, rel = spec.partition(":")
            p = workdir / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            os.mkfifo(p)
            if how == "drain":
                self.drains[rel] = _Drain(p)

    def release(self) -> dict:
        """What arrived at each drained FIFO (rel path -> bytes); a reader still waiting is
        released."""
        got = {rel: d.result() for rel, d in self.drains.items()}
        self.drains = {}
        return got


class _Drain:
    """A thread that reads a FIFO to its end."""

    def __init__(self, path: Path):
        self.path, self.data = path, b""
        self.t = threading.Thread(target=self._run, daemon=True)
        self.t.start()

    def _run(self):
        try:
            with open(self.path, "rb") as fh:
                self.data = fh.read()
        except OSError:
            pass

    def result(self) -> bytes:
        self.t.join(2)
        # the command never opened it: open the writing end once so the reader returns
        if self.t.is_alive():
            try:
                os.close(os.open(self.path, os.O_WRONLY | os.O_NONBLOCK))
            except OSError:
                pass
            self.t.join(5)
        return self.data


def _q(a: str) -> str:
    a = str(a)
    if len(a) > 60:
        a = a[:40] + f"...({len(a)} chars)"
    return a if re.fullmatch(r"[\w./:,=@+-]+", a) else repr(a)


def _json_flag(ch, argv, p=0.8):
    if ch.random() < p:
        argv += ["--json", "-"]
    return argv


def design_case(ch, designs=DESIGNS) -> Case:
    name = ch.choice(designs)
    desc, data = mutate_yaml(ch, shipped(name))
    rel = "d/" + Path(name).name
    argv = ["evaluate", rel]
    r = ch.random()
    if r < 0.15:
        argv += ["--methods"]
    elif r < 0.2:
        argv += ["--frf", "frf.png"]
    elif r < 0.23:
        argv += ["--plot", "p.png"]
    return Case("design", f"{name}: {desc}", _json_flag(ch, argv), {rel: data})


def problem_case(ch, problems=FAST_PROBLEMS) -> Case:
    name = ch.choice(problems)
    desc, data = mutate_yaml(ch, shipped(name))
    rel = "p/" + name
    argv = ["solve", rel, "--no-sensitivity", "--top", "2"]
    if ch.random() < 0.1:
        argv = ["solve", rel]
    return Case("problem", f"{name}: {desc}", _json_flag(ch, argv), {rel: data})


def _tiny_sweep(tree, name: str, fast: bool):
    """Every swept key cut to at most two values (only the first key keeps two), the sweep's base
    kept."""
    sweep = tree.get("sweep", {})
    first = True
    for k, v in list(sweep.items()):
        keep = 2 if first else 1
        if name in ("gantry_weights.yaml", "teaching_random.yaml"):  # zip: equal lengths
            keep = 2
        if isinstance(v, list):
            sweep[k] = v[:keep]
        elif isinstance(v, dict) and "steps" in v:
            v["steps"] = keep
        elif isinstance(v, dict) and isinstance(v.get("random"), dict):
            v["random"]["n"] = (
                2
                if name in ("gantry_weights.yaml", "teaching_random.yaml", "vmc_random_1000.yaml")
                else keep
            )
        first = False
    if tree.get("combine") == "zip":
        for k, v in sweep.items():
            if isinstance(v, dict) and isinstance(v.get("random"), dict):
                v["random"]["n"] = 2
            elif isinstance(v, list):
                sweep[k] = v[:2]
    if fast and isinstance(tree.get("base"), str):
        tree["base"] = "../teaching_problem.yaml"
    return tree


def study_case(ch, studies=STUDIES, fast=True) -> Case:
    name = ch.choice(studies)
    tree = _tiny_sweep(yaml.safe_load(shipped("studies/" + name)), name, fast)
    files = {}
    base = tree.get("base")
    base_name = base.split("/")[-1] if isinstance(base, str) else None
    if base_name:
        files["p/" + base_name] = shipped(base_name)
    target = "study"
    if base_name and ch.random() < 0.3:
        target = "base"
        desc, files["p/" + base_name] = mutate_yaml(ch, shipped(base_name))
        desc = f"base {base_name}: {desc}"
        study_bytes = dump_yaml(tree)
    else:
        where = None if ch.random() < 0.5 else [("sweep",)]
        if ch.random() < 0.25:
            desc, study_bytes = mutate_text(ch, dump_yaml(tree), "yaml")
        else:
            desc = mutate_tree(ch, tree, where)
            study_bytes = dump_yaml(tree)
    files["p/studies/" + name] = study_bytes
    argv = ["study", "p/studies/" + name, "--out", "out", "--workers", "0", "--quiet"]
    return Case("study", f"studies/{name} (tiny sweep) {target}: {desc}", argv, files)


_CAL_CACHE: dict = {}


def calibration_bytes(runner=None) -> bytes:
    """A calibration saved by ``diagnose`` on the shipped data (made once per process)."""
    if "cal" not in _CAL_CACHE:
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "cal.yaml"
            argv = [
                "diagnose",
                str(PROBLEMS / DATA_CSV),
                "--design",
                str(PROBLEMS / DATA_DESIGN),
                "--save-calibration",
                str(out),
            ]
            r = subprocess.run(
                [sys.executable, "-m", "axisopt", *argv],
                capture_output=True,
                timeout=120,
                cwd=str(ROOT),
            )
            if r.returncode != 0:
                raise RuntimeError(f"cannot make the calibration: {r.stderr.decode()[-500:]}")
            _CAL_CACHE["cal"] = out.read_bytes()
    return _CAL_CACHE["cal"]


# Every baseline parameter and every effect that evaluate applies, with plausible values (a saved
# calibration carries only the accepted effects): the calibration cases mutate this one or the saved
# one.
RICH_CALIBRATION = """\
axisopt_calibration: 1
design: table-x
baseline:
  screw_modulus: {value: 202.7 GPa, kind: pressure}
  coulomb_friction: {value: 60 N, kind: force}
  damping_ratio: {value: 0.03, kind: dimensionless}
effects:
- name: support_condition
  parameters:
    far_end_stiffness: {value: 89.9 N/um, kind: stiffness}
- name: hertz_contact
  parameters:
    nut_preload: {value: 1500 N, kind: force}
- name: compliance_offset
  parameters:
    extra_compliance: {value: 0.002 um/N, kind: compliance}
- name: added_mass
  parameters:
    added_mass: {value: 20 kg, kind: mass}
- name: extra_mode
  parameters:
    mode_frequency: {value: 300 Hz, kind: frequency}
- name: viscous
  parameters:
    viscous_coefficient: {value: 500 N.s/m, kind: damping}
- name: load_dependent_friction
  parameters:
    friction_coefficient: {value: 0.004, kind: dimensionless}
"""


def calibration_case(ch) -> Case:
    rich = ch.random() < 0.6
    desc, data = mutate_yaml(ch, RICH_CALIBRATION.encode() if rich else calibration_bytes())
    desc = f"{'every effect' if rich else 'saved'}: {desc}"
    files = {"cal.yaml": data, "table_x.yaml": shipped(DATA_DESIGN)}
    argv = ["evaluate", "table_x.yaml", "--calibration", "cal.yaml"]
    return Case("calibration", f"calibration: {desc}", _json_flag(ch, argv, 0.85), files)


_DATA_CACHE: dict = {}


def synthetic_datasets() -> dict:
    """Natural-frequency, friction and frequency-response tests of the shipped table_x axis (made
    once per process with ``axisopt.identify.tables.synth``, as problems/data/generate.py makes the
    stiffness test)."""
    if not _DATA_CACHE:
        import numpy as np

        from axisopt.design import load_design
        from axisopt.identify import plant_from_design
        from axisopt.identify.tables.data import write_dataset
        from axisopt.identify.tables.synth import simulate

        plant = plant_from_design(load_design(PROBLEMS / DATA_DESIGN))
        v = np.r_[np.linspace(-0.5, -0.005, 8), np.linspace(0.005, 0.5, 8)]
        f = np.geomspace(20, 400, 30)
        specs = {
            "frequency.csv": (
                "frequency",
                dict(position=np.linspace(0, 0.8, 5)),
                {"added_mass": {"added_mass": 30.0}},
            ),
            "friction.csv": (
                "friction",
                dict(velocity=np.tile(v, 3), position=np.repeat([0.1, 0.4, 0.7], 16)),
                {},
            ),
            "frf.csv": (
                "frf",
                dict(frequency=np.tile(f, 3), position=np.repeat([0.0, 0.4, 0.8], 30)),
                {},
            ),
        }
        with tempfile.TemporaryDirectory() as d:
            for i, (name, (kind, cols, eff)) in enumerate(specs.items()):
                ds = simulate(plant, kind, cols, effects=eff, seed=i + 1, source=name)
                write_dataset(ds, Path(d) / name)
                _DATA_CACHE[name] = (Path(d) / name).read_bytes()
    return _DATA_CACHE


def data_case(ch) -> Case:
    sets = {"stiffness.csv": shipped(DATA_CSV), **synthetic_datasets()}
    name = ch.choice(sorted(sets))
    desc, data = mutate_csv(ch, sets[name])
    files = {"data.csv": data, "table_x.yaml": shipped(DATA_DESIGN)}
    argv = ["diagnose", "data.csv", "--design", "table_x.yaml"]
    if ch.random() < 0.15:  # a second, unmutated test of the same axis: shared parameters
        other = ch.choice(sorted(set(sets) - {name}))
        files["other.csv"] = sets[other]
        argv.append("other.csv")
        desc += f" (with unmutated {other})"
    r = ch.random()
    if r < 0.3:
        argv += [
            "--effects",
            ",".join(sorted({ch.choice(EFFECTS) for _ in range(ch.randint(1, 3))})),
        ]
    elif r < 0.4:
        argv += ["--max-effects", str(ch.choice((0, 1, 3, 13)))]
    return Case("data", f"{name}: {desc}", _json_flag(ch, argv, 0.85), files)


def _prefixed_table(table: str) -> tuple[list, list]:
    rows = read_csv_rows((CATALOGS / f"{table}.csv").read_bytes())
    head = rows[0]
    idc = head.index("id")
    sc = head.index("screw_id") if "screw_id" in head else None
    for r in rows[1:]:
        r[idc] = "U-" + r[idc]
        if sc is not None:
            r[sc] = "U-" + r[sc]
    return head, rows[1:]


def catalog_case(ch) -> Case:
    """A user catalog directory (the shipped tables with every id prefixed 'U-'), one table mutated,
    used by ``parts``, ``evaluate`` (a design of U- parts) or ``solve`` (the teaching problem over
    both catalogs)."""
    table = ch.choice(TABLES)
    design = yaml.safe_load(shipped("vmc_x_design.yaml"))
    used = {
        "screws": design["parts"]["screw"],
        "nuts": design["parts"]["nut"],
        "bearings": design["parts"]["bearing"],
        "guides": design["parts"]["guide"],
        "motors": design["parts"]["motor"],
        "couplings": design["parts"]["coupling"],
    }
    files = {}
    for t in TABLES:
        head, body = _prefixed_table(t)
        if t == table:
            interest = [i for i, r in enumerate(body) if r[0] == "U-" + used[t]]
            if ch.random() < 0.5:
                vendor_rows = [
                    i
                    for i, r in enumerate(body)
                    if "HIWIN" in r[1] or "Yaskawa" in r[1] or "RINGFEDER" in r[1]
                ]
                interest = vendor_rows or interest
            desc, files[f"cat/{t}.csv"] = mutate_csv(
                ch, write_csv_rows([head] + body), interest, text_share=0.1
            )
        else:
            files[f"cat/{t}.csv"] = write_csv_rows([head] + body)
    cmd = ch.choice(("parts", "evaluate", "evaluate", "solve"))
    if cmd == "parts":
        argv = ["parts", table, "--catalogs", "cat"]
    elif cmd == "evaluate":
        design["catalogs"] = ["cat"]
        for k in ("screw", "nut", "bearing", "guide", "motor", "coupling"):
            design["parts"][k] = "U-" + design["parts"][k]
        files["design.yaml"] = dump_yaml(design)
        argv = ["evaluate", "design.yaml"]
    else:
        prob = yaml.safe_load(shipped("teaching_problem.yaml"))
        prob["catalogs"] = ["cat"]
        prob["catalog"]["require"] = {
            "coupling": ["U-RINGFEDER-GWB-AKN-30", "RINGFEDER-GWB-AKN-60"]
        }
        files["problem.yaml"] = dump_yaml(prob)
        argv = ["solve", "problem.yaml", "--no-sensitivity", "--top", "2"]
    return Case(
        "catalog", f"catalogs/{table}.csv (U- copy): {desc}", _json_flag(ch, argv, 0.8), files
    )


def compare_case(ch) -> Case:
    a = ch.choice(DESIGNS)
    b = ch.choice(DESIGNS + ("teaching_problem.yaml",))
    mutated = ch.choice(("a", "b"))
    files = {"a.yaml": shipped(a), "b.yaml": shipped(b)}
    desc, files[f"{mutated}.yaml"] = mutate_yaml(ch, files[f"{mutated}.yaml"])
    argv = ["compare", "a.yaml", "b.yaml"]
    if ch.random() < 0.3:
        argv += ["--csv", "c.csv"]
    return Case(
        "compare", f"compare {a} {b}, {mutated} mutated: {desc}", _json_flag(ch, argv, 0.8), files
    )


def _flag_cases():
    """(description, argv, files) of command-line mutations on shipped (unmutated) inputs."""
    D = "d.yaml"
    P = "p.yaml"
    S = "s.yaml"
    C = "data.csv"
    dfiles = {D: shipped("vmc_x_design.yaml")}
    pfiles = {P: shipped("teaching_problem.yaml")}
    tx = {C: shipped(DATA_CSV), D: shipped(DATA_DESIGN)}
    st = _tiny_sweep(
        yaml.safe_load(shipped("studies/teaching_random.yaml")), "teaching_random.yaml", True
    )
    sfiles = {S: dump_yaml(st)}
    out = []
    for m in (
        "nut:hertz",
        "bearings:palmgren",
        "nut:",
        ":",
        ",,,",
        "all,all",
        "nut:hertz,nut:hertz",
        "xyz",
        HUGE[:5000],
        "screw:eq7,bearings:kraemer",
        "nut:catalog",
        "-",
        "nut:hertz:x",
        " ",
    ):
        out.append(
            (f"--methods {m[:20]!r}", ["evaluate", D, "--methods", m, "--json", "-"], dfiles)
        )
    for t in ("0", "-1", "1000000", "x", "1e3", "99999999999999999999", ""):
        out.append(
            (f"--top {t!r}", ["solve", P, "--no-sensitivity", "--top", t, "--json", "-"], pfiles)
        )
    for t in ("nan", "inf", "-inf", "-1", "0", "1e-300", "1e300", "x"):
        out.append(
            (f"--time-limit {t}", ["solve", P, "--no-sensitivity", "--time-limit", t], pfiles)
        )
    for t in ("nan", "1e-300"):
        out.append(
            (
                f"bonmin --time-limit {t}",
                ["solve", P, "--method", "bonmin", "--no-sensitivity", "--time-limit", t],
                pfiles,
            )
        )
    for m in ("exhaustive", "bonmin", "BONMIN", ""):
        out.append(
            (
                f"--method {m!r}",
                ["solve", P, "--no-sensitivity", "--method", m, "--json", "-"],
                pfiles,
            )
        )
    for e in (
        "",
        ",",
        "support_condition,support_condition",
        "nope",
        "SUPPORT_CONDITION",
        HUGE[:3000],
        " , ",
    ):
        out.append(
            (
                f"--effects {e[:20]!r}",
                ["diagnose", C, "--design", D, "--effects", e, "--json", "-"],
                tx,
            )
        )
    for n in ("-1", "0", "1000000000", "x", "1e9"):
        out.append(
            (
                f"--max-effects {n}",
                ["diagnose", C, "--design", D, "--max-effects", n, "--json", "-"],
                tx,
            )
        )
    for w in ("-1", "x", "1e9", "1000"):
        out.append(
            (f"--workers {w}", ["study", S, "--out", "out", "--workers", w, "--quiet"], sfiles)
        )
    out.append(
        (
            "--resume on a fresh dir",
            ["study", S, "--out", "out", "--workers", "0", "--resume", "--quiet"],
            sfiles,
        )
    )
    out.append(
        (
            "--out is a file",
            ["study", S, "--out", D, "--workers", "0", "--quiet"],
            {**sfiles, **dfiles},
        )
    )
    out.append(
        (
            "--scheduler and --workers",
            ["study", S, "--scheduler", "tcp://127.0.0.1:1", "--workers", "1"],
            sfiles,
        )
    )
    out.append(
        (
            "--scheduler garbage",
            ["study", S, "--out", "o", "--scheduler", "nonsense:://", "--quiet"],
            sfiles,
        )
    )
    for v in ("NOPE", "", "HIWIN"):
        out.append((f"parts --vendor {v!r}", ["parts", "--vendor", v, "--json", "-"], {}))
    for s in ("NOPE", "", "user", "vendor"):
        out.append((f"parts --status {s!r}", ["parts", "nuts", "--status", s, "--json", "-"], {}))
    out.append(("parts --catalogs missing dir", ["parts", "--catalogs", "nodir"], {}))
    out.append(("parts --catalogs a file", ["parts", "--catalogs", D], dfiles))
    out.append(
        ("parts --catalogs empty dir", ["parts", "--catalogs", "emptydir"], {"emptydir/.keep": b""})
    )
    out.append(("parts --catalogs shipped dir again", ["parts", "--catalogs", str(CATALOGS)], {}))
    out.append(("parts unknown kind", ["parts", "widgets"], {}))
    # files that are not what the command expects
    out.append(("design is a directory", ["evaluate", "."], {}))
    out.append(("design does not exist", ["evaluate", "missing.yaml"], {}))
    out.append(("design is /dev/null", ["evaluate", "/dev/null", "--json", "-"], {}))
    out.append(("design is the data CSV", ["evaluate", C], tx))
    out.append(("problem is a design", ["solve", D, "--json", "-"], dfiles))
    out.append(("design is a problem", ["evaluate", P, "--json", "-"], pfiles))
    out.append(("design is a study", ["evaluate", S], sfiles))
    out.append(
        ("study is a problem", ["study", P, "--out", "o", "--workers", "0", "--quiet"], pfiles)
    )
    out.append(("calibration is a design", ["evaluate", D, "--calibration", D], dfiles))
    out.append(("calibration missing", ["evaluate", D, "--calibration", "none.yaml"], dfiles))
    out.append(("data is a YAML", ["diagnose", D, "--design", D], tx))
    out.append(("design of diagnose is a CSV", ["diagnose", C, "--design", C], tx))
    out.append(("diagnose same data twice", ["diagnose", C, C, "--design", D, "--json", "-"], tx))
    out.append(("diagnose data is a directory", ["diagnose", ".", "--design", D], tx))
    out.append(("diagnose --report is a file", ["diagnose", C, "--design", D, "--report", C], tx))
    out.append(
        (
            "diagnose --save-calibration is a dir",
            ["diagnose", C, "--design", D, "--save-calibration", "."],
            tx,
        )
    )
    out.append(("compare nothing", ["compare"], {}))
    out.append(("compare the same design twice", ["compare", D, D, "--json", "-"], dfiles))
    out.append(("compare a study", ["compare", S], sfiles))
    out.append(("compare with --csv a directory", ["compare", D, "--csv", "."], dfiles))
    out.append(("--json is a directory", ["evaluate", D, "--json", "."], dfiles))
    out.append(
        ("--json into a missing directory", ["evaluate", D, "--json", "no/such/dir/x.json"], dfiles)
    )
    out.append(("--plot without extension", ["evaluate", D, "--plot", "plot"], dfiles))
    out.append(("--plot .pdf", ["evaluate", D, "--plot", "p.pdf"], dfiles))
    out.append(("--plot .xyz", ["evaluate", D, "--plot", "p.xyz"], dfiles))
    out.append(
        (
            "--frf without a motor",
            ["evaluate", "t.yaml", "--frf", "f.png", "--json", "-"],
            {"t.yaml": shipped("teaching_design.yaml")},
        )
    )
    out.append(("no arguments", [], {}))
    out.append(("unknown command", ["frobnicate"], {}))
    out.append(("unknown flag", ["evaluate", D, "--frobnicate"], dfiles))
    out.append(("--version", ["--version"], {}))
    out.append(("evaluate --help", ["evaluate", "--help"], {}))
    out.append(("non-UTF-8 file name", ["evaluate", "d\udcff.yaml"], {}))
    out.append(("10^5-character file name", ["evaluate", "x" * 100_000 + ".yaml"], {}))
    out.append(("--json - twice", ["evaluate", D, "--json", "-", "--json", "-"], dfiles))
    return out


FLAG_CASES = _flag_cases()


def flags_case(ch) -> Case:
    desc, argv, files = ch.choice(FLAG_CASES)
    return Case("flags", desc, list(argv), dict(files))


def fifo_case() -> Case:
    """A named pipe nobody writes to, given as a design: reading it blocks (a possible hang)."""
    return Case(
        "flags",
        "design is a named pipe (FIFO) nobody writes",
        ["evaluate", "fifo.yaml"],
        {},
        special="fifo:fifo.yaml",
    )


def _zero_column(data: bytes, column: str) -> bytes:
    """A CSV (time record or table) with every cell of ``column`` set to 0."""
    out, j = [], None
    for line in data.decode("utf-8").splitlines():
        if line.startswith("#") or not line.strip():
            out.append(line)
        elif j is None:
            j = next(i for i, h in enumerate(line.split(",")) if h.strip().startswith(column))
            out.append(line)
        else:
            cells = line.split(",")
            cells[j] = "0"
            out.append(",".join(cells))
    return ("\n".join(out) + "\n").encode()


def _catalog_with(table: str, cell: str) -> bytes:
    rows = read_csv_rows((CATALOGS / f"{table}.csv").read_bytes())
    row = list(rows[1])
    row[rows[0].index("id")] = cell
    return write_csv_rows([rows[0], row])


def _hardening_cases() -> list:
    """One case per class of issue 24 ("Hardening, second round"): output paths that are FIFOs, '-'
    or /dev/stdout; inputs that are FIFOs, devices, oversized; a time record without force; a duty
    cycle faster than the axis; multi-line values; silent acceptances; CSV cells that are
    formulas."""
    D, P, S, C = "d.yaml", "p.yaml", "s.yaml", "data.csv"
    dfiles = {D: shipped("vmc_x_design.yaml")}
    pfiles = {P: shipped("teaching_problem.yaml")}
    tx = {C: shipped(DATA_CSV), "t.yaml": shipped(DATA_DESIGN)}
    est, val = shipped("data/table_x_run_est.csv"), shipped("data/table_x_run_val.csv")
    runs = {"est.csv": est, "val.csv": val, "t.yaml": shipped(DATA_DESIGN)}
    st = _tiny_sweep(
        yaml.safe_load(shipped("studies/teaching_random.yaml")), "teaching_random.yaml", True
    )
    sfiles = {S: dump_yaml(st)}
    quiet_study = ["--workers", "0", "--quiet"]
    teach = shipped("teaching_problem.yaml")
    vmc = shipped("vmc_x_design.yaml")
    fast_move = vmc.replace(
        b"  table_length: 600 mm\n",
        b"  table_length: 600 mm\n  duty_cycle:\n"
        b"    - {move: 300 mm, speed: 60 m/min}\n    - {move: -300 mm}\n",
    )
    hard_move = vmc.replace(
        b"  table_length: 600 mm\n",
        b"  table_length: 600 mm\n  duty_cycle:\n"
        b"    - {move: 300 mm, acceleration: 8 m/s^2}\n    - {move: -300 mm}\n",
    )
    no_acc = (
        b"\n".join(ln for ln in teach.splitlines() if not ln.strip().startswith(b"acceleration:"))
        + b"\n"
    )
    rows = shipped(DATA_CSV).decode().splitlines()
    rows[5] = rows[5].replace(",", ',"', 1)
    stray = ("\n".join(rows) + "\n").encode()
    head, body = rows[0], [r for r in rows[1:] if r and not r.startswith("#")]
    many = ("\n".join([head] + body * (50_001 // len(body) + 1)) + "\n").encode()
    together = (
        b"name: together\nbase: p.yaml\ncombine: product\nsweep:\n"
        b"  continuous.nut_preload.min: [100 N, 5 kN]\n  continuous.nut_preload.max: [1 kN, 10 "
        b"kN]\n"
    )
    cases = [
        # 1. outputs: FIFOs (a reader drains them), '-', /dev/stdout
        Case(
            "hardening",
            "parts --csv to a FIFO",
            ["parts", "screws", "--csv", "o.fifo"],
            {},
            special="drain:o.fifo",
        ),
        Case(
            "hardening",
            "parts --json to a FIFO",
            ["parts", "--json", "o.fifo"],
            {},
            special="drain:o.fifo",
        ),
        Case(
            "hardening",
            "schema --out to a FIFO",
            ["schema", "design", "--out", "o.fifo"],
            {},
            special="drain:o.fifo",
        ),
        Case(
            "hardening",
            "evaluate --json to a FIFO",
            ["evaluate", D, "--json", "o.fifo"],
            dfiles,
            special="drain:o.fifo",
        ),
        Case(
            "hardening",
            "compare --csv to a FIFO",
            ["compare", D, D, "--csv", "o.fifo"],
            dfiles,
            special="drain:o.fifo",
        ),
        Case("hardening", "parts --csv -", ["parts", "screws", "--csv", "-"], {}),
        Case(
            "hardening", "parts --json /dev/stdout", ["parts", "nuts", "--json", "/dev/stdout"], {}
        ),
        Case("hardening", "schema --out -", ["schema", "problem", "--out", "-"], {}),
        Case(
            "hardening",
            "compare --csv - --json -",
            ["compare", D, D, "--csv", "-", "--json", "-"],
            dfiles,
        ),
        Case("hardening", "evaluate --plot -", ["evaluate", D, "--plot", "-"], dfiles),
        Case(
            "hardening",
            "solve --save-design -",
            ["solve", P, "--no-sensitivity", "--save-design", "-"],
            pfiles,
        ),
        Case("hardening", "study --out -", ["study", S, "--out", "-", *quiet_study], sfiles),
        Case(
            "hardening",
            "solve --save-design ''",
            ["solve", P, "--no-sensitivity", "--save-design", ""],
            pfiles,
        ),
        Case("hardening", "schema --out ''", ["schema", "design", "--out", ""], {}),
        # 2. inputs that are not regular files, or too large
        Case(
            "hardening",
            "diagnose data is a FIFO nobody writes",
            ["diagnose", "f.csv", "--design", "t.yaml"],
            tx,
            special="fifo:f.csv",
        ),
        Case(
            "hardening",
            "diagnose validation run is a FIFO",
            ["diagnose", "est.csv", "v.csv", "--design", "t.yaml"],
            runs,
            special="fifo:v.csv",
        ),
        Case(
            "hardening", "diagnose /dev/zero", ["diagnose", "/dev/zero", "--design", "t.yaml"], tx
        ),
        Case(
            "hardening",
            "catalog CSV is a FIFO",
            ["parts", "--catalogs", "cat"],
            {},
            special="fifo:cat/screws.csv",
        ),
        Case(
            "hardening",
            "calibration is a FIFO",
            ["evaluate", D, "--calibration", "c.yaml"],
            dfiles,
            special="fifo:c.yaml",
        ),
        Case(
            "hardening",
            "study base is a FIFO",
            ["study", S, "--out", "out", *quiet_study],
            {S: b"name: f\nbase: b.yaml\nsweep:\n  axis.stroke: [300 mm]\n"},
            special="fifo:b.yaml",
        ),
        Case(
            "hardening",
            "diagnose CSV with too many rows",
            ["diagnose", "m.csv", "--design", "t.yaml"],
            {"m.csv": many, "t.yaml": shipped(DATA_DESIGN)},
        ),
        # 3. a time record with all-zero force
        Case(
            "hardening",
            "time record with zero force (estimation)",
            ["diagnose", "z.csv", "val.csv", "--design", "t.yaml"],
            {**runs, "z.csv": _zero_column(est, "force")},
        ),
        Case(
            "hardening",
            "time record with zero force (validation)",
            ["diagnose", "est.csv", "z.csv", "--design", "t.yaml", "--json", "-"],
            {**runs, "z.csv": _zero_column(val, "force")},
        ),
        Case(
            "hardening",
            "time record with constant position",
            ["diagnose", "z.csv", "--design", "t.yaml"],
            {**runs, "z.csv": _zero_column(est, "position")},
        ),
        # 4. the motion commanded
        Case(
            "hardening",
            "duty-cycle move faster than max_speed",
            ["evaluate", D, "--json", "-"],
            {D: fast_move},
        ),
        Case(
            "hardening",
            "duty-cycle move harder than axis.acceleration",
            ["evaluate", D, "--json", "-"],
            {D: hard_move},
        ),
        Case(
            "hardening",
            "drive search without acceleration",
            ["solve", P, "--no-sensitivity"],
            {P: no_acc},
        ),
        # 5. errors that were not one line
        Case(
            "hardening",
            "YAML value with a newline",
            ["evaluate", D],
            {D: vmc.replace(b"  stroke: 800 mm", b'  stroke: "800\\nkg\\n"')},
        ),
        Case(
            "hardening",
            "stray quote in a diagnose CSV",
            ["diagnose", "q.csv", "--design", "t.yaml"],
            {"q.csv": stray, "t.yaml": shipped(DATA_DESIGN)},
        ),
        Case(
            "hardening",
            "study --scheduler ''",
            ["study", S, "--out", "out", "--scheduler", ""],
            sfiles,
        ),
        Case(
            "hardening",
            "value that is a list of quantities",
            ["evaluate", D],
            {D: vmc.replace(b"  stroke: 800 mm", b"  stroke: [300 mm, 400 mm]")},
        ),
        # 6. studies
        Case(
            "hardening",
            "sweep invalid only together (product)",
            ["study", S, "--out", "out", *quiet_study],
            {S: together, P: teach},
        ),
        Case(
            "hardening",
            "study --report into a missing directory",
            ["study", S, "--out", "out", *quiet_study, "--report", "no/dir/r.html"],
            sfiles,
        ),
        # 7. silent acceptances
        Case(
            "hardening",
            "require with an empty list",
            ["solve", P, "--no-sensitivity"],
            {P: teach.replace(b"require: {coupling: [", b"require: {screw: [], coupling: [")},
        ),
        Case(
            "hardening",
            "YAML tag on a mapping",
            ["evaluate", D],
            {D: vmc.replace(b"axis:\n", b"axis: !custom\n")},
        ),
        Case(
            "hardening",
            "!!omap axis",
            ["evaluate", D],
            {D: b"name: x\naxis: !!omap\n  - stroke: 800 mm\nparts: {}\n"},
        ),
        Case(
            "hardening",
            "problem file name with a newline, --save-design",
            ["solve", "p\nmotor: X\n.yaml", "--no-sensitivity", "--save-design", "best.yaml"],
            {"p\nmotor: X\n.yaml": teach},
        ),
        # 8. CSV cells that are formulas
        Case(
            "hardening",
            "user catalog id that is a formula, parts --csv",
            ["parts", "couplings", "--catalogs", "cat", "--csv", "c.csv"],
            {"cat/couplings.csv": _catalog_with("couplings", '=HYPERLINK("http://x")')},
        ),
    ]
    return cases


HARDENING_CASES = _hardening_cases()


def hardening_case(ch) -> Case:
    c = ch.choice(HARDENING_CASES)
    return Case(c.kind, c.mutation, list(c.argv), dict(c.files), c.dirs, c.special)


MAKERS = {
    "design": design_case,
    "problem": problem_case,
    "study": study_case,
    "calibration": calibration_case,
    "data": data_case,
    "catalog": catalog_case,
    "flags": flags_case,
    "compare": compare_case,
    "hardening": hardening_case,
}


def make_case(ch, kind: str | None = None, fast: bool = True) -> Case:
    kind = kind or ch.choice(KINDS)
    if kind == "problem" and not fast:
        return problem_case(ch, ALL_PROBLEMS)
    if kind == "study":
        return study_case(
            ch,
            STUDIES
            if not fast
            else ("teaching_random.yaml", "vmc_stroke_mounting.yaml", "gantry_weights.yaml"),
            fast=fast,
        )
    return MAKERS[kind](ch)


# --------------------------------------------------------------------------------------------------
# ------------
# the contract

OUTCOMES = (
    "ok",
    "negative",
    "clean error",
    "multi-line error",
    "traceback",
    "hang",
    "bad output",
    "crash",
    "silent negative",
    "warning",
)
BAD = ("multi-line error", "traceback", "hang", "bad output", "crash", "silent negative", "warning")
# leaf keys of a --json output that must not be negative (the path decides), and the signed ones
# (the last key)
_NON_NEGATIVE = re.compile(
    r"(mass|stiffness|N_per_um|length|stroke|frequency|_Hz|^cost$|price|position|inertia|"
    r"preload|rigidity|life|noise_floor|rms|drag_torque|friction)",
    re.I,
)
_SIGNED = re.compile(
    r"(dBIC|gain|delta|change|residual|displacement|margin|value|offset|thermal|objective|eta|"
    r"phase|real|imag|direction|acceleration|axial_load)",
    re.I,
)


def _bad_const(name):
    raise ValueError(f"JSON contains {name}")


def json_problems(text: str) -> list[str]:
    """What is wrong with a --json output: not JSON, NaN/Infinity, a negative physical quantity."""
    try:
        obj = json.loads(text, parse_constant=_bad_const)
    except ValueError as exc:
        return [f"not valid finite JSON ({str(exc)[:120]})"]
    bad: list[str] = []

    def walk(o, key, path):
        if len(bad) > 3:
            return
        if isinstance(o, dict):
            for k, v in o.items():
                walk(v, str(k), f"{path}.{k}")
        elif isinstance(o, list):
            for i, v in enumerate(o):
                walk(v, key, f"{path}[{i}]")
        elif isinstance(o, float) and not math.isfinite(o):
            bad.append(f"{path} = {o}")
        elif isinstance(o, (int, float)) and not isinstance(o, bool) and o < 0:
            if _NON_NEGATIVE.search(path) and not _SIGNED.search(key):
                bad.append(f"{path} = {o} (negative)")

    walk(obj, "", "")  # the path decides what must not be negative, its last key what may be
    return bad


@dataclass
class Outcome:
    rc: int | None  # None: timed out
    stdout: str
    stderr: str
    seconds: float
    json_files: dict = field(default_factory=dict)  # name -> text of JSON files written
    drained: dict = field(default_factory=dict)  # FIFO output path -> what its reader received


# a value far outside machine-tool practice (axisopt.design.plausible): used and said in one line
# naming the file, line and key: part of the contract, not a stray warning
PLAUSIBILITY = re.compile(
    r"^warning: .*key '[^']+': .* is far (below|above) machine-tool practice \(.*\): check "
    r"the value and its unit$"
)


def classify(case: Case, out: Outcome) -> tuple[str, str]:
    """(outcome class, detail) of one run against the CLI contract (the plausibility warnings set
    aside)."""
    err = "".join(
        ln for ln in out.stderr.splitlines(keepends=True) if not PLAUSIBILITY.match(ln.rstrip("\n"))
    )
    lines = [ln for ln in err.splitlines() if ln.strip()]
    if out.rc is None:
        return "hang", f"no exit within {out.seconds:.0f} s"
    if "Traceback (most recent call last)" in err:
        tail = [ln for ln in lines if not ln.startswith(" ")]
        return "traceback", (tail[-1] if tail else lines[-1])[:300]
    if out.rc not in (0, 1, 2, 3):
        return "crash", f"exit code {out.rc}; " + " | ".join(lines[-3:])[:300]
    if out.rc == 2:
        if (
            len(lines) == 1
            and lines[0].startswith("error: ")
            and len(err.strip().splitlines()) == 1
        ):
            return "clean error", lines[0][:300]
        return "multi-line error", f"{len(err.splitlines())} stderr lines: " + " | ".join(
            lines[:4]
        )[:300]
    if out.rc in (1, 3):  # 1 proven negative, 3 unproven (Bonmin, a time limit): both must explain
        if not (out.stdout.strip() or err.strip()):
            return "silent negative", f"exit {out.rc} with no output"
        return "negative", (lines[-1] if lines else out.stdout.strip().splitlines()[-1])[:300]
    # exit 0
    if any(w in err for w in ("Warning", "warning:")):
        return "warning", " | ".join(lines[:3])[:300]
    problems = []
    if "--json" in case.argv:
        i = case.argv.index("--json")
        target = case.argv[i + 1] if i + 1 < len(case.argv) else None
        if target == "-":
            problems += json_problems(out.stdout)
        elif target in out.json_files:
            problems += json_problems(out.json_files[target])
    for name, text in out.drained.items():
        if not text.strip():
            problems.append(f"exit 0 but nothing arrived at the FIFO {name}")
    for name, text in out.json_files.items():
        if name.startswith("out/"):
            problems += [f"{name}: {p}" for p in json_problems(text)]
    shown = _without_echoed_names(case, out.stdout)
    m = NAN_TEXT.search(shown) if "--json" not in case.argv or _json_target(case) != "-" else None
    if m:
        line = next(ln for ln in shown.splitlines() if NAN_TEXT.search(ln))
        problems.append(f"text output shows {m.group(0).strip()!r}: {line.strip()[:150]}")
    if problems:
        return "bad output", "; ".join(problems[:3])[:300]
    return "ok", ""


_ECHOED = re.compile(r"^\s*(name|description):\s*(.+?)\s*$", re.M)


def _without_echoed_names(case: Case, text: str) -> str:
    """``text`` without the free-text names and descriptions of the case's own files (a study named
    'nan mm' is echoed as given: that is the user's text, not a computed NaN)."""
    for data in case.files.values():
        try:
            src = data.decode("utf-8")
        except (UnicodeDecodeError, AttributeError):
            continue
        for m in _ECHOED.finditer(src):
            name = m.group(2).strip("'\"")
            if name and NAN_TEXT.search(name):
                text = text.replace(name, "<name>")
    return text


NAN_TEXT = re.compile(r"(?<![A-Za-z_])([-+]?nan|[-+]?inf|[-+]?infinity)(?![A-Za-z_])", re.I)


def _json_target(case: Case):
    i = case.argv.index("--json")
    return case.argv[i + 1] if i + 1 < len(case.argv) else None


def collect_json_files(case: Case, workdir: Path) -> dict:
    """JSON files a run wrote: its --json target and the study's case files."""
    out = {}
    if "--json" in case.argv:
        i = case.argv.index("--json")
        if (
            i + 1 < len(case.argv)
            and case.argv[i + 1] != "-"
            and not case.argv[i + 1].startswith("/dev/")
        ):
            p = workdir / case.argv[i + 1]
            if p.is_file():
                out[case.argv[i + 1]] = p.read_text(errors="replace")
    cases = workdir / "out" / "cases"
    if cases.is_dir():
        for p in sorted(cases.glob("*.json"))[:20]:
            out[f"out/cases/{p.name}"] = p.read_text(errors="replace")
    return out


# --------------------------------------------------------------------------------------------------
# ------------
# runners


# address space per case: a runaway allocation is a MemoryError, not a dead machine
MEMORY_LIMIT = 6 * 2**30


def _limit_memory(extra: int = 0) -> None:
    import resource

    try:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT + extra, MEMORY_LIMIT + extra))
    except (ValueError, OSError):
        pass


def _vm_size() -> int:
    try:
        return int(Path("/proc/self/statm").read_text().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError):
        return 0


def run_subprocess(
    case: Case, workdir: Path, timeout: float = 60.0, python=sys.executable
) -> Outcome:
    """``python -m axisopt ...`` in ``workdir`` with a time limit (the whole process group is
    killed) and an address-space limit of ``MEMORY_LIMIT``."""
    case.materialize(workdir)
    env = dict(os.environ, PYTHONPATH=str(ROOT), MPLBACKEND="Agg", PYTHONUNBUFFERED="1")
    t0 = time.perf_counter()
    argv = [python, "-m", "axisopt", *case.argv]
    try:
        p = subprocess.Popen(
            argv,
            cwd=workdir,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            stdin=subprocess.DEVNULL,
            env=env,
            start_new_session=True,
            preexec_fn=_limit_memory,
        )
    except (ValueError, OSError) as exc:  # e.g. a NUL in an argument: the OS cannot pass it
        return Outcome(2, "", f"error: cannot start: {exc}", 0.0)
    try:
        so, se = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        so, se = p.communicate()
        rc = None
    dt = time.perf_counter() - t0
    out = Outcome(rc, so.decode("utf-8", "replace"), se.decode("utf-8", "replace"), dt)
    out.json_files = collect_json_files(case, workdir)
    out.drained = {rel: data.decode("utf-8", "replace") for rel, data in case.release().items()}
    if "--json" in case.argv and _json_target(case) in out.drained:
        out.json_files[_json_target(case)] = out.drained[_json_target(case)]
    return out


_DEFAULT_WARNINGS = (
    ("ignore", DeprecationWarning),
    ("ignore", PendingDeprecationWarning),
    ("ignore", ImportWarning),
    ("ignore", ResourceWarning),
)


def _child(argv, out_path, err_path):  # pragma: no cover - runs in the forked child
    import warnings

    rc = 70
    try:
        fo = os.open(out_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
        fe = os.open(err_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
        os.dup2(fo, 1)
        os.dup2(fe, 2)
        sys.stdout = open(1, "w", encoding="utf-8", errors="surrogateescape", closefd=False)
        sys.stderr = open(2, "w", encoding="utf-8", errors="backslashreplace", closefd=False)
        sys.stdin = open(os.devnull)
        _limit_memory(_vm_size())
        warnings.resetwarnings()  # the CLI's defaults, not pytest's "error"
        for action, cat in _DEFAULT_WARNINGS:
            warnings.simplefilter(action, cat)
        from axisopt.cli import main

        try:
            rc = main(argv)
            rc = 0 if rc is None else int(rc)
        except SystemExit as exc:
            code = exc.code
            if code is None:
                rc = 0
            elif isinstance(code, int):
                rc = code
            else:
                print(code, file=sys.stderr)
                rc = 1
        except BaseException:  # what the interpreter does with an uncaught exception
            traceback.print_exc()
            rc = 1
    finally:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        except Exception:  # noqa: BLE001
            pass
        os._exit(rc)


def run_forked(case: Case, workdir: Path, timeout: float = 20.0) -> Outcome:
    """``axisopt.cli.main(argv)`` in a forked copy of this process (the imports and caches are warm,
    so a case costs milliseconds, and a hang is killed after ``timeout`` seconds without stopping
    the caller)."""
    case.materialize(workdir)
    out_p, err_p = workdir / ".stdout", workdir / ".stderr"
    t0 = time.perf_counter()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:  # pragma: no cover
        try:
            os.chdir(workdir)
            _child(case.argv, str(out_p), str(err_p))
        finally:
            os._exit(70)
    rc = None
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            rc = os.waitstatus_to_exitcode(status)
            break
        if time.perf_counter() - t0 > timeout:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            break
        time.sleep(0.005)
    dt = time.perf_counter() - t0
    read = lambda p: p.read_bytes().decode("utf-8", "replace") if p.exists() else ""  # noqa: E731
    out = Outcome(rc, read(out_p), read(err_p), dt)
    out.json_files = collect_json_files(case, workdir)
    return out
