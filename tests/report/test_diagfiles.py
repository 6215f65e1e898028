"""The diagnosis report files (report.diagfiles): residual plots draw categorical factors as
categories."""

from pathlib import Path

from axisopt.cli import main


def test_residual_plot_draws_direction_as_categories(tmp_path, monkeypatch):
    # direction is +-1: a category per tick, not a continuous axis from -1 to 1
    import axisopt.report.diagfiles as rep  # the residual figures and categories since the split

    figs = []
    monkeypatch.setattr(rep, "save_figure", lambda fig, path, dpi=90: figs.append(fig))
    root = Path(__file__).resolve().parents[2] / "problems" / "data"
    assert (
        main(
            [
                "diagnose",
                str(root / "table_x_stiffness.csv"),
                "--design",
                str(root / "table_x.yaml"),
                "--report",
                str(tmp_path / "r"),
            ]
        )
        == 0
    )
    axes = {ax.get_xlabel(): ax for fig in figs for ax in fig.axes}
    d = axes["direction"]
    assert [t.get_text() for t in d.get_xticklabels()] == ["-1", "+1"]
    assert axes["position [mm]"].get_xticklabels()[0].get_text() != "-1"
    assert rep.categories("position", [0.0, 100.0, 200.0, 300.0]) is None
