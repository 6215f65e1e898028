"""Every shipped catalog row against its kind's physical sanity rules, and against
catalogs/SOURCES.md.

The rules are the vendors' own statements (preload fractions, rating order) and monotonic size laws;
a row that breaks one is a transcription error or a mislabelled part.  Each failure names the row.
"""

import re

import numpy as np
import pandas as pd
import pytest

from axisopt.catalog.columns import SHIPPED_DIR
from axisopt.catalog.loading import load_catalogs

N_PER_UM = 1e6
SOURCES = (SHIPPED_DIR / "SOURCES.md").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def cat():
    return load_catalogs()


def _reference_keys():
    """Keys of the 'Primary documents' table of SOURCES.md (first cell of each row)."""
    part = SOURCES.split("## Primary documents", 1)[1].split("\n## ", 1)[0]
    keys = set()
    for line in part.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and cells[0] not in ("Ref", "") and not set(cells[0]) <= set("-: "):
            keys.add(cells[0])
    return keys


def test_every_row_names_a_documented_source(cat):
    keys = _reference_keys()
    assert len(keys) >= 6
    for kind in ("screws", "nuts", "bearings", "guides"):
        df = cat.table(kind)
        assert set(df["status"]) <= {"vendor", "stiffness-derived", "paper", "derived"}, kind
        for pid, src in df["source"].items():
            first = re.split(r"[\s;,]", src.strip(), maxsplit=1)[0]
            assert first in keys, (
                f"{kind} {pid}: source '{src}' does not start with a SOURCES.md reference key"
            )


def test_every_vendor_and_series_is_described_in_sources(cat):
    # each vendor of each kind appears in SOURCES.md, so a reader can find the rule behind its rows
    for kind in ("screws", "nuts", "bearings", "guides"):
        for vendor in set(cat.table(kind)["vendor"]):
            assert vendor in SOURCES, f"{kind}: vendor {vendor} not described in SOURCES.md"


def test_nut_ratings_and_preload_rules(cat):
    n = cat.nuts
    for pid, r in n.iterrows():
        assert r["static_load_rating"] >= r["dynamic_load_rating"], f"{pid}: C0 < C"
        assert r["preload_min"] <= r["preload_max"], pid
        # HIWIN H-BS 3.6.2, THK: preload at most 10 % of C for a preloaded nut; a single nut is a
        # nut with play or a light oversize-ball preload (<= 5 % C)
        limit = 0.10 if r["type"] == "double" else 0.05
        assert r["preload_max"] <= limit * r["dynamic_load_rating"] * (1 + 1e-3), (
            f"{pid}: preload above {limit} C"
        )
        # vendors quote rigidity at 10 % C (preloaded) up to 30 % C (single nut under load)
        assert 0.02 <= r["stiffness_preload"] / r["dynamic_load_rating"] <= 0.31, (
            f"{pid}: rigidity basis"
        )
        if r["type"] == "double":
            assert r["axial_play"] == 0, f"{pid}: a preloaded nut has no play"
        else:
            assert r["axial_play"] > 0 or r["preload_max"] > 0, (
                f"{pid}: a single nut has play or preload"
            )


def _dominance(df, group, size_cols, y, min_pairs):
    """Within a group, a part larger in every size column is not softer (y not lower, 0.5 %
    rounding)."""
    pairs = 0
    for key, g in df.groupby(group):
        a = g[size_cols].to_numpy()
        k = g[y].to_numpy()
        for i in range(len(g)):
            bigger = (a > a[i]).all(axis=1)
            pairs += int(bigger.sum())
            bad = bigger & (k < k[i] * 0.995)
            assert not bad.any(), (
                f"{key}: {g.index[np.argmax(bad)]} is larger than {g.index[i]} in "
                f"{size_cols} but has the lower {y}"
            )
    assert pairs >= min_pairs


def test_nut_stiffness_rises_with_size(cat):
    # same vendor, nut type, lead and ball: a nut on a larger shaft with a higher load rating
    # carries more loaded balls and is never softer.  (Size alone is not enough: HIWIN's R63-40K2
    # has fewer circuits and a lower rating than R50-40, and is softer.)  Rigidities quoted at
    # different loads are compared at 10 % C by the cube-root law (seed eq. 9).  Only nuts of one
    # design are compared (the design code in the id: HIWIN FSC/FDC cassette or FSI/FDI internal
    # return, THK BNFN/DIK/BNF, Rexroth FEMES/FDMES): the designs carry different ball counts per
    # rating, e.g. HIWIN R80-10K5-FDC (86.2 kN, 2 230 N/um, H-BS Table 6.5) is softer than
    # R63-10T6-FDI (68.87 kN, 2 280 N/um, Table 6.7), both as printed.
    n = cat.nuts.join(cat.screws[["nominal_diameter", "lead", "ball_diameter"]], on="screw_id")
    n["k_10"] = n["stiffness"] * np.cbrt(0.1 * n["dynamic_load_rating"] / n["stiffness_preload"])
    n["ball"] = n["ball_diameter"].fillna(0.0)
    n["design"] = n.index.str.extract(r"-([A-Z]{2,})(?=\d|-|$)", expand=False)
    assert n["design"].notna().all(), n.index[n["design"].isna()].tolist()
    _dominance(
        n,
        ["vendor", "type", "design", "lead", "ball"],
        ["nominal_diameter", "dynamic_load_rating"],
        "k_10",
        10,
    )


def test_screw_geometry(cat):
    s = cat.screws
    for pid, r in s.iterrows():
        assert r["root_diameter"] < r["nominal_diameter"], pid
        if not np.isnan(r["ball_diameter"]):  # THK does not list it
            assert r["ball_diameter"] < r["root_diameter"], pid
            # the root lies about one ball diameter below the nominal diameter (Gothic arch: 0.5-1.3
            # Dw)
            assert (
                0.4 <= (r["nominal_diameter"] - r["root_diameter"]) / r["ball_diameter"] <= 1.3
            ), pid
        assert r["support_bore_min"] <= r["support_bore_max"] < r["root_diameter"] + 1e-9, pid
        # steel shaft: mass per length between the root-diameter and nominal-diameter cylinders
        lo, hi = (7850 * np.pi / 4 * d**2 for d in (r["root_diameter"], r["nominal_diameter"]))
        assert 0.95 * lo <= r["mass_per_length"] <= 1.05 * hi, pid


def _monotonic(df, group, x, ys, min_groups):
    checked = 0
    for key, g in df.groupby(group):
        g = g.sort_values(x)
        if g[x].nunique() < 2:
            continue
        checked += 1
        for y in ys:
            best = g.groupby(x)[y].max()
            assert (np.diff(best.to_numpy()) >= -1e-9).all(), (
                f"{key}: {y} falls with {x}: {best.to_dict()}"
            )
    assert checked >= min_groups


def test_bearing_rules(cat):
    b = cat.bearings
    for pid, r in b.iterrows():
        assert r["static_load_rating"] > 0 and r["dynamic_load_rating"] > 0, pid
        assert r["outer_diameter"] > r["bore"], pid
        assert 0 < r["preload"] < r["dynamic_load_rating"], pid
        # lift-off of a preloaded pair is 2^1.5 = 2.83 x preload (SKF-LF); a DBD/DFD set lifts off
        # earlier, a 3-against-1 set (DFT) at 1.80 x its preload loaded on the single row and 5.41 x
        # on the three (Hertz's set rule: IBC TI-I-5010.2 Table 2.2's 2.83 and 8.49 x the pair's
        # preload, physics.bearingsets)
        low = 1.75 if r["arrangement"] in ("DFT", "DBT") else 2.0
        assert low * r["preload"] <= r["lift_off_load"] <= 2.9 * r["preload"], pid
        strong = r.get("lift_off_load_strong", np.nan)
        assert np.isnan(strong) or 5.3 * r["preload"] <= strong <= 5.5 * r["preload"], pid
        st = r["starting_torque"]
        assert np.isnan(st) or 0 < st < 5.0, pid
    # within a series, arrangement and preload class, rigidity and rating rise with bore a bearing
    # of the same family, arrangement and class that is larger in bore and outside diameter is not
    # softer (equal OD with a larger bore means smaller balls: ZKLN60110 is softer than ZKLN50110)
    fam = b.assign(family=b["id"].str.extract(r"^([A-Za-z]+-[A-Za-z]+)")[0])
    _dominance(
        fam,
        ["family", "arrangement", "preload_class"],
        ["bore", "outer_diameter"],
        "axial_rigidity",
        10,
    )
    # more bearings in a stack: stiffer (same bearing, same class)
    base = b.assign(
        bearing=b["id"].str.replace(r"-?(DBD|DBB|DFD|DFF|DB|DF)(?=-|$)", "", regex=True)
    )
    checked = 0
    for key, g in base.groupby(["bearing", "preload_class"]):
        if g["rows"].nunique() < 2:
            continue
        checked += 1
        k = g.groupby("rows")["axial_rigidity"].max().sort_index()
        assert (np.diff(k.to_numpy()) > 0).all(), f"{key}: {k.to_dict()}"
    assert checked >= 5


def test_guide_rules(cat):
    g = cat.guides
    for pid, r in g.iterrows():
        assert r["static_load_rating"] >= r["dynamic_load_rating"] * 0.9, pid
        # vendors' heaviest standard preload classes are about 0.13-0.16 C
        assert 0 <= r["preload"] <= 0.17 * r["dynamic_load_rating"], pid
    _monotonic(
        g,
        ["vendor", "series", "preload_class"],
        "size",
        ["normal_rigidity", "dynamic_load_rating", "block_mass", "rail_mass_per_length"],
        6,
    )
    # heavier preload class of the same guide: stiffer
    checked = 0
    for key, s in g.groupby(["vendor", "series", "size"]):
        if len(s) < 2:
            continue
        checked += 1
        s = s.sort_values("preload")
        assert (np.diff(s["normal_rigidity"].to_numpy()) > 0).all(), key
    assert checked >= 8


def test_each_kind_has_three_vendors_with_real_rows(cat):
    for kind in ("screws", "nuts", "bearings", "guides"):
        df = cat.table(kind)
        # catalog parts, ratings from the vendor
        real = df[df["status"].isin(("vendor", "stiffness-derived"))]
        assert real["vendor"].nunique() >= 3, (
            f"{kind}: vendors with real rows: {sorted(set(real['vendor']))}"
        )


def test_counts_table_matches_catalog(cat):
    from axisopt.cli.parts import counts

    recs = pd.DataFrame(counts(cat))
    for kind in ("screws", "nuts", "bearings", "guides"):
        assert recs[recs["kind"] == kind]["rows"].sum() == len(cat.table(kind))
