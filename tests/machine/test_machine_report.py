"""The machine's HTML report: the stiffness chain at the tool with every link (shares that add up to
the tool's compliance), the per-axis designs, the frequencies, the sequential sizing; the figure
checked by what it draws."""

import pytest
from machinegen import random_machine

from axisopt.cli import main
from axisopt.machine import load_machine, solve_machine
from axisopt.report.machine import format_machine
from axisopt.report.machine_html import compliance_figure, link_rows, machine_page


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    p = tmp_path_factory.mktemp("mr") / "m.yaml"
    p.write_text(random_machine(4))
    res = solve_machine(load_machine(p))
    assert res.best is not None
    return p, res


def test_every_link_shown_and_the_shares_add_up(solved):
    _p, res = solved
    md = res.best
    rows = link_rows(md)
    assert len(rows) == 3 * (len(md.axes) + 1)
    for d in "xyz":
        mine = [r for r in rows if r[1] == d]
        assert [r[0] for r in mine] == [a.name for a in md.axes] + ["tool"]
        assert sum(float(r[6].rstrip(" %")) for r in mine[:-1]) == pytest.approx(
            100.0, abs=0.1 * len(mine)
        )
        tool = float(mine[-1][5].replace(",", ""))
        assert tool == pytest.approx(md.k_tool["xyz".index(d)] * 1e-6, abs=0.051)


def test_the_figure_stacks_every_link_to_the_tool_compliance(solved):
    _p, res = solved
    md = res.best
    fig = compliance_figure(md)
    ax = fig.axes[0]
    bars = ax.patches
    assert len(bars) == 3 * 2 * len(md.axes)
    for i in range(3):
        total = sum(b.get_width() for b in bars if abs(b.get_y() + b.get_height() / 2 - i) < 1e-9)
        assert total == pytest.approx(1e9 / md.k_tool[i], rel=1e-9)
    assert len(ax.get_legend().get_texts()) == 2 * len(md.axes)


def test_page_and_cli_report(solved, tmp_path):
    p, res = solved
    html = machine_page(res, format_machine(res)).render("no")
    for text in (
        "Joint optimum: stiffness at the tool, each link",
        "Sequential sizing: every axis",
        "natural frequencies",
        "Dunkerley",
        "<svg",
    ):
        assert text in html
    out = tmp_path / "m.html"
    assert main(["machine", "solve", str(p), "--report", str(out)]) == 0
    assert "Compliance at the tool, each link" in out.read_text()
    assert main(["machine", "solve", str(p), "--report", str(tmp_path / "m.txt")]) == 2
