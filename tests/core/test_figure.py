"""axisopt in a notebook (issue 30 item 3): ``import axisopt`` is light, its functions return
results with ``to_frame()`` (units in the column names), a short repr in engineering units and an
HTML table."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"


def test_plot_profiles_returns_a_figure_and_writes_only_with_a_path(tmp_path, monkeypatch):
    import axisopt

    ev = axisopt.evaluate(axisopt.load_design(PROBLEMS / "teaching_design.yaml"))
    # restored after the test: others read paths relative to the repository
    monkeypatch.chdir(tmp_path)
    fig = axisopt.plot_profiles(ev)
    assert [a.get_ylabel() for a in fig.axes[:2]] == [
        "axial stiffness [N/um]",
        "1st natural frequency [Hz]",
    ]
    assert list(tmp_path.iterdir()) == []
    axisopt.plot_profiles([ev], tmp_path / "p.png")
    assert (tmp_path / "p.png").stat().st_size > 1000
