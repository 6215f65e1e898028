"""What an external solver's C code writes to file descriptor 2 during a solve stays off the user's terminal
and is kept for the notes (SoPlex printed 'Cannot set feasibility tolerance ... without GMP' hundreds of times
on one `solve --method scip` of the vertical problem)."""

import os

from axisopt.search.scip import _c_stderr_to_file


def test_c_level_stderr_is_captured_and_restored(capfd):
    with _c_stderr_to_file() as lines:
        os.write(2, b"Cannot set feasibility tolerance\n  \nCannot set feasibility tolerance\nother\n")
    assert lines == ["Cannot set feasibility tolerance", "other"]
    os.write(2, b"after\n")
    assert capfd.readouterr().err == "after\n"
