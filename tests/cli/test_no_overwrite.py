"""Never write onto an input of the same command; every output path refused before the work starts.

The files a new user wrote (issue 57): ``axisopt solve p.yaml --save-design p.yaml`` and
``--json p.yaml`` replaced the problem with exit 0; ``--json nodir/x.json`` and ``--plot out.txt``
failed only after the solve."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from cli_helpers import one_line_error

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
TEACHING = ROOT / "problems" / "teaching_problem.yaml"
DESIGN = ROOT / "problems" / "teaching_design.yaml"


@pytest.fixture
def no_work(monkeypatch):
    """The search and the model refuse to run: a refusal must come before them."""
    import axisopt.model as model
    import axisopt.search as search

    def fail(*a, **k):
        raise AssertionError("the work started before the output paths were checked")

    monkeypatch.setattr(search, "solve", fail)
    monkeypatch.setattr(model, "evaluate", fail)


@pytest.fixture
def problem(tmp_path):
    p = tmp_path / "p.yaml"
    shutil.copy(TEACHING, p)
    return p


@pytest.mark.parametrize("option", ["--save-design", "--json", "--plot", "--report"])
def test_solve_never_writes_onto_its_problem(problem, option, capsys, no_work):
    before = problem.read_bytes()
    target = str(problem) if option not in ("--plot", "--report") else None
    if option == "--plot":  # a problem file named like a figure
        target = str(problem.with_name("p.png"))
        shutil.copy(problem, target)
        problem = Path(target)
    if option == "--report":
        target = str(problem.with_name("p.html"))
        shutil.copy(problem, target)
        problem = Path(target)
    assert main(["solve", str(problem), option, target]) == 2
    err = one_line_error(capsys)
    assert option in err and "would overwrite the problem file" in err
    assert problem.read_bytes() == before


def test_same_file_by_another_name(problem, tmp_path, capsys, no_work):
    """A relative path, a symbolic link and a hard link to the input are the input."""
    os.symlink(problem, tmp_path / "link.yaml")
    os.link(problem, tmp_path / "hard.yaml")
    before = problem.read_bytes()
    for target in (
        str(tmp_path / "." / "p.yaml"),
        str(tmp_path / "link.yaml"),
        str(tmp_path / "hard.yaml"),
    ):
        assert main(["solve", str(problem), "--json", target]) == 2, target
        assert "would overwrite" in one_line_error(capsys)
    assert main(["solve", str(tmp_path / "link.yaml"), "--save-design", str(problem)]) == 2
    one_line_error(capsys)
    assert problem.read_bytes() == before


def test_save_design_directory_holding_the_problem(tmp_path, capsys, no_work):
    d = tmp_path / "out"
    d.mkdir()
    shutil.copy(TEACHING, d / "1.yaml")
    assert main(["solve", str(d / "1.yaml"), "--save-design", str(d)]) == 2
    assert "would write over the problem file" in one_line_error(capsys)


def test_evaluate_compare_diagnose_inputs(tmp_path, capsys, no_work):
    design = tmp_path / "d.yaml"
    shutil.copy(DESIGN, design)
    before = design.read_bytes()
    for argv in (
        ["evaluate", str(design), "--json", str(design)],
        ["compare", str(TEACHING), str(design), "--csv", str(design)],
        ["compare", str(design), str(design), "--json", str(design)],
    ):
        assert main(argv) == 2, argv
        assert "would overwrite" in one_line_error(capsys)
    data = tmp_path / "static.csv"
    data.write_text("position [mm],force [N],displacement [um]\n0,0,0\n", encoding="utf-8")
    assert main(["diagnose", str(data), "--design", str(design), "--json", str(data)]) == 2
    assert "would overwrite a data file" in one_line_error(capsys)
    assert (
        main(["diagnose", str(data), "--design", str(design), "--save-calibration", str(design)])
        == 2
    )
    assert "would overwrite the design file" in one_line_error(capsys)
    assert design.read_bytes() == before


def test_catalog_directory_file(tmp_path, capsys):
    cat = tmp_path / "cat"
    cat.mkdir()
    (cat / "screws.csv").write_text("x\n", encoding="utf-8")
    assert main(["parts", "screws", "--catalogs", str(cat), "--csv", str(cat / "screws.csv")]) == 2
    assert "would overwrite a catalog file" in one_line_error(capsys)
    assert (cat / "screws.csv").read_text(encoding="utf-8") == "x\n"


def test_two_outputs_onto_one_file(problem, tmp_path, capsys, no_work):
    out = str(tmp_path / "a.json")
    assert main(["solve", str(problem), "--json", out, "--report", str(tmp_path / "a.json")]) == 2
    one_line_error(capsys)
    assert main(["solve", str(problem), "--json", out, "--save-design", out]) == 2
    assert "wants a directory" in one_line_error(capsys)
    assert not os.path.exists(out)


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--json", "{tmp}/nodir/x.json"], "does not exist"),
        (["--plot", "{tmp}/out.txt"], "extensions png"),
        (["--plot", "{tmp}/nodir/x.png"], "does not exist"),
        (["--save-design", "{tmp}/file.txt/"], "in the way"),
    ],
)
def test_output_paths_before_the_solve(problem, tmp_path, argv, words, capsys, no_work):
    (tmp_path / "file.txt").write_text("", encoding="utf-8")
    argv = [a.format(tmp=tmp_path) for a in argv]
    if argv[1].endswith("/"):
        argv[1] = argv[1][:-1]
    assert main(["solve", str(problem)] + argv) == 2
    assert words in one_line_error(capsys)


def test_evaluate_outputs_before_the_model(tmp_path, capsys, no_work):
    for opt, name in (
        ("--frf", "f.txt"),
        ("--plot", "p"),
        ("--ss", "nodir/s.npz"),
        ("--json", "nodir/j"),
    ):
        assert main(["evaluate", str(DESIGN), opt, str(tmp_path / name)]) == 2, opt
        assert opt in one_line_error(capsys)


def test_stdout_and_fifo_still_written(tmp_path, capsys):
    """'-' and a FIFO are outputs in place, as before: never compared with the inputs."""
    assert main(["evaluate", str(DESIGN), "--json", "-"]) == 0
    assert capsys.readouterr().out.lstrip().startswith("{")
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    import threading

    got = []

    def read():
        with open(fifo, encoding="utf-8") as fh:
            got.append(fh.read())

    t = threading.Thread(target=read)
    t.start()
    assert main(["evaluate", str(DESIGN), "--json", str(fifo)]) == 0
    t.join(10)
    assert got and got[0].lstrip().startswith("{")
