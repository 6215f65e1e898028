"""The baseline a table diagnosis fits (identify.tables.measure): its names and kinds are the ones a
calibration may carry."""

from identify_helpers import DESIGN

from axisopt.design import load_design
from axisopt.identify import plant_from_design


def test_calibration_baseline_names_match_the_fit():
    """The names and kinds a calibration may carry are the ones diagnose fits
    (measure.baseline_params)."""
    from axisopt.identify.calibration import BASELINE_KINDS
    from axisopt.identify.tables.measure import baseline_params

    params = baseline_params(
        {"stiffness", "friction", "frf"}, plant_from_design(load_design(DESIGN))
    )
    assert {p.name: p.kind for p in params} == BASELINE_KINDS
