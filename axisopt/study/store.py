"""Where a study keeps its finished cases: ``DIR/cases/<case_id>.json``, one atomically written file
per case (shared by the runner, which writes them, and the tables, which read them)."""

from __future__ import annotations

import json
import re
from pathlib import Path

from ..errors import InputError
from ..fileio import refuse_inputs, same_file
from ..search.result import FEASIBLE, INFEASIBLE, OPTIMAL, SOLVER_FAILED, TIME_LIMIT

OK_STATUSES = (OPTIMAL, FEASIBLE)
# every status a case record may hold: the solver's (axisopt.search.result.STATUS_TABLE) and the
# runner's
CASE_STATUSES = OK_STATUSES + (
    INFEASIBLE,
    TIME_LIMIT,
    SOLVER_FAILED,
    "input_error",
    "error",
    "worker_died",
)
RECORD_VERSION = 1


def valid_record(rec, case_id: str) -> bool:
    """A case record read back is trusted only when it is a mapping of this record version for this
    very case (``case_id``), with a known status and fields of the right type; anything else is
    solved again."""
    if (
        not isinstance(rec, dict)
        or rec.get("version") != RECORD_VERSION
        or rec.get("case_id") != case_id
    ):
        return False
    if rec.get("status") not in CASE_STATUSES or not isinstance(rec.get("reason", ""), str):
        return False
    if (
        not isinstance(rec.get("index"), int)
        or isinstance(rec.get("index"), bool)
        or not isinstance(rec.get("inputs"), dict)
    ):
        return False
    for key in (
        "objective",
        "best",
        "profile",
        "drive",
        "checks",
        "certificate",
        "pareto",
        "drive_margins",
    ):
        if rec.get(key) is not None and not isinstance(rec[key], dict):
            return False
    if rec["status"] in OK_STATUSES and not isinstance(rec.get("objective"), dict):
        return False
    t = rec.get("time_s")
    return t is None or (isinstance(t, (int, float)) and not isinstance(t, bool))


class CaseStore:
    """``DIR/cases/<case_id>.json``, one file per finished case, each written atomically."""

    def __init__(self, out_dir):
        self.dir = Path(out_dir) / "cases"

    def prepare(self) -> None:
        from ..fileio import make_output_dir

        make_output_dir(self.dir)
        sweep_temporaries(self.dir)

    def existing(self) -> set:
        if not self.dir.is_dir():
            return set()
        return {p.stem for p in self.dir.glob("*.json")}

    def write(self, rec: dict) -> None:
        import os
        import stat

        from ..fileio import write_text_atomic

        # no fsync per case: after a power loss an unreadable case file is treated as missing and
        # solved again
        text = json.dumps(rec, indent=1, allow_nan=False, default=_json_default)
        path = self.dir / f"{rec['case_id']}.json"
        # a FIFO or device planted in the study's own cases directory is removed, never written to
        try:
            if not stat.S_ISREG(os.lstat(path).st_mode) and not path.is_dir():
                path.unlink()
        except OSError:
            pass
        write_text_atomic(path, text, what="case result", fsync=False)

    def read(self, case_id: str) -> dict | None:
        """The record of ``case_id``, or None when it is missing, unreadable (not a regular file,
        too large, not JSON) or not a valid record of that case (:func:`valid_record`): such a case
        is solved again."""
        from ..errors import InputError
        from ..fileio import read_input

        try:
            rec = json.loads(read_input(self.dir / f"{case_id}.json", "case", what="case result"))
        except (InputError, ValueError, RecursionError):
            return None
        return rec if valid_record(rec, case_id) else None


# .NAME.PID.RANDOM.tmp of atomic_file (and .CASE.PID.tmp of earlier versions)
_TEMPORARY = re.compile(r"^\..+\.\d+(\.[0-9a-f]{8})?\.tmp$")


def sweep_temporaries(d: Path) -> None:
    """Remove the temporary files of :func:`axisopt.report.atomic_file` left by a run killed
    mid-write (only under the study lock: no other run is writing here)."""
    for tmp in d.glob(".*.tmp"):
        if _TEMPORARY.match(tmp.name):
            try:
                tmp.unlink()
            except OSError:
                pass


def _json_default(o):
    import numpy as np

    if isinstance(o, np.generic):
        return o.item()
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def refuse_inputs_in(out, inputs, files, folders=("cases", "plots")) -> None:
    """Refuse an output directory ``out`` where a study would write over (or, run again with
    overwrite, delete) one of the files it reads (``inputs``: the study file, its base problem or
    machine): one of the ``files`` it writes there, or a file inside one of the ``folders`` it
    fills.  The command line checks the same (cli/outputs.py); this is the check for the Python
    functions."""
    out = Path(out)
    inputs = [i for i in inputs if i and Path(i).is_file()]
    for name in files:
        refuse_inputs(
            out / name, inputs, what=f"study's {name}", where="out", hint="give another out"
        )
    for name in folders:
        for i in inputs:
            if any(same_file(parent, out / name) for parent in Path(i).resolve().parents):
                raise InputError(
                    f"the study's {name}/ folder holds the input {i}; give another out",
                    source=str(out),
                    where="out",
                )
