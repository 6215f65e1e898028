"""The drive-type catalogs (axisopt.drivecatalog): the cached tables read a changed file again."""

from axisopt.catalog.columns import SHIPPED_DIR


def test_the_cached_drive_tables_read_a_changed_file_again(tmp_path):
    from axisopt.drivecatalog import default_drive_tables

    d = tmp_path / "mine"
    d.mkdir()
    lines = (SHIPPED_DIR / "racks.csv").read_text().splitlines()
    rack = lines[0] + "\n" + lines[1].replace(lines[1].split(",")[0], "MY-RACK-A", 1) + "\n"
    (d / "racks.csv").write_text(rack)
    assert "MY-RACK-A" in {r["id"] for r in default_drive_tables((d,)).racks}
    (d / "racks.csv").write_text(rack.replace("MY-RACK-A", "MY-RACK-B"))
    ids = {r["id"] for r in default_drive_tables((d,)).racks}
    assert "MY-RACK-B" in ids and "MY-RACK-A" not in ids
