"""Load and validate part catalogs (``catalogs/*.csv``) into SI pandas tables.

One strict reader (:func:`load_records`, the csv module, no pandas) validates every file;
:func:`load_catalogs` turns its records into the pandas tables the search uses, and
``axisopt parts`` lists the records as they are (its start-up then imports neither pandas nor
numpy).

Each CSV header carries the vendor's unit (``lead [mm]``); values are converted once here.
Errors (unknown unit, missing column, duplicate id, non-numeric cell, non-positive stiffness,
dangling reference) name the file, line and column.  A user catalog directory is merged after the
shipped one; its ids must not collide with the shipped ids.
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import InputError
from ..units import read_header
from .columns import (
    COLUMNS,
    OPTIONAL_COLUMNS,
    PROVENANCE,
    SCHEMA,
    SHIPPED_DIR,
    TABLES,
    USER_STATUS,
    row_problem,
)

if TYPE_CHECKING:
    import pandas as pd

    from .parttable import PartTable, Row

MAX_CATALOG_BYTES = 50_000_000
# Tables the axis model needs in every catalog; the drive tables may be absent (empty then).
REQUIRED_TABLES = ("screws", "nuts", "bearings", "guides")


class Catalog:
    """The part tables in SI, indexed by part id, plus where each row came from.  ``motors``,
    ``couplings`` and ``reductions`` (the drive) are empty tables when no catalog directory has
    them.

    Each table is given as a :class:`~axisopt.catalog.parttable.PartTable` (what
    :func:`load_catalogs` builds, no pandas) or a pandas DataFrame indexed by part id.
    ``cat.screws`` (and the other five) is the pandas table (built on first use); :meth:`rows` is
    the same table without pandas, as the search and the model read it. :meth:`replace` swaps tables
    (``cat.replace(guides=df)``)."""

    __slots__ = ("_given", "_rows", "_frames")

    def __init__(
        self, screws, nuts, bearings, guides, motors=None, couplings=None, reductions=None
    ):
        given = dict(zip(TABLES, (screws, nuts, bearings, guides, motors, couplings, reductions)))
        self._given = {k: (_empty_table(k) if v is None else v) for k, v in given.items()}
        self._rows: dict = {}
        self._frames: dict = {}

    def replace(self, **tables) -> Catalog:
        """A catalog with some tables swapped (``cat.replace(guides=df)``)."""
        unknown = set(tables) - set(TABLES)
        if unknown:
            raise TypeError(f"unknown catalog table(s) {', '.join(sorted(unknown))}")
        return Catalog(**{**self._given, **tables})

    def rows(self, name: str) -> PartTable:
        """Table ``name`` as a :class:`~axisopt.catalog.parttable.PartTable` (no pandas)."""
        t = self._rows.get(name)
        if t is None:
            from .parttable import PartTable

            src = self._given[name]
            t = src if isinstance(src, PartTable) else PartTable.from_frame(src)
            self._rows[name] = t
        return t

    def table(self, name: str) -> pd.DataFrame:
        """Table ``name`` as a pandas DataFrame indexed by part id (imports pandas; the same object
        each time)."""
        df = self._frames.get(name)
        if df is None:
            from .parttable import PartTable

            src = self._given[name]
            df = src.to_frame() if isinstance(src, PartTable) else src
            self._frames[name] = df
        return df

    screws = property(lambda self: self.table("screws"), doc="screws (pandas DataFrame by part id)")
    nuts = property(lambda self: self.table("nuts"), doc="nuts (pandas DataFrame by part id)")
    bearings = property(
        lambda self: self.table("bearings"), doc="support bearings (pandas DataFrame by part id)"
    )
    guides = property(
        lambda self: self.table("guides"), doc="linear guides (pandas DataFrame by part id)"
    )
    motors = property(lambda self: self.table("motors"), doc="motors (pandas DataFrame by part id)")
    couplings = property(
        lambda self: self.table("couplings"), doc="couplings (pandas DataFrame by part id)"
    )
    reductions = property(
        lambda self: self.table("reductions"), doc="reductions (pandas DataFrame by part id)"
    )

    def __repr__(self) -> str:
        return "Catalog(" + ", ".join(f"{n}: {len(self.rows(n))}" for n in TABLES) + ")"

    def part(
        self, table: str, part_id: str, *, source: str | None = None, key: str | None = None
    ) -> Row:
        """The row of ``part_id`` in ``table`` as a :class:`~axisopt.catalog.parttable.Row`; an
        unknown id is a one-line error with the closest id."""
        t = self.rows(table)
        i = t.position(part_id)
        if i is None:
            near = _closest(part_id, t.ids)
            hint = f"; did you mean '{near}'?" if near else ""
            raise InputError(f"unknown {table[:-1]} id '{part_id}'{hint}", source=source, where=key)
        return t.row(i)


def _table_columns(name: str) -> list[str]:
    """The columns of a loaded part table: the schema's, then where each row came from."""
    return list(SCHEMA[name]) + ["_source", *PROVENANCE]


def _empty_table(name: str) -> PartTable:
    from .parttable import PartTable

    return PartTable([], _table_columns(name), ids=[])


def _closest(word: str, options) -> str | None:
    from ..yamlio import close_matches

    m = close_matches(str(word), [str(o) for o in options])
    return m[0] if m else None


def _read_records(path: Path, name: str) -> list[dict]:
    """The rows of one CSV as validated records in SI (``status`` and ``source`` filled in for a
    table without them); the first problem raises a one-line :class:`InputError` naming the file,
    line and column."""
    schema = SCHEMA[name]
    src = str(path)
    try:
        from ..fileio import read_input, refuse_nul  # regular files only, at most MAX_CATALOG_BYTES

        text = refuse_nul(read_input(path, "catalog", what="catalog", encoding="utf-8-sig"), src)
        with io.StringIO(text, newline="") as fh:
            reader = csv.reader(fh)
            try:
                rows = list(reader)
            except csv.Error as exc:
                raise InputError(
                    f"malformed CSV ({exc})", source=src, where=f"line {reader.line_num}"
                ) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(
            f"cannot read catalog ({exc.__class__.__name__}: "
            f"{getattr(exc, 'strerror', None) or exc})",
            source=src,
        ) from None
    if not rows:
        raise InputError("empty catalog file", source=src)
    header = rows[0]

    def unknown(col: str) -> str:
        near = _closest(col, schema)
        return f"unknown column '{col}'" + (f"; did you mean '{near}'?" if near else "")

    # the header by the strict unit-CSV rules (units.read_header): text and count columns take no
    # unit
    kinds = {c: (None if k in ("str", "int") else k) for c, k in schema.items()} | dict.fromkeys(
        PROVENANCE
    )
    header_cols = read_header(header, line=1, source=src, kinds=kinds, unknown=unknown)
    # (name, SI factor or None, kind) per column
    cols = [
        (c.name, c.factor, "str" if c.name in PROVENANCE else schema[c.name]) for c in header_cols
    ]
    seen = {c.name for c in header_cols}
    # an optional column with an estimate (or a meaning when empty, or one that applies only under a
    # flag) may be left out of the header: every row then takes the estimate (is empty)
    omitted = [
        c.name
        for c in COLUMNS[name]
        if c.optional and (c.estimate or c.blank or c.applies) and c.name not in seen
    ]
    missing = [c for c in schema if c not in seen and c not in omitted]
    if missing:
        raise InputError(f"missing column(s) {', '.join(missing)}", source=src, where="line 1")

    records = []
    ids: dict[str, int] = {}
    for i, row in enumerate(rows[1:], start=2):
        if not row or all(not c.strip() for c in row):
            continue
        if len(row) != len(cols):
            raise InputError(
                f"has {len(row)} cells, header has {len(cols)}", source=src, where=f"line {i}"
            )
        rec = dict.fromkeys(omitted, math.nan)
        for j, ((col, factor, kind), cell) in enumerate(zip(cols, row), start=1):
            cell = cell.strip()
            where = f"line {i}, column {j} ({col})"
            if kind == "str":
                if not cell:
                    raise InputError("empty cell", source=src, where=where)
                rec[col] = cell
                continue
            if not cell and col in OPTIONAL_COLUMNS.get(name, ()):
                rec[col] = math.nan
                continue
            try:
                val = float(cell)
            except ValueError:
                raise InputError(f"'{cell}' is not a number", source=src, where=where) from None
            if not math.isfinite(val):
                raise InputError(f"'{cell}' is not a finite number", source=src, where=where)
            if kind == "int":
                if val != int(val):
                    raise InputError(f"'{cell}' is not a whole number", source=src, where=where)
                rec[col] = int(val)
                continue
            rec[col] = val * factor
        names = [n for n, _, _ in cols]
        if "status" in rec and rec["status"] not in PROVENANCE["status"]:
            j = names.index("status") + 1
            raise InputError(
                f"status '{rec['status']}' is not one of {', '.join(PROVENANCE['status'])}",
                source=src,
                where=f"line {i}, column {j} (status)",
            )
        bad = row_problem(name, rec)
        if bad is not None:
            c, msg = bad
            j = names.index(c)
            if msg.startswith(c):  # an ordered pair: "<high> is below <low>"
                text = f"{msg} ({row[j].strip()})"
            elif msg.startswith("'"):  # a choice: the message shows the value
                text = f"{c} {msg}"
            else:
                text = f"{c} {msg}, got {row[j].strip()}"
            raise InputError(text, source=src, where=f"line {i}, column {j + 1} ({c})")
        if rec["id"] in ids:
            raise InputError(
                f"duplicate id '{rec['id']}' (first on line {ids[rec['id']]})",
                source=src,
                where=f"line {i}, column 1 (id)",
            )
        ids[rec["id"]] = i
        rec["_source"] = f"{src}:{i}"
        rec.setdefault("status", USER_STATUS)
        rec.setdefault("source", "")
        records.append(rec)
    return records


class PartRows:
    """The validated catalog rows as plain records (dicts in SI, keyed by column, plus ``_source``,
    ``status`` and ``source``), per table in file order: what :func:`load_records` returns and
    :func:`load_catalogs` builds its pandas tables from."""

    def __init__(self, tables: dict[str, list[dict]]):
        self._tables = tables
        self._ids = {name: {r["id"]: r for r in rows} for name, rows in tables.items()}

    def table(self, name: str) -> list[dict]:
        return self._tables[name]

    def part(
        self, table: str, part_id: str, *, source: str | None = None, key: str | None = None
    ) -> dict:
        """The row of ``part_id`` (same error as :meth:`Catalog.part` for an unknown id)."""
        rows = self._ids[table]
        if part_id not in rows:
            near = _closest(part_id, rows)
            hint = f"; did you mean '{near}'?" if near else ""
            raise InputError(f"unknown {table[:-1]} id '{part_id}'{hint}", source=source, where=key)
        return rows[part_id]


def load_records(extra_dirs=(), *, shipped: bool = True) -> PartRows:
    """Read and validate the shipped catalogs and any user catalog directories (later ones add
    parts), without
    pandas: every check of :func:`load_catalogs` (which builds its tables from these records)."""
    dirs = ([SHIPPED_DIR] if shipped else []) + [Path(d) for d in extra_dirs]
    tables: dict[str, list[list[dict]]] = {name: [] for name in SCHEMA}
    for d in dirs:
        if not d.is_dir():
            raise InputError("catalog directory not found", source=str(d))
        for name in SCHEMA:
            p = d / f"{name}.csv"
            if p.exists():
                tables[name].append(_read_records(p, name))
    out: dict[str, list[dict]] = {}
    for name, parts in tables.items():
        if not parts:
            if name not in REQUIRED_TABLES:
                out[name] = []
                continue
            raise InputError(
                f"no {name}.csv found in catalog directories", source=", ".join(map(str, dirs))
            )
        rows = [r for part in parts for r in part]
        last: dict[str, dict] = {}
        first_dup = None
        for r in rows:  # each file's ids are unique already: a repeat comes from another directory
            if r["id"] in last and first_dup is None:
                first_dup = r["id"]
            last[r["id"]] = r
        if first_dup is not None:
            raise InputError(
                f"duplicate id '{first_dup}' across catalog directories",
                source=last[first_dup]["_source"],
            )
        out[name] = rows
    screws = {r["id"]: r for r in out["screws"]}
    for r in out["nuts"]:
        if r["screw_id"] not in screws:
            raise InputError(
                f"screw_id '{r['screw_id']}' is not in screws.csv",
                source=r["_source"],
                where="column screw_id",
            )
    for r in out["nuts"]:
        v = screws[r["screw_id"]]["vendor"]
        if r["vendor"] != v:
            raise InputError(
                f"nut '{r['id']}' of vendor {r['vendor']} is listed on screw '{r['screw_id']}' of "
                f"vendor {v}: a nut runs only on its own vendor's shaft",
                source=r["_source"],
                where="column screw_id",
            )
    return PartRows(out)


def load_catalogs(extra_dirs=(), *, shipped: bool = True) -> Catalog:
    """Load the shipped catalogs and any user catalog directories (later ones add parts) as a
    :class:`Catalog` (its tables are built without pandas; ``cat.screws`` and the others give pandas
    tables on demand).

    A user directory may hold any subset of screws/nuts/bearings/guides CSVs.
    """
    from .parttable import PartTable

    rows = load_records(extra_dirs, shipped=shipped)
    return Catalog(**{name: PartTable(rows.table(name), _table_columns(name)) for name in SCHEMA})


_CACHE: dict[tuple, Catalog] = {}


def files_state(dirs, names) -> tuple:
    """What a load reads, as a cache key: each directory's ``<name>.csv`` files with a digest of
    their bytes (None for an absent one), so an edited, added or removed file is read again, never
    served stale."""
    import hashlib

    out = []
    for d in dirs:
        for name in names:
            p = Path(d) / f"{name}.csv"
            try:
                digest = hashlib.blake2b(p.read_bytes(), digest_size=16).hexdigest()
            except OSError:
                digest = None
            out.append((str(p), digest))
    return tuple(out)


def default_catalog(extra_dirs=()) -> Catalog:
    """Cached :func:`load_catalogs` (the tables are treated as read-only), keyed by the directories
    and the contents of the files read (:func:`files_state`): a catalog file changed in a running
    process is reloaded."""
    dirs = [Path(d).resolve() for d in extra_dirs]
    key = (tuple(map(str, dirs)), files_state([SHIPPED_DIR, *dirs], SCHEMA))
    if key not in _CACHE:
        if len(_CACHE) > 16:
            _CACHE.clear()
        _CACHE[key] = load_catalogs(extra_dirs)
    return _CACHE[key]
