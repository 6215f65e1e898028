"""A problem file given where a design is read (``axisopt evaluate``) says so in one line, exit 2
(issue 42: it said "missing required key 'parts'")."""

from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.errors import InputError

P = Path(__file__).resolve().parents[2] / "problems"


@pytest.mark.parametrize("name", ["teaching_problem.yaml", "vmc_x_problem.yaml"])
def test_evaluate_of_a_problem_file_names_it(name, capsys):
    assert main(["evaluate", str(P / name)]) == 2
    err = capsys.readouterr().err.strip()
    assert (
        len(err.splitlines()) == 1
        and "a problem file, not a design" in err
        and "axisopt solve" in err
    )
    assert "missing required key" not in err
    with pytest.raises(InputError, match="problem file"):
        load_design(P / name)


def test_a_design_without_parts_still_says_parts_is_missing(tmp_path, capsys):
    path = tmp_path / "d.yaml"
    path.write_text((P / "teaching_design.yaml").read_text().split("\nparts:")[0] + "\n")
    assert main(["evaluate", str(path)]) == 2
    assert "missing required key 'parts'" in capsys.readouterr().err
