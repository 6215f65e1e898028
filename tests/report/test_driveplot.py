"""The plot of a drive types' answer (report.driveplot) draws what it says: one bar per (design,
margin) whose length is that margin, the line at 1, and one point per design at (cost,
objective)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.patches import Rectangle

from axisopt.problem import load_problem
from axisopt.report.driveplot import plot_drive_designs
from axisopt.report.drivetype import LABELS
from axisopt.search.drivetype import solve_drive_types

ROOT = Path(__file__).resolve().parents[2]


def test_bars_are_the_margins_and_points_the_designs(tmp_path):
    res = solve_drive_types(load_problem(ROOT / "problems" / "laser_lm_problem.yaml"), top=3)
    designs = [res.best] + list(res.runners_up)
    path = tmp_path / "p.png"
    fig = plot_drive_designs(res, str(path), top=3)
    assert path.stat().st_size > 0
    ax1, ax2 = fig.axes[:2]
    keys = sorted({k for d in designs for k in d.margins})
    for i, d in enumerate(designs, start=1):
        cont = [c for c in ax1.containers if c.get_label() == f"#{i} {LABELS[d.drive_type]}"]
        assert len(cont) == 1
        assert all(isinstance(b, Rectangle) for b in cont[0].patches)
        widths = [b.get_width() for b in cont[0].patches]
        np.testing.assert_allclose(widths, [d.margins.get(k, np.nan) for k in keys], rtol=1e-12)
        (pt,) = [ln for ln in ax2.lines if ln.get_gid() == f"design-{i}"]
        assert pt.get_xdata()[0] == d.cost and pt.get_ydata()[0] == d.objective
    ones = [ln for ln in ax1.lines if list(ln.get_xdata()) == [1.0, 1.0]]
    assert len(ones) == 1
