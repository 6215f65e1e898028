"""Study summary plots: lines never join cases that differ in another swept input, the
cost/stiffness staircase never joins different machines (axis inputs), infeasible cases are shown,
not dropped."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pandas as pd

import axisopt.study.plots as table


def _study():
    sweeps = [
        SimpleNamespace(key="axis.stroke", values=["500 mm", "800 mm", "1100 mm"]),
        SimpleNamespace(key="limits.max_cost", values=["4000 EUR", "6000 EUR"]),
    ]
    return SimpleNamespace(name="s", sweeps=sweeps, cases=[])


def _frame():
    rows = []
    rng = np.random.default_rng(1)
    for stroke in (500.0, 800.0, 1100.0):
        for cost in (4000.0, 6000.0):
            infeasible = stroke == 1100.0 and cost == 4000.0
            rows.append(
                {
                    "axis.stroke [mm]": stroke,
                    "limits.max_cost [EUR]": cost,
                    "mounting": "fixed-fixed",
                    "status": "infeasible" if infeasible else "optimal",
                    "min_stiffness [N/um]": np.nan
                    if infeasible
                    else 300 - stroke / 10 + cost / 100,
                    "min_frequency [Hz]": np.nan if infeasible else 200 - stroke / 20,
                    "cost [EUR]": np.nan if infeasible else cost - rng.uniform(0, 500),
                }
            )
    return pd.DataFrame(rows)


def _figures(monkeypatch, tmp_path):
    figs = {}

    def keep(fig, path, dpi=110):
        figs[path.name] = fig

    monkeypatch.setattr(table, "save_figure", keep)
    table.summary_plots(_study(), _frame(), tmp_path / "plots", tmp_path)
    return figs


def test_lines_against_stroke_hold_the_other_input_fixed(monkeypatch, tmp_path):
    figs = _figures(monkeypatch, tmp_path)
    ax = figs["best_vs_axis_stroke.png"].axes[0]
    df = _frame()
    ok = df[df.status == "optimal"]
    shaded = [ln for ln in ax.get_lines() if ln.get_color() == "tab:red"]
    lines = [ln for ln in ax.get_lines() if ln not in shaded]
    assert len(lines) == 2  # one per max_cost value, never a line mixing the two budgets
    # lines that could coincide stay apart: each its own dash pattern and marker
    assert len({(ln.get_linestyle(), ln.get_marker()) for ln in lines}) == 2
    for ln in lines:
        x, y = ln.get_xdata(), ln.get_ydata()
        label = ln.get_label()
        assert label.startswith("max_cost = ") and label.endswith(" EUR")  # the input with its unit
        cost = float(label.split("=")[1].split()[0])
        want = ok[ok["limits.max_cost [EUR]"] == cost].sort_values("axis.stroke [mm]")
        assert np.allclose(x, want["axis.stroke [mm]"]) and np.allclose(
            y, want["min_stiffness [N/um]"]
        )
    # a case without a design has no value: its input is shaded across the panel, never drawn as a
    # zero
    assert len(shaded) == 1 and list(shaded[0].get_xdata()) == [1100.0, 1100.0]
    assert list(shaded[0].get_ydata()) == [0, 1] and "infeasible" in shaded[0].get_label()
    assert all(np.all(np.asarray(ln.get_ydata(), float) > 0) for ln in lines)


def test_tradeoff_staircase_stays_within_one_stroke(monkeypatch, tmp_path):
    figs = _figures(monkeypatch, tmp_path)
    ax = figs["tradeoff_cost_stiffness.png"].axes[0]
    df = _frame().dropna()
    steps = [ln for ln in ax.get_lines() if len(ln.get_xdata())]
    assert steps
    for ln in steps:
        xs = set(np.round(ln.get_xdata(), 6))
        strokes = set(df[np.isin(np.round(df["cost [EUR]"], 6), list(xs))]["axis.stroke [mm]"])
        assert len(strokes) == 1
    assert any("1 cases without a design" in t.get_text() for t in ax.texts)


def test_many_inputs_without_a_design_are_a_rug_not_bands(monkeypatch, tmp_path):
    """A random sweep leaves hundreds of distinct inputs without a design: they are one row of red
    ticks along the panel's bottom (one artist), not a band each that would paint the panel red."""
    df = _frame()
    rng = np.random.default_rng(3)
    extra = df[df.status != "optimal"].iloc[[0] * 30].copy()
    extra["axis.stroke [mm]"] = rng.uniform(500, 1500, 30)
    df = pd.concat([df, extra], ignore_index=True)
    figs = {}
    monkeypatch.setattr(
        table, "save_figure", lambda fig, path, dpi=110: figs.__setitem__(path.name, fig)
    )
    table.summary_plots(_study(), df, tmp_path / "plots", tmp_path)
    ax = figs["best_vs_axis_stroke.png"].axes[0]
    red = [ln for ln in ax.get_lines() if ln.get_color() == "tab:red"]
    assert len(red) == 1 and red[0].get_marker() == "|" and red[0].get_linestyle() == "None"
    bad = sorted(set(df[df.status != "optimal"]["axis.stroke [mm]"]))
    assert np.allclose(sorted(red[0].get_xdata()), bad) and set(red[0].get_ydata()) == {0.0}
    assert "31 cases" in red[0].get_label()
