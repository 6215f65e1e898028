"""``axisopt schema``: the JSON Schemas written from the readers' key tables (yamlio.Spec).

Every shipped YAML validates against its schema; a misspelt key, a unit of the wrong kind or a value
out of range fails both the schema and the loader; the schema holds every key the readers declare
(it is their translation, not a second copy); the command's bad input is one line and exit code 2.
"""

from __future__ import annotations

import json

import pytest

from axisopt.cli import main
from axisopt.schema import KINDS_OF_FILE, json_schema

# --------------------------------------------------------------------------------------------------
# --- the CLI


def test_cli_prints_and_writes_the_schema(tmp_path, capsys):
    assert main(["schema", "design"]) == 0
    assert json.loads(capsys.readouterr().out) == json_schema("design")
    out = tmp_path / "design.schema.json"
    assert main(["schema", "problem", "--out", str(out)]) == 0
    assert json.loads(out.read_text()) == json_schema("problem")
    assert capsys.readouterr().out == ""


@pytest.mark.parametrize(
    "argv",
    [["schema", "nope"], ["schema"], ["schema", "design", "--out", "/nonexistent/dir/x.json"]],
)
def test_cli_bad_input_is_one_line_and_exit_2(capsys, argv):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("error:") and "\n" not in err, err


def test_cli_kinds_are_the_schema_kinds():
    from axisopt.cli.schema import FILE_KINDS

    assert FILE_KINDS == KINDS_OF_FILE
