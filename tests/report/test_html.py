"""``--report FILE.html`` on evaluate, solve, compare, study and diagnose: one self-contained file that a real
headless browser (Debian's Chromium, installed by .ci/run) loads without console errors, with every figure
drawn and no sideways scrolling at a phone's width.

Without Chromium, chromedriver or selenium the browser part is skipped, unless AXISOPT_REQUIRE_BROWSER=1
(set by .ci/run), which turns the skip into a failure."""

import os
import re
import shutil
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
P = ROOT / "problems"
PHONE = (412, 900)


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
        "evaluate": (["evaluate", str(P / "vmc_x_design.yaml")], 2),
        "solve": (["solve", str(P / "teaching_problem.yaml"), "--top", "3", "--no-sensitivity"], 1),
        "pareto": (["solve", str(P / "pareto_problem.yaml"), "--no-sensitivity"], 1),
        "compare": (["compare", str(P / "vmc_x_design.yaml"), str(P / "paper_3_1_3_d40.yaml")], 1),
        "study": (["study", str(P / "studies" / "teaching_random.yaml"), "--out", str(d / "study"),
                   "--workers", "0", "--quiet"], None),
        "diagnose": (["diagnose", str(P / "data" / "table_x_stiffness.csv"), "--design",
                      str(P / "data" / "table_x.yaml")], 1),
    }
    out = {}
    for name, (argv, figs) in runs.items():
        path = d / f"{name}.html"
        assert main([*argv, "--report", str(path)]) in (0, 1), name  # the study has infeasible cases: 1
        out[name] = (path, figs)
    return out


def test_reports_are_self_contained(reports):
    for name, (path, _) in reports.items():
        text = path.read_text(encoding="utf-8")
        assert text.startswith("<!DOCTYPE html>") and 'name="viewport"' in text, name
        # nothing fetched from elsewhere: no external script, stylesheet or image
        assert not re.search(r'<(script|link|img)[^>]+(src|href)="(https?:)?//', text), name


def test_reports_render_in_a_headless_browser(reports):
    _browser_or_skip()
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    opts = Options()
    opts.binary_location = shutil.which("chromium")
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--enable-unsafe-swiftshader", f"--window-size={PHONE[0]},{PHONE[1]}"):
        opts.add_argument(a)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=opts)
    try:
        for name, (path, figs) in reports.items():
            driver.get(path.as_uri())
            driver.get_log("browser")  # logs are read per page below; clear what loading left behind
            driver.refresh()
            n_plots = driver.execute_script("return document.querySelectorAll('.js-plotly-plot').length")
            drawn = driver.execute_script(
                "return Array.from(document.querySelectorAll('.js-plotly-plot'))"
                ".filter(p => p.querySelector('.main-svg') && p.getBoundingClientRect().height > 100).length")
            errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
            assert not errors, (name, errors)
            assert n_plots >= (figs or 1) and drawn == n_plots, (name, n_plots, drawn)
            if figs is not None:
                assert n_plots == figs, (name, n_plots)
            width, inner = driver.execute_script(
                "return [document.documentElement.scrollWidth, window.innerWidth]")
            assert width <= inner + 1, (name, width, inner)  # wide tables scroll inside their box
            headings = driver.execute_script("return document.querySelectorAll('h2').length")
            cards = driver.execute_script("return document.querySelectorAll('.card').length")
            assert headings >= 2 and cards >= 2, name
    finally:
        driver.quit()


def test_report_contents(reports):
    ev = reports["evaluate"][0].read_text(encoding="utf-8")
    assert "min axial stiffness" in ev and "130.4 N/um" in ev  # README's VMC figure
    assert "4,353 rpm" in ev  # the critical speed with its unit, as evaluate prints it
    diag = reports["diagnose"][0].read_text(encoding="utf-8")
    assert "Residuals: table_x_stiffness.csv" in diag


@pytest.mark.parametrize("argv", [
    ["evaluate", str(P / "vmc_x_design.yaml"), "--report", "out.txt"],
    ["solve", str(P / "teaching_problem.yaml"), "--report", "out.png"],
])
def test_report_needs_an_html_name(argv, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--report" in err and ".html" in err
