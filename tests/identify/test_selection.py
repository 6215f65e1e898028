"""The forward-selection rule (:mod:`axisopt.identify.selection`): the first criterion failed is the
reason, in each pipeline's order; implausible values are added when they are not the reason; pairs
must beat the better member alone; the pair pools of tables and time records."""

from types import SimpleNamespace

from axisopt.identify.selection import TABLE_RULE, TIME_RULE


def test_the_pipelines_keep_their_constants():
    assert TABLE_RULE.accept_dbic == TIME_RULE.accept_dbic == -10.0
    assert TABLE_RULE.min_gain == TIME_RULE.min_gain == 5.0
    assert (TABLE_RULE.pair_pool, TIME_RULE.pair_pool) == (5, 6)
    assert TABLE_RULE.gain(2.0, 1.0) == 50.0 and TIME_RULE.gain(0.0, 1.0) == 0.0


def test_reason_is_the_first_criterion_failed_in_each_order():
    assert TABLE_RULE.reason(-20.0, 10.0, "") == ""
    assert TABLE_RULE.reason(-5.0, 1.0, "") == "dBIC -5.0 not below -10"
    assert (
        TABLE_RULE.reason(-5.0, 1.0, "x = 3") == "dBIC -5.0 not below -10; and it would need x = 3"
    )
    # tables judge plausibility before the gain, time records after it
    assert TABLE_RULE.reason(-20.0, 1.0, "x = 3") == "would need x = 3"
    assert (
        TIME_RULE.reason(-20.0, 1.0, "x = 3")
        == "held-out gain 1.0 % below 5 %; and it would need x = 3"
    )
    assert TIME_RULE.reason(-20.0, 10.0, "x = 3") == "would need x = 3"


def test_the_gain_is_computed_only_when_judged():
    calls = []

    def gain():
        calls.append(1)
        return 10.0

    assert TABLE_RULE.reason(-5.0, gain, "") and not calls
    assert TABLE_RULE.reason(-20.0, gain, "x") == "would need x" and not calls
    assert TABLE_RULE.reason(-20.0, gain, "") == "" and calls == [1]


def test_a_pair_must_beat_the_better_member_alone():
    assert TIME_RULE.pair_reason(-20.0, 12.0, "", 9.0) == (
        "held-out gain 12.0 % is not 5 % above the better member alone (9.0 %)"
    )
    assert TIME_RULE.pair_reason(-20.0, 20.0, "", 9.0) == ""
    assert TABLE_RULE.pair_reason(-20.0, 20.0, "x = 3", 9.0) == "would need x = 3"


def test_pair_pools():
    scored = [SimpleNamespace(dbic=d) for d in (-50.0, -30.0, -3.0, 1.0, 2.0, 4.0, 8.0)]
    assert [c.dbic for c in TABLE_RULE.pair_pool_of(scored)] == [-50.0, -30.0, -3.0, 1.0, 2.0]
    assert [c.dbic for c in TIME_RULE.pair_pool_of(scored)] == [-50.0, -30.0, -3.0]
