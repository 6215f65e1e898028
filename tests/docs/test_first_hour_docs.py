"""What a new user read and found untrue or missing (issue 57): the tutorial names every machine
template, the templates of machines that do not turn quote no turning rule of thumb, study.md's
pointer to "Output paths" names the page that has it, and the README says what the test suite takes
and needs."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from axisopt.cli.init import MACHINES, template

ROOT = Path(__file__).resolve().parents[2]


def test_the_tutorial_lists_every_machine_template():
    text = (ROOT / "docs" / "tutorial.md").read_text(encoding="utf-8")
    line = next(x for x in text.splitlines() if x.startswith("`--machine` is one of"))
    assert set(re.findall(r"`(\w+)`", line)) >= set(MACHINES)


@pytest.mark.parametrize("machine", MACHINES)
@pytest.mark.parametrize("kind", ["problem", "design"])
def test_only_the_lathe_template_quotes_the_turning_rule(machine, kind):
    text = template(kind, machine)
    assert ("Turning rule of thumb" in text) == (machine == "lathe")


def test_output_paths_pointer_names_its_page():
    study = (ROOT / "docs" / "study.md").read_text(encoding="utf-8")
    assert '"Output paths" above' not in study and "(errors.md)" in study
    assert "**Output paths.**" in (ROOT / "docs" / "errors.md").read_text(encoding="utf-8")


def test_readme_says_what_the_suite_takes_and_needs():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    # the README quotes a measured time of the suite on 2 cores, with its date
    assert re.search(r"took [\d,]+ s on (CI's )?2 (idle )?cores[^.]*\(\d{4}-\d\d-\d\d\)", text)
    assert "chromium-driver" in text and ".ci/run" in text
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert "chromium chromium-driver" in ci  # what the README says .ci/run installs
