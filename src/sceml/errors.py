"""Exceptions for input SceML cannot use at all, located gcc-style as file:line: message."""

from __future__ import annotations

from pathlib import Path


class SceMLError(Exception):
    """Base of every error SceML raises on purpose; it carries where the problem is."""

    exit_code = 1

    def __init__(
        self,
        message: str,
        *,
        file: str | Path | None = None,
        line: int | None = None,
        element: str | None = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        self.file = str(file) if file is not None else None
        self.line = line
        self.element = element

    def __str__(self) -> str:
        where = ""
        if self.file:
            where = self.file + (f":{self.line}" if self.line else "") + ": "
        suffix = f" ({self.element})" if self.element else ""
        return f"{where}{self.message}{suffix}"


class LoadError(SceMLError):
    """A model file cannot be read: missing, malformed, hostile or of the wrong kind."""

    exit_code = 2


class ArgumentError(SceMLError):
    """A value given to an operation (a command-line option) cannot be used: a usage error.

    The library's parsers raise it; the CLI's option types call those parsers, so an option is
    accepted or refused by the same rule as the Python API.
    """

    exit_code = 2


class SaveError(SceMLError):
    """A model could not be written; the previous file, if any, is untouched."""

    exit_code = 1


class BuildError(SceMLError):
    """The Python builder API was called with arguments that make no model."""

    exit_code = 2
