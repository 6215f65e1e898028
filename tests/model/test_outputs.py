"""The output table (axisopt.model.outputs) says what the model does: every declared output is
computed, with its shape; ``chain=False`` and ``regen=False`` leave out what the table says; the
preload directions the search's exact 1-D solve rests on hold; the outputs marked as changed by the
coupling are those a softer coupling changes; the outputs not marked as changed by a drive are the
same for every motor, coupling and reduction."""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from axisopt.catalog.loading import load_catalogs
from axisopt.design import load_design
from axisopt.model import (
    FULL,
    OUTPUT_TABLE,
    OUTPUTS,
    PROFILE_OUTPUTS,
    SCALAR_OUTPUTS,
    axis_response,
    design_params,
)
from axisopt.model import positions as stroke_positions
from axisopt.model.outputs import (
    CHAIN_OUTPUTS,
    COUPLING_OUTPUTS,
    DRIVE_OUTPUTS,
    EXTRA_OUTPUTS,
    REGEN_OUTPUTS,
)

ROOT = Path(__file__).resolve().parents[2]
CHECK_PREFIXES = ("margin_", "available_", "needed_")


def _designs():
    cat = load_catalogs()
    vmc = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    geared = dataclasses.replace(vmc, reduction=cat.reductions.loc["BK-TP010-MF-4"])
    vertical = dataclasses.replace(vmc, axis=dataclasses.replace(vmc.axis, orientation="vertical"))
    return {"vmc": vmc, "geared": geared, "vertical": vertical}


DESIGNS = _designs()


def _response(design, preload=None, **kw):
    p = design_params(design)
    x = stroke_positions(design.axis)
    return x, axis_response(
        p, x, design.axis.mounting, design.preload if preload is None else preload, FULL.but(**kw)
    )


def _changed(a, b, keys):
    return {
        k
        for k in keys
        if k in a
        and k in b
        and not np.allclose(np.asarray(a[k], float), np.asarray(b[k], float), rtol=1e-12, atol=0.0)
    }


def test_every_declared_output_is_computed_with_its_shape():
    x, out = _response(DESIGNS["vmc"])
    assert PROFILE_OUTPUTS + SCALAR_OUTPUTS  # the Function's outputs
    for o in OUTPUT_TABLE:
        assert o.name in out, o.name
        assert np.shape(out[o.name]) == ((len(x),) if o.profile else ()), o.name
    assert len(OUTPUTS) == len(OUTPUT_TABLE)  # each declared once


def test_chain_false_leaves_out_the_chain_outputs():
    _, full = _response(DESIGNS["vmc"])
    _, bare = _response(DESIGNS["vmc"], extras=False, chain=False)
    declared = set(OUTPUTS)
    assert set(full) >= declared
    assert declared - set(bare) == set(CHAIN_OUTPUTS) | set(EXTRA_OUTPUTS)
    _, no_extras = _response(DESIGNS["vmc"], extras=False)
    assert declared - set(no_extras) == set(EXTRA_OUTPUTS)


def test_regen_false_leaves_out_the_regenerated_energy():
    _, full = _response(DESIGNS["vmc"])
    _, bare = _response(DESIGNS["vmc"], regen=False)
    assert set(REGEN_OUTPUTS) <= set(full)
    assert set(OUTPUTS) & (set(full) - set(bare)) == set(REGEN_OUTPUTS)


@pytest.mark.parametrize("name", sorted(DESIGNS))
def test_preload_directions_hold(name):
    d = DESIGNS[name]
    base = d.preload
    seen = 0
    for lo, hi in ((0.6 * base, base), (base, 1.4 * base)):
        _, a = _response(d, lo)
        _, b = _response(d, hi)
        for o in OUTPUT_TABLE:
            if o.preload in (1, -1):
                step = o.preload * (np.asarray(b[o.name], float) - np.asarray(a[o.name], float))
                assert np.all(step >= -1e-9 * np.abs(np.asarray(a[o.name], float))), (name, o.name)
                seen += bool(np.any(step > 0))
    assert seen >= 10  # the directions are not all flat here


@pytest.mark.parametrize("name", ["vmc", "geared"])
def test_coupling_outputs_are_those_a_softer_coupling_changes(name):
    d = DESIGNS[name]
    p = design_params(d)
    x = stroke_positions(d.axis)
    soft = dict(p, coupling_stiffness=0.5 * p["coupling_stiffness"])
    a = axis_response(p, x, d.axis.mounting, d.preload)
    b = axis_response(soft, x, d.axis.mounting, d.preload)
    assert _changed(a, b, OUTPUTS) == set(COUPLING_OUTPUTS)


def test_outputs_not_marked_drive_are_the_same_for_every_drive():
    cat = load_catalogs()
    d = DESIGNS["vertical"]
    _, a = _response(d)
    others = [
        dataclasses.replace(d, motor=cat.motors.loc["SGM7J-04A"]),
        dataclasses.replace(d, reduction=cat.reductions.loc["BK-TP010-MF-7"]),
        dataclasses.replace(d, coupling=cat.couplings.iloc[0]),
    ]
    for other in others:
        _, b = _response(other)
        scalars = {o.name for o in OUTPUT_TABLE if not o.coupling}
        moved = _changed(a, b, scalars)
        assert moved, "the drive change moved nothing: the test would not see a wrong mark"
        assert moved <= set(DRIVE_OUTPUTS), moved


def test_each_unit_reads_in_pint_and_matches_its_limits_kind():
    from axisopt.model.limits import LIMIT_TABLE
    from axisopt.units import KINDS, _registry

    ureg = _registry()
    for o in OUTPUT_TABLE:
        ureg.Quantity(1.0, o.unit or "dimensionless")  # each unit parses
    for lim in LIMIT_TABLE:
        dim = KINDS[lim.kind][0]
        got = ureg.Quantity(1.0, OUTPUTS[lim.output].unit or "dimensionless").dimensionality
        assert got == ureg.Quantity(1.0, KINDS[lim.kind][1] or "dimensionless").dimensionality, (
            lim.key,
            dim,
        )
