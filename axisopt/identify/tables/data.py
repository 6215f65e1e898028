"""Measured-data formats: read a test CSV (units in headers) into SI arrays, strictly.

Four test types, told apart by their columns (units in brackets; any unit of the same quantity):

* static stiffness  : ``position [mm]``, ``force [N]``, ``displacement [um]``; optional ``direction``
  (+1/-1, direction of motion while the reading was taken), ``cycle``, ``time [s]``, ``temperature [degC]``
* natural frequency : ``position [mm]``, ``frequency [Hz]``; optional ``mode``
* friction          : ``velocity [mm/s]`` (signed) and ``friction_force [N]`` or ``drag_torque [N.m]``;
  optional ``normal_load [N]``, ``axial_load [N]``, ``position [mm]``, ``cycle``
* frequency response: ``frequency [Hz]``, ``position [mm]`` and ``real [um/N]`` + ``imag [um/N]`` or
  ``magnitude [um/N]`` + ``phase [deg]``

Every file may also carry ``exclude`` (0/1): rows marked 1 are left out of the fit and listed in the
report.  ``position`` is the table coordinate along the stroke, 0 at the stroke start (the nut is
then ``start_offset`` from the fixed bearing).  A missing column, an unknown column or unit, a
non-numeric, empty or NaN cell is an :class:`InputError` naming the file, line and column.
"""  # noqa: E501

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ...errors import InputError
from ...fileio import MAX_DATA_ROWS, read_input
from ...units import check_plausible, check_width, read_header, read_number, to_si, unit_factor
from ...yamlio import close_matches

# column -> quantity kind (None: a plain number without unit)
COLUMNS = {
    "position": "length",
    "force": "force",
    "displacement": "length",
    "direction": None,
    "cycle": None,
    "time": "time",
    "temperature": "temperature",
    "frequency": "frequency",
    "mode": None,
    "velocity": "speed",
    "friction_force": "force",
    "drag_torque": "torque",
    "normal_load": "force",
    "axial_load": "force",
    "real": "compliance",
    "imag": "compliance",
    "magnitude": "compliance",
    "phase": "angle",
    "exclude": None,
}

KINDS = {
    "stiffness": dict(
        required=("position", "force", "displacement"),
        optional=("direction", "cycle", "time", "temperature"),
    ),
    "frf": dict(
        required=("frequency", "position"), optional=("real", "imag", "magnitude", "phase", "cycle")
    ),
    "frequency": dict(required=("position", "frequency"), optional=("mode", "cycle")),
    "friction": dict(
        required=("velocity",),
        optional=(
            "friction_force",
            "drag_torque",
            "normal_load",
            "axial_load",
            "position",
            "cycle",
            "time",
            "temperature",
        ),
    ),
}
KIND_LABELS = {
    "stiffness": "static stiffness test",
    "frequency": "natural-frequency test",
    "friction": "friction test",
    "frf": "frequency-response test",
}
# display units for reports (name -> (unit, factor SI->unit))
DISPLAY = {
    "position": ("mm", 1e3),
    "force": ("N", 1.0),
    "displacement": ("um", 1e6),
    "direction": ("", 1.0),
    "cycle": ("", 1.0),
    "time": ("s", 1.0),
    "temperature": ("K", 1.0),
    "frequency": ("Hz", 1.0),
    "mode": ("", 1.0),
    "velocity": ("mm/s", 1e3),
    "friction_force": ("N", 1.0),
    "normal_load": ("N", 1.0),
    "axial_load": ("N", 1.0),
    "compliance": ("um/N", 1e6),
}


@dataclass
class Dataset:
    """One measured test in SI.  ``columns`` holds only kept rows; ``excluded`` lists (line,
    reason)."""

    kind: str
    source: str
    columns: dict
    lines: np.ndarray
    excluded: list = field(default_factory=list)

    @property
    def n(self) -> int:
        return len(self.lines)

    def has(self, name: str, varying: bool = False) -> bool:
        if name not in self.columns:
            return False
        return not varying or np.ptp(self.columns[name]) > 0

    @property
    def label(self) -> str:
        return f"{KIND_LABELS[self.kind]} ({Path(self.source).name})"


def detect_kind(names, source: str) -> str:
    s = set(names)
    if "displacement" in s or "force" in s:
        return "stiffness"
    if "velocity" in s or "friction_force" in s or "drag_torque" in s:
        return "friction"
    if s & {"real", "imag", "magnitude", "phase"}:
        return "frf"
    if "frequency" in s:
        return "frequency"
    raise InputError(
        "cannot tell the test type from the header: expected displacement (static stiffness), "
        "frequency (natural frequency / FRF) or velocity (friction) columns",
        source=source,
        where="line 1",
    )


def read_dataset(path) -> Dataset:
    """Read one test CSV.  See the module docstring for the formats."""
    src = str(path)
    try:
        # regular files only, size cap
        text = read_input(path, "data", what="data file", encoding="utf-8-sig")
        with io.StringIO(text, newline="") as fh:
            reader = csv.reader(fh)
            try:
                rows = []
                for r in reader:
                    rows.append(r)
                    if len(rows) > MAX_DATA_ROWS + 100:  # header and comments besides the rows
                        raise InputError(
                            f"too many rows (at most {MAX_DATA_ROWS:,} readings)",
                            source=src,
                            where=f"line {reader.line_num}",
                        )
                    if any("\n" in c or "\r" in c for c in r):  # a stray quote swallowed line ends
                        raise InputError(
                            "malformed CSV (a quoted cell runs over several lines: a stray '\"'?)",
                            source=src,
                            where=f"line {reader.line_num}",
                        )
            except csv.Error as exc:
                raise InputError(
                    f"malformed CSV ({exc})", source=src, where=f"line {reader.line_num}"
                ) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(
            f"cannot read data file ({getattr(exc, 'strerror', None) or exc})", source=src
        ) from None
    rows = [
        (i, r)
        for i, r in enumerate(rows, start=1)
        if r and any(c.strip() for c in r) and not r[0].lstrip().startswith("#")
    ]
    if not rows:
        raise InputError("empty data file", source=src)
    hline, header = rows[0]

    def unknown(name):
        near = close_matches(name, list(COLUMNS))
        return f"unknown column '{name}'" + (f"; did you mean '{near[0]}'?" if near else "")

    cols = [
        (c.name, c.unit, c.kind)
        for c in read_header(header, line=hline, source=src, kinds=COLUMNS, unknown=unknown)
    ]
    names = [c[0] for c in cols]
    kind = detect_kind(names, src)
    spec = KINDS[kind]
    missing = [c for c in spec["required"] if c not in names]
    if kind == "friction" and not ({"friction_force", "drag_torque"} & set(names)):
        missing.append("friction_force or drag_torque")
    if kind == "frf" and not (
        {"real", "imag"} <= set(names) or {"magnitude", "phase"} <= set(names)
    ):
        missing.append("real + imag or magnitude + phase")
    if missing:
        raise InputError(
            f"missing column(s) {', '.join(missing)} for a {KIND_LABELS[kind]}",
            source=src,
            where=f"line {hline}",
        )
    allowed = set(spec["required"]) | set(spec["optional"]) | {"exclude"}
    for j, n in enumerate(names, start=1):
        if n not in allowed:
            raise InputError(
                f"column '{n}' does not belong in a {KIND_LABELS[kind]}",
                source=src,
                where=f"line {hline}, column {j}",
            )

    data = np.empty((len(rows) - 1, len(cols)))
    lines = np.empty(len(rows) - 1, dtype=int)
    for r, (i, row) in enumerate(rows[1:]):
        check_width(row, len(cols), source=src, line=i)
        lines[r] = i
        for j, ((name, unit, qkind), cell) in enumerate(zip(cols, row), start=1):
            cell = cell.strip()
            where = f"line {i}, column {j} ({name})"
            val = read_number(cell, source=src, where=where)
            if name == "direction" and val not in (1.0, -1.0):
                raise InputError(
                    f"direction must be +1 or -1, got '{cell}'", source=src, where=where
                )
            if name == "exclude" and val not in (0.0, 1.0):
                raise InputError(f"exclude must be 0 or 1, got '{cell}'", source=src, where=where)
            if name in ("cycle", "mode") and val < 0:
                raise InputError(
                    f"{name} must not be negative, got '{cell}'", source=src, where=where
                )
            if qkind is not None:
                val = check_plausible(
                    to_si(val, unit, qkind), qkind, f"{cell} {unit}", source=src, key=where
                )
            data[r, j - 1] = val
    if len(lines) == 0:
        raise InputError("no data rows", source=src)
    columns = {n: data[:, j] for j, n in enumerate(names)}
    excluded = []
    keep = np.ones(len(lines), dtype=bool)
    if "exclude" in columns:
        keep &= columns.pop("exclude") == 0.0
        excluded += [(int(i), "marked exclude = 1") for i in lines[~keep]]
    if kind == "friction":
        zero = (columns["velocity"] == 0.0) & keep
        excluded += [(int(i), "velocity 0: friction direction undefined") for i in lines[zero]]
        keep &= ~zero
        _check_friction_sign(columns, keep, lines, names, src)
    if kind == "frf":
        if "magnitude" in columns:
            mag, ph = columns.pop("magnitude"), columns.pop("phase")
            columns["real"], columns["imag"] = mag * np.cos(ph), mag * np.sin(ph)
        for c in ("magnitude", "phase"):
            columns.pop(c, None)
        bad = (columns["frequency"] <= 0) & keep
        excluded += [(int(i), "frequency <= 0") for i in lines[bad]]
        keep &= ~bad
    if kind == "frequency":
        bad = columns["frequency"] <= 0
        if bad.any():
            i = int(np.argmax(bad))
            raise InputError(
                "frequency must be positive",
                source=src,
                where=f"line {lines[i]}, column {names.index('frequency') + 1} (frequency)",
            )
    if not keep.any():
        raise InputError("every row is excluded", source=src)
    columns = {k: v[keep] for k, v in columns.items()}
    return Dataset(kind, src, columns, lines[keep], sorted(excluded))


def _check_friction_sign(columns, keep, lines, names, src) -> None:
    """A friction table takes the signed force (or torque) the drive supplies: negative at negative
    velocity.  Magnitudes given with a signed velocity -- positive on both sides and about equal
    there, where a real friction's odd part (its Coulomb level) would be -- would fit a Coulomb
    level of about zero and a spurious
    offset: refused with the convention.  (A vertical axis whose weight exceeds its friction is
    positive on both sides too, but differs between them by twice the friction, and passes.)"""
    meas = "friction_force" if "friction_force" in columns else "drag_torque"
    v, f = columns["velocity"][keep], columns[meas][keep]
    neg, pos = v < 0, v > 0
    if neg.sum() < 2 or pos.sum() < 2:
        return
    if np.mean(f[neg] > 0) < 0.95 or np.mean(f[pos] > 0) < 0.95:
        return
    fp, fn = float(np.median(f[pos])), float(np.median(f[neg]))
    if abs(fp - fn) / 2 >= 0.25 * (fp + fn) / 2:
        return
    i = int(np.nonzero(neg & (f > 0))[0][0])
    raise InputError(
        f"{meas} is positive at negative velocity and about equal in both directions ({fn:.4g} "
        f"against {fp:.4g}): a magnitude? A friction table takes the signed value the drive "
        "supplies, negative at negative velocity (F(|v|) sgn v)",
        source=src,
        where=f"line {lines[keep][i]}, column {names.index(meas) + 1} ({meas})",
    )


def write_dataset(ds: Dataset, path, units: dict | None = None) -> None:
    """Write a dataset as CSV in display units (mm, N, um, ...); used for shipped examples."""
    units = units or {}
    names = list(ds.columns)
    heads, factors = [], []
    for n in names:
        q = COLUMNS[n]
        if q is None:
            heads.append(n)
            factors.append((1.0, 0.0))
            continue
        u = (
            units.get(n)
            or {"compliance": "um/N", "angle": "deg", "temperature": "degC", "torque": "N.m"}.get(q)
            or DISPLAY[n][0]
        )
        heads.append(f"{n} [{u}]")
        factors.append((1.0 / unit_factor(u, q), -273.15 if q == "temperature" else 0.0))
    from ...fileio import atomic_file

    with atomic_file(path, "w", what="data CSV") as fh:
        w = csv.writer(fh)
        w.writerow(heads)
        for r in range(ds.n):
            w.writerow([_fmt(ds.columns[n][r] * f + off) for n, (f, off) in zip(names, factors)])


def _fmt(v: float) -> str:
    return f"{v:.6g}"
