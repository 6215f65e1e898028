"""Output files written whole or not at all (every file axisopt writes goes through here), output
directories and figures.  Below every layer that writes (identify, search, study, report)."""

from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path

from .errors import InputError

PLOT_FORMATS = ("png", "pdf", "svg", "jpg", "jpeg")


def make_output_dir(path):
    """Create an output directory (and its parents); a path that cannot be one is an InputError."""
    d = Path(path)
    if d.exists() and not d.is_dir():
        raise InputError("cannot create output directory: a file of that name is in the way", source=str(d))
    try:
        d.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot create output directory ({exc.strerror or exc})", source=str(d)) from None
    return d


@contextmanager
def atomic_file(path, mode: str = "w", *, what: str = "file", fsync: bool = True):
    """Open ``path`` for writing so that it is replaced whole or not at all.

    Every output file of axisopt goes through here: the content goes to a temporary file in the same
    directory (``.NAME.PID.RANDOM.tmp``), which ``os.replace`` then puts in place atomically.  A write that
    fails (disk full, no permission, a directory in the way) or a process killed mid-write leaves the old
    file untouched; the temporary file is removed on failure (one left by ``kill -9`` is swept by the next
    study run).  ``mode`` is ``"w"`` (UTF-8 text, newlines written as given) or ``"wb"``.  ``fsync`` also
    guards the content against a power loss right after the rename.  An ``OSError`` becomes an InputError
    naming ``path`` (one line, exit code 2).
    """
    import os
    import secrets

    if mode not in ("w", "wb"):
        raise ValueError(f"mode must be 'w' or 'wb', got {mode!r}")
    p = Path(path)
    if p.is_dir():
        raise InputError(f"cannot write {what}: a directory of that name is in the way", source=str(p))
    tmp = p.with_name(f".{p.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp")
    done = False
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)  # 0o666 & ~umask, as open() would
        with open(fd, mode, **({"encoding": "utf-8", "newline": ""} if mode == "w" else {})) as fh:
            yield fh
            fh.flush()
            if fsync:
                os.fsync(fh.fileno())
        os.replace(tmp, p)
        done = True
    except OSError as exc:
        raise InputError(f"cannot write {what} ({exc.strerror or exc})", source=str(p)) from None
    finally:
        if not done:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def write_text_atomic(path, text: str, *, what: str = "file", fsync: bool = True) -> None:
    """Write a text file (UTF-8) whole or not at all, through :func:`atomic_file`."""
    with atomic_file(path, "w", what=what, fsync=fsync) as fh:
        fh.write(text)


def tidy_layout(fig) -> None:
    """``fig.tight_layout()`` without matplotlib's warning when it cannot make room (a long legend or title
    in a small figure): the figure is then saved as laid out, which is no reason to print a Python warning
    to the user."""
    import warnings

    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Tight layout not applied", category=UserWarning)
        fig.tight_layout()


def save_figure(fig, path, dpi: int = 110) -> None:
    """Save and close a matplotlib figure, atomically (:func:`atomic_file`); a bad path or format is an
    InputError (one line, exit 2)."""
    import matplotlib.pyplot as plt

    ext = Path(path).suffix.lower().lstrip(".")
    try:
        if ext not in PLOT_FORMATS:
            raise InputError(f"plot file needs one of the extensions {', '.join(PLOT_FORMATS)}", source=str(path))
        with atomic_file(path, "wb", what="plot") as fh:
            fig.savefig(fh, format=ext, dpi=dpi)
    except ValueError as exc:
        raise InputError(f"cannot write plot ({exc})", source=str(path)) from None
    finally:
        plt.close(fig)
