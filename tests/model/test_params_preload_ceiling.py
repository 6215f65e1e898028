"""Issue 26 item 3: the vendors' preload ceiling of a preloaded ball nut as a check
(margin_nut_preload).

THK Ball Screw General Catalog, "Preload" (A-687): "The maximum preload should be set at 10% of the
basic dynamic load rating (Ca)"; HIWIN H-BS 3.6.2: at most 10 % for double nuts.  No vendor found
states a ceiling by speed or DN (the preload's heat enters through the heat balance)."""

from dataclasses import replace
from pathlib import Path

import pytest

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.model.function import check_rows

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def vmc():
    return load_design(ROOT / "problems" / "vmc_x_design.yaml")


def test_ceiling_is_ten_percent_of_ca(vmc):
    ev = evaluate(vmc, use_casadi=False)
    ca = float(vmc.nut["dynamic_load_rating"])  # N
    assert float(ev["available_nut_preload"]) == pytest.approx(0.10 * ca, rel=1e-12)
    assert float(ev["margin_nut_preload"]) == pytest.approx(0.10 * ca / vmc.preload, rel=1e-12)


def test_a_nut_preloaded_above_the_ceiling_fails(vmc):
    ca = float(vmc.nut["dynamic_load_rating"])
    nut = vmc.nut.copy()
    nut["preload_max"] = 0.2 * ca  # a user catalog row more generous than the vendors' rule
    d = replace(vmc, nut=nut, nut_preload=0.15 * ca)
    ev = evaluate(d, use_casadi=False)
    assert float(ev["margin_nut_preload"]) == pytest.approx(0.10 / 0.15, rel=1e-12)
    rows = {r["check"]: r for r in check_rows(ev)}
    assert rows["nut_preload"]["pass"] is False


def test_a_nut_with_play_is_not_checked(vmc):
    from axisopt.model.drive import NOT_APPLICABLE

    nut = vmc.nut.copy()
    nut["type"] = "single"
    d = replace(vmc, nut=nut, nut_preload=0.0)
    ev = evaluate(d, use_casadi=False)
    assert float(ev["margin_nut_preload"]) >= NOT_APPLICABLE


def test_search_keeps_preloads_under_the_ceiling():
    """A catalog whose preloaded nuts allow up to 20 % Ca (more than any vendor): the search's
    preload range stops at the ceiling, so the optimum's preload is at most 10 % Ca, its check
    passes, and the default method still equals exhaustive enumeration."""
    from axisopt.problem import load_problem
    from axisopt.search import solve

    p = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    nuts = p.catalog.nuts.copy()
    double = nuts["type"] != "single"
    nuts.loc[double, "preload_max"] = 0.2 * nuts.loc[double, "dynamic_load_rating"]
    # drag and life loose enough that the preload would climb above the ceiling if the range allowed
    # it
    p = replace(p, catalog=p.catalog.replace(nuts=nuts)).with_limit("max_drag_torque", 20.0)
    p = p.with_limit("min_life", 1000 * 3600.0)
    from axisopt.search.parts import build_space

    sp = build_space(p)
    ceiling = 0.1 * sp.nuts.number("dynamic_load_rating")
    assert (sp.preload_hi <= ceiling * (1 + 1e-12)).all() and (sp.preload_hi > 0.99 * ceiling).any()
    d = solve(p, top=1, sensitivities=False)
    # an hour, not the default 100 s wall: on a loaded machine the exhaustive reference's CPU can
    # take longer (it stopped at the limit, unproven, on a shared 2-core machine)
    e = solve(p, "exhaustive", top=1, sensitivities=False, time_limit=3600.0)
    assert e.status == "optimal"
    assert d.best.combination == e.best.combination
    assert d.best.objective == pytest.approx(e.best.objective, rel=1e-9)
    ca = float(d.best.design.nut["dynamic_load_rating"])
    assert d.best.nut_preload <= 0.1 * ca * (1 + 1e-12)
    ev = evaluate(d.best.design, use_casadi=False)
    assert float(ev["margin_nut_preload"]) >= 1.0 - 1e-9


def test_nuts_whose_whole_range_is_above_the_ceiling_are_named_in_the_error():
    from axisopt.errors import InputError
    from axisopt.problem import load_problem
    from axisopt.search import solve

    p = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    nuts = p.catalog.nuts.copy()
    double = nuts["type"] != "single"
    nuts.loc[double, "preload_min"] = 0.12 * nuts.loc[double, "dynamic_load_rating"]
    nuts.loc[double, "preload_max"] = 0.2 * nuts.loc[double, "dynamic_load_rating"]
    with pytest.raises(InputError, match="preload ceiling"):
        solve(replace(p, catalog=p.catalog.replace(nuts=nuts)), top=1, sensitivities=False)
