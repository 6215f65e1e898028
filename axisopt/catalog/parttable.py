"""A part table without pandas: the catalog rows the search and the model read, column by column.

pandas takes about a third of a second to import, more than a whole search of the teaching problem,
so the paths a designer waits for (``axisopt solve``, ``evaluate``, a study's cases) work on
:class:`PartTable`: one numpy array per column (float for numbers, object for text) and the part
ids.  A row is a :class:`Row`, a dict with the part id as ``name`` (what a pandas row offers
the model: ``row["lead"]``, ``row.get(...)``, ``row.name``).  :meth:`PartTable.to_frame` gives the
pandas table where one is wanted (``Catalog.screws``, a study's tables);
:meth:`PartTable.from_frame` takes a pandas table a user built.
"""

from __future__ import annotations

import math

import numpy as np


class Row(dict):
    """One part: its columns (SI numbers, text) as a dict, the part id as ``name``.  Its repr,
    ``to_frame()`` and notebook table show the numbers in the units of the vendor's catalog
    (``dynamic_load_rating 51.3 kN``, the shipped catalog file's header;
    :mod:`axisopt.catalog.partrow`)."""

    __slots__ = ("name",)

    def __init__(self, values=(), name=None):
        super().__init__(values)
        self.name = self.get("id") if name is None else name

    def copy(self) -> Row:
        """A copy with the same ``name``."""
        return Row(self, self.name)

    def to_dict(self) -> dict:
        """The columns as a plain dict (SI numbers, as the model reads them)."""
        return dict(self)

    def to_frame(self):
        """pandas DataFrame of the part, one row per column: ``column``, ``value`` (numbers in the
        unit the vendor's catalog quotes, as the catalog file writes them) and ``unit``
        (:mod:`axisopt.catalog.partrow`)."""
        from .partrow import row_frame

        return row_frame(self)

    def __repr__(self) -> str:  # the values in vendor units, not SI (axisopt.catalog.partrow)
        from .partrow import row_repr

        return row_repr(self)

    def _repr_html_(self) -> str:
        from .partrow import row_html

        return row_html(self)


def _column(values: list) -> np.ndarray:
    """float64 when every value is a number (None: NaN), else object (text)."""
    if all(
        isinstance(v, (int, float, np.number)) and not isinstance(v, bool) or v is None
        for v in values
    ):
        return np.array([math.nan if v is None else v for v in values], dtype=float)
    return np.array(values, dtype=object)


class PartTable:
    """Part rows by column.  ``records``: one dict per part, in order; ``names``: the columns
    (default: the first record's keys); ``ids``: the part ids (default: each record's ``id``).  The
    rows keep their values as given (``row(i)``); a column is a numpy array built on first use
    (``t["lead"]``)."""

    __slots__ = ("_records", "_columns", "_names", "ids", "_pos")

    def __init__(self, records: list[dict], names=None, *, ids=None):
        self._records = list(records)
        self._names = (
            list(names) if names is not None else (list(self._records[0]) if self._records else [])
        )
        self.ids = (
            np.array([r["id"] for r in self._records], dtype=object)
            if ids is None
            else np.asarray(ids, dtype=object)
        )
        self._columns: dict[str, np.ndarray] = {}
        self._pos: dict | None = None

    # ---------------------------------------------------------------- building
    @classmethod
    def from_frame(cls, df) -> PartTable:
        """The rows of a pandas table (index: part id)."""
        names = [str(c) for c in df.columns]
        cols = [df[c].to_numpy() for c in df.columns]
        records = [
            Row({n: _scalar(col[i]) for n, col in zip(names, cols)}, df.index[i])
            for i in range(len(df))
        ]
        return cls(records, names, ids=[str(i) for i in df.index])

    def to_frame(self):
        """The pandas table of these rows, indexed by part id (imports pandas)."""
        import pandas as pd

        df = pd.DataFrame.from_records([dict(r) for r in self._records], columns=self._names)
        df.index = pd.Index(list(self.ids), name="id" if "id" in self._names else None)
        return df

    # ---------------------------------------------------------------- reading
    @property
    def columns(self) -> list[str]:
        return list(self._names)

    def __len__(self) -> int:
        return len(self._records)

    def __contains__(self, column) -> bool:
        return column in self._names

    def __getitem__(self, column: str) -> np.ndarray:
        """The column as a numpy array (read-only: shared with every table taken from this one)."""
        col = self._columns.get(column)
        if col is None:
            if column not in self._names:
                raise KeyError(column)
            col = _column([r.get(column) for r in self._records])
            col.flags.writeable = False
            self._columns[column] = col
        return col

    def number(self, column: str) -> np.ndarray:
        """The column as float64."""
        return np.asarray(self[column], dtype=float)

    def row(self, i: int) -> Row:
        r = self._records[int(i)]
        return r.copy() if isinstance(r, Row) else Row(r, self.ids[int(i)])

    def position(self, part_id) -> int | None:
        if self._pos is None:
            self._pos = {str(k): i for i, k in enumerate(self.ids)}
        return self._pos.get(str(part_id))

    def isin(self, column: str, values) -> np.ndarray:
        """Boolean mask: rows whose ``column`` is one of ``values``."""
        allowed = set(values)
        src = self.ids if column == "id" and column not in self._names else self[column]
        return np.fromiter((v in allowed for v in src), dtype=bool, count=len(self))

    # ---------------------------------------------------------------- subsets
    def take(self, which) -> PartTable:
        """The rows of a boolean mask or of integer positions, in that order."""
        which = np.asarray(which)
        idx = np.nonzero(which)[0] if which.dtype == bool else which.astype(np.int64)
        out = PartTable([self._records[i] for i in idx], self._names, ids=self.ids[idx])
        out._columns = {k: _frozen(v[idx]) for k, v in self._columns.items()}
        return out

    def by_id(self, ids) -> PartTable:
        """The rows of these part ids, in that order (KeyError for an unknown id)."""
        pos = [self.position(i) for i in ids]
        if any(p is None for p in pos):
            raise KeyError(next(i for i, p in zip(ids, pos) if p is None))
        return self.take(np.array(pos, dtype=np.int64))

    def __repr__(self) -> str:
        return (
            f"PartTable({len(self)} rows: "
            f"{', '.join(map(str, self.ids[:4]))}{', ...' if len(self) > 4 else ''})"
        )


def _frozen(a: np.ndarray) -> np.ndarray:
    a.flags.writeable = False
    return a


def _scalar(v):
    """A pandas cell as a plain Python value (numpy scalars to int/float; text as it is)."""
    if isinstance(v, np.generic):
        return v.item()
    return v
