"""The generated reference pages equal what the code's tables give, and the site builds without a
warning."""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _gen():
    spec = importlib.util.spec_from_file_location("gen_docs", ROOT / "tools" / "gen_docs.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("page", ["yaml", "cli"])
def test_generated_page_is_up_to_date(page):
    gen = _gen()
    text = gen.generate()[page]
    assert gen.PAGES[page].read_text(encoding="utf-8") == text, (
        "stale: run python tools/gen_docs.py"
    )


def test_yaml_reference_lists_every_limit_check_and_column():
    from axisopt.catalog.columns import COLUMNS
    from axisopt.model.limits import CHECK_TABLE, LIMIT_TABLE

    text = _gen().yaml_reference()
    for name in [lim.key for lim in LIMIT_TABLE] + [c.name for c in CHECK_TABLE]:
        assert f"| `{name}` |" in text, name
    for table, cols in COLUMNS.items():
        assert f"### `{table}.csv`" in text
        assert all(f"| `{c.name}` |" in text for c in cols)
    assert "| `stroke` | length > 0 (e.g. `mm`) | **required** | travel of the table |" in text


def test_cli_reference_has_every_command():
    text = _gen().cli_reference()
    for cmd in ("evaluate", "solve", "diagnose", "compare", "study", "parts", "schema", "init"):
        assert f"## `axisopt {cmd}`" in text and f"usage: axisopt {cmd}" in text


def _gen_api():
    spec = importlib.util.spec_from_file_location("gen_api", ROOT / "tools" / "gen_api.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_api_reference_is_up_to_date_and_gives_units():
    # issue 42: an API reference page generated from the docstrings, with each field's unit
    gen = _gen_api()
    text = gen.generate()
    assert gen.PAGE.read_text(encoding="utf-8") == text, "stale: run python tools/gen_api.py"
    for name in gen.FUNCTIONS:
        assert f"### `axisopt.{name}(" in text, name
    assert "| `min_stiffness` | N/um | `float` |" in text and "| `cost` | EUR | `float` |" in text
    assert "| `time` | s | `float` |" in text and "| `objective` | as `objective_unit` |" in text
    assert "- `to_frame()`: pandas DataFrame of this design" in text  # Candidate's own table


def test_site_builds_strict(tmp_path):
    mkdocs = shutil.which("mkdocs") or str(Path(sys.executable).with_name("mkdocs"))
    if not Path(mkdocs).exists():
        pytest.skip("mkdocs is not installed (extra 'docs' or 'test')")
    r = subprocess.run(
        [mkdocs, "build", "--strict", "--site-dir", str(tmp_path / "site")],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r.returncode == 0, r.stderr[-2000:]
    assert (tmp_path / "site" / "tutorial" / "index.html").exists()
