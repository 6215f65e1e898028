"""Shared pieces of the command modules: the argument parser, exit codes, JSON output."""

from __future__ import annotations

import argparse
import json
import math

from ..errors import InputError

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


def _finite(obj):
    """``obj`` with every NaN or infinite float replaced by None (JSON null: no value, never NaN)."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: _finite(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_finite(v) for v in obj]
    if hasattr(obj, "dtype") and hasattr(obj, "tolist"):  # numpy scalars and arrays
        return _finite(obj.tolist())
    return obj


def write_json(obj, target: str) -> None:
    """Write ``obj`` as JSON to a file (atomically: the old file stays whole if writing fails), or to stdout
    when ``target`` is '-'.  A file that cannot be written is an InputError naming it."""
    text = json.dumps(_finite(obj), indent=2, default=json_default, allow_nan=False)
    if target == "-":
        print(text)
        return
    from ..fileio import write_text_atomic

    write_text_atomic(target, text + "\n", what="JSON")
