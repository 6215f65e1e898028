"""Helpers of the study tests: small studies on the teaching problem (about 0.06 s per case)."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"
STUDIES = PROBLEMS / "studies"
PYTHON = sys.executable

# time and worker differ between runs of one study; everything else must match exactly
VOLATILE = ["solve_time [s]", "worker"]


def write_study(tmp_path: Path, body: str, name: str = "study.yaml") -> Path:
    p = tmp_path / name
    p.write_text(textwrap.dedent(body).replace("@PROBLEMS@", str(PROBLEMS)), encoding="utf-8")
    return p


def small_study(tmp_path) -> Path:
    """8 cases: 4 strokes x 2 mountings of the teaching problem, one budget too tight
    (infeasible)."""
    return write_study(
        tmp_path,
        """\
        name: small
        base: @PROBLEMS@/teaching_problem.yaml
        sweep:
          axis.stroke: [300 mm, 500 mm, 700 mm]
          catalog.mountings: [[fixed-supported], [fixed-supported, fixed-fixed]]
          limits.max_cost: [3500 EUR, 600 EUR]
        """,
    )


def stable(df):
    """The table without the columns that legitimately differ between runs."""
    return df.drop(columns=VOLATILE).reset_index(drop=True)


def kill_group(proc) -> None:
    """kill -9 a study subprocess started with start_new_session=True and every worker it
    started."""
    import os
    import signal

    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def study_code(df) -> int:
    """The exit code of a study whose results table is ``df``: 1 when a case has no design, else
    0."""
    return int(bool((~df["status"].isin(["optimal", "feasible"])).any()))
