"""A figure whose decorations cannot fit (the study's trade-off plot with a long legend did this in
bench_study) is saved without matplotlib's 'Tight layout not applied' UserWarning reaching the user."""

import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from axisopt.fileio import tidy_layout  # noqa: E402


def _crowded():
    fig, ax = plt.subplots(figsize=(2, 1.5))
    ax.set_title("line\n" * 30)
    return fig


def test_plain_tight_layout_warns_and_tidy_layout_does_not():
    fig = _crowded()
    with pytest.warns(UserWarning, match="Tight layout not applied"):
        fig.tight_layout()
    fig = _crowded()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        tidy_layout(fig)
    plt.close("all")
