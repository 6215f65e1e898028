import pytest
from identify_helpers import DESIGN

from axisopt.design import load_design
from axisopt.identify import plant_from_design


@pytest.fixture(scope="module")
def plant():
    """The shipped table_x axis (problems/data/table_x.yaml) as the identification sees it, built
    once a module."""
    return plant_from_design(load_design(DESIGN))
