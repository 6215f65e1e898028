"""What the solvers' C and C++ code writes straight to the process's file descriptors, kept off the
user's
terminal: Bonmin/CBC's node logs on descriptor 1, SCIP/SoPlex's messages on descriptor 2 (e.g.
'Cannot set feasibility tolerance to small value 1e-12 without GMP', hundreds of times on a long
solve).  Python's ``sys.stdout``/``sys.stderr`` do not see these writes; the descriptors themselves
are redirected."""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile


@contextlib.contextmanager
def quiet_stdout():
    """Send what is written to file descriptor 1 during the block to /dev/null."""
    sys.stdout.flush()
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):  # e.g. captured stdout without a descriptor
        yield
        return
    saved = os.dup(fd)
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), fd)
            yield
    finally:
        os.dup2(saved, fd)
        os.close(saved)


@contextlib.contextmanager
def c_stderr_to_file():
    """Send what is written to file descriptor 2 during the block to a temporary file instead of the
    user's terminal; yields a list that holds its distinct lines afterwards."""
    lines: list = []
    fd = 2  # the C library's stderr, whatever Python's sys.stderr is
    with contextlib.suppress(AttributeError, OSError, ValueError):
        sys.stderr.flush()
    try:
        tmp = tempfile.TemporaryFile()
    except OSError:  # no room for the file: leave the messages where they go
        yield lines
        return
    with tmp:  # closed on every path, also when descriptor 2 cannot be duplicated
        try:
            saved = os.dup(fd)
        except OSError:  # no descriptor 2 (a daemon): leave the messages where they go
            saved = None
        if saved is None:
            yield lines
            return
        try:
            os.dup2(tmp.fileno(), fd)
            try:
                yield lines
            finally:
                os.dup2(saved, fd)
        finally:
            os.close(saved)
        tmp.seek(0)
        text = tmp.read().decode("utf-8", "replace").splitlines()
        lines.extend(dict.fromkeys(t.strip() for t in text if t.strip()))


__all__ = ["quiet_stdout", "c_stderr_to_file"]
