"""What every subcommand shares: turning SceML errors into clean messages and exit codes.

`sceml --help` imports this module and nothing of the model: what a command needs of pyecore,
the generated classes or lxml is imported by the command's own module or inside the helper that
uses it, so listing the commands costs click and this file only.
"""

from __future__ import annotations

import gc
import importlib
import sys
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import click

from ..errors import ArgumentError, SceMLError

if TYPE_CHECKING:
    from ..diagnostics import Diagnostic
    from ..model.documents import Document

F = TypeVar("F", bound=Callable[..., Any])

#: Whether this process ends with its command (set by the console script, `sceml.cli.main`).
_process_ends_with_command = False


def freezing_imports_before_the_command() -> None:
    """Have each command, once its modules are imported, put every object alive then out of
    the cyclic collector's reach (`gc.freeze`), for a process that ends with the command.

    The modules, pyecore's metamodel and the generated classes are some 40,000 objects that
    live as long as the process; a full collection during the command walked all of them to
    find them alive (35-40 ms of `sceml simulate` UIS2, issue 31). Only the console script asks
    for it: a frozen object is never freed, which a test run or an editor calling commands in
    one process again and again must not pile up.
    """
    global _process_ends_with_command
    _process_ends_with_command = True
    # Nor does the collector run while they are imported: its full pass there (about 20 ms,
    # `sceml sample` and `sceml validate` had one) would find every one of them alive too.
    # It is turned back on once they are frozen (`SceMLCommand.invoke`).
    gc.disable()


class ReportedError(click.ClickException):
    """A SceMLError shown by click as `Error: file:line: message`, with the error's exit code."""

    def __init__(self, error: SceMLError) -> None:
        super().__init__(str(error))
        # click declares exit_code on the class; each SceML error carries its own.
        setattr(self, "exit_code", error.exit_code)  # noqa: B010


def exit_if_broken(errors: list[SceMLError]) -> None:
    """Report errors found after a command did its work (e.g. broken module references in a
    file that was still summarised or drawn), one `Error:` line each as for a raised SceMLError,
    then exit 1 if there were any."""
    for error in errors:
        click.echo(f"Error: {error}", err=True)
    if errors:
        raise click.exceptions.Exit(1)


class SceMLCommand(click.Command):
    """The base of every command: the one place a SceMLError becomes a message and exit code.

    Like click's own ClickException handling: the command body raises, this prints
    `Error: file:line: message` and exits with the error's code (2 for input or arguments that
    cannot be used, 1 otherwise), never with a traceback.
    """

    #: Whether the command notes on stderr each file it read that was saved with an older
    #: metamodel release (validate and migrate report those themselves).
    notes_migrations = True

    def invoke(self, ctx: click.Context) -> Any:
        from ..model.xmiresource import migration_notices  # the model, only once a command runs

        notice = _note_migration if self.notes_migrations else _ignore
        if _process_ends_with_command:
            gc.freeze()
            gc.enable()
        try:
            with migration_notices(notice):
                return super().invoke(ctx)
        except SceMLError as error:
            raise ReportedError(error) from None


def _note_migration(report: Any) -> None:
    click.echo(
        f"note: {report.file}: {report.summary()}; `sceml migrate {report.file} --in-place` "
        "rewrites it",
        err=True,
    )


def _ignore(report: Any) -> None:
    pass


class ReportsMigrations(SceMLCommand):
    """A command that reports migrated files itself (validate's warning, migrate's report)."""

    notes_migrations = False


class SceMLGroup(click.Group):
    """A click group whose commands (and subgroups) report SceMLError without a traceback."""

    command_class = SceMLCommand

    def invoke(self, ctx: click.Context) -> Any:
        try:
            return super().invoke(ctx)
        except SceMLError as error:
            raise ReportedError(error) from None


SceMLGroup.group_class = SceMLGroup


class LazySceMLGroup(SceMLGroup):
    """A SceMLGroup whose commands are imported by name when first asked for.

    `lazy_commands` maps each command name to "module:attribute" within this package.
    """

    def __init__(self, *args: Any, lazy_commands: dict[str, str], **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.lazy_commands = dict(lazy_commands)

    def list_commands(self, ctx: click.Context) -> list[str]:
        return [
            *self.lazy_commands,
            *(n for n in super().list_commands(ctx) if n not in self.lazy_commands),
        ]

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        """The list of commands, from their summaries: nothing is imported to show it."""
        from .summaries import summaries

        names = self.list_commands(ctx)
        known = summaries(self.lazy_commands)
        if any(name not in known and name not in self.commands for name in names):
            super().format_commands(ctx, formatter)  # a command without a summary: import all
            return
        limit = formatter.width - 6 - max(len(name) for name in names)
        rows = []
        for name in names:
            command = self.commands.get(name)
            if command is None:  # shortened by click's own rule, as the command would be
                command = click.Command(name, help=known[name])
            if not command.hidden:
                rows.append((name, command.get_short_help_str(limit)))
        with formatter.section("Commands"):
            formatter.write_dl(rows)

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        target = self.lazy_commands.get(cmd_name)
        if target is None or cmd_name in self.commands:
            return super().get_command(ctx, cmd_name)
        module_name, attribute = target.split(":")
        module = importlib.import_module(f"{__package__}.{module_name}")
        command = getattr(module, attribute)
        if not isinstance(command, click.Command):
            raise TypeError(f"{target} is not a click command")
        self.add_command(command, cmd_name)
        return command


class Parsed(click.ParamType[Any]):
    """An option value read by the library's own parser, so CLI and API accept the same text.

    The parser raises ArgumentError for text it cannot use; click shows that as a usage error
    (exit 2) naming the option.
    """

    def __init__(self, name: str, parse: Callable[[str], Any]) -> None:
        self.name = name
        self.parse = parse

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if not isinstance(value, str):
            return value  # a default, already parsed
        try:
            return self.parse(value)
        except ArgumentError as error:
            self.fail(error.message, param, ctx)


def echo_diagnostics(
    diagnostics: Iterable[Diagnostic], document: Document | None = None, file: Path | None = None
) -> None:
    """The one diagnostic formatter of the commands: `file:line: severity[CODE] message (path)`
    on standard error, one line each.

    A diagnostic found on a model in memory is placed where `document` read its element from,
    else in `file`.
    """
    for diagnostic in diagnostics:
        click.echo(str(locate(diagnostic, document, file)), err=True)


def locate(
    diagnostic: Diagnostic, document: Document | None = None, file: Path | None = None
) -> Diagnostic:
    """The diagnostic with the file and line of its element filled in where they were missing."""
    where, line = diagnostic.file, diagnostic.line
    element = diagnostic.element
    if document is not None and element is not None and where is None and element.eResource:
        where, found = document.where(element)
        line = line or found
    if where is None and (file or document) is not None:
        where = str(file or document.path)  # type: ignore[union-attr]
    return replace(diagnostic, file=where, line=line)


def input_file(name: str = "file") -> Callable[[F], F]:
    """The existing file a command reads, as a Path argument named `name`."""
    return click.argument(name, type=click.Path(exists=True, dir_okay=False, path_type=Path))


def output_file(
    help: str, *, metavar: str | None = None, required: bool = True
) -> Callable[[F], F]:
    """-o/--output: the one file a command writes (if not `required`, None when not given)."""
    return click.option(
        "-o",
        "--output",
        required=required,
        default=None,
        type=click.Path(dir_okay=False, path_type=Path),
        metavar=metavar,
        help=help,
    )


def output_folder(help: str) -> Callable[[F], F]:
    """-o/--output DIR, required: the folder a command writes its files into (as `out_dir`)."""
    return click.option(
        "-o",
        "--output",
        "out_dir",
        type=click.Path(file_okay=False, path_type=Path),
        metavar="DIR",
        required=True,
        help=help,
    )


#: --seed, on every command that draws random numbers.
seed_option = click.option(
    "--seed", type=click.IntRange(min=0), default=0, show_default=True, help="Seed."
)


def written_version_option(help: str) -> Callable[[F], F]:
    """--osc-version of the .xosc files a batch writes: any supported version, the newest by
    default."""
    from ..xosc.schema import SUPPORTED_VERSIONS

    return click.option(
        "--osc-version",
        type=click.Choice(SUPPORTED_VERSIONS),
        default=SUPPORTED_VERSIONS[-1],
        show_default=True,
        help=help,
    )


#: --workers, on every command that runs batch work (with `executor_options`).
workers_option = click.option(
    "--workers",
    type=click.IntRange(min=1),
    default=None,
    help="Worker processes of the processes executor, or of the dask executor's LocalCluster "
    "[default: the processors this process may use].",
)


def allow_option(command: F) -> F:
    """--allow, on every command that reads a model: one more folder references may reach."""
    return click.option(
        "--allow",
        "allow",
        multiple=True,
        type=click.Path(file_okay=False, path_type=Path),
        help="Another folder that files the input refers to (module libraries, maps) may be read "
        "from; repeatable. Always allowed: the input's folder and its project root (the "
        "nearest folder above with .git, .hg, .svn or .sceml-root), with their subfolders.",
    )(command)


@contextmanager
def file_progress(files: tuple[Path, ...], label: str) -> Iterator[Iterator[Path]]:
    """Iterate over files with a progress bar when a person is watching several of them.

    CI logs and pipes get no bar: it would only add noise there.
    """
    if len(files) > 1 and sys.stderr.isatty():
        with click.progressbar(files, label=label, file=sys.stderr) as bar:
            yield iter(bar)
    else:
        yield iter(files)


def report_options(json_help: str) -> Callable[[F], F]:
    """The options of every command that writes a diagnostics report: --format, --strict, -o."""

    def decorate(command: F) -> F:
        command = output_file(
            "Write the report to this file (atomically) instead of standard output.",
            required=False,
        )(command)
        command = click.option(
            "--strict", is_flag=True, help="Count warnings as errors (exit 1, JUnit failures)."
        )(command)
        return click.option(
            "--format",
            "output_format",
            type=click.Choice(["text", "json", "junit"]),
            default="text",
            show_default=True,
            help=f"text: compiler-style lines; json: {json_help}; junit: JUnit XML, one testcase "
            "per file and one failure per error.",
        )(command)

    return decorate


def emit_report(text: str, output: Path | None) -> None:
    """Write a report to `output` atomically, or to standard output."""
    if output is not None:
        from ..files.writing import write_atomically

        write_atomically(output, text.encode("utf-8"))
    else:
        click.echo(text, nl=False)


def executor_options(command: F) -> F:
    """--executor and --scheduler, on every command that runs batch work (sceml.executors).

    The command checks them with `sceml.executors.check` before it starts any work.
    """
    from ..executors import EXECUTORS, INSTALL_HINT  # the engines load only when a run opens one

    command = click.option(
        "--scheduler",
        metavar="ADDRESS",
        default=None,
        help="A running Dask scheduler, e.g. tcp://10.0.0.5:8786 (with --executor dask); "
        "without it the dask executor starts a LocalCluster of --workers processes.",
    )(command)
    return click.option(
        "--executor",
        type=click.Choice(EXECUTORS),
        default="processes",
        show_default=True,
        help="local: in this process; processes: a pool of --workers processes (one runs "
        f"in-process); dask: a Dask cluster (needs {INSTALL_HINT}).",
    )(command)
