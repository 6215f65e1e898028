"""``--report FILE.html`` on evaluate, solve, compare, study and diagnose: one self-contained file
that a real headless browser (Debian's Chromium, installed by .ci/run) loads without console errors,
with every figure drawn, every table fitting a 1280 px window and readable at a phone's 390 px (no
column hidden, a table wider than the phone scrolls inside its own box, the page never sideways),
and each page at most 1.5 MB (static SVG figures by default; ``--plotly inline`` interactive
figures).

Without Chromium, chromedriver or selenium the browser part is skipped, unless
AXISOPT_REQUIRE_BROWSER=1 (set by .ci/run), which turns the skip into a failure."""

import os
import re
import shutil
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
P = ROOT / "problems"
PHONE = (390, 900)  # a small phone's CSS width
DESKTOP = (1280, 900)  # a laptop window (issue 42: the compare and Pareto tables overflowed it)
MAX_PAGE_BYTES = 1_500_000  # issue 42: every page embedded plotly, 4.8-5.2 MB


def _browser_or_skip():
    missing = [n for n in ("chromium", "chromedriver") if shutil.which(n) is None]
    try:
        import selenium  # noqa: F401
    except ImportError:
        missing.append("selenium")
    if missing:
        if os.environ.get("AXISOPT_REQUIRE_BROWSER") == "1":
            pytest.fail(f"AXISOPT_REQUIRE_BROWSER=1 but {', '.join(missing)} not installed")
        pytest.skip(f"no {', '.join(missing)}")


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    """Every command's HTML report, written once: name -> (path, figures expected)."""
    pytest.importorskip("plotly")
    d = tmp_path_factory.mktemp("html")
    runs = {
        # profiles with the drive, chain, FRF
        "evaluate": (["evaluate", str(P / "vmc_x_design.yaml")], 3),
        # + drive
        "interactive": (["evaluate", str(P / "vmc_x_design.yaml"), "--plotly", "inline"], 4),
        # the best designs' profiles and drive, the winner's chain and FRF
        "solve": (["solve", str(P / "teaching_problem.yaml"), "--top", "3", "--no-sensitivity"], 3),
        "pareto": (["solve", str(P / "pareto_problem.yaml"), "--no-sensitivity"], 1),
        "compare": (["compare", str(P / "vmc_x_design.yaml"), str(P / "paper_3_1_3_d40.yaml")], 1),
        "study": (
            [
                "study",
                str(P / "studies" / "teaching_random.yaml"),
                "--out",
                str(d / "study"),
                "--workers",
                "0",
                "--quiet",
            ],
            None,
        ),
        "diagnose": (
            [
                "diagnose",
                str(P / "data" / "table_x_stiffness.csv"),
                "--design",
                str(P / "data" / "table_x.yaml"),
            ],
            1,
        ),
    }
    out = {}
    for name, (argv, figs) in runs.items():
        path = d / f"{name}.html"
        # the study has infeasible cases: 1
        assert main([*argv, "--report", str(path)]) in (0, 1), name
        out[name] = (path, figs)
    return out


def test_reports_are_self_contained(reports):
    for name, (path, _) in reports.items():
        text = path.read_text(encoding="utf-8")
        assert text.startswith("<!DOCTYPE html>") and 'name="viewport"' in text, name
        # nothing fetched from elsewhere: no external script, stylesheet or image
        assert not re.search(r'<(script|link|img)[^>]+(src|href)="(https?:)?//', text), name


def test_default_reports_are_small_and_need_no_plotly(reports):
    for name, (path, _) in reports.items():
        size = path.stat().st_size
        text = path.read_text(encoding="utf-8")
        if name == "interactive":  # plotly.js inlined: the option, not the default
            assert "Plotly" in text
            continue
        assert size <= MAX_PAGE_BYTES, (name, size)
        # static SVG figures, no script at all
        assert "<script" not in text and "<svg" in text, name


def _driver(size):
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    opts = Options()
    opts.binary_location = shutil.which("chromium")
    for a in (
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-dev-shm-usage",
        "--enable-unsafe-swiftshader",
        f"--window-size={size[0]},{size[1]}",
    ):
        opts.add_argument(a)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=opts)


# per table: its width, the width of the box it sits in, whether that box scrolls sideways, and the
# cells that are not shown (display none, hidden, zero width or clipped by an ancestor other than
# the table's own box)
_TABLES = """
return Array.from(document.querySelectorAll('table')).map(t => {
  const box = t.parentElement, cs = getComputedStyle(box);
  const cells = Array.from(t.querySelectorAll('th, td'));
  const hidden = cells.filter(c => { const s = getComputedStyle(c), r = c.getBoundingClientRect();
    return s.display === 'none' || s.visibility === 'hidden' || r.width < 1; }).length;
  const widths = Array.from(t.rows[0].cells).map(c => c.getBoundingClientRect().width);
  return {first: t.rows[0].cells[0].textContent,
          width: t.getBoundingClientRect().width, box: box.clientWidth, scrolls: cs.overflowX === 'auto',
          hidden: hidden, columns: t.rows[0].cells.length, narrowest: Math.min(...widths)};
});"""  # noqa: E501


@pytest.mark.parametrize("size", [DESKTOP, PHONE], ids=["1280px", "390px"])
def test_every_table_fits_or_scrolls_inside_its_box(reports, size):
    _browser_or_skip()
    driver = _driver(size)
    try:
        for name, (path, _) in reports.items():
            driver.get(path.as_uri())
            inner, page = driver.execute_script(
                "return [window.innerWidth, document.documentElement.scrollWidth]"
            )
            assert page <= inner + 1, (name, size, page, inner)  # never a page-wide sideways scroll
            tables = driver.execute_script(_TABLES)
            for t in tables:
                assert t["hidden"] == 0 and t["narrowest"] >= 8, (name, size, t)  # no column hidden
                if size == DESKTOP:
                    # every column in view at 1280 px
                    assert t["width"] <= t["box"] + 1, (name, size, t)
                else:  # at 390 px: fits, or scrolls inside its own box (reachable, never cut off)
                    assert t["width"] <= t["box"] + 1 or t["scrolls"], (name, size, t)
            if name in ("evaluate", "solve") and size == PHONE:
                # the checks table reads on a phone without scrolling: margin and result in view
                assert all(t["width"] <= t["box"] + 1 for t in tables), (name, tables)
    finally:
        driver.quit()


def test_reports_render_in_a_headless_browser(reports):
    _browser_or_skip()
    driver = _driver(PHONE)
    try:
        for name, (path, figs) in reports.items():
            driver.get(path.as_uri())
            # logs are read per page below; clear what loading left behind
            driver.get_log("browser")
            driver.refresh()
            n_plots = driver.execute_script("return document.querySelectorAll('.fig').length")
            drawn = driver.execute_script(
                "return Array.from(document.querySelectorAll('.fig'))"
                ".filter(p => p.querySelector('svg') && p.getBoundingClientRect().height > "
                "100).length"
            )
            errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
            assert not errors, (name, errors)
            assert n_plots >= (figs or 1) and drawn == n_plots, (name, n_plots, drawn)
            if figs is not None:
                assert n_plots == figs, (name, n_plots)
            width, inner = driver.execute_script(
                "return [document.documentElement.scrollWidth, window.innerWidth]"
            )
            assert width <= inner + 1, (name, width, inner)  # wide tables scroll inside their box
            headings = driver.execute_script("return document.querySelectorAll('h2').length")
            cards = driver.execute_script("return document.querySelectorAll('.card').length")
            assert headings >= 2 and cards >= 2, name
    finally:
        driver.quit()


def test_report_contents(reports):
    ev = reports["evaluate"][0].read_text(encoding="utf-8")
    assert "min axial stiffness" in ev and "125.7 N/um" in ev  # README's VMC figure
    assert "4,328 rpm" in ev  # the critical speed with its unit, as evaluate prints it
    diag = reports["diagnose"][0].read_text(encoding="utf-8")
    assert "Residuals: table_x_stiffness.csv" in diag


@pytest.mark.parametrize(
    "argv",
    [
        ["evaluate", str(P / "vmc_x_design.yaml"), "--report", "out.txt"],
        ["solve", str(P / "teaching_problem.yaml"), "--report", "out.png"],
    ],
)
def test_report_needs_an_html_name(argv, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--report" in err and ".html" in err


def test_cdn_option_links_plotly_instead_of_inlining_it(tmp_path):
    pytest.importorskip("plotly")
    from plotly.offline import get_plotlyjs
    from plotly.offline.offline import get_plotlyjs_version

    inline, cdn = tmp_path / "inline.html", tmp_path / "cdn.html"
    assert (
        main(
            [
                "evaluate",
                str(P / "vmc_x_design.yaml"),
                "--report",
                str(inline),
                "--plotly",
                "inline",
            ]
        )
        == 0
    )
    assert (
        main(["evaluate", str(P / "vmc_x_design.yaml"), "--report", str(cdn), "--plotly", "cdn"])
        == 0
    )
    a, b = inline.read_text(encoding="utf-8"), cdn.read_text(encoding="utf-8")
    src = f'<script src="https://cdn.plot.ly/plotly-{get_plotlyjs_version()}.min.js"'
    assert src in b and src not in a
    # plotly.js (about 4.7 MB) is not in the file
    assert len(a) - len(b) > 0.95 * len(get_plotlyjs())
    assert "works offline" in a and "loaded from https://cdn.plot.ly/" in b


def test_margins_are_coloured_by_how_close_they_are():
    from axisopt.report.html import margin_class

    assert [margin_class(m) for m in (0.5, 0.999, 1.0, 1.05, 1.1, 1.49, 1.5, 76.0)] == [
        "m-fail",
        "m-fail",
        "m-tight",
        "m-tight",
        "m-fair",
        "m-fair",
        "m-ample",
        "m-ample",
    ]
    assert margin_class(None) == "" and margin_class(float("nan")) == ""
    # a check that passes on its limit (the solver's 0.9999999, printed 1.00) is tight, not red
    assert margin_class(0.9999999, True) == "m-tight" and margin_class(0.9999999, False) == "m-fail"


def _rows(html_text, heading):
    """The body rows of the first table after the section heading ``heading`` (cells as text)."""
    part = html_text.split(heading, 1)[1].split("</table>", 1)[0]
    return [
        re.findall(r"<td[^>]*>(.*?)</td>", tr) for tr in re.findall(r"<tr>(.*?)</tr>", part)[1:]
    ]


def test_evaluate_page_colours_every_margin(reports):
    import html as h

    from axisopt.design import load_design
    from axisopt.model import evaluate
    from axisopt.report.evaluation import check_rows
    from axisopt.report.html import margin_class

    text = reports["evaluate"][0].read_text(encoding="utf-8")
    for r in check_rows(evaluate(load_design(P / "vmc_x_design.yaml"))):
        if r["margin"] is not None:
            cell = f'<td class="{margin_class(r["margin"], r["pass"])} n">{r["margin"]:.2f}</td>'
            assert cell in text.split(h.escape(r["label"]), 1)[1].split("</tr>", 1)[0], r["check"]
    assert "drive against the motor" in text and "Dynamic compliance of the table" in text
    interactive = reports["interactive"][0].read_text(encoding="utf-8")
    assert "Drive: duty cycle against the motor" in interactive


def test_pareto_page_lists_every_point(reports):
    from axisopt.problem import load_problem
    from axisopt.search import solve

    front = solve(load_problem(P / "pareto_problem.yaml"), sensitivities=False).pareto
    rows = _rows(reports["pareto"][0].read_text(encoding="utf-8"), "Every point of the front")
    assert len(rows) == len(front.points) >= 5
    assert [r[0] for r in rows] == [str(i) for i in range(1, len(front.points) + 1)]


def test_compare_page_is_a_table_naming_failed_checks(reports):
    from axisopt.design import load_design
    from axisopt.model import evaluate
    from axisopt.report.evaluation import check_rows

    text = reports["compare"][0].read_text(encoding="utf-8")
    rows = _rows(text, "Side by side")
    assert len(rows) == 2
    failed = [
        r["check"]
        for r in check_rows(evaluate(load_design(P / "paper_3_1_3_d40.yaml")))
        if not r["pass"]
    ]
    assert failed and rows[1][-1] == ", ".join(failed) and rows[0][-1] == "none"


def test_study_page_has_no_raw_markdown_and_gives_the_reasons(reports):
    text = reports["study"][0].read_text(encoding="utf-8")
    body = text.split("</head>", 1)[1]  # past the style sheet
    assert "![" not in body and "](plots/" not in body
    cases = body.split("Cases", 1)[1].split("</table>", 1)[0]
    assert "<th>reason</th>" in cases and "<th>status</th>" in cases
    assert "<th>parts: screw / nut / bearing / guide / motor" in cases.replace("<wbr>", "")


def test_a_successful_diagnosis_is_not_red(reports):
    # issue 42: the verdict card of a diagnosis that named its cause was red
    text = reports["diagnose"][0].read_text(encoding="utf-8")
    card = text.split('<div class="k">verdict</div>', 1)[0].rsplit('<div class="card', 1)[1]
    assert card.startswith(' ok"'), card
