"""The project's own exceptions.  The CLI turns :class:`InputError` into one line and exit code
2."""

from __future__ import annotations


class AxisoptError(Exception):
    """Base class of every error axisopt raises on purpose."""


class InputError(AxisoptError):
    """Bad user input: a file, line, column or key is named in the message."""

    def __init__(self, message: str, *, source: str | None = None, where: str | None = None):
        self.source = source
        self.where = where
        self.message = message
        prefix = ""
        if source:
            prefix = f"{source}"
            if where:
                prefix += f": {where}"
            prefix += ": "
        elif where:
            prefix = f"{where}: "
        super().__init__(prefix + message)


class ImplausibleInput(UserWarning):
    """A value far outside machine-tool practice (axisopt.design.plausible): used as given, and
    said.  The CLI prints each as one 'warning:' line on stderr naming the file, line and key."""
