import pytest
from study_helpers import small_study as _small_study


@pytest.fixture
def small_study(tmp_path):
    return _small_study(tmp_path)
