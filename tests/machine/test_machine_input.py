"""Bad machine files: one line naming the file and key, exit code 2."""

import pytest

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.machine import load_machine

GOOD = "problems/machines/vmc_machine.yaml"


def _variant(tmp_path, old, new):
    with open(GOOD) as f:
        text = f.read()
    assert old in text
    p = tmp_path / "m.yaml"
    p.write_text(text.replace(old, new, 1))
    return p


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("carried_by: Y", "carried_by: X", "carried by itself"),
        ("    carried_by: frame\n    direction: y", "    carried_by: X\n    direction: y", "cycle"),
        (
            "    frame_stiffness: estimate # the column: no figure yet, the stated estimate\n",
            "",
            "frame_stiffness",
        ),
        ("tool_point: {X: 400 mm", "tool_point: {X: 900 mm", "outside axis X's stroke"),
        ("carried_by: Y", "carried_by: Q", "neither 'frame' nor an axis"),
        (
            "normal: y                 # the head's",
            "normal: z                 # the head's",
            "direction of travel",
        ),
        ("moving_mass: 400 kg", "moving_mass: 400", "unit"),
    ],
)
def test_bad_machine_is_one_line_exit_2(tmp_path, capsys, old, new, words):
    p = _variant(tmp_path, old, new)
    with pytest.raises(InputError, match=None) as e:
        load_machine(p)
    assert words in str(e.value)
    assert main(["machine", "solve", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and str(p) in err


def test_an_axis_problem_may_not_set_the_objective(tmp_path):
    p = _variant(
        tmp_path,
        "      limits:\n        max_drag_torque: 2 N.m",
        "      objective: stiffness\n      limits:\n        max_drag_torque: 2 N.m",
    )
    with pytest.raises(InputError, match="the machine's"):
        load_machine(p)


def test_shipped_machine_loads():
    m = load_machine(GOOD)
    assert [a.name for a in m.axes] == ["Y", "X", "Z"]
    assert m.estimated_frames == ("Z",)
    assert m.min_tool_stiffness == (40e6, 40e6, 40e6)


def test_machine_axis_listing_drive_types_is_refused(tmp_path, capsys):
    """A machine sizes its axes as screw drives: an axis problem listing rack and pinion or linear
    motors is a one-line error naming the key (not a screw sized without a word), exit 2; listing
    the screw alone is fine."""
    with open(GOOD) as f:
        text = f.read()
    first = text.index("      catalog:")
    bad = text[:first] + "      search: {drive_types: [screw, linear_motor]}\n" + text[first:]
    p = tmp_path / "m.yaml"
    p.write_text(bad)
    assert main(["machine", "solve", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "search.drive_types" in err and "screw drives" in err
    ok = text[:first] + "      search: {drive_types: [screw]}\n" + text[first:]
    p.write_text(ok)
    load_machine(p)
