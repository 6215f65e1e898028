"""The pandas-free part tables (axisopt.catalog.parttable) against the pandas tables they stand in
for."""

import math
import pickle

import numpy as np
import pandas as pd
import pytest

from axisopt.catalog.columns import PROVENANCE, SCHEMA, TABLES
from axisopt.catalog.loading import Catalog, load_catalogs, load_records
from axisopt.catalog.parttable import PartTable, Row
from axisopt.errors import InputError


@pytest.fixture(scope="module")
def cat():
    return load_catalogs()


def test_pandas_tables_are_the_records_as_pandas_reads_them(cat):
    """cat.screws (and the others) equal pandas' own reading of the validated records: same values,
    dtypes, column order and id index as the loader built before the part tables existed."""
    rows = load_records()
    for name in TABLES:
        want = pd.DataFrame.from_records(
            rows.table(name), columns=list(SCHEMA[name]) + ["_source", *PROVENANCE]
        )
        want = want.set_index("id", drop=False)
        pd.testing.assert_frame_equal(cat.table(name), want)
        assert cat.table(name) is cat.table(name)  # built once


def test_columns_match_pandas(cat):
    for name in TABLES:
        t, df = cat.rows(name), cat.table(name)
        assert len(t) == len(df) and list(t.ids) == list(df.index)
        for c in df.columns:
            col = t[c]
            if df[c].dtype.kind in "fi":
                np.testing.assert_array_equal(col, df[c].to_numpy(float))
                assert col.dtype == float
            else:
                assert list(col) == list(df[c])


def test_rows_are_the_pandas_rows(cat):
    t, df = cat.rows("nuts"), cat.table("nuts")
    for i in (0, len(t) // 2, len(t) - 1):
        r, s = t.row(i), df.iloc[i]
        assert isinstance(r, Row) and r.name == s.name
        for k, v in s.items():
            assert r[k] == v or (isinstance(v, float) and math.isnan(v) and math.isnan(r[k]))
    r = t.row(0)
    r2 = r.copy()
    r2["lead"] = -1.0
    # a copy does not touch the table
    assert isinstance(r2, Row) and r2.name == r.name and _same(t.row(0), r)
    with pytest.raises(ValueError):  # the shared column arrays are read-only
        t["preload_max"][0] = 0.0
    back = pickle.loads(pickle.dumps(r))  # a study's workers send designs back pickled
    assert isinstance(back, Row) and back.name == r.name and _same(back, r)


def _same(a: dict, b: dict) -> bool:
    """Equal rows, an empty optional cell (NaN, e.g. a nut's rotating-unit columns) equal to
    another."""

    def eq(x, y):
        return x == y or (
            isinstance(x, float) and isinstance(y, float) and math.isnan(x) and math.isnan(y)
        )

    return a.keys() == b.keys() and all(eq(a[k], b[k]) for k in a)


def test_take_isin_by_id_and_the_frame_round_trip(cat):
    g = cat.rows("guides")
    df = cat.table("guides")
    mask = g.isin("vendor", {"HIWIN", "IKO"}) & (g["size"] > 0.02)
    sub = g.take(mask)
    want = df[df["vendor"].isin(["HIWIN", "IKO"]) & (df["size"] > 0.02)]
    assert list(sub.ids) == list(want.index) and len(sub) > 0
    np.testing.assert_array_equal(sub["size"], want["size"].to_numpy(float))
    ids = list(want.index[::-1][:3])
    assert list(g.by_id(ids).ids) == ids
    with pytest.raises(KeyError):
        g.by_id(["no-such-guide"])
    back = PartTable.from_frame(want)
    pd.testing.assert_frame_equal(back.to_frame(), want)


def test_a_catalog_of_user_dataframes_is_read_the_same(cat):
    """A Catalog built from pandas tables (what a user or a test writes) gives the same part tables
    and rows."""
    frames = Catalog(*(cat.table(n) for n in TABLES))
    for name in TABLES:
        a, b = cat.rows(name), frames.rows(name)
        assert list(a.ids) == list(b.ids)
        for c in a.columns:
            x, y = a[c], b[c]
            if x.dtype == float:
                np.testing.assert_array_equal(x, y)
            else:
                assert list(x) == list(y)
    assert frames.part("screws", cat.rows("screws").ids[0]) == cat.part(
        "screws", cat.rows("screws").ids[0]
    )
    swapped = cat.replace(guides=cat.table("guides").iloc[:3])
    assert len(swapped.rows("guides")) == 3 and len(swapped.rows("nuts")) == len(cat.rows("nuts"))
    with pytest.raises(TypeError):
        cat.replace(gides=None)


def test_unknown_part_id_names_the_closest(cat):
    some = str(cat.rows("screws").ids[0])
    with pytest.raises(InputError, match="did you mean"):
        cat.part("screws", some[:-1] + "X")
