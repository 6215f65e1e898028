"""axisopt machine compare: machines side by side from their files or their saved results."""

import json

from machinegen import random_machine

from axisopt.cli import main


def test_compare_a_saved_result_with_a_machine_file(tmp_path, capsys):
    a = tmp_path / "a.yaml"
    a.write_text(random_machine(4))
    b = tmp_path / "b.yaml"
    b.write_text(
        random_machine(4)
        .replace("moving_mass: 350 kg", "moving_mass: 600 kg")
        .replace("name: random", "name: heavy")
    )
    saved = tmp_path / "a.json"
    assert main(["machine", "solve", str(a), "--json", str(saved)]) == 0
    capsys.readouterr()
    assert (
        main(["machine", "compare", str(saved), str(b), "--json", str(tmp_path / "both.json")]) == 0
    )
    out = capsys.readouterr().out.splitlines()
    both = json.loads((tmp_path / "both.json").read_text())
    assert [r["machine"] for r in both] == ["random", "heavy"]
    assert both[0] == json.loads(saved.read_text())
    masses = [r["best"]["moving_mass_kg"] for r in both]
    assert masses[1] > masses[0]
    row = next(line for line in out if line.startswith("moving masses [kg]"))
    assert f"{masses[0]:,.1f}" in row and f"{masses[1]:,.1f}" in row and row.endswith(" *")
    assert next(line for line in out if line.startswith("status")).split() == [
        "status",
        "optimal",
        "optimal",
    ]
    for d in "xyz":
        assert any(line.startswith(f"k_{d} at the tool [N/um]") for line in out)


def test_a_file_that_is_not_a_machine_result_is_one_line(tmp_path, capsys):
    bad = tmp_path / "x.json"
    bad.write_text('{"status": "optimal"}')
    assert main(["machine", "compare", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "not a machine result" in err
    bad.write_text("{")
    assert main(["machine", "compare", str(bad)]) == 2
