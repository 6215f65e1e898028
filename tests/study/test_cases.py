"""Study cases (study.cases): a product expansion into cases with stable ids, each built into its
problem."""

from __future__ import annotations

import pytest

from axisopt.study import build_problem, load_study


def test_product_expansion_and_problem_fields(small_study):
    st = load_study(small_study)
    assert len(st.cases) == 12
    assert len({c.case_id for c in st.cases}) == 12
    c = st.cases[-1]
    assert c.inputs() == {
        "axis.stroke": "700 mm",
        "catalog.mountings": ["fixed-supported", "fixed-fixed"],
        "limits.max_cost": "600 EUR",
    }
    p = build_problem(st.context(), c)
    assert p.axis.stroke == pytest.approx(0.7)
    assert p.mountings == ("fixed-supported", "fixed-fixed")
    assert p.limit_map["max_cost"] == pytest.approx(600.0)
    # the ids depend on the inputs: the same file gives the same ids
    assert [x.case_id for x in load_study(small_study).cases] == [x.case_id for x in st.cases]
