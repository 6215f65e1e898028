"""The CasADi expression graph as the SCIP translation reads it: every node's value on a batch of
points equals CasADi's own evaluation, dependency masks name the inputs, an operation without a
translation is refused, and the double nut's shift is replaced only while the model is built."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import nut as pn
from axisopt.search.minlp.translate import Graph, implicit_shift


def test_graph_values_equal_casadi():
    x, y = ca.SX.sym("x", 2), ca.SX.sym("y")
    out = [
        ca.sqrt(x[0]) * y + ca.fmin(x[0], x[1]) ** 1.5,
        ca.if_else(x[1] < y, ca.exp(y) / x[0], ca.log(x[1]) - ca.fabs(y)),
    ]
    f = ca.Function("f", [x, y], [ca.vertcat(*out)])
    rng = np.random.default_rng(0)
    flat = rng.uniform(0.1, 3.0, (3, 50))
    g = Graph(f)
    g.evaluate(flat)
    np.testing.assert_allclose(g.output_values(0), np.asarray(f(flat[:2], flat[2:])), rtol=1e-12)


def test_dependency_masks_name_the_inputs():
    x, y = ca.SX.sym("x"), ca.SX.sym("y")
    f = ca.Function("f", [x, y], [2.0 * x, x * y + 1.0])
    g = Graph(f)
    assert [g.dep[n] for n in (g.outputs[0][0], g.outputs[1][0])] == [1, 3]


def test_operation_without_translation_is_refused():
    x = ca.SX.sym("x")
    with pytest.raises(NotImplementedError, match="no SCIP translation"):
        Graph(ca.Function("f", [x], [ca.sin(x)]))


def test_implicit_shift_only_while_building():
    real = pn.double_nut_shift
    record = []
    with implicit_shift(record) as shift:
        assert shift is real and pn.double_nut_shift is not real
        s = pn.double_nut_shift(ca.SX.sym("f"))
        assert len(record) == 1 and record[0][0] is s
    assert pn.double_nut_shift is real
