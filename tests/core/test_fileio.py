"""The one output opener and the one input opener (axisopt.fileio), through the commands that use
them.

Issue 24, items 1 and 2: an output path that is a FIFO, a device or standard output is written in
place and never replaced; '-' is stdout everywhere an output path is accepted; an input that is not
a regular file is refused without being opened, and every input kind has a size cap.  Devices are
never written here: FIFOs made with os.mkfifo in a temporary directory stand for them."""

from __future__ import annotations

import json
import os
import stat
import threading
from pathlib import Path

import pytest
from cli_helpers import one_line_error

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.fileio import (
    INPUT_LIMITS,
    check_input,
    csv_cell,
    open_output,
    output_target,
    read_input,
    write_text_atomic,
)

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"
DESIGN = PROBLEMS / "teaching_design.yaml"

pytestmark = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs named pipes")


class Drain:
    """Read a FIFO in a thread (as a shell's `cat fifo` would) and keep what arrived."""

    def __init__(self, path: Path):
        self.path, self.data = path, b""
        self.t = threading.Thread(target=self._run, daemon=True)
        self.t.start()

    def _run(self):
        with open(self.path, "rb") as fh:
            self.data = fh.read()

    def result(self) -> bytes:
        self.t.join(10)
        if self.t.is_alive():  # the command never opened it: release the reader
            os.close(os.open(self.path, os.O_WRONLY | os.O_NONBLOCK))
            self.t.join(5)
        return self.data


@pytest.mark.parametrize(
    "argv",
    [
        ["parts", "screws", "--csv", "@"],
        ["parts", "--json", "@"],
        ["schema", "design", "--out", "@"],
        ["compare", str(DESIGN), str(DESIGN), "--csv", "@"],
        ["evaluate", str(DESIGN), "--json", "@"],
    ],
)
def test_output_to_a_fifo_is_streamed_and_the_fifo_stays(tmp_path, capsys, argv):
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    drain = Drain(fifo)
    assert main([str(fifo) if a == "@" else a for a in argv]) == 0
    data = drain.result()
    assert len(data) > 100  # the reader received the output
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)  # never replaced by a regular file
    assert [p.name for p in tmp_path.iterdir()] == ["out.fifo"]  # no temporary file left
    if "--json" in argv:
        json.loads(data)


@pytest.mark.parametrize(
    "argv, head",
    [
        (["parts", "screws", "--csv", "-"], "id,vendor"),
        (["schema", "design", "--out", "-"], "{"),
        (["compare", str(DESIGN), str(DESIGN), "--csv", "-"], "label,"),
        (["parts", "screws", "--json", "-"], "{"),
    ],
)
def test_dash_is_stdout_and_nothing_else_is_printed(tmp_path, capsys, monkeypatch, argv, head):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert out.startswith(head), out[:200]
    assert not (tmp_path / "-").exists()


def test_save_design_dash_prints_the_design_only(tmp_path, capsys, monkeypatch):
    import yaml

    monkeypatch.chdir(tmp_path)
    assert (
        main(
            [
                "solve",
                str(PROBLEMS / "teaching_problem.yaml"),
                "--no-sensitivity",
                "--save-design",
                "-",
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert out.startswith("# written by axisopt solve") and yaml.safe_load(out)["parts"]
    assert list(tmp_path.iterdir()) == []


def test_two_outputs_on_stdout_and_dash_as_a_directory_are_refused(tmp_path, capsys):
    assert main(["compare", str(DESIGN), "--csv", "-", "--json", "-"]) == 2
    assert "standard output" in one_line_error(capsys)
    assert main(["study", str(PROBLEMS / "studies" / "teaching_random.yaml"), "--out", "-"]) == 2
    assert "cannot be an output directory" in one_line_error(capsys)


def test_standard_output_path_is_written_in_place(tmp_path):
    """/dev/stdout (here: a path that is this process's stdout) is stdout, never renamed over."""
    import subprocess
    import sys

    target = tmp_path / "captured.txt"
    with open(target, "wb") as fh:
        r = subprocess.run(
            [sys.executable, "-m", "axisopt", "parts", "couplings", "--json", "/dev/stdout"],
            stdout=fh,
            stderr=subprocess.PIPE,
            env=dict(os.environ, PYTHONPATH=str(ROOT)),
            timeout=120,
        )
    assert r.returncode == 0, r.stderr
    assert json.loads(target.read_text())["kind"] == "couplings"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["captured.txt"]


def test_output_target_kinds(tmp_path):
    fifo = tmp_path / "f"
    os.mkfifo(fifo)
    assert output_target(fifo) == "stream"
    assert output_target(tmp_path / "new.json") == "atomic"
    (tmp_path / "old.json").write_text("{}")
    assert output_target(tmp_path / "old.json") == "atomic"
    assert output_target("-") == "stdout"
    with pytest.raises(InputError, match="directory"):
        output_target(tmp_path)
    with pytest.raises(InputError, match="empty"):
        output_target("")


def test_symlink_to_a_regular_file_stays_a_link(tmp_path):
    real = tmp_path / "real.txt"
    real.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(real)
    write_text_atomic(link, "new")
    assert link.is_symlink() and real.read_text() == "new"


def test_failed_write_leaves_the_old_file_and_no_temporary(tmp_path):
    p = tmp_path / "x.txt"
    p.write_text("old")
    with pytest.raises(RuntimeError):
        with open_output(p) as fh:
            fh.write("half")
            raise RuntimeError("stop")
    assert p.read_text() == "old" and [q.name for q in tmp_path.iterdir()] == ["x.txt"]


def test_empty_output_names_are_refused(capsys):
    assert main(["schema", "design", "--out", ""]) == 2
    assert "empty file name" in one_line_error(capsys)
    assert main(["solve", str(PROBLEMS / "teaching_problem.yaml"), "--save-design", ""]) == 2
    assert "--save-design" in one_line_error(capsys)
    assert main(["evaluate", str(DESIGN), "--json", " "]) == 2
    one_line_error(capsys)


# --------------------------------------------------------------------------------------------------
# -- inputs


def _fifo(tmp_path, name) -> Path:
    p = tmp_path / name
    os.mkfifo(p)
    return p


def test_fifo_inputs_are_refused_without_blocking(tmp_path, capsys):
    """Nobody writes these FIFOs: opening one for reading would block for ever."""
    tx = PROBLEMS / "data"
    cases = [
        ["evaluate", str(_fifo(tmp_path, "d.yaml"))],
        ["diagnose", str(_fifo(tmp_path, "data.csv")), "--design", str(tx / "table_x.yaml")],
        [
            "diagnose",
            str(tx / "table_x_run_est.csv"),
            str(_fifo(tmp_path, "val.csv")),
            "--design",
            str(tx / "table_x.yaml"),
        ],
        ["evaluate", str(DESIGN), "--calibration", str(_fifo(tmp_path, "cal.yaml"))],
        ["solve", str(_fifo(tmp_path, "p.yaml"))],
    ]
    for argv in cases:
        assert main(argv) == 2, argv
        err = one_line_error(capsys)
        assert "not a regular file" in err and "FIFO" in err, err


def test_fifo_in_a_catalog_directory_is_refused(tmp_path, capsys):
    cat = tmp_path / "cat"
    cat.mkdir()
    os.mkfifo(cat / "screws.csv")
    assert main(["parts", "--catalogs", str(cat)]) == 2
    assert "not a regular file" in one_line_error(capsys)


def test_directory_and_device_inputs_are_refused_by_stat(tmp_path):
    with pytest.raises(InputError, match="directory"):
        read_input(tmp_path, "yaml")
    # /dev/zero is only stat'ed, never opened (reading it would never end)
    with pytest.raises(InputError, match="character device"):
        check_input("/dev/zero", "data")


def test_size_caps_are_checked_before_reading(tmp_path, monkeypatch):
    big = tmp_path / "big.csv"
    with open(big, "wb") as fh:  # sparse: no real disk use
        fh.truncate(INPUT_LIMITS["data"] + 1)
    with pytest.raises(InputError, match="too large"):
        read_input(big, "data")
    monkeypatch.setitem(INPUT_LIMITS, "yaml", 10)
    small = tmp_path / "s.yaml"
    small.write_text("a: 1\n" * 5)
    with pytest.raises(InputError, match="too large"):
        read_input(small, "yaml")


def test_diagnose_row_cap(tmp_path, capsys, monkeypatch):
    import axisopt.identify.tables.data as data

    monkeypatch.setattr(data, "MAX_DATA_ROWS", 20)
    src = (PROBLEMS / "data" / "table_x_stiffness.csv").read_text()
    p = tmp_path / "s.csv"
    p.write_text(src)
    assert main(["diagnose", str(p), "--design", str(PROBLEMS / "data" / "table_x.yaml")]) == 2
    assert "too many rows" in one_line_error(capsys)


def test_time_record_sample_cap(capsys, monkeypatch):
    import axisopt.identify.records.record as tr

    monkeypatch.setattr(tr, "MAX_TIME_SAMPLES", 300)
    data = PROBLEMS / "data"
    assert (
        main(
            ["diagnose", str(data / "table_x_run_est.csv"), "--design", str(data / "table_x.yaml")]
        )
        == 2
    )
    assert "too many samples" in one_line_error(capsys)


def test_stray_quote_in_diagnose_csv_is_one_line(tmp_path, capsys):
    lines = (PROBLEMS / "data" / "table_x_stiffness.csv").read_text().splitlines()
    lines[5] = lines[5].replace(",", ',"', 1)
    p = tmp_path / "q.csv"
    p.write_text("\n".join(lines) + "\n")
    assert main(["diagnose", str(p), "--design", str(PROBLEMS / "data" / "table_x.yaml")]) == 2
    err = one_line_error(capsys)
    assert len(err) < 500


# --------------------------------------------------------------------------------------------------
# -- CSV cells


def test_csv_cells_are_escaped_as_owasp_advises():
    assert csv_cell("=1+2") == "'=1+2"
    assert csv_cell("+cmd") == "'+cmd"
    assert csv_cell("-2+3+cmd|' /C calc'!A0") == "'-2+3+cmd|' /C calc'!A0"
    assert csv_cell("@SUM(A1)") == "'@SUM(A1)"
    assert csv_cell("\tx") == "'\tx" and csv_cell("\rx") == "'\rx"
    # numbers written as text stay numbers
    assert csv_cell("-3.5") == "-3.5" and csv_cell("+1e3") == "+1e3"
    assert csv_cell(-3.5) == -3.5 and csv_cell("HIWIN-G") == "HIWIN-G"


def test_parts_csv_escapes_a_user_catalog_formula(tmp_path, monkeypatch, capsys):
    import csv as _csv

    cat = tmp_path / "cat"
    cat.mkdir()
    rows = list(
        _csv.reader((ROOT / "catalogs" / "couplings.csv").read_text(encoding="utf-8").splitlines())
    )
    head, row = rows[0], list(rows[1])
    row[head.index("id")] = '=HYPERLINK("http://x")'
    with open(cat / "couplings.csv", "w", newline="", encoding="utf-8") as fh:
        _csv.writer(fh).writerows([head, row])
    out = tmp_path / "c.csv"
    assert main(["parts", "couplings", "--catalogs", str(cat), "--csv", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "'=HYPERLINK" in text and "\n=HYPERLINK" not in text


# ------------------------------------------------------------------------- tidy_layout (was
# test_tidy_layout.py) A figure whose decorations cannot fit (the study's trade-off plot with a long
# legend did this in bench_study) is saved without matplotlib's 'Tight layout not applied'
# UserWarning reaching the user.


def _crowded():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(2, 1.5))
    ax.set_title("line\n" * 30)
    return fig


def test_plain_tight_layout_warns_and_tidy_layout_does_not():
    import warnings

    import matplotlib.pyplot as plt

    from axisopt.fileio import tidy_layout

    fig = _crowded()
    with pytest.warns(UserWarning, match="Tight layout not applied"):
        fig.tight_layout()
    fig = _crowded()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        tidy_layout(fig)
    plt.close("all")
