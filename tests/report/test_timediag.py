"""Time-record diagnosis output (:mod:`axisopt.report.timediag`): the JSON carries the unexplained
verdict."""

import json

from identify_helpers import DESIGN, records, truth_for

from axisopt.cli import main


def test_json_carries_the_unexplained_verdict(tmp_path, capsys):
    truth = truth_for(3, ripple=40.0, ripple_period=0.025)
    paths = records(tmp_path, truth, 3)
    assert main(["diagnose", *map(str, paths), "--design", str(DESIGN), "--json", "-"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert (
        d["unexplained"]["remaining"]
        and d["unexplained"]["signatures"][0]["kind"] == "position_periodic"
    )
    assert all(c["reason"] for c in d["not_accepted"])
