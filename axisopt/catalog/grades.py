"""Lead accuracy grades of ball screws (JIS B 1192 / ISO 3408 C0-C10): the tolerance tables, the
grades each screw series is made in, and the illustrative price factor of a grade.

Three shipped tables (catalogs/SOURCES.md):

* ``catalogs/lead_tolerances.csv``: the representative travel deviation e_p and the variation v_u of
  grades C0-C5 by useful travel (THK General Catalog A-678 Table 1, JIS B 1192-1997);
* ``catalogs/lead_grades.csv``: per grade, the variation over 300 mm and per turn (v_300, v_2pi;
  A-678 Table 2), the travel error per 300 mm of the grades C7-C10 (A-678 Table 1), HIWIN's standard
  axial play of a grade (HIWIN S99TE20 Table 4.4) and the price factor on the screw shaft's price
  (illustrative, like every price);
* ``catalogs/screw_grades.csv``: the grades each (vendor, series) of ``screws.csv`` is made in (THK
  A-678 Table 3: precision C0-C7, rolled C7-C10; HIWIN S99TE20 Table 4.2: ground C0-C6; Rexroth
  P1/P3/P5).

The tables are read once (:func:`grade_table`); a bad cell is a one-line error naming the file, line
and column.  Lengths leave in SI (m).
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from types import MappingProxyType

from ..errors import InputError

SHIPPED_DIR = Path(__file__).resolve().parent.parent.parent / "catalogs"
UM = 1e-6
PER_LENGTH = 0.300  # [m] the 300 mm of v_300 and of the C7-C10 travel error
# a screw series not in screw_grades.csv (a user's or an inline screw): the precision grades of THK
# A-678 Table 3
PRECISION_GRADES = ("C0", "C1", "C2", "C3", "C5", "C7")

_TOL_HEADER = (
    "grade",
    "length_over [mm]",
    "length_upto [mm]",
    "travel_deviation [um]",
    "variation [um]",
    "source",
)
_GRADE_HEADER = (
    "grade",
    "variation_300 [um]",
    "variation_2pi [um]",
    "travel_error_300 [um]",
    "axial_play [um]",
    "price_factor [-]",
    "status",
    "source",
)
_SERIES_HEADER = ("vendor", "series", "grades", "source")


@dataclass(frozen=True)
class Grade:
    """One lead accuracy grade: its tolerances [m] (NaN where the grade has none) and price factor
    [-]."""

    name: str
    variation_300: float  # v_300 [m] (C0-C5)
    variation_2pi: float  # v_2pi [m] (C0-C5)
    travel_error_300: float  # e_300 [m] per 300 mm (C7-C10)
    # standard axial play of a single nut of the grade [m] (HIWIN; NaN: none listed)
    axial_play: float
    price_factor: float  # on the screw shaft's price [-] (illustrative)
    bands: tuple  # ((length_over, length_upto, e_p, v_u) [m], ...) ascending (C0-C5)


@dataclass(frozen=True)
class GradeTable:
    """The shipped grades, in the order of the table (most accurate first), and the grades of each
    series."""

    grades: MappingProxyType  # name -> Grade
    series: MappingProxyType  # (vendor, series) -> tuple of grade names

    @property
    def names(self) -> tuple:
        return tuple(self.grades)

    def grade(self, name: str) -> Grade:
        g = self.grades.get(name)
        if g is None:
            raise KeyError(name)
        return g

    def orderable(self, vendor: str, series: str) -> tuple:
        """The grades a screw of this vendor and series is made in (a series not listed: the
        precision grades)."""
        return self.series.get((vendor, series), PRECISION_GRADES)

    def lead_error(self, name: str, travel: float) -> float:
        """The largest lead (travel) error of grade ``name`` over ``travel`` [m]
        (:func:`axisopt.physics.accuracy.lead_error`): e_p + v_u of the band holding the travel for
        C0-C5, the error per 300 mm scaled to the travel (at least one 300 mm) for C7-C10.  NaN
        where the grade's table stops short of the travel (THK lists no C0 beyond 1600 mm)."""
        from ..physics.accuracy import lead_error_per_300, lead_error_tolerance

        g = self.grade(name)
        if math.isfinite(g.travel_error_300):
            return float(lead_error_per_300(g.travel_error_300, travel, PER_LENGTH))
        for lo, hi, ep, vu in g.bands:
            if lo < travel <= hi or (lo == 0.0 and travel <= hi):
                return float(lead_error_tolerance(ep, vu))
        return math.nan

    def compensated_error(self, name: str, travel: float) -> float:
        """The lead error left after pitch-error compensation [m]: the controller's table removes
        the representative travel line's deviation e_p (THK A-677 Fig. 1: what ISO 230-2's
        compensation measures), not the fluctuation v_u about it, which is what remains for C0-C5;
        for C7-C10 (no v_u) the error per 300 mm, unscaled (the compensation points are tens of mm
        apart; within them the error stays).  NaN where the grade's table stops short of the
        travel."""
        g = self.grade(name)
        if math.isfinite(g.travel_error_300):
            return float(g.travel_error_300)
        for lo, hi, _ep, vu in g.bands:
            if lo < travel <= hi or (lo == 0.0 and travel <= hi):
                return float(vu)
        return math.nan

    def error_per_300(self, name: str) -> float:
        """The grade's lead error per 300 mm [m]: v_300 for C0-C5, the travel error per 300 mm for
        C7-C10."""
        g = self.grade(name)
        return g.travel_error_300 if math.isfinite(g.travel_error_300) else g.variation_300

    def grade_for(self, accuracy: float, travel: float, names=None) -> str | None:
        """The least accurate grade of ``names`` (default: all) whose error per 300 mm meets a
        positioning accuracy (+-) over a travel [m], as THK's selection examples choose it (A-723,
        A-737: :func:`axisopt.physics.accuracy.required_error_per_300`); None if none does."""
        from ..physics.accuracy import required_error_per_300

        need = required_error_per_300(accuracy, travel)
        ok = [
            n for n in self.names if (names is None or n in names) and self.error_per_300(n) <= need
        ]
        return ok[-1] if ok else None

    def cheapest(self, names) -> str:
        """The grade of ``names`` with the lowest price factor; of equal ones the most accurate
        (first listed)."""
        names = [n for n in self.names if n in set(names)]
        return min(names, key=lambda n: (self.grades[n].price_factor, self.names.index(n)))


def _rows(path: Path, header: tuple) -> list:
    src = str(path)
    try:
        from ..fileio import read_input

        text = read_input(path, "catalog", what="catalog", encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(
            f"cannot read grade table ({exc.__class__.__name__})", source=src
        ) from None
    rows = list(csv.reader(io.StringIO(text, newline="")))
    if not rows or tuple(c.strip() for c in rows[0]) != header:
        raise InputError(f"header must be: {','.join(header)}", source=src, where="line 1")
    out = []
    for i, row in enumerate(rows[1:], start=2):
        if not row or all(not c.strip() for c in row):
            continue
        if len(row) != len(header):
            raise InputError(
                f"has {len(row)} cells, header has {len(header)}", source=src, where=f"line {i}"
            )
        out.append((i, [c.strip() for c in row]))
    return out


def _number(cell: str, src: str, i: int, j: int, col: str, optional: bool = False) -> float:
    where = f"line {i}, column {j} ({col})"
    if not cell:
        if optional:
            return math.nan
        raise InputError("empty cell", source=src, where=where)
    try:
        v = float(cell)
    except ValueError:
        raise InputError(f"'{cell}' is not a number", source=src, where=where) from None
    if not math.isfinite(v) or v < 0:
        raise InputError(f"'{cell}' is not a finite number >= 0", source=src, where=where)
    return v


def load_grade_table(directory=SHIPPED_DIR) -> GradeTable:
    """Read and check the three grade tables of ``directory`` (see the module docstring)."""
    d = Path(directory)
    bands: dict = {}
    p = d / "lead_tolerances.csv"
    for i, r in _rows(p, _TOL_HEADER):
        vals = [
            _number(r[j], str(p), i, j + 1, _TOL_HEADER[j]) * (1e-3 if j < 3 else UM)
            for j in range(1, 5)
        ]
        if vals[0] >= vals[1]:
            raise InputError(
                "length_upto must exceed length_over", source=str(p), where=f"line {i}"
            )
        bands.setdefault(r[0], []).append(tuple(vals))
    grades = {}
    p = d / "lead_grades.csv"
    for i, r in _rows(p, _GRADE_HEADER):
        name = r[0]
        if name in grades:
            raise InputError(
                f"duplicate grade '{name}'", source=str(p), where=f"line {i}, column 1 (grade)"
            )
        v = [
            _number(r[j], str(p), i, j + 1, _GRADE_HEADER[j], optional=j != 5) for j in range(1, 6)
        ]
        if v[4] <= 0:
            raise InputError(
                "price_factor must be positive", source=str(p), where=f"line {i}, column 6"
            )
        b = tuple(sorted(bands.pop(name, ())))
        if math.isnan(v[2]) == (len(b) == 0):
            raise InputError(
                f"grade '{name}' needs either travel_error_300 or rows in lead_tolerances.csv "
                "(not both)",
                source=str(p),
                where=f"line {i}",
            )
        grades[name] = Grade(name, v[0] * UM, v[1] * UM, v[2] * UM, v[3] * UM, v[4], b)
    if bands:
        raise InputError(
            f"grade '{next(iter(bands))}' of lead_tolerances.csv is not in lead_grades.csv",
            source=str(d / "lead_tolerances.csv"),
        )
    series = {}
    p = d / "screw_grades.csv"
    for i, r in _rows(p, _SERIES_HEADER):
        names = tuple(r[2].split())
        bad = [n for n in names if n not in grades]
        if not names or bad:
            raise InputError(
                f"unknown grade '{bad[0] if bad else ''}' (known: {', '.join(grades)})",
                source=str(p),
                where=f"line {i}, column 3 (grades)",
            )
        series[(r[0], r[1])] = names
    return GradeTable(MappingProxyType(grades), MappingProxyType(series))


@lru_cache(maxsize=1)
def grade_table() -> GradeTable:
    """The shipped grade tables (read once per process)."""
    return load_grade_table(SHIPPED_DIR)


def lead_errors(names, travel, compensated: bool = False):
    """:meth:`GradeTable.lead_error` of each grade name of ``names`` (an array of names) over
    ``travel`` [m] (a float, or an array that broadcasts with the names: each row's stroke + nut
    length) (``compensated``: :meth:`GradeTable.compensated_error`, what pitch-error compensation
    leaves)."""
    t = grade_table()
    import numpy as np  # here: `axisopt parts screws` reads the grade tables without numpy

    names, travel = np.broadcast_arrays(np.asarray(names), np.asarray(travel, dtype=float))
    uniq, inv = np.unique(names, return_inverse=True)
    lens, linv = np.unique(travel, return_inverse=True)
    how = t.compensated_error if compensated else t.lead_error
    vals = np.array([[how(str(n), float(x)) for x in lens] for n in uniq]).reshape(len(uniq), -1)
    return vals[inv.ravel(), linv.ravel()].reshape(names.shape)


@dataclass(frozen=True)
class ScaleGrade:
    """A linear scale's accuracy grade: +-``accuracy`` per metre of travel (at least one metre:
    Heidenhain's grade bounds any section up to 1 m) and its read head's repeatability band [m],
    with the source."""

    accuracy: float  # [m per m]
    repeatability: float  # [m], the band (2 x the +- figure); 0 where the vendor states none
    source: str


# Linear-scale grades for ``axis.feedback: linear_scale`` (vendor-data-sources-drives.md sec. 7):
# AMO LMB (amosin.com/lmb-100: "accuracy after linear compensation down to +-3 um/m / +-5 um/m"),
# HIWIN Positioning Measurement System magnetic scale PS (accuracy at 20 degC +-20 um/m, read head
# repeatability +-3 um).  How a grade reads over a travel: Heidenhain's definition, the extreme
# values over any section of at most 1 m lie within
# +-a (content.heidenhain.de, accuracy grade); a longer travel takes a per metre (conservative).
SCALE_GRADES = {
    "AMO-LMB-3": ScaleGrade(3e-6, 0.0, "AMO LMB +-3 um/m"),
    "AMO-LMB-5": ScaleGrade(5e-6, 0.0, "AMO LMB +-5 um/m"),
    "HIWIN-PMS": ScaleGrade(20e-6, 6e-6, "HIWIN PMS +-20 um/m, head +-3 um"),
}


def scale_error(grade: str, travel: float) -> float:
    """The scale's largest error over ``travel`` [m]: its grade's +-a per metre, at least one
    metre's."""
    return SCALE_GRADES[grade].accuracy * max(travel, 1.0)


def price_factors(names):
    """The price factor of each grade name of ``names``."""
    t = grade_table()
    import numpy as np

    names = np.asarray(names)
    uniq, inv = np.unique(names, return_inverse=True)
    vals = np.array([t.grade(str(n)).price_factor for n in uniq])
    return vals[inv].reshape(names.shape)


__all__ = [
    "Grade",
    "GradeTable",
    "PRECISION_GRADES",
    "SCALE_GRADES",
    "ScaleGrade",
    "grade_table",
    "lead_errors",
    "load_grade_table",
    "price_factors",
    "scale_error",
]
