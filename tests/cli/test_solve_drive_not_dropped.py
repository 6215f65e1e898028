"""Nothing dropped silently (issue 42): the drive is sized whenever the catalogs have motors and the
axis a motion to size it on, unless the problem says 'drive: no'; a drive left out is stated on its
own line, with why, in the text and the JSON."""

from __future__ import annotations

import json
import re
from pathlib import Path

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
LATHE = (ROOT / "problems" / "lathe_z_problem.yaml").read_text(encoding="utf-8")


def _write(tmp_path, text, name="p.yaml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return str(path)


def _solve_json(path, capsys):
    main(["solve", path, "--json", "-", "--top", "1"])
    return json.loads(capsys.readouterr().out)


def test_widening_the_search_keeps_the_drive(tmp_path, capsys):
    """The lathe Z without its 'drive: yes' line (a user widening the search): the motor is still
    chosen."""
    text = LATHE.replace("  drive: yes\n", "")
    assert text != LATHE
    res = _solve_json(_write(tmp_path, text), capsys)
    assert res["best"]["motor"] and "left_out" not in res


def test_drive_no_is_stated_on_its_own_line(tmp_path, capsys):
    path = _write(tmp_path, LATHE.replace("  drive: yes\n", "  drive: no\n"))
    # one solve for both: the JSON to a file, the text on stdout
    rj = tmp_path / "r.json"
    main(["solve", path, "--json", str(rj), "--top", "1"])
    lines = capsys.readouterr().out.splitlines()
    res = json.loads(rj.read_text(encoding="utf-8"))
    assert res["best"]["motor"] == "" and res["left_out"] == [
        "the drive (motor, coupling, reduction) is not sized: catalog.drive: no; the axis's "
        "motor_inertia and coupling values stand in and no motor check is made"
    ]
    assert any(
        ln.startswith(
            "  left out: the drive (motor, coupling, reduction) is not sized: catalog.drive: no"
        )
        for ln in lines
    )


def test_an_axis_without_motion_says_why_the_drive_is_not_sized(tmp_path, capsys):
    """No acceleration and no duty cycle: no inertia torque to size a motor on; said, not an
    error."""
    text = re.sub(r"(?ms)^  duty_cycle:.*?(?=^  \S|^\S)", "", LATHE.replace("  drive: yes\n", ""))
    text = re.sub(r"(?m)^(  acceleration:).*$", r"\1 0 m/s^2", text)
    res = _solve_json(_write(tmp_path, text), capsys)
    assert (
        res["left_out"]
        and "axis.acceleration is 0 and there is no axis.duty_cycle" in res["left_out"][0]
    )


# ----------------------------------------------------------------------------- plausibility and
# currency
TEACHING = (ROOT / "problems" / "teaching_problem.yaml").read_text(encoding="utf-8")


def test_an_acceleration_in_the_wrong_unit_is_warned_about(tmp_path, capsys):
    """5 mm/s^2 (meant: 5 m/s^2) solves, with one warning line naming the file, line and key."""
    text, n = re.subn(r"(?m)^(  acceleration:).*$", r"\1 5 mm/s^2", TEACHING)
    assert n == 1
    path = _write(tmp_path, text)
    assert main(["solve", path, "--top", "1"]) == 0
    err = capsys.readouterr().err.splitlines()
    [line] = [ln for ln in err if ln.startswith("warning:")]
    assert f"{path}: line " in line and "key 'axis.acceleration'" in line
    assert "0.005 m/s^2 is far below machine-tool practice (0.1-50 m/s^2)" in line


def test_plausible_values_give_no_warning(tmp_path, capsys):
    assert main(["solve", str(ROOT / "problems" / "teaching_problem.yaml"), "--top", "1"]) == 0
    assert "warning:" not in capsys.readouterr().err


def test_a_budget_in_usd_needs_a_rate(tmp_path, capsys):
    text, n = re.subn(r"(?m)^(  max_cost:).*$", r"\1 3000 USD", TEACHING)
    assert n == 1
    assert main(["solve", _write(tmp_path, text)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert (
        len(err) == 1
        and "key 'limits.max_cost'" in err[0]
        and "no exchange rate is assumed" in err[0]
    )
