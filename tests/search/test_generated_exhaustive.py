"""Default == exhaustive on the generated axes' sample (issue 52).

bench/axis_generator.py writes one case in five as a shortlist (one supplier per part kind, one
series each, as a machine builder with framework contracts writes it): at most 10^6 combinations,
few enough to enumerate.  The
sample: the shortlist cases of seed 0 among its first 100 with at most 10^5 combinations (their
indices are listed; the test checks each is still a shortlist of that size).  Each is solved by the
default method and by ``--method exhaustive`` (every combination, its preload on a grid): the same
status, and the same optimum or the same proof that no combination meets every limit.
bench/bench_generalize.py --compare runs the same comparison on larger samples."""

import sys
import warnings
from pathlib import Path

import pytest

from axisopt.errors import ImplausibleInput
from axisopt.problem import load_problem
from axisopt.search import solve

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
from axis_generator import make  # noqa: E402

SAMPLE = (35, 42, 53, 60, 78)


@pytest.mark.slow
@pytest.mark.parametrize("index", SAMPLE)
def test_default_equals_exhaustive_on_generated_shortlists(tmp_path, index):
    case = make(0, index)
    assert "  reductions: no" in case.text and "  nut_types: [double]" in case.text  # a shortlist
    f = tmp_path / f"{case.name}.yaml"
    f.write_text(case.text)
    with warnings.catch_warnings():  # a unit slip the generator drew is said, not refused
        warnings.simplefilter("ignore", ImplausibleInput)
        problem = load_problem(f)
    default = solve(problem, sensitivities=False)
    exhaustive = solve(problem, "exhaustive", sensitivities=False, time_limit=3600.0)
    assert default.certificate.combinations <= 100_000
    assert exhaustive.status in ("optimal", "infeasible")
    assert default.status == exhaustive.status
    assert default.certificate.proven
    if default.status == "optimal":
        assert default.best.objective == pytest.approx(exhaustive.best.objective, rel=1e-6)
    else:
        assert default.best is None and exhaustive.best is None
        # the same limits no combination meets on its own
        assert sorted(u[0] for u in default.infeasibility.unmeetable) == sorted(
            u[0] for u in exhaustive.infeasibility.unmeetable
        )
