"""``axisopt parts``: listing and filtering the catalogs, and refusals that name the parts that do
fit.

The expected rows are read straight from the shipped CSV files with the csv module (not the catalog
loader), so a filter that drops or adds a row fails here."""

import csv
import json
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
CATALOGS = ROOT / "catalogs"
SCREW = "HIWIN-G-40x20-b6p35"


def _rows(table):
    """The rows of a shipped catalog CSV, keys without their unit ('bore [mm]' -> 'bore')."""
    with open(CATALOGS / f"{table}.csv", encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    return [{k.split(" [")[0]: v for k, v in r.items()} for r in rows]


def _unit(table, column):
    with open(CATALOGS / f"{table}.csv", encoding="utf-8") as fh:
        head = next(line for line in fh if not line.startswith("#"))
    return next(
        h.split("[")[1].rstrip("]\n") for h in head.split(",") if h.startswith(column + " [")
    )


def _json(capsys, *argv):
    assert main(["parts", *argv, "--json", "-"]) == 0
    return json.loads(capsys.readouterr().out)["rows"]


def test_nuts_that_fit_a_screw(capsys):
    want = {r["id"] for r in _rows("nuts") if r["screw_id"] == SCREW}
    # HIWIN lists a single and a double nut for the 40x20 ground screw (H-BS Tables 6.4-6.5)
    assert want
    assert {r["id"] for r in _json(capsys, "nuts", "--fits", SCREW)} == want


def test_bearings_whose_bore_the_screw_end_takes(capsys):
    screw = next(r for r in _rows("screws") if r["id"] == SCREW)
    lo, hi = float(screw["support_bore_min"]), float(screw["support_bore_max"])
    want = {r["id"] for r in _rows("bearings") if lo <= float(r["bore"]) <= hi}
    got = _json(capsys, "bearings", "--fits", SCREW)
    assert {r["id"] for r in got} == want
    assert all(lo <= r["bore [mm]"] <= hi for r in got)


def test_diameter_lead_and_preload_class(capsys):
    screws = {
        r["id"]
        for r in _rows("screws")
        if float(r["nominal_diameter"]) == 40 and float(r["lead"]) == 10
    }
    assert {r["id"] for r in _json(capsys, "screws", "--diameter", "40", "--lead", "10")} == screws
    nuts = {r["id"] for r in _rows("nuts") if r["screw_id"] in screws}
    assert {r["id"] for r in _json(capsys, "nuts", "--diameter", "40", "--lead", "10")} == nuts
    light = {r["id"] for r in _rows("guides") if r["preload_class"] == "ZA"}
    assert {r["id"] for r in _json(capsys, "guides", "--preload-class", "ZA")} == light


def test_table_fits_100_columns_and_csv_has_every_column(tmp_path, capsys):
    for kind in ("screws", "nuts", "bearings", "guides", "motors", "couplings"):
        assert main(["parts", kind]) == 0
        out = capsys.readouterr().out
        assert max(len(line) for line in out.splitlines()) <= 100, kind
    out_csv = tmp_path / "n.csv"
    assert main(["parts", "nuts", "--fits", SCREW, "--csv", str(out_csv)]) == 0
    with open(out_csv, encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    raw = {r["id"]: r for r in _rows("nuts")}
    assert _unit("nuts", "stiffness") == "N/um" and _unit("nuts", "dynamic_load_rating") == "kN"
    for r in rows:  # vendor units: N/um as in the catalog; its kN ratings exported in N
        assert float(r["stiffness [N/um]"]) == pytest.approx(float(raw[r["id"]]["stiffness"]))
        assert float(r["dynamic_load_rating [N]"]) == pytest.approx(
            float(raw[r["id"]]["dynamic_load_rating"]) * 1e3
        )
        assert r["source"] == raw[r["id"]]["source"]


@pytest.mark.parametrize(
    ("argv", "text"),
    [
        (["motors", "--fits", SCREW], "applies to nuts and bearings"),
        (["nuts", "--fits", "HIWIN-G-40x20"], "did you mean 'HIWIN-G-40x20-b6p35'"),
        (["nuts", "--lead", "abc"], "--lead"),
        (["nuts", "--diameter", "1e99"], "--diameter"),
        (["bearings", "--preload-class", "zz"], "classes are"),
        (["--fits", SCREW], "needs a kind"),
    ],
)
def test_bad_filters_are_one_line(capsys, argv, text):
    assert main(["parts", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and text in err


def test_a_nut_for_another_screw_is_refused_with_the_nuts_that_fit(tmp_path, capsys):
    design = (ROOT / "problems" / "vmc_x_design.yaml").read_text(encoding="utf-8")
    p = tmp_path / "d.yaml"
    p.write_text(
        design.replace("nut: HIWIN-R40-20K4-FDC", "nut: HIWIN-R16-5T4-FDI"), encoding="utf-8"
    )
    assert main(["evaluate", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "parts.nut" in err
    for nut in (r["id"] for r in _rows("nuts") if r["screw_id"] == SCREW):
        assert nut in err


def test_nuts_listed_under_their_own_screw(capsys):
    """The text listing groups nuts under a 'screw ID' heading: every nut sits under the screw its
    CSV row names (catalogs add nuts for a screw further down the file, e.g. Rexroth's FDMES after
    its FEMES)."""
    assert main(["parts", "nuts"]) == 0
    screw_of = {r["id"]: r["screw_id"] for r in _rows("nuts")}
    under, seen = None, set()
    for line in capsys.readouterr().out.splitlines():
        word = line.split(" ", 1)[0]
        if line.startswith("screw "):
            under = line.split()[1]
        elif word in screw_of:
            assert screw_of[word] == under, (
                f"{word} listed under {under}, made for {screw_of[word]}"
            )
            seen.add(word)
    assert seen == set(screw_of)
