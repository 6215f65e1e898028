"""Shipped catalogs: contents the brief asks for, values checked against the seed paper, loader
errors."""

import shutil

import numpy as np
import pytest

from axisopt.catalog.columns import SHIPPED_DIR
from axisopt.catalog.loading import load_catalogs
from axisopt.errors import InputError

N_PER_UM = 1e6


@pytest.fixture(scope="module")
def cat():
    return load_catalogs()


def test_catalog_sizes(cat):
    pairs = cat.nuts.merge(cat.screws, left_on="screw_id", right_index=True)
    assert len(pairs) >= 30
    assert set(cat.nuts["type"]) == {"single", "double"}
    assert len(cat.bearings) >= 10
    assert set(cat.bearings["preload_class"]) == {"light", "medium", "heavy"}
    sizes = cat.guides["size"].round(4).unique()
    assert len(sizes) >= 8
    for size in sizes:
        assert cat.guides[np.isclose(cat.guides["size"], size)]["preload_level"].nunique() >= 3
    diam = set((cat.screws["nominal_diameter"] * 1e3).round().astype(int))
    assert {25, 32, 40, 50, 63} <= diam
    leads = cat.screws["lead"] * 1e3
    assert leads.min() <= 5 and leads.max() >= 40


@pytest.mark.published
def test_paper_nut_stiffness_for_40mm_screw(cat):
    # Seed paper section 3.2: catalog [21], 40 mm screw: 1710 N/um at 10 mm lead, 1030 N/um at 20 mm
    # lead.
    nuts = cat.nuts.merge(cat.screws, left_on="screw_id", right_index=True)
    d40 = nuts[np.isclose(nuts["nominal_diameter"], 0.040)]
    for lead, k in ((0.010, 1710), (0.020, 1030)):
        ks = d40[np.isclose(d40["lead"], lead)]["stiffness"] / N_PER_UM
        assert any(np.isclose(ks, k)), (lead, sorted(ks))


# Seed paper Table 4 (after catalog [12]): axial rigidity ranges [N/um] of angular contact bearing
# sets.
TABLE4 = {
    10: ((8.8, 35.8), (14.1, 63.2), (19.6, 88.8)),
    12: ((9.4, 42.8), (15, 66.8), (20.8, 103.1)),
    15: ((11.4, 49.7), (18.2, 84.4), (25.2, 117.3)),
    17: ((17, 53.3), (19.2, 89.9), (26.5, 124.6)),
    20: ((15, 63.7), (23.7, 106), (32.7, 146.7)),
    25: ((17, 69.2), (26.8, 115.2), (36.9, 158.8)),
    30: ((21.3, 90.4), (34.8, 148.3), (44.5, 203.3)),
    35: ((24.5, 103.21), (38.6, 169.4), (53, 232.2)),
    40: ((26.6, 113.5), (41.8, 184.3), (57.2, 251.6)),
    45: ((30.8, 120.8), (48.4, 196.1), (66.2, 267.8)),
}


@pytest.mark.published
def test_angular_contact_sets_within_paper_table4(cat):
    # Table 4 is for angular contact (spindle type, 15-40 deg) sets; 60 deg screw-support bearings
    # are several times stiffer and are not covered by it (see catalogs/SOURCES.md).  Only the
    # derived rows whose rigidity was taken from Table 4 are checked: vendor rows (THK support
    # units) carry the vendor's figure.
    b = cat.bearings
    ac = b[(np.degrees(b["contact_angle"]) < 45) & b["source"].str.contains("P Table 4")]
    checked = 0
    for _, row in ac.iterrows():
        bore = int(round(row["bore"] * 1e3))
        if bore not in TABLE4:
            continue
        lo, hi = TABLE4[bore][("light", "medium", "heavy").index(row["preload_class"])]
        assert lo <= row["axial_rigidity"] / N_PER_UM <= hi, row["id"]
        checked += 1
    assert checked >= 10


@pytest.mark.published
def test_guide_tangential_to_normal_ratio(cat):
    # Seed paper Table 1: k_t / k_n = 0.71 for rolling guides.
    r = cat.guides["tangential_rigidity"] / cat.guides["normal_rigidity"]
    assert np.allclose(r, 0.71, atol=0.01)


def _copy(tmp_path):
    d = tmp_path / "cat"
    shutil.copytree(SHIPPED_DIR, d)
    return d


def _edit(path, old, new, count=1):
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, count))


@pytest.mark.parametrize(
    "file, old, new, expect",
    [
        ("screws.csv", "lead [mm]", "lead [zz]", "line 1, column 5"),
        ("screws.csv", "lead [mm]", "lead [kg]", "line 1, column 5"),
        ("nuts.csv", ",mass [kg]", "", "missing column(s) mass"),
        ("guides.csv", "HIWIN-HG15-ZB,", "HIWIN-HG15-ZA,", "duplicate id 'HIWIN-HG15-ZA'"),
        (
            "nuts.csv",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,single,120,",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,single,0,",
            "line 2, column 5 (stiffness)",
        ),
        (
            "nuts.csv",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,single,120,",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,single,12O,",
            "'12O' is not a number",
        ),
        (
            "nuts.csv",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,",
            "HIWIN-R16-5T4-FSI,HIWIN,NO-SUCH-SCREW,",
            "screw_id 'NO-SUCH-SCREW'",
        ),
        (
            "nuts.csv",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,single,120,",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,single,nan,",
            "not a finite number",
        ),
        # a load rating scaled to 1e-297 N overflowed the life formula's cube (fuzz case 375):
        # refused
        (
            "nuts.csv",
            "single,120,2621,0,0,9.36,",
            "single,120,2621,0,0,9.36e-300,",
            "line 2, column 9 (dynamic_load_rating): dynamic_load_rating too small to be meant",
        ),
        # a motor whose peak torque is below its rated torque (issue 10: one-line error naming file
        # and key)
        (
            "motors.csv",
            "SGM7J-01A,Yaskawa,Sigma-7 SGM7J,100,0.318,1.11,",
            "SGM7J-01A,Yaskawa,Sigma-7 SGM7J,100,0.318,0.2,",
            "line 3, column 6 (peak_torque): peak_torque is below rated_torque",
        ),
        (
            "couplings.csv",
            ",22,8000,0.5,12700,8,26,",
            ",22,8000,0.5,12700,30,26,",
            "bore_max is below bore_min",
        ),
        (
            "nuts.csv",
            "HIWIN-R16-5T4-FSI,HIWIN,HIWIN-G-16x5-b3p175,",
            "HIWIN-R16-5T4-FSI,HIWIN,THK-BNFN-16x5,",
            "of vendor HIWIN is listed on screw 'THK-BNFN-16x5' of vendor THK",
        ),
    ],
)
def test_loader_errors_name_file_line_column(tmp_path, file, old, new, expect):
    d = _copy(tmp_path)
    _edit(d / file, old, new)
    with pytest.raises(InputError) as exc:
        load_catalogs([d], shipped=False)
    msg = str(exc.value)
    assert expect in msg and "\n" not in msg
    assert "cat" in msg  # names the file


def test_user_catalog_directory_adds_parts(tmp_path):
    d = tmp_path / "mine"
    d.mkdir()
    header = (SHIPPED_DIR / "guides.csv").read_text().splitlines()
    row = header[1].replace("HIWIN-HG15-ZA", "MY-GUIDE-15")
    (d / "guides.csv").write_text(header[0] + "\n" + row + "\n")
    cat = load_catalogs([d])
    assert "MY-GUIDE-15" in cat.guides.index and "HIWIN-HG15-ZA" in cat.guides.index
    (d / "guides.csv").write_text(header[0] + "\n" + header[1] + "\n")
    with pytest.raises(InputError, match="duplicate id 'HIWIN-HG15-ZA' across catalog"):
        load_catalogs([d])


def test_the_cached_catalog_reads_a_changed_file_again(tmp_path):
    """default_catalog keeps one load per process (shared by every problem and design read), keyed
    by the contents of the files: a user file rewritten at the same path, even to the same size at
    once, is read again; an unchanged one is served from the cache."""
    from axisopt.catalog.loading import default_catalog

    d = tmp_path / "mine"
    d.mkdir()
    header = (SHIPPED_DIR / "guides.csv").read_text().splitlines()
    (d / "guides.csv").write_text(
        header[0] + "\n" + header[1].replace("HIWIN-HG15-ZA", "MY-GUIDE-15") + "\n"
    )
    first = default_catalog((d,))
    assert "MY-GUIDE-15" in first.guides.index and default_catalog((d,)) is first
    (d / "guides.csv").write_text(
        header[0] + "\n" + header[1].replace("HIWIN-HG15-ZA", "MY-GUIDE-16") + "\n"
    )
    again = default_catalog((d,))
    assert "MY-GUIDE-16" in again.guides.index and "MY-GUIDE-15" not in again.guides.index
    (d / "guides.csv").unlink()
    assert "MY-GUIDE-16" not in default_catalog((d,)).guides.index


# a text cell (was accepted)
@pytest.mark.parametrize(
    "old, new", [("HIWIN,ground", "HIWIN\x00,ground"), (",16,5,", ",16\x00,5,")]
)  # a number cell
def test_nul_byte_is_refused_naming_file_and_line(tmp_path, capsys, old, new):
    # issue 42 item 7: the fuzz harness found a NUL in a catalog text cell accepted
    from cli_helpers import one_line_error

    from axisopt.cli import main

    d = _copy(tmp_path)
    _edit(d / "screws.csv", old, new)
    assert main(["parts", "screws", "--catalogs", str(d)]) == 2
    err = one_line_error(capsys)
    assert "NUL byte" in err and "screws.csv" in err and "line 2" in err and "\x00" not in err
