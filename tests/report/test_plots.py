"""Plots that tell the truth: legends name every part that differs, limits are drawn, the Pareto
plot shows every objective pair with the front marked against the designs it dominates."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from axisopt.cli import main
from axisopt.report.plots import distinct_labels

ROOT = Path(__file__).resolve().parents[2]


def _capture(monkeypatch, module):
    figs = []

    def keep(fig, path, dpi=110):
        figs.append(fig)

    monkeypatch.setattr(module, "save_figure", keep)
    return figs


def test_labels_name_each_differing_part_and_only_those():
    items = [
        {"mounting": "fixed-fixed", "screw": "S1", "nut": "N1", "guide": "G1"},
        {"mounting": "fixed-fixed", "screw": "S1", "nut": "N1", "guide": "G2"},
        {"mounting": "fixed-supported", "screw": "S1", "nut": "N1", "guide": "G1"},
    ]
    labels = distinct_labels(items, ["#1", "#2", "#3"])
    assert len(set(labels)) == 3
    assert labels[1] == "#2 fixed-fixed / G2"  # the guide is the difference between #1 and #2
    assert all("S1" not in lab and "N1" not in lab for lab in labels)  # shared parts are left out


def test_solve_plot_legend_tells_runners_up_apart_and_draws_the_limit(monkeypatch, tmp_path):
    import axisopt.report.plots as plots

    figs = _capture(monkeypatch, plots)
    text = (ROOT / "problems" / "teaching_problem.yaml").read_text()
    text = text.replace("limits:\n", "limits:\n  min_stiffness: 60 N/um\n", 1)
    prob = tmp_path / "t_problem.yaml"
    prob.write_text(text)
    assert (
        main(
            [
                "solve",
                str(prob),
                "--top",
                "4",
                "--no-sensitivity",
                "--plot",
                str(tmp_path / "p.png"),
            ]
        )
        == 0
    )
    ax, ax2 = figs[0].axes[0], figs[0].axes[1]
    # the designs' legend sits below the frequency panel (off the data); every rank is named exactly
    # once, designs whose curves coincide share one line (no curve drawn twice over another)
    legend = [t.get_text() for t in ax2.get_legend().get_texts()]
    designs = [lab for lab in legend if lab.startswith("#")]
    ranks = [
        r for lab in designs for r in re.findall(r"#(\d+)", lab.split(" (")[0].split(" HIWIN")[0])
    ]
    assert sorted(ranks) == ["1", "2", "3", "4"]
    curves = [ln for ln in ax.get_lines() if ln.get_label().startswith("#")]
    assert len(curves) == len(designs)
    ys = [np.round(ln.get_ydata(), 3).tobytes() for ln in curves]
    assert len(set(ys)) == len(ys), "two legend entries draw the same curve"
    assert any("the same curves" in lab for lab in designs)  # #1/#2 differ only in the motor
    limit = [ln for ln in ax.get_lines() if ln.get_label().startswith("min_stiffness")]
    assert len(limit) == 1 and np.allclose(limit[0].get_ydata(), 60.0)
    assert any(lab.startswith("min_stiffness") for lab in legend)


@pytest.fixture(scope="module")
def pareto_result():
    from axisopt.problem import load_problem
    from axisopt.search import solve

    return solve(load_problem(ROOT / "problems" / "pareto_problem.yaml"))


def test_pareto_plot_is_a_scatter_matrix_with_the_front_marked(
    monkeypatch, tmp_path, pareto_result
):
    import axisopt.fileio as fileio
    import axisopt.report.solve as solve_report
    import axisopt.search.pareto as pareto

    figs = _capture(monkeypatch, fileio)
    front = pareto_result.pareto
    d = len(front.keys)
    assert d == 4
    solve_report.plot_pareto(front, str(tmp_path / "f.png"))
    fig = figs[0]
    grid = [ax for ax in fig.axes if ax.get_label() != "<colorbar>"]
    assert len(grid) == d * d
    # every off-diagonal panel: the dominated sample (grey) and exactly the front's points
    off = [ax for k, ax in enumerate(grid) if k // d != k % d]
    for ax in off:
        sizes = sorted(len(c.get_offsets()) for c in ax.collections)
        assert len(front.points) in sizes and max(sizes) == min(front.feasible, pareto.CLOUD)
    labels = {ax.get_xlabel() for ax in grid} | {ax.get_ylabel() for ax in grid}
    for k, u in zip(front.keys, front.units):
        assert any(k.replace("_", " ") in lab and u in lab for lab in labels)


def test_front_points_are_not_dominated_by_the_cloud(pareto_result):
    # the grey sample must lie on the dominated side: no sampled design beats a front point
    # everywhere
    f = pareto_result.pareto
    sign = np.array([1.0 if s == "max" else -1.0 for s in f.senses])
    C = np.asarray(f.cloud) * sign
    fields = {
        "stiffness": "min_stiffness",
        "frequency": "min_frequency",
        "cost": "cost",
        "total_mass": "total_mass",
    }
    F = np.array([[getattr(p, fields[k]) for k in f.keys] for p in f.points]) * sign
    # the cloud comes from the numpy evaluation, the front points from the CasADi one: equal up to
    # rounding
    tol = 1e-12 * np.maximum(np.abs(F), 1.0)[None, :, :]
    strictly = (C[:, None, :] >= F[None, :, :] - tol).all(-1) & (
        C[:, None, :] > F[None, :, :] + tol
    ).any(-1)
    assert not strictly.any() and len(C) == min(f.feasible, 4000)
