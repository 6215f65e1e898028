"""chain_response: the outputs the coupling's stiffness changes, as axis_response gives them
(issue 52: the infeasibility explanation evaluates these once per coupling stiffness without the
rest of the model)."""

from pathlib import Path

import numpy as np
import pytest

from axisopt.design import load_design
from axisopt.model import SCREEN, axis_response, chain_response, design_params
from axisopt.model.params import positions
from axisopt.search.task.space import COUPLING_KEYS

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", ["teaching_design.yaml", "vmc_x_design.yaml"])
def test_chain_response_equals_axis_response(name):
    design = load_design(ROOT / "problems" / name)
    p = design_params(design)
    x = positions(design.axis)
    for preload in (800.0, 1500.0):
        full = axis_response(p, x, design.axis.mounting, preload, SCREEN)
        part = chain_response(p, x, design.axis.mounting, preload)
        keys = [k for k in COUPLING_KEYS if k in full]
        assert {"k_total", "k_tool", "f1", "kv"} <= set(keys)
        for k in keys:
            np.testing.assert_array_equal(np.asarray(part[k]), np.asarray(full[k]), err_msg=k)
        # a stiffer coupling: the chain's stiffness rises, as in the whole model
        stiff = dict(p, coupling_stiffness=10.0 * float(np.asarray(p["coupling_stiffness"])))
        assert np.all(
            chain_response(stiff, x, design.axis.mounting, preload)["k_total"] >= part["k_total"]
        )
