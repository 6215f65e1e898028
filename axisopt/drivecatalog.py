"""The drive-type catalogs: rack-and-pinion sets (``racks.csv``) and linear motors
(``linear_motors.csv``).

Headers carry vendor units (``permissible_force [kN]``); rows come back as dicts in SI, text columns
as strings, an empty optional cell as ``None``.  Every bad cell (a pinion with zero teeth, a NaN
force constant, an unknown unit, a missing required value) is an :class:`~axisopt.errors.InputError`
naming the file, line and column.  The shipped directory is read first; a user's catalog directories
add rows (an id already known is an error).  ``pitch_error`` is the rack's cumulative pitch error
per 1000 mm of rack.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path

from .errors import InputError
from .units import split_header, unit_factor

SHIPPED_DIR = Path(__file__).resolve().parent.parent / "catalogs"
MAX_BYTES = 2_000_000

# column -> (unit kind, fixed unit or None, required); every number is finite and positive unless
# noted
RACK_COLUMNS = {
    "kind": ("text", None, True),
    "quality": ("count", None, True),
    "module": ("length", None, True),
    "teeth": ("count", None, True),
    "helix_angle": ("angle", None, True),  # may be 0 (spur)
    "pitch_diameter": ("length", None, True),
    "face_width": ("length", None, True),
    "permissible_force": ("force", None, True),
    "pitch_error": ("length", None, True),
    "pinion_price": ("money", None, True),
    "rack_price_per_length": ("money_per_length", None, True),
    "rack_mass_per_length": ("mass_per_length", None, True),
}
LM_COLUMNS = {
    "kind": ("text", None, True),
    "continuous_force": ("force", None, True),
    "peak_force": ("force", None, True),
    "force_constant": ("ratio", "N/A", False),
    "continuous_current": ("ratio", "A", False),
    "peak_current": ("ratio", "A", False),
    "forcer_mass": ("mass", None, True),
    "attraction_force": ("force", None, False),  # may be 0 (ironless); empty: the estimate
    "accuracy": ("length", None, True),
    "forcer_price": ("money", None, True),
    "track_price_per_length": ("money_per_length", None, True),
}
KINDS = {"racks": ("spur", "helical"), "linear_motors": ("iron-core", "ironless")}
ZERO_OK = {"helix_angle", "attraction_force"}
# an iron-core motor's magnetic attraction where the data sheet gives none: ATTRACTION_PER_FC x its
# continuous force -- an estimate of ours (no reachable vendor row lists it, catalogs/SOURCES.md)
ATTRACTION_PER_FC = 5.0


@dataclass(frozen=True)
class DriveTables:
    racks: tuple  # rows (dicts, SI)
    linear_motors: tuple


def _number(text: str, name: str, kind: str, fixed, unit, where, source) -> float:
    try:
        v = float(text)
    except ValueError:
        raise InputError(
            f"column '{name}': '{text}' is not a number", source=source, where=where
        ) from None
    if not math.isfinite(v):
        raise InputError(
            f"column '{name}': {text} is not a finite number", source=source, where=where
        )
    if v < 0 or (v == 0 and name not in ZERO_OK):
        raise InputError(f"column '{name}': {text} must be positive", source=source, where=where)
    if kind == "count":
        if v != int(v):
            raise InputError(
                f"column '{name}': {text} must be a whole number", source=source, where=where
            )
        return v
    if fixed is not None:
        if unit != fixed:
            raise InputError(
                f"column '{name}' must be in [{fixed}], got [{unit}]", source=source, where=where
            )
        return v
    return v * unit_factor(unit, kind)


def read_table(path: Path, table: str) -> list:
    """The rows of one drive-type CSV in SI (see the module)."""
    spec = RACK_COLUMNS if table == "racks" else LM_COLUMNS
    source = str(path)
    if path.stat().st_size > MAX_BYTES:
        raise InputError(f"larger than {MAX_BYTES} bytes", source=source)
    reader = csv.reader(io.StringIO(path.read_text(encoding="utf-8")))
    header = next(reader, None)
    if not header:
        raise InputError("empty file", source=source)
    cols = [split_header(h) for h in header]
    names = [c[0] for c in cols]
    for name, (kind, _fixed, required) in spec.items():
        if name not in names and required:
            raise InputError(f"missing column '{name}'", source=source, where="line 1")
        if name in names:
            unit = cols[names.index(name)][1]
            if kind not in ("text", "count") and unit is None:
                raise InputError(
                    f"column '{name}' needs a unit in brackets", source=source, where="line 1"
                )
            if kind not in ("text", "count", "ratio"):
                try:
                    unit_factor(unit, kind)
                except ValueError as e:
                    raise InputError(
                        f"column '{name}': {e}", source=source, where="line 1"
                    ) from None
    if "id" not in names:
        raise InputError("missing column 'id'", source=source, where="line 1")
    rows = []
    for line, cells in enumerate(reader, start=2):
        if not any(c.strip() for c in cells):
            continue
        if len(cells) != len(names):
            raise InputError(
                f"{len(cells)} cells, the header has {len(names)}",
                source=source,
                where=f"line {line}",
            )
        raw = dict(zip(names, (c.strip() for c in cells)))
        row = {
            "id": raw["id"],
            "vendor": raw.get("vendor", ""),
            "series": raw.get("series", ""),
            "status": raw.get("status", ""),
            "source": raw.get("source", ""),
            "estimated": [],
        }
        if not row["id"]:
            raise InputError("empty id", source=source, where=f"line {line}")
        for name, (kind, fixed, required) in spec.items():
            where = f"line {line}, column {name}"
            text = raw.get(name, "")
            if kind == "text":
                if text not in KINDS[table]:
                    raise InputError(
                        f"column '{name}': '{text}' is not one of {', '.join(KINDS[table])}",
                        source=source,
                        where=where,
                    )
                row[name] = text
                continue
            if text == "":
                if required:
                    raise InputError(f"column '{name}' is empty", source=source, where=where)
                row[name] = None
                continue
            unit = cols[names.index(name)][1]
            row[name] = _number(text, name, kind, fixed, unit, where, source)
        if table == "linear_motors":
            if row["attraction_force"] is None:
                iron = row["kind"] == "iron-core"
                row["attraction_force"] = (
                    ATTRACTION_PER_FC * row["continuous_force"] if iron else 0.0
                )
                if iron:
                    row["estimated"].append("attraction_force")
            if row["peak_force"] < row["continuous_force"]:
                raise InputError(
                    "peak_force below continuous_force", source=source, where=f"line {line}"
                )
        else:
            if row["teeth"] < 6:
                raise InputError(
                    f"column 'teeth': a pinion needs at least 6 teeth, got {row['teeth']:g}",
                    source=source,
                    where=f"line {line}, column teeth",
                )
        rows.append(row)
    return rows


def load_drive_tables(extra_dirs=(), *, shipped: bool = True) -> DriveTables:
    """Racks and linear motors of the shipped catalogs and ``extra_dirs`` (each file optional)."""
    out = {"racks": [], "linear_motors": []}
    dirs = ([SHIPPED_DIR] if shipped else []) + [Path(d) for d in extra_dirs]
    for d in dirs:
        for table in out:
            path = d / f"{table}.csv"
            if not path.is_file():
                continue
            rows = read_table(path, table)
            known = {r["id"] for r in out[table]}
            for r in rows:
                if r["id"] in known:
                    raise InputError(f"{table} id '{r['id']}' is listed twice", source=str(path))
                known.add(r["id"])
            out[table].extend(rows)
    return DriveTables(tuple(out["racks"]), tuple(out["linear_motors"]))


_CACHE: dict = {}


def default_drive_tables(extra_dirs=()) -> DriveTables:
    """Cached :func:`load_drive_tables`, keyed by the directories and the contents of the files read
    (an edited file is read again)."""
    from .catalog.loading import files_state

    dirs = [Path(d).resolve() for d in extra_dirs]
    key = (tuple(map(str, dirs)), files_state([SHIPPED_DIR, *dirs], ("racks", "linear_motors")))
    if key not in _CACHE:
        if len(_CACHE) > 16:
            _CACHE.clear()
        _CACHE[key] = load_drive_tables(extra_dirs)
    return _CACHE[key]
