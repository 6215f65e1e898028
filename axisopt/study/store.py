"""Where a study keeps its finished cases: ``DIR/cases/<case_id>.json``, one atomically written file per
case (shared by the runner, which writes them, and the tables, which read them)."""

from __future__ import annotations

import json
import re
from pathlib import Path

OK_STATUSES = ("optimal", "feasible")


class CaseStore:
    """``DIR/cases/<case_id>.json``, one file per finished case, each written atomically."""

    def __init__(self, out_dir):
        self.dir = Path(out_dir) / "cases"

    def prepare(self) -> None:
        from ..fileio import make_output_dir

        make_output_dir(self.dir)
        _sweep_temporaries(self.dir)

    def existing(self) -> set:
        if not self.dir.is_dir():
            return set()
        return {p.stem for p in self.dir.glob("*.json")}

    def write(self, rec: dict) -> None:
        from ..fileio import write_text_atomic

        # no fsync per case: after a power loss an unreadable case file is treated as missing and solved again
        text = json.dumps(rec, indent=1, allow_nan=False, default=_json_default)
        write_text_atomic(self.dir / f"{rec['case_id']}.json", text, what="case result", fsync=False)

    def read(self, case_id: str) -> dict | None:
        try:
            with open(self.dir / f"{case_id}.json", encoding="utf-8") as fh:
                return json.load(fh)
        except (OSError, ValueError):
            return None


# .NAME.PID.RANDOM.tmp of atomic_file (and .CASE.PID.tmp of earlier versions)
_TEMPORARY = re.compile(r"^\..+\.\d+(\.[0-9a-f]{8})?\.tmp$")


def _sweep_temporaries(d: Path) -> None:
    """Remove the temporary files of :func:`axisopt.report.atomic_file` left by a run killed mid-write
    (only under the study lock: no other run is writing here)."""
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
