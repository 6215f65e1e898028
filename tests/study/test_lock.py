"""The study lock (study.lock): a stale lock (dead, garbled or reused pid) is taken over, another
host's is not."""

from __future__ import annotations

import json
import os
import socket
import subprocess

import pytest
from study_helpers import PYTHON

from axisopt.errors import InputError
from axisopt.study.run import StudyLock


@pytest.mark.parametrize("holder", ["dead", "garbled", "reused", "other host"])
def test_stale_lock_is_taken_over_and_foreign_one_is_not(tmp_path, holder):
    dead = subprocess.run(
        [PYTHON, "-c", "import os; print(os.getpid())"], capture_output=True, text=True
    )
    me = {"pid": int(dead.stdout), "host": socket.gethostname(), "start": 1, "since": "earlier"}
    if holder == "garbled":  # killed between creating the file and writing it
        text = ""
    # the pid now belongs to another process (this one), started at another time
    elif holder == "reused":
        text = json.dumps({**me, "pid": os.getpid()})
    elif holder == "other host":  # its process may be alive: never taken over
        text = json.dumps({**me, "pid": os.getpid(), "host": "elsewhere.example"})
    else:
        text = json.dumps(me)
    lock = tmp_path / ".lock"
    lock.write_text(text, encoding="utf-8")
    if holder == "other host":
        with pytest.raises(InputError, match="elsewhere.example"):
            StudyLock(tmp_path).acquire()
        assert lock.read_text(encoding="utf-8") == text
    else:
        with StudyLock(tmp_path):
            assert json.loads(lock.read_text(encoding="utf-8"))["pid"] == os.getpid()
        assert not lock.exists()
