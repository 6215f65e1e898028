"""Part columns the model reads (model.paramnames): every one is a column of its catalog table, and
the small readers treat an empty (NaN) or missing optional column as the text says."""

from __future__ import annotations

import math

import numpy as np
import pytest

from axisopt.catalog.columns import SCHEMA
from axisopt.model.paramnames import (
    PART_PARAMS,
    column_value,
    columns_read,
    listed_or,
    optional_column,
)


@pytest.mark.parametrize("table", sorted(PART_PARAMS))
def test_the_model_reads_only_catalog_columns_once(table):
    cols = columns_read(table)
    assert len(cols) == len(set(cols))
    assert cols[: len(PART_PARAMS[table])] == tuple(c for c, _ in PART_PARAMS[table])
    assert set(cols) <= set(SCHEMA[table]), set(cols) - set(SCHEMA[table])


def test_listed_or_falls_back_where_empty():
    assert listed_or(3.0, 7.0) == 3.0 and isinstance(listed_or(3.0, 7.0), float)
    assert listed_or(float("nan"), 7.0) == 7.0
    np.testing.assert_array_equal(listed_or(np.array([1.0, np.nan, 2.0]), 9.0), [1.0, 9.0, 2.0])


def test_column_readers():
    row = {"lead": np.int64(5), "mass": [1, 2]}
    assert column_value(row, "lead") == 5.0 and isinstance(column_value(row, "lead"), float)
    got = column_value(row, "mass")
    assert got.dtype == float and list(got) == [1.0, 2.0]
    assert math.isnan(optional_column(row, "starting_torque"))
    with pytest.raises(KeyError):
        column_value(row, "starting_torque")
