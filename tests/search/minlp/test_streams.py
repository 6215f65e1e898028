"""What an external solver's C code writes to file descriptor 2 during a solve stays off the user's
terminal and is kept for the notes (SoPlex printed 'Cannot set feasibility tolerance ... without
GMP' hundreds of times on one `solve --method scip` of the vertical problem)."""

import os

from axisopt.search.minlp import streams
from axisopt.search.minlp.streams import c_stderr_to_file


def test_c_level_stderr_is_captured_and_restored(capfd):
    with c_stderr_to_file() as lines:
        os.write(
            2, b"Cannot set feasibility tolerance\n  \nCannot set feasibility tolerance\nother\n"
        )
    assert lines == ["Cannot set feasibility tolerance", "other"]
    os.write(2, b"after\n")
    assert capfd.readouterr().err == "after\n"


def test_temporary_file_closed_when_descriptor_2_cannot_be_duplicated(monkeypatch):
    """No descriptor 2 to duplicate (a daemon): the messages stay where they go, and the temporary
    file opened for them is closed at once (it was left open for the garbage collector)."""
    import tempfile

    opened, real = [], tempfile.TemporaryFile

    def temporary_file(*a, **k):
        opened.append(real(*a, **k))
        return opened[-1]

    def no_dup(fd):
        raise OSError(9, "Bad file descriptor")

    monkeypatch.setattr(streams.tempfile, "TemporaryFile", temporary_file)
    monkeypatch.setattr(streams.os, "dup", no_dup)
    with c_stderr_to_file() as lines:
        pass
    assert lines == [] and len(opened) == 1 and opened[0].closed
