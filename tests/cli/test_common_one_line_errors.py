"""Inputs refused in one line on stderr (exit 2) naming the file and key (issue 24, items 3, 5 and
7): a time record without force, line breaks and internal objects in messages, YAML tags, inputs
that used to be accepted silently; a saved design's header cannot inject YAML.  Item 4 (the motion
commanded): tests/design/test_keys_duty_cycle.py."""

from __future__ import annotations

from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.cli import main
from axisopt.cli.common import MAX_ERROR_CHARS, one_line

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"
DATA = PROBLEMS / "data"
VMC = (PROBLEMS / "vmc_x_design.yaml").read_text(encoding="utf-8")


# ------------------------------------------------------------------------- 3. a time record with
# all-zero force


def _zero_force(tmp_path, src: Path, name: str) -> str:
    out, header = [], None
    for line in src.read_text(encoding="utf-8").splitlines():
        if line.startswith("#") or not line.strip():
            out.append(line)
        elif header is None:
            header = line.split(",")
            j = next(i for i, h in enumerate(header) if h.startswith("force"))
            out.append(line)
        else:
            cells = line.split(",")
            cells[j] = "0"
            out.append(",".join(cells))
    return write_file(tmp_path, name, "\n".join(out) + "\n")


@pytest.mark.parametrize("which", ["estimation", "validation"])
def test_time_record_with_zero_force_is_aone_line_error(tmp_path, capsys, which):
    est, val = DATA / "table_x_run_est.csv", DATA / "table_x_run_val.csv"
    if which == "estimation":
        files = [_zero_force(tmp_path, est, "est.csv"), str(val)]
    else:
        files = [str(est), _zero_force(tmp_path, val, "val.csv")]
    assert main(["diagnose", *files, "--design", str(DATA / "table_x.yaml")]) == 2
    err = one_line_error(capsys)
    assert "force column is constant" in err and "column 3" in err


# ------------------------------------------------------------------------- 5. one line, no internal
# objects


def test_one_line_escapes_line_breaks_and_caps_the_length():
    assert one_line("a\nb\r\nc\x00d\u2028e") == "a\\nb\\r\\nc\\x00d\\u2028e"
    long = one_line("x" * 10_000)
    assert len(long) <= MAX_ERROR_CHARS and long.endswith("characters)")


def test_yaml_value_with_a_newline_is_one_line(tmp_path, capsys):
    text = VMC.replace("  stroke: 800 mm", '  stroke: "800\\nkg\\n"')
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    one_line_error(capsys)


def test_messages_show_values_not_nodes(tmp_path, capsys):
    text = VMC.replace("  stroke: 800 mm", "  stroke: [300 mm, 400 mm]")
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert "Node(" not in err and "['300 mm', '400 mm']" in err


# ------------------------------------------------------------------------- 7. silent acceptances


def test_empty_require_list_is_refused(tmp_path, capsys):
    problem = (PROBLEMS / "teaching_problem.yaml").read_text(encoding="utf-8")
    problem = problem.replace("require: {coupling: [", "require: {screw: [], coupling: [")
    assert "screw: []" in problem
    assert main(["solve", write_file(tmp_path, "p.yaml", problem)]) == 2
    err = one_line_error(capsys)
    assert "require.screw" in err and "at least one" in err


@pytest.mark.parametrize(
    "tagged",
    [
        "axis: !!omap\n  - stroke: 800 mm\n",
        "axis: !custom\n  stroke: 800 mm\n",
        "axis: !!set {a, b}\n",
    ],
)
def test_yaml_tags_on_mappings_and_lists_are_refused(tmp_path, capsys, tagged):
    text = "name: x\n" + tagged + "parts: {}\n"
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert "line 2" in err and ("tag" in err or "malformed" in err)


def test_saved_design_header_cannot_inject_yaml(tmp_path, capsys):
    import yaml

    odd = tmp_path / "p\nmotor: INJECTED\n.yaml"
    odd.write_text(
        (PROBLEMS / "teaching_problem.yaml").read_text(encoding="utf-8"), encoding="utf-8"
    )
    out = tmp_path / "best.yaml"
    assert main(["solve", str(odd), "--no-sensitivity", "--save-design", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert (
        text.splitlines()[0].startswith("# written by axisopt solve ")
        and "\\n" in text.splitlines()[0]
    )
    assert "INJECTED" not in str(yaml.safe_load(text))
    capsys.readouterr()
    assert main(["evaluate", str(out), "--json", "-"]) == 0
