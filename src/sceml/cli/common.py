"""What every subcommand shares: turning SceML errors into clean messages and exit codes."""

from __future__ import annotations

from typing import Any

import click

from ..errors import SceMLError


class ReportedError(click.ClickException):
    """A SceMLError shown by click as `Error: file:line: message`, with the error's exit code."""

    def __init__(self, error: SceMLError) -> None:
        super().__init__(str(error))
        # click declares exit_code on the class; each SceML error carries its own.
        setattr(self, "exit_code", error.exit_code)  # noqa: B010


class SceMLGroup(click.Group):
    """A click group whose commands report SceMLError without a traceback."""

    def invoke(self, ctx: click.Context) -> Any:
        try:
            return super().invoke(ctx)
        except SceMLError as error:
            raise ReportedError(error) from None
