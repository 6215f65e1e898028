"""Time records of a moving axis: strict CSV reader, zero-phase low-pass, cut-off from the data,
differentiation and parallel decimation (the signal processing of IDIM, Gautier's inverse dynamic
identification model; the regression itself is in :mod:`.idim`).

Format (units in the headers, any unit of the quantity)::

    # gain: 0.85 N.m/A            (only with a current column; or the CLI's --gain)
    time [s], position [mm], force [N], reference [mm]

* ``time``: strictly increasing, uniform sampling (a gap of more than 25 % of the median step is
  refused).
* ``position``: table position (length unit), or motor angle (``rad``, ``deg``, ``rev``) turned into
  table travel through the screw lead.  ``reference`` (optional) takes the same kind of unit.
* exactly one effort column: ``force [N]`` (table side), ``torque [N.m]`` (motor side) or
  ``current [A]`` with a gain in ``N.m/A`` (motor torque) or ``N/A`` (table force).
* ``motor_position`` (optional): the motor encoder's position, in a length unit (converted through
  the lead by the drive) or an angle unit, beside a ``position`` measured at the table (a linear
  scale).  The two together measure the lost motion (backlash) and the windup of the transmission
  (:mod:`.idim`).
* ``normal_load [N]`` (optional): a normal load on the guide carriages besides the table's weight (a
  payload, a vertical process force); ``temperature [degC]`` (or K, optional): the axis's
  temperature (nut, guides or lubricant), for the friction laws in temperature
  (:mod:`.effects.load`).
* ``payload [kg]`` (optional): a mass the run carries besides the axis's own, one value through a
  run (a validation run with 350 kg more): taken as known, M a of it is moved to the effort's side,
  so the fitted mass is the axis's own and runs with different payloads share one model.
* ``external_force [N]`` (optional): a process force acting on the table (cutting, a spring, a
  weight), positive in +x.  The drive then supplies f = M a + F(v) - F_ext, so the identification
  fits f + F_ext; for torque records the force is taken to the motor as F_ext p / (2 pi eta) (lead
  p, screw efficiency eta).

The identification keeps the input's quantity: force data is identified in table coordinates (q [m],
M [kg], Fv [N s/m], Fc [N]); torque data in motor coordinates (q [rad], J [kg m^2], Fv [N m s/rad],
Fc [N m]).  At least ``MIN_SAMPLES`` rows; every cell must be a finite number.
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ...errors import InputError
from ...fileio import MAX_TIME_SAMPLES, read_input
from ...units import (
    PLAUSIBLE_MAX,
    check_plausible,
    check_width,
    read_header,
    read_number,
    split_header,
    unit_factor,
)

MIN_SAMPLES = 200
EFFORTS = ("force", "torque", "current")
COLUMNS = (
    ("time", "position", "reference")
    + EFFORTS
    + ("external_force", "motor_position", "normal_load", "temperature", "payload")
)
# angle units spelled as revolutions that the unit library does not know (it knows 'turn')
_REV = {"rev": "turn", "revs": "turn", "revolution": "turn", "revolutions": "turn"}
CURRENT_UNITS = {"A": 1.0, "mA": 1e-3, "kA": 1e3}
_GAIN_LINE = re.compile(r"^\s*#\s*gain\s*:\s*(.+?)\s*$", re.IGNORECASE)
_NUMBER_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.+?)\s*$")
# columns that make a file one of the reduced-table tests of .data, even when it has a time column
_TABLE_COLUMNS = {
    "displacement",
    "velocity",
    "friction_force",
    "drag_torque",
    "frequency",
    "real",
    "magnitude",
}


@dataclass
class TimeRecord:
    """One time record in SI, in the coordinate of its effort (see the module docstring)."""

    source: str
    t: np.ndarray  # [s]
    q: np.ndarray  # table position [m] (quantity 'force') or motor angle [rad] (quantity 'torque')
    effort: np.ndarray  # [N] or [N m]
    quantity: str  # 'force' | 'torque'
    reference: np.ndarray | None
    header: tuple  # column names as read (validation runs must match the estimation run)
    effort_column: str
    lines: np.ndarray
    gain_note: str = ""
    # external force on the table in the effort's coordinate [N] or [N m]
    external: np.ndarray | None = None
    # motor encoder position in the record's coordinate (as ``q``)
    motor_q: np.ndarray | None = None
    # normal_load [N] on the guides, temperature [K]: conditions
    aux: dict = field(default_factory=dict)
    # (start, end) of each window a long record is read in (:func:`.signal.windowed`); () whole
    segments: tuple = ()
    whole: tuple = ()  # a windowed record's (samples, seconds) as read

    def run_note(self) -> str:
        """The run's payload and windows, for the report's line of the run ('' when neither)."""
        out = []
        if "payload" in self.aux:
            out.append(
                f"payload {self.aux['payload'][0]:g} kg"
                + (" (a known mass)" if self.quantity == "force" else " as motor inertia [kg.m^2]")
            )
        if self.segments:
            size = self.segments[0][1] - self.segments[0][0]
            out.append(
                f"{len(self.segments)} windows of {size / self.fs:.3g} s fitted, spread over its "
                f"{self.whole[0]:,} samples ({self.whole[1]:.4g} s)"
            )
        return "; ".join(out)

    @property
    def n(self) -> int:
        return len(self.t)

    @property
    def fs(self) -> float:
        return 1.0 / float(np.median(np.diff(self.t)))

    @property
    def name(self) -> str:
        return Path(self.source).name


def _header_names(path) -> list:
    # the stat comes first (a FIFO or device is refused, never opened); then only the head is read
    text = read_input(path, "time record", what="data file", encoding="utf-8-sig", head=65536)
    try:
        for line in text.splitlines():
            if line.strip() and not line.lstrip().startswith("#"):
                return [split_header(h)[0] for h in next(csv.reader([line]))]
    except csv.Error:
        return []
    return []


def is_time_record(path) -> bool:
    """True if the file's header has a ``time`` column and none of the reduced-table test columns.
    A path that is not a readable regular file within the size cap is an InputError (nothing is
    opened first)."""
    names = set(_header_names(path))
    return "time" in names and not names & _TABLE_COLUMNS


# SI kind of each column, for the range check of every cell (current has no kind: its gain gives it
# one)
_KIND = {
    "time": "time",
    "position": "length",
    "reference": "length",
    "force": "force",
    "torque": "torque",
    "external_force": "force",
    "motor_position": "length",
    "normal_load": "force",
    "temperature": "temperature",
    "payload": "mass",
}


def parse_gain(text: str, *, source=None, where=None) -> tuple:
    """``'0.85 N.m/A'`` -> (0.85, 'torque'); ``'120 N/A'`` -> (120.0, 'force').  SI per ampere."""
    m = _NUMBER_UNIT.match(text or "")
    bad = InputError(
        f"gain '{text}' must be a number with a unit per ampere, e.g. '0.85 N.m/A' or '120 N/A'",
        source=source,
        where=where,
    )
    if not m:
        raise bad
    value, unit = float(m.group(1)), m.group(2).replace(" ", "")
    num, sep, den = unit.rpartition("/")
    if not sep or den not in CURRENT_UNITS or not num:
        raise bad
    for kind in ("torque", "force"):
        try:
            f = unit_factor(num, kind)
        except ValueError:
            continue
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"gain must be positive, got '{text}'", source=source, where=where)
        return value * f / CURRENT_UNITS[den], kind
    raise bad


def read_time_record(
    path, *, lead: float, gain: str | None = None, efficiency: float = 1.0
) -> TimeRecord:
    """Read one time record (see the module docstring).  ``lead`` [m] converts motor angles and
    chooses nothing else; ``gain`` is the CLI's text for current columns (a ``# gain:`` line in the
    file wins); ``efficiency`` takes an external force to the motor side of a torque record."""
    src = str(path)
    raw = read_input(path, "time record", what="data file", encoding="utf-8-sig").splitlines()
    file_gain, gain_line = None, None
    rows = []
    for i, line in enumerate(raw, start=1):
        if not line.strip():
            continue
        if line.lstrip().startswith("#"):
            m = _GAIN_LINE.match(line)
            if m:
                file_gain, gain_line = m.group(1), i
            continue
        rows.append((i, line))
    if not rows:
        raise InputError("empty data file", source=src)
    hline, htext = rows[0]
    try:
        header = next(csv.reader([htext]))
    except csv.Error as exc:
        raise InputError(
            f"malformed CSV header ({exc})", source=src, where=f"line {hline}"
        ) from None
    cols = [
        (c.name, c.unit, c.factor)
        for c in read_header(
            header,
            line=hline,
            source=src,
            kinds={c: _KIND.get(c, "current") for c in COLUMNS},
            unknown=lambda name: (
                f"unknown column '{name}' in a time record; expected {', '.join(COLUMNS)}"
            ),
            factor=lambda name, unit, kind, where: _factor(name, unit, src, where, lead),
        )
    ]
    names = [c[0] for c in cols]
    for need in ("time", "position"):
        if need not in names:
            raise InputError(
                f"missing column '{need}' for a time record", source=src, where=f"line {hline}"
            )
    efforts = [n for n in names if n in EFFORTS]
    if len(efforts) != 1:
        what = "no" if not efforts else f"{len(efforts)} effort columns ({', '.join(efforts)});"
        raise InputError(
            f"{what} a time record needs exactly one of force, torque or current",
            source=src,
            where=f"line {hline}",
        )
    effort_col = efforts[0]
    quantity, note = ("force", "") if effort_col == "force" else ("torque", "")
    gscale = 1.0
    if effort_col == "current":
        if file_gain is not None:
            gscale, quantity = parse_gain(file_gain, source=src, where=f"line {gain_line}")
            note = f"current x gain {file_gain} (line {gain_line})"
        elif gain is not None:
            gscale, quantity = parse_gain(gain, source="--gain")
            note = f"current x gain {gain} (--gain)"
        else:
            raise InputError(
                "current column needs a gain: a line '# gain: 0.85 N.m/A' in the file or --gain",
                source=src,
                where=f"line {hline}, column {names.index('current') + 1}",
            )
    n = len(rows) - 1
    if n > MAX_TIME_SAMPLES:
        raise InputError(f"too many samples ({n:,}; at most {MAX_TIME_SAMPLES:,})", source=src)
    data = _fast_cells(rows[1:], cols, names)
    lines = np.fromiter((i for i, _ in rows[1:]), dtype=int, count=n)
    slow = data is None
    if slow:
        data = np.empty((n, len(cols)))
    # the cell by cell check names the bad cell
    for r, (i, text) in enumerate(rows[1:] if slow else ()):
        cells = text.split(",")
        check_width(cells, len(cols), source=src, line=i)
        lines[r] = i
        for j, cell in enumerate(cells):
            where = f"line {i}, column {j + 1} ({names[j]})"
            val = read_number(cell, source=src, where=where)
            # the tables' range check (data.py): a value no axis can produce is refused
            if names[j] in _KIND:
                check_plausible(
                    val * cols[j][2],
                    _KIND[names[j]],
                    cell.strip(),
                    source=src,
                    key=where,
                    tiny=False,
                )
            data[r, j] = val
    if n < MIN_SAMPLES:
        raise InputError(f"{n} samples; a time record needs at least {MIN_SAMPLES}", source=src)
    col = {c[0]: data[:, j] * c[2] for j, c in enumerate(cols)}
    t = col["time"]
    jt = names.index("time") + 1
    dt = np.diff(t)
    bad = np.nonzero(dt <= 0)[0]
    if len(bad):
        k = bad[0] + 1
        raise InputError(
            f"time {data[k, jt - 1]:g} does not increase (previous {data[k - 1, jt - 1]:g})",
            source=src,
            where=f"line {lines[k]}, column {jt} (time)",
        )
    med = float(np.median(dt))
    gap = np.nonzero(np.abs(dt - med) > 0.25 * med)[0]
    if len(gap):
        k = gap[0] + 1
        raise InputError(
            f"irregular sampling: step {dt[k - 1]:.4g} s against the median {med:.4g} s (the "
            "filters need a uniform rate)",
            source=src,
            where=f"line {lines[k]}, column {jt} (time)",
        )
    # position and reference to the effort's coordinate: table [m] for force, motor angle [rad] for
    # torque
    to_q = 1.0 if quantity == "force" else 2.0 * math.pi / lead
    q = col["position"] * to_q
    ref = col["reference"] * to_q if "reference" in col else None
    effort = col[effort_col] * gscale
    je = names.index(effort_col) + 1
    # no force signal at all: nothing to fit, no error to divide by
    if float(np.ptp(effort)) == 0.0:
        raise InputError(
            f"the {effort_col} column is constant ({data[0, je - 1]:g} throughout): a time record "
            "needs the effort of the moving axis",
            source=src,
            where=f"column {je} ({effort_col})",
        )
    if float(np.ptp(q)) == 0.0:
        jq = names.index("position") + 1
        raise InputError(
            "the position column is constant: the axis does not move in this record",
            source=src,
            where=f"column {jq} (position)",
        )
    motor_q = col["motor_position"] * to_q if "motor_position" in col else None
    if motor_q is not None and float(np.ptp(motor_q)) == 0.0:
        jm = names.index("motor_position") + 1
        raise InputError(
            "the motor_position column is constant: the motor does not move in this record",
            source=src,
            where=f"column {jm} (motor_position)",
        )
    ext = None
    if "external_force" in col:
        ext = col["external_force"] * (
            1.0 if quantity == "force" else lead / (2.0 * math.pi * efficiency)
        )
    aux = {}
    if "normal_load" in col:
        aux["normal"] = col["normal_load"]
    if "payload" in col:  # a known mass the run carries, constant through the run
        aux["payload"] = _payload(col["payload"], data, names, lines, lead, quantity, src)
    if "temperature" in col:  # absolute [K]: the column's unit is a temperature, its offset applied
        aux["temperature"] = col["temperature"] + _KELVIN.get(
            cols[names.index("temperature")][1].strip(), 0.0
        )
    return TimeRecord(
        src, t, q, effort, quantity, ref, tuple(names), effort_col, lines, note, ext, motor_q, aux
    )


_KELVIN = {"degC": 273.15, "C": 273.15, "celsius": 273.15}


def _payload(m: np.ndarray, data, names, lines, lead: float, quantity: str, src: str) -> np.ndarray:
    """The payload column [kg] in the record's coordinate (a torque record's motor side: m (p/2
    pi)^2); one value through a run: a payload that changes within it conflicts (InputError naming
    the line)."""
    j = names.index("payload")
    change = np.nonzero(m != m[0])[0]
    if len(change):
        k = int(change[0])
        raise InputError(
            f"conflicting payloads in one run: {data[0, j]:g} at the start, {data[k, j]:g} here; a "
            "run carries one payload (give each payload its own record)",
            source=src,
            where=f"line {lines[k]}, column {j + 1} (payload)",
        )
    if m[0] < 0:
        raise InputError(
            f"payload {data[0, j]:g} is negative", source=src, where=f"column {j + 1} (payload)"
        )
    return m * (1.0 if quantity == "force" else (lead / (2.0 * math.pi)) ** 2)


def _fast_cells(rows: list, cols: list, names: list):
    """The data cells as an (n, columns) array when every row has the header's width and every cell
    is a finite number within the plausible range of its column; else None, and the caller's
    cell-by-cell reading names the first bad cell."""
    k = len(cols)
    if not rows or any(text.count(",") != k - 1 for _, text in rows):
        return None
    try:
        data = np.array(",".join(text for _, text in rows).split(","), dtype=float).reshape(
            len(rows), k
        )
    except ValueError:
        return None
    if not np.isfinite(data).all():
        return None
    for j, name in enumerate(names):
        if name in _KIND and np.max(np.abs(data[:, j])) * abs(cols[j][2]) > PLAUSIBLE_MAX.get(
            _KIND[name], 1e12
        ):
            return None
    return data


def _factor(name, unit, src, where, lead) -> float:
    """SI factor of a column; positions in an angle unit become table travel [m] through the
    lead."""
    try:
        if name == "time":
            return unit_factor(unit, "time")
        if name in ("position", "reference", "motor_position"):
            try:
                return unit_factor(unit, "length")
            except ValueError:
                return unit_factor(_REV.get(unit.strip(), unit), "angle") * lead / (2.0 * math.pi)
        if name in ("force", "external_force", "normal_load"):
            return unit_factor(unit, "force")
        if name == "temperature":
            if unit.strip() not in ("degC", "K", "C", "celsius"):
                raise ValueError(f"temperature unit '{unit}' (degC or K)")
            return 1.0
        if name == "torque":
            return unit_factor(unit, "torque")
        if name == "payload":
            return unit_factor(unit, "mass")
    except ValueError as exc:
        raise InputError(f"{exc} in column '{name}'", source=src, where=where) from None
    if unit.strip() not in CURRENT_UNITS:
        raise InputError(
            f"unknown unit '{unit}' in column 'current' (A or mA)", source=src, where=where
        )
    return CURRENT_UNITS[unit.strip()]


def check_same_columns(est: TimeRecord, other: TimeRecord) -> None:
    """A validation run must carry the estimation run's columns (same effort, same reference)."""
    if set(est.header) != set(other.header):
        diff = sorted(set(est.header) ^ set(other.header))
        j = next((k for k, n in enumerate(other.header) if n in diff), len(other.header) - 1) + 1
        raise InputError(
            f"validation run has columns {', '.join(other.header)} but the estimation run "
            f"{est.name} has {', '.join(est.header)}",
            source=other.source,
            where=f"line {other.lines[0] - 1 if len(other.lines) else 1}, column {j}",
        )
