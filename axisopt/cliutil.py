"""Shared pieces of the command-line modules (``cli.py`` and ``*_cli.py``)."""

from __future__ import annotations

import argparse
import json

from .errors import InputError

EXIT_OK, EXIT_NEGATIVE, EXIT_INPUT = 0, 1, 2


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (InputError, exit code 2)."""

    def error(self, message):
        raise InputError(f"{self.prog}: {message}")


def json_default(o):
    import numpy as np

    if isinstance(o, np.generic):
        return o.item()
    if isinstance(o, np.ndarray):
        return o.tolist()
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def write_json(obj, target: str) -> None:
    """Write ``obj`` as JSON to a file, or to stdout when ``target`` is '-'."""
    text = json.dumps(obj, indent=2, default=json_default, allow_nan=False)
    if target == "-":
        print(text)
        return
    try:
        with open(target, "w", encoding="utf-8") as fh:
            fh.write(text + "\n")
    except OSError as exc:
        raise InputError(f"cannot write JSON ({exc.strerror})", source=target) from None
