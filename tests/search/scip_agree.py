"""SCIP's answer against the exhaustive method's, shared by the SCIP test files."""

from __future__ import annotations

import pytest

REL = 1e-4


def agrees_with_exhaustive(s, e):
    """SCIP's answer against the exhaustive one: the same optimum (or worse only when stopped)."""
    assert e.status in ("optimal", "infeasible")
    if e.best is None:
        assert s.status == "infeasible" and s.best is None
        return
    assert s.status in ("optimal", "time_limit"), s.message
    if s.best is None:  # stopped without a design it could confirm: nothing claimed
        assert s.status == "time_limit" and not s.certificate.proven
        return
    if s.status == "optimal":
        assert s.best.objective == pytest.approx(e.best.objective, rel=REL)
        assert s.certificate.proven and s.certificate.gap <= 1e-4
    assert s.best.objective <= e.best.objective * (1 + 1e-6)
    # the reported design is the model's evaluation of the chosen parts and preload
    assert s.best.design is not None and s.best.design.nut_preload == pytest.approx(
        s.best.nut_preload
    )
    assert (
        s.certificate.feasible is None and s.certificate.combinations == e.certificate.combinations
    )
