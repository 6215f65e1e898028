"""Every file axisopt writes or reads goes through here: one output opener (:func:`open_output`:
atomic for regular files, streamed in place for FIFOs, devices and standard output, ``-`` for
stdout) and one input opener (:func:`read_input`: regular files only, stat before open, a size cap
per kind); also output directories and figures.  Below every layer that writes (identify, search,
study, report)."""

from __future__ import annotations

import os
import stat as _stat
import sys
from contextlib import contextmanager
from pathlib import Path

from .errors import InputError

PLOT_FORMATS = ("png", "pdf", "svg", "jpg", "jpeg")

# Size caps of input files by kind [bytes], checked on the file's stat before it is opened (and
# again while reading: a file that grows past its cap is refused too).
INPUT_LIMITS = {
    "yaml": 20_000_000,  # design, problem, study, calibration YAML
    "catalog": 50_000_000,  # one catalog CSV
    "data": 10_000_000,  # a reduced-table diagnose CSV (static, friction, frequency, FRF)
    # a diagnose time record (a 20-minute record at 1 kHz is about 70 MB)
    "time record": 250_000_000,
    "case": 20_000_000,  # a study's case record (JSON)
}
# Rows of the diagnose files (the fits grow faster than linearly with them)
MAX_DATA_ROWS = 50_000
# 50 minutes at 1 kHz; beyond 150 000 samples a record is fitted in windows
MAX_TIME_SAMPLES = 3_000_000

_KIND_NAMES = {
    _stat.S_IFIFO: "a FIFO (named pipe)",
    _stat.S_IFCHR: "a character device",
    _stat.S_IFBLK: "a block device",
    _stat.S_IFSOCK: "a socket",
    _stat.S_IFDIR: "a directory",
    _stat.S_IFLNK: "a symbolic link",
}


def _kind_name(mode: int) -> str:
    return _KIND_NAMES.get(_stat.S_IFMT(mode), "not a regular file")


def check_input(path, kind: str, *, what: str = "file"):
    """``os.stat`` of input ``path``, refused (InputError naming ``path``, one line, exit 2) unless
    it is a regular file of at most ``INPUT_LIMITS[kind]`` bytes: a FIFO, device, socket or
    directory is never opened (a FIFO or ``/dev/zero`` would block or never end)."""
    limit = INPUT_LIMITS[kind]
    src = str(path)
    try:
        st = os.stat(path)
    except (OSError, ValueError) as exc:
        raise InputError(
            f"cannot read {what} ({getattr(exc, 'strerror', None) or exc})", source=src
        ) from None
    if not _stat.S_ISREG(st.st_mode):
        raise InputError(
            f"cannot read {what}: not a regular file ({_kind_name(st.st_mode)})", source=src
        )
    if st.st_size > limit:
        raise InputError(f"{what} too large ({st.st_size:,} bytes; at most {limit:,})", source=src)
    return st


def read_input(
    path, kind: str, *, what: str = "file", encoding: str = "utf-8", head: int | None = None
) -> str:
    """The text of input file ``path``, read whole (or its first ``head`` bytes), through
    :func:`check_input` first: nothing but a regular file within its size cap is opened.  After
    opening, the descriptor is checked again and at most the cap is read, so a file swapped or
    growing meanwhile is refused too.  ``encoding`` ``"utf-8-sig"`` drops a byte-order mark (CSV
    from Excel); a file that is not text in it is an InputError."""
    limit = INPUT_LIMITS[kind]
    src = str(path)
    check_input(path, kind, what=what)
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_NONBLOCK", 0))
        with open(fd, "rb") as fh:
            if not _stat.S_ISREG(os.fstat(fh.fileno()).st_mode):  # swapped since the stat
                raise InputError(f"cannot read {what}: not a regular file", source=src)
            data = fh.read(limit + 1 if head is None else min(head, limit + 1))
    except OSError as exc:
        raise InputError(f"cannot read {what} ({exc.strerror or exc})", source=src) from None
    if len(data) > limit:
        raise InputError(f"{what} too large (more than {limit:,} bytes)", source=src)
    try:
        return data.decode(encoding, errors="strict" if head is None else "ignore")
    except UnicodeDecodeError as exc:
        raise InputError(
            f"cannot read {what} (UnicodeDecodeError: not {encoding.upper()} text, byte "
            f"{exc.start:,})",
            source=src,
        ) from None


def refuse_nul(text: str, source: str) -> str:
    """``text`` unchanged, or a one-line InputError naming the line of its first NUL character (the
    csv module reads a NUL inside a cell as text, so a catalog with one would be accepted)."""
    if "\0" in text:
        line = text.count("\n", 0, text.index("\0")) + 1
        raise InputError(
            "a NUL byte in the file (is it plain text?)", source=source, where=f"line {line}"
        )
    return text


# CSV injection (OWASP, "CSV Injection"): a text cell starting with one of these is read by a
# spreadsheet as a formula; it is written with a leading single quote.  Numbers (also negative ones)
# stay numbers.
CSV_FORMULA_CHARS = ("=", "+", "-", "@", "\t", "\r")
_PLAIN_NUMBER = None


def csv_cell(value):
    """``value`` safe for a CSV cell opened in a spreadsheet: a text cell that starts with
    ``= + - @``, a tab or a carriage return gets a leading ``'`` (OWASP's advice against CSV
    injection), unless the whole text is a plain number such as ``-3.5`` (numeric cells, and text
    that is only a number, are never changed)."""
    global _PLAIN_NUMBER
    if not isinstance(value, str) or not value.startswith(CSV_FORMULA_CHARS):
        return value
    if _PLAIN_NUMBER is None:
        import re

        _PLAIN_NUMBER = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")
    return value if _PLAIN_NUMBER.match(value) else "'" + value


def csv_safe(df):
    """A copy of DataFrame ``df`` with every text cell (and column name) passed through
    :func:`csv_cell`; what every CSV axisopt writes goes through (parts --csv, compare --csv, a
    study's results.csv)."""
    out = df.copy()
    for c in out.columns:
        if out[c].dtype == object or str(out[c].dtype) in ("string", "str"):
            out[c] = out[c].map(csv_cell)
    out.columns = [csv_cell(c) if isinstance(c, str) else c for c in out.columns]
    return out


def make_output_dir(path):
    """Create an output directory (and its parents); a path that cannot be one is an InputError."""
    if str(path) == "":
        raise InputError("empty output directory name")
    if str(path) == "-":
        raise InputError(
            "'-' (standard output) cannot be an output directory; give a directory name"
        )
    d = Path(path)
    if d.exists() and not d.is_dir():
        raise InputError(
            "cannot create output directory: a file of that name is in the way", source=str(d)
        )
    try:
        d.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(
            f"cannot create output directory ({exc.strerror or exc})", source=str(d)
        ) from None
    return d


def is_stdout(path) -> bool:
    """``-`` (or a path that is this process's standard output, such as ``/dev/stdout``)."""
    if str(path) == "-":
        return True
    try:
        return os.path.samestat(os.stat(path), os.fstat(sys.stdout.fileno()))
    except (OSError, ValueError, AttributeError, TypeError):
        return False


def output_target(path) -> str:
    """How :func:`open_output` writes ``path``: ``"stdout"`` (``-`` or this process's standard
    output), ``"stream"`` (an existing FIFO, device or socket, or anything under ``/dev`` or
    ``/proc``: written in place, never replaced) or ``"atomic"`` (a regular file or a missing path:
    a temporary file renamed over it).  A directory, or an empty name, is an InputError."""
    p = str(path)
    if p == "":
        raise InputError("empty output file name")
    if is_stdout(p):
        return "stdout"
    try:
        st = os.stat(p)
    except FileNotFoundError:
        return "atomic"
    except (OSError, ValueError) as exc:
        raise InputError(
            f"cannot write to this path ({getattr(exc, 'strerror', None) or exc})", source=p
        ) from None
    if _stat.S_ISDIR(st.st_mode):
        raise InputError("cannot write: a directory of that name is in the way", source=p)
    real = os.path.realpath(p)
    if not _stat.S_ISREG(st.st_mode) or any(
        x.startswith(("/dev/", "/proc/")) for x in (os.path.abspath(p), real)
    ):
        return "stream"
    return "atomic"


def check_output_path(path, *, what: str = "file", where: str | None = None) -> None:
    """Refuse an output path before the work starts (InputError, one line): an empty name, a
    directory in the way, or (for a file written atomically) a parent that is not an existing,
    writable directory."""
    try:
        how = output_target(path)
    except InputError as exc:
        raise InputError(exc.message, source=exc.source, where=where) from None
    if how != "atomic":
        return
    parent = os.path.dirname(os.path.abspath(os.path.realpath(str(path)))) or "."
    if not os.path.isdir(parent):
        raise InputError(
            f"cannot write {what}: directory '{parent}' does not exist",
            source=str(path),
            where=where,
        )
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InputError(
            f"cannot write {what}: no permission to write in '{parent}'",
            source=str(path),
            where=where,
        )


def same_file(a, b) -> bool:
    """Whether two paths name one existing file (hard and symbolic links included)."""
    try:
        return os.path.samefile(str(a), str(b))
    except (OSError, ValueError):
        return False


def refuse_inputs(
    path,
    inputs,
    *,
    what: str = "file",
    where: str | None = None,
    hint: str = "give another file name",
) -> None:
    """Refuse (InputError, one line) an output ``path`` that is one of ``inputs`` (the files the
    work read): the Python functions' counterpart of the command line's output check, so that a call
    such as ``save_calibration(diag, "run1.csv", sources=["run1.csv"])`` cannot replace the measured
    data."""
    for src in inputs:
        if src and same_file(path, src):
            raise InputError(
                f"would overwrite the input {src} with the {what}; {hint}",
                source=str(path),
                where=where,
            )


class _NoClose:
    """Standard output lent to a writer: flushed, never closed."""

    def __init__(self, stream):
        self._s = stream

    def write(self, data):
        return self._s.write(data)

    def __getattr__(self, name):
        return getattr(self._s, name)


@contextmanager
def open_output(path, mode: str = "w", *, what: str = "file", fsync: bool = True):
    """Open output ``path`` for writing: the one way axisopt writes a file.

    * ``-`` (or this process's own standard output, e.g. ``/dev/stdout``): written to stdout, after
      what the command printed so far.
    * a regular file or a missing path: replaced whole or not at all -- the content goes to a
      temporary file in the same directory (``.NAME.PID.RANDOM.tmp``), which ``os.replace`` then
      puts in place atomically.  A write that fails (disk full, no permission) or a process killed
      mid-write leaves the old file untouched; the temporary file is removed on failure (one left by
      ``kill -9`` is swept by the next study run).  A symbolic link stays a link: its target is
      replaced.  ``fsync`` also guards the content against a power loss right after the rename.
    * anything else that exists (a FIFO, a character device such as ``/dev/full``, a socket,
      anything under ``/dev`` or ``/proc``): opened and written in place, streamed; it is never
      replaced or created.

    ``mode`` is ``"w"`` (UTF-8 text, newlines written as given) or ``"wb"``.  An ``OSError``
    (including a full device) becomes an InputError naming ``path`` (one line, exit code 2); a
    directory in the way or an empty name too.
    """
    if mode not in ("w", "wb"):
        raise ValueError(f"mode must be 'w' or 'wb', got {mode!r}")
    how = output_target(path)
    p = str(path)
    if how == "stdout":
        out = sys.stdout
        try:
            out.flush()
            if mode == "wb":
                raw = getattr(out, "buffer", None)
                if raw is None:
                    raise InputError(
                        f"cannot write {what} to standard output (not a byte stream)", source=p
                    )
                yield _NoClose(raw)
                raw.flush()
            else:
                yield _NoClose(out)
                out.flush()
        except OSError as exc:
            raise InputError(f"cannot write {what} ({exc.strerror or exc})", source=p) from None
        return
    if how == "stream":
        try:
            fd = os.open(p, os.O_WRONLY | getattr(os, "O_NOCTTY", 0))  # never O_CREAT: it exists
            st = os.fstat(fd)
            if _stat.S_ISREG(st.st_mode):
                os.ftruncate(fd, 0)
            with open(
                fd, mode, **({"encoding": "utf-8", "newline": ""} if mode == "w" else {})
            ) as fh:
                yield fh
                fh.flush()
        except OSError as exc:
            raise InputError(f"cannot write {what} ({exc.strerror or exc})", source=p) from None
        return
    yield from _atomic(
        Path(os.path.realpath(p)) if os.path.islink(p) else Path(p), mode, what, fsync, p
    )


def _atomic(p: Path, mode: str, what: str, fsync: bool, shown: str):
    import secrets

    tmp = p.with_name(f".{p.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp")
    done = False
    try:
        # 0o666 & ~umask, as open() would
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        with open(fd, mode, **({"encoding": "utf-8", "newline": ""} if mode == "w" else {})) as fh:
            yield fh
            fh.flush()
            if fsync:
                os.fsync(fh.fileno())
        os.replace(tmp, p)
        done = True
    except OSError as exc:
        raise InputError(f"cannot write {what} ({exc.strerror or exc})", source=shown) from None
    finally:
        if not done:
            try:
                os.unlink(tmp)
            except OSError:
                pass


# the name every writer used before open_output also handled '-' and special files
atomic_file = open_output


def write_text_atomic(path, text: str, *, what: str = "file", fsync: bool = True) -> None:
    """Write a text file (UTF-8) through :func:`open_output` (atomic for a regular file, ``-`` is
    stdout)."""
    with open_output(path, "w", what=what, fsync=fsync) as fh:
        fh.write(text)


def tidy_layout(fig) -> None:
    """``fig.tight_layout()`` without matplotlib's warning when it cannot make room (a long legend
    or title in a small figure): the figure is then saved as laid out, which is no reason to print a
    Python warning to the user."""
    import warnings

    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Tight layout not applied", category=UserWarning)
        fig.tight_layout()


def save_figure(fig, path, dpi: int = 110) -> None:
    """Save and close a matplotlib figure, atomically (:func:`atomic_file`); a bad path or format is
    an InputError (one line, exit 2).  A figure outside pyplot (axisopt's own) is saved without
    importing pyplot."""
    ext = Path(path).suffix.lower().lstrip(".")
    try:
        if ext not in PLOT_FORMATS:
            raise InputError(
                f"plot file needs one of the extensions {', '.join(PLOT_FORMATS)}", source=str(path)
            )
        with open_output(path, "wb", what="plot") as fh:
            fig.savefig(fh, format=ext, dpi=dpi)
    except ValueError as exc:
        raise InputError(f"cannot write plot ({exc})", source=str(path)) from None
    finally:
        # a pyplot figure: released from pyplot's list
        if getattr(fig.canvas, "manager", None) is not None:
            import matplotlib.pyplot as plt

            plt.close(fig)
