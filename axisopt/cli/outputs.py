"""Every output path of a command checked before the command does any work: never onto one of its
inputs (``axisopt solve p.yaml --save-design p.yaml`` would replace the problem), never two outputs
onto one file, a file's directory existing and writable, a figure's extension known.  Standard
output (``-``), FIFOs and devices are written in place as before and are not compared."""

from __future__ import annotations

import os
import re
import stat as _stat

from ..errors import InputError
from ..fileio import PLOT_FORMATS, check_output_path, output_target, same_file
from .common import OUTPUT_OPTIONS

# output options beyond the shared list: evaluate's state-space file
EXTRA_OUTPUTS = ("--ss",)
# options that name a figure (their extension must be one matplotlib writes)
PLOT_OPTIONS = ("--plot", "--frf")
# argparse attributes that are never paths
_NOT_PATHS = {
    "command",
    "func",
    "method",
    "plotly",
    "machine",
    "kind",
    "vendor",
    "status",
    "fits",
    "diameter",
    "lead",
    "preload_class",
    "effects",
    "gain",
    "scheduler",
    "time_limit",
    "top",
    "workers",
}
# what each output is, in the error (the writers' own words)
_WHAT = {
    "--json": "JSON",
    "--csv": "CSV",
    "--plot": "plot",
    "--frf": "plot",
    "--report": "HTML report",
    "--save-design": "design YAML",
    "--save-calibration": "calibration",
    "--ss": "state-space file",
    "--out": "file",
}
# a --save-design directory gets 1.yaml, 2.yaml ... (01.yaml from 10 designs)
_RANKED_YAML = re.compile(r"^\d+\.yaml$")


def _attr(option: str) -> str:
    return option[2:].replace("-", "_")


def _is_dir_output(command: str, option: str, value: str) -> bool:
    """An output option that names a directory (files are written inside it)."""
    low = value.lower()
    if option == "--out":
        return command == "study"
    if option == "--save-design":
        return not low.endswith((".yaml", ".yml")) and value != "-"
    if option == "--report":
        return command == "diagnose" and not low.endswith((".html", ".htm"))
    return False


def _regular(path: str) -> bool:
    try:
        return _stat.S_ISREG(os.stat(path).st_mode)
    except (OSError, ValueError):
        return False


def _inputs(args, outputs: set) -> list:
    """The regular files the command reads: every path-like argument that names one (a directory's
    files for a directory argument such as ``parts --catalogs DIR``)."""
    found = []
    for name, value in vars(args).items():
        if name in _NOT_PATHS or name in outputs:
            continue
        values = value if isinstance(value, (list, tuple)) else [value]
        for v in values:
            if not isinstance(v, str) or not v or v == "-":
                continue
            if _regular(v):
                found.append((name, v))
            elif os.path.isdir(v):
                try:
                    found += [
                        (name, os.path.join(v, f))
                        for f in sorted(os.listdir(v))
                        if _regular(os.path.join(v, f))
                    ]
                except OSError:
                    pass
    return found


def _named(name: str) -> str:
    return {
        "problem": "the problem file",
        "design": "the design file",
        "files": "an input file",
        "study": "the study file",
        "data": "a data file",
        "calibration": "the calibration file",
        "catalogs": "a catalog file",
    }.get(name, f"an input ({name})")


def check_outputs(args) -> None:
    """Refuse (InputError, one line, exit 2) before any work: an output that is one of the command's
    inputs, two outputs naming one file, a file output whose directory is missing or not writable, a
    figure with an extension matplotlib does not write, a directory output that is a file."""
    command = getattr(args, "command", "") or ""
    given = [
        (o, getattr(args, _attr(o)))
        for o in OUTPUT_OPTIONS + EXTRA_OUTPUTS
        if isinstance(getattr(args, _attr(o), None), str)
    ]
    if not given:
        return
    inputs = _inputs(args, {_attr(o) for o, _ in given})
    files, dirs = [], []
    for option, value in given:
        if _is_dir_output(command, option, value):
            if os.path.exists(value) and not os.path.isdir(value):
                raise InputError(
                    "cannot create output directory: a file of that name is in the way",
                    source=value,
                    where=option,
                )
            for name, path in inputs:
                if (
                    option == "--save-design"
                    and _RANKED_YAML.match(os.path.basename(path))
                    and same_file(os.path.dirname(path) or ".", value)
                ):
                    raise InputError(
                        f"would write over {_named(name)} {path} of this command; give another "
                        f"directory",
                        where=option,
                    )
            dirs.append((option, value))
            continue
        if option in PLOT_OPTIONS:  # save_figure refuses these too, but only after the work
            ext = os.path.splitext(value)[1].lower().lstrip(".")
            if ext not in PLOT_FORMATS:
                raise InputError(
                    f"plot file needs one of the extensions {', '.join(PLOT_FORMATS)}",
                    source=value,
                    where=option,
                )
        how = output_target(value)
        if how == "atomic":
            for name, path in inputs:
                if same_file(path, value):
                    raise InputError(
                        f"would overwrite {_named(name)} {path} of this command; give another "
                        f"file name",
                        where=option,
                    )
            for other, earlier in files:
                if os.path.realpath(earlier) == os.path.realpath(value) or same_file(
                    earlier, value
                ):
                    raise InputError(
                        f"{other} and {option} name the same file {value}; give each its own",
                        where=option,
                    )
            files.append((option, value))
    for option, value in dirs:
        for other, f in files:
            if os.path.realpath(f) == os.path.realpath(value):
                raise InputError(
                    f"{other} writes a file where {option} wants a directory ({value}); give each "
                    f"its own name",
                    where=option,
                )
    # directories the command itself creates first (a --report or --out directory and its parents):
    # a file output in one of them is written after they exist
    made = set()
    for _, value in dirs:
        d = os.path.abspath(value)
        while d and not os.path.exists(d):
            made.add(d)
            d = os.path.dirname(d)
    for option, value in given:
        if (option, value) in dirs:
            continue
        if output_target(value) == "atomic" and os.path.dirname(os.path.abspath(value)) in made:
            continue
        check_output_path(value, what=_WHAT.get(option, "file"), where=option)
