"""``DIR/.lock``: one study run at a time writes to a study directory (:class:`StudyLock`).

The lock file holds the pid, host and process start time of the run; a second run stops with an
InputError, a lock left by a run that is gone is taken over.
"""

from __future__ import annotations

import json
import os
import socket
import time
from pathlib import Path

from ..errors import InputError


class StudyLock:
    """``DIR/.lock``: one run at a time writes to a study directory.

    The file is created with ``O_CREAT | O_EXCL`` and holds one JSON line: pid, host and start time
    of the holding process.  A lock whose process is gone (same host; a pid now used by another
    process does not count) is taken over; taking it is serialised with ``flock`` on the directory,
    so two runs cannot both take over the same stale lock.  A lock from another host is never
    taken over: delete it by hand when that run is gone.
    """

    def __init__(self, out_dir):
        self.dir = Path(out_dir)
        self.path = self.dir / ".lock"
        self.mine = None

    def __enter__(self):
        self.acquire()
        return self

    def __exit__(self, *exc) -> None:
        self.release()

    def acquire(self) -> None:
        me = {
            "pid": os.getpid(),
            "host": socket.gethostname(),
            "start": _process_start(os.getpid()),
            "since": time.strftime("%Y-%m-%d %H:%M:%S"),
        }
        text = json.dumps(me) + "\n"
        try:
            with _directory_flock(self.dir):
                try:
                    self._create(text)
                except FileExistsError:
                    holder = self._holder()
                    if _holder_alive(holder):
                        raise self._busy(holder) from None
                    os.unlink(self.path)  # stale: its run is gone
                    self._create(text)
        except OSError as exc:
            raise InputError(
                f"cannot take the study lock ({exc.strerror or exc})", source=str(self.path)
            ) from None
        self.mine = me

    def _create(self, text: str) -> None:
        fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
        try:
            os.write(fd, text.encode())
        except OSError:  # disk full: no lock without its holder
            os.close(fd)
            os.unlink(self.path)
            raise
        os.close(fd)

    def _holder(self) -> dict:
        try:
            d = json.loads(self.path.read_text(encoding="utf-8"))
        except ValueError:
            return {}  # written only in part: its writer died between create and write
        return d if isinstance(d, dict) else {}

    def _busy(self, h: dict) -> InputError:
        return InputError(
            f"another study run (pid {h.get('pid')} on {h.get('host')}, since {h.get('since')}) is "
            f"writing to this directory; wait for it to end, or delete {self.path} if that run "
            f"is gone",
            source=str(self.dir),
        )

    def release(self) -> None:
        if self.mine is None:
            return
        try:
            if self._holder().get("pid") == self.mine["pid"]:
                os.unlink(self.path)
        except OSError:
            pass  # left behind: the next run finds its process gone and takes it over
        self.mine = None


class _directory_flock:
    """Exclusive ``flock`` on a directory while a lock file in it is checked and taken (no-op
    without fcntl)."""

    def __init__(self, d: Path):
        self.d = d
        self.fd = None

    def __enter__(self):
        try:
            import fcntl
        except ImportError:  # pragma: no cover - not POSIX
            return self
        self.fd = os.open(self.d, os.O_RDONLY)
        try:
            fcntl.flock(self.fd, fcntl.LOCK_EX)
        except OSError:  # a file system without flock: the lock file alone still keeps runs apart
            pass
        return self

    def __exit__(self, *exc) -> None:
        if self.fd is not None:
            os.close(self.fd)  # releases the flock


def _process_start(pid: int):
    """Start time of a process in clock ticks since boot (Linux ``/proc``), else None."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as fh:
            return int(fh.read().rsplit(")", 1)[1].split()[19])
    except (OSError, ValueError, IndexError):
        return None


def _holder_alive(h: dict) -> bool:
    """Whether the run recorded in a lock file may still be running."""
    if not h or not isinstance(h.get("pid"), int):
        return False  # garbled: its writer died while writing it
    if h.get("host") != socket.gethostname():
        return True  # cannot tell: another host's run is never taken over
    try:
        os.kill(h["pid"], 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass  # a process of another user has that pid
    start = _process_start(h["pid"])
    return not (start is not None and h.get("start") is not None and start != h["start"])


__all__ = ["StudyLock"]
