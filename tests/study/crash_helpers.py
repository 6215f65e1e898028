"""Helpers of the hardening tests: a study whose files live in the test's own directory, a case
solver that kills its worker process on chosen cases, a disk that fills up, and worker processes to
kill."""

from __future__ import annotations

import errno
import json
import os
import signal
from pathlib import Path

from study_helpers import STUDIES

from axisopt.study.run import solve_case as _solve_case

CRASH_CONFIG = "crash.json"


def copy_study(tmp_path: Path, n: int = 16) -> Path:
    """A copy of the example study ``teaching_random`` (inline base, ~0.15 s a case) cut to its
    first ``n``
    cases: its case ids are those of the original's first cases, and ``ctx['base_dir']`` is
    ``tmp_path`` (where :func:`crashing_solve` looks)."""
    text = (STUDIES / "teaching_random.yaml").read_text(encoding="utf-8")
    assert text.count("n: 24,") == 4
    dest = Path(tmp_path) / "teaching_random.yaml"
    dest.write_text(text.replace("n: 24,", f"n: {n},"), encoding="utf-8")
    return dest


def crashing_solve(ctx: dict, case):
    """``solve_case``, except that the worker kills itself (SIGKILL) while solving the cases listed
    in ``base_dir/crash.json``: ``{"always": [index, ...], "once": [index, ...]}``; a "once" case
    leaves a marker file so that its second try succeeds."""
    base = Path(ctx["base_dir"])
    try:
        cfg = json.loads((base / CRASH_CONFIG).read_text(encoding="utf-8"))
    except FileNotFoundError:
        cfg = {}
    crash = case.index in cfg.get("always", ())
    if case.index in cfg.get("once", ()):
        marker = base / f"crashed-{case.index}"
        try:
            os.close(os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
            crash = True
        except FileExistsError:
            pass
    if crash:
        os.kill(os.getpid(), signal.SIGKILL)
    return _solve_case(ctx, case)


class FullDisk:
    """A file object whose writes fail with ENOSPC (or another errno) once ``budget`` bytes are
    written."""

    def __init__(self, fh, budget: int, code: int):
        self.fh, self.left, self.code = fh, budget, code

    def write(self, data):
        if len(data) > self.left:
            self.fh.write(data[: self.left])
            self.fh.flush()
            self.left = 0
            raise OSError(self.code, os.strerror(self.code))
        self.left -= len(data)
        return self.fh.write(data)

    def __getattr__(self, name):
        return getattr(self.fh, name)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.fh.close()

    def __iter__(self):
        return iter(self.fh)


def fill_disk_on(monkeypatch, name: str, budget: int = 100, code: int = errno.ENOSPC) -> None:
    """Make every write to a file called ``name`` (or to a temporary file for it, ``.NAME.*``) fail
    with ``code`` after ``budget`` bytes, whoever opens it (``open``, ``io.open``,
    ``Path.write_text``); other files are written normally.  Linux only (an open file descriptor's
    name is read from /proc)."""
    import builtins
    import io

    real_open = builtins.open

    def fake_open(file, mode="r", *a, **kw):
        fh = real_open(file, mode, *a, **kw)
        if any(m in mode for m in "wax"):
            target = (
                os.readlink(f"/proc/self/fd/{file}") if isinstance(file, int) else os.fspath(file)
            )
            base = os.path.basename(target)
            if base == name or base.startswith(f".{name}."):
                return FullDisk(fh, budget, code)
        return fh

    monkeypatch.setattr(builtins, "open", fake_open)
    monkeypatch.setattr(io, "open", fake_open)


def worker_pid(out: Path, exclude=()) -> int | None:
    """The pid of a pool worker that wrote the newest case file in ``out/cases`` and is not in
    ``exclude``."""
    recs = []
    for p in (Path(out) / "cases").glob("*.json"):
        try:
            recs.append((p.stat().st_mtime, json.loads(p.read_text(encoding="utf-8"))["worker"]))
        except (OSError, ValueError, KeyError):
            continue
    for _, w in sorted(recs, reverse=True):
        pid = int(w.rsplit(":", 1)[1]) if w else None
        if pid is not None and pid not in exclude:
            return pid
    return None
