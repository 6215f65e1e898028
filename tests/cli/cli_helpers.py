"""What the tests of refused inputs share: the one-line error on stderr, and a file written for a
command."""

from __future__ import annotations


def one_line_error(capsys) -> str:
    """The error the command printed: one line on stderr, starting 'error: ', no traceback."""
    cap = capsys.readouterr()
    err = cap.err.strip()
    assert err.startswith("error: ") and "\n" not in err and "Traceback" not in cap.err, cap.err
    return err


def write_file(tmp_path, name, text) -> str:
    """``text`` written as UTF-8 to ``tmp_path / name``; its path as a string (a command-line
    argument)."""
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)
