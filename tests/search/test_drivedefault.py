"""The default drive-type offer (search.drivedefault): equal to the exhaustive answer over every
type, and it leaves out the types that do not apply."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from drive_spaces import drive_problem, lms, racks

from axisopt.drivecatalog import DriveTables
from axisopt.problem import load_problem
from axisopt.search import drivebest
from axisopt.search.drivetype import (
    OBJECTIVES,
    rank_key,
    solve_drive_types,
)

ROOT = Path(__file__).resolve().parents[2]


def _default_problem(tmp_path, rng, objective):
    """A screw problem with no search.drive_types (the default offer's case): the teaching axis
    without its screw-only drag limit, with the reductions the random rack spaces keep, and random
    drive-type rows."""
    drive_problem(tmp_path, rng, objective, "screw, linear_motor")  # its text, the random draws
    text = (tmp_path / "p.yaml").read_text(encoding="utf-8")
    text = text.replace("  max_drag_torque: 1.2 N.m\n", "").replace("  reductions: no\n", "")
    text = text.replace("search:\n  drive_types: [screw, linear_motor]\n", "")
    (tmp_path / "p.yaml").write_text(text, encoding="utf-8")
    prob = load_problem(tmp_path / "p.yaml")
    # the teaching problem's vendor filter keeps them
    mark = {"vendor": "HIWIN", "status": "vendor"}
    tables = DriveTables(
        tuple({**r, **mark} for r in racks(rng, 3)), tuple({**r, **mark} for r in lms(rng, 4))
    )
    return prob, tables


def test_default_offer_equals_exhaustive_over_every_type(tmp_path, monkeypatch):
    """Issue 54: without search.drive_types the screw answer stands unless a rack or linear-motor
    design beats it; the types that cannot are pruned by their bound (never searched).  The winner
    equals the exhaustive search over every type listed (every rack and linear-motor combination
    evaluated)."""
    from axisopt.design.drivechoice import DriveChoice
    from axisopt.search import drivedefault, solve

    monkeypatch.setattr(drivedefault, "RACK_MIN_STROKE", 0.0)  # the teaching axis is 400 mm
    seen = {"bounded": 0, "searched": 0, "winners": set()}
    for seed in range(6):
        objective = ("stiffness", "frequency", "cost")[seed % 3]
        if seed >= 3:
            # the rack space by (rack, reduction, twin) blocks
            monkeypatch.setattr(drivebest, "LEVEL1_MIN", 1)
        rng = np.random.default_rng(300 + seed)
        prob, tables = _default_problem(tmp_path, rng, objective)
        assert prob.drives is None
        screw = solve(prob, "default", top=3, sensitivities=False)
        got = drivedefault.offer(prob, screw, "default", top=3, tables=tables)
        types, _, kept = drivedefault.offered(prob, tables)
        # the ground truth: every rack and linear-motor combination evaluated (the screw answer's
        # own proof is tested with the screw search), ranked with the screw's best by the tie rule
        e = solve_drive_types(
            replace(prob, drives=DriveChoice(types=types, tables=kept)), "exhaustive", top=1
        )
        sense = OBJECTIVES[objective][3]
        sign = -1.0 if sense == "max" else 1.0
        pool = [
            (rank_key(d.objective, d.cost, d.moving_mass, sign), 1 + types.index(d.drive_type), d)
            for d in ([e.best] if e.best is not None else [])
        ]
        if screw.best is not None:
            b = screw.best
            pool.append((rank_key(b.objective, b.cost, b.moving_mass, sign), 0, None))
        pool.sort(key=lambda t: t[:2])
        truth = pool[0][2] if pool else None  # None: the screw (or nothing) wins
        if got.result is None:
            assert truth is None, (seed, got.reasons, truth)
        else:
            assert truth is not None and got.result.best.drive_type == truth.drive_type
            assert got.result.best.parts == truth.parts
            assert got.result.best.objective == pytest.approx(truth.objective, rel=1e-12)
            seen["winners"].add(truth.drive_type)
        for kind, why in got.reasons.items():
            seen["bounded"] += why.startswith("bounded out") or why.startswith("no drive passes")
            seen["searched"] += why == "searched"
            # the bound holds: no design of the type beats the screw
            if why.startswith("bounded out"):
                best = [t.best for t in e.types if t.drive_type == kind and t.best is not None]
                assert not best or (
                    best[0] <= screw.best.objective
                    if sense == "max"
                    else best[0] >= screw.best.objective
                )
    # the cases are not all one way: some types pruned by bound, some searched, some won
    assert seen["bounded"] and seen["searched"] and seen["winners"], seen


def test_default_offer_leaves_out_what_does_not_apply(tmp_path):
    """A vertical axis without a counterbalance is offered no linear motor (the vendors ask a brake;
    listed explicitly it is an input error), a short stroke no rack, a screw-only limit nothing."""
    from axisopt.drivecatalog import default_drive_tables
    from axisopt.search import drivedefault

    rng = np.random.default_rng(7)
    prob, tables = _default_problem(tmp_path, rng, "stiffness")
    assert drivedefault.offered(prob, tables)[0] == ("linear_motor",)  # 400 mm: no rack by default
    long = replace(prob, axis=replace(prob.axis, stroke=5.0))
    assert drivedefault.offered(long, tables)[0] == ("rack_pinion", "linear_motor")
    vertical = replace(long, axis=replace(long.axis, orientation="vertical"))
    types, why, _ = drivedefault.offered(vertical, tables)
    assert types == ("rack_pinion",) and "brake" in why["linear_motor"]
    teaching = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    assert "max_drag_torque" in drivedefault.left_out(teaching, "default")
    assert drivedefault.left_out(prob, "scip") and not drivedefault.left_out(prob, "default")
    assert default_drive_tables().racks  # the shipped catalogs offer both
    assert default_drive_tables().linear_motors
