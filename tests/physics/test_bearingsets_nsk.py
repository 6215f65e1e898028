"""NSK's printed load split of preloaded sets with as many bearings each way
(physics.bearingsets.nsk_pair_halves, issue 53): NSK super-precision bearings (Russian edition),
"life of preloaded angular-contact ball bearings", DB p. 140 and DBB p. 141, against the
formulas as printed there (typed from the page, not from the code)."""

from __future__ import annotations

import numpy as np
import pytest

from axisopt import mathx as mx
from axisopt.physics.bearingsets import hertz_set_halves, nsk_pair_halves

F_AO = 3350.0  # NSK 30TAC62B DF C10 preload [N] (NSK-SP p. 168)


def _db_printed(fao, fae):
    """NSK-SP p. 140, DB (Fre = 0, so Fap = Fao): Fa1 = 2/3 Fae + Fap, Fa2 = Fap - 1/3 Fae; when
    Fa2 < 0 the preload is lost: Fa1 = Fae, Fa2 = 0."""
    fa1, fa2 = 2.0 / 3.0 * fae + fao, fao - 1.0 / 3.0 * fae
    return (fae, 0.0) if fa2 < 0 else (fa1, fa2)


def _dbb_printed(fao, fae):
    """NSK-SP p. 141, DBB (Fre = 0, so each bearing's Fap = Fao / 2): per bearing Fa1 = 1/3 Fae +
    Fap, Fa2 = Fap - 1/6 Fae; after the unloading Fa1 = Fae / 2, Fa2 = 0.  Returned per group
    (two bearings each way)."""
    fap = fao / 2.0
    fa1, fa2 = fae / 3.0 + fap, fap - fae / 6.0
    return (fae, 0.0) if fa2 < 0 else (2.0 * fa1, 2.0 * fa2)


@pytest.mark.published
@pytest.mark.parametrize("fae", [0.0, 500.0, 3350.0, 9000.0, 10049.0, 10051.0, 25000.0])
@pytest.mark.parametrize("printed", [_db_printed, _dbb_printed])
def test_nsk_split_as_printed(fae, printed):
    want = printed(F_AO, fae)
    plus, minus = nsk_pair_halves(F_AO, fae)
    assert float(plus) == pytest.approx(want[0], rel=1e-12)
    assert float(minus) == pytest.approx(want[1], abs=1e-9)
    # the other direction mirrors it
    plus, minus = nsk_pair_halves(F_AO, -fae)
    assert (float(minus), float(plus)) == pytest.approx(want, abs=1e-9)


def test_nsk_line_lies_above_hertz_and_meets_it_at_no_load():
    """The printed line is a chord of Hertz's convex split: equal at no load, above it up to the
    unloading, and both carry the whole load beyond 3 F."""
    loads = np.linspace(0.0, 4.0 * F_AO, 41)
    nsk = np.asarray(nsk_pair_halves(F_AO, loads)[0], dtype=float)
    hz = np.asarray(hertz_set_halves(F_AO, loads, 1.0, 1.0)[0], dtype=float)
    assert nsk[0] == pytest.approx(hz[0])
    assert np.all(nsk >= hz - 1e-6)
    assert nsk[-1] == pytest.approx(hz[-1])


def test_nsk_split_on_symbols():
    import casadi as ca

    f = ca.SX.sym("f")
    plus, minus = nsk_pair_halves(F_AO, f)
    fn = ca.Function("s", [f], [plus, minus])
    for load in (-12000.0, -1000.0, 2000.0, 11000.0):
        got = [float(v) for v in fn(load)]
        assert got == pytest.approx([float(v) for v in nsk_pair_halves(F_AO, load)])
    assert mx.is_symbolic(plus)
