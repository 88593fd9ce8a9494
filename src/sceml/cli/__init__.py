"""The `sceml` command line: one module per subcommand, registered on one click group.

A command's module (and what it imports: numpy for sampling, Jinja2 for export, graphviz for
drawing) is imported only when that command runs, or when `--help` lists them all: starting
`sceml validate` should cost the validator, not the whole toolchain.
"""

from __future__ import annotations

import atexit
import gc
import os
import sys
import threading

import click

from .common import LazySceMLGroup

#: Command name -> "module:function", in the order `sceml --help` lists them.
COMMANDS = {
    "info": "info:info",
    "validate": "validate:validate",
    "render": "render:render",
    "report": "report:report",
    "export": "export:export",
    "check-xosc": "check_xosc:check_xosc",
    "import": "import_:import_command",
    "extract": "extract:extract_command",
    "concretize": "concretize:concretize",
    "promote": "promote:promote",
    "sample": "sample:sample",
    "simulate": "simulate:simulate_command",
    "check-run": "check_run:check_run",
    "explore": "explore:explore_command",
    "export-distribution": "export_logical:export_distribution_command",
    "module": "module:module",
    "flatten": "flatten:flatten",
    "migrate": "migrate:migrate",
    "dev": "dev:dev",
    "edit": "edit:edit",
    "diff": "diff:diff",
    "merge": "merge:merge",
    "git-setup": "git_setup:git_setup",
}


@click.group(
    cls=LazySceMLGroup,
    lazy_commands=COMMANDS,
    context_settings={"help_option_names": ["-h", "--help"]},
)
@click.version_option(None, "--version", prog_name="sceml", package_name="sceml")
def cli() -> None:
    """SceML: model, check, draw and export driving scenarios.

    Scenarios are XMI files in the SceML notation: a root node with actors and map, maneuver and
    condition nodes joined by flows, joins, an end node, and modules from libraries.
    """


def main() -> None:
    """Console-script entry point: run the command, then end the process without teardown."""
    from ..model.collector import ending_with_command
    from .blas_threads import one_blas_thread
    from .common import freezing_imports_before_the_command
    from .deferred import defer_unused_imports

    defer_unused_imports()
    one_blas_thread()
    ending_with_command()
    freezing_imports_before_the_command()
    try:
        cli()
    except SystemExit as done:
        # A message instead of a status (sys.exit("...")) is printed by the ordinary exit.
        if done.code is None or isinstance(done.code, int):
            end_now(done.code or 0)
        raise
    finally:
        # Reached only on the way to the ordinary exit (end_now does not return when it ends
        # the process): every object back in the collector's reach, as Python's exit expects,
        # so that its last collection frees what it always did.
        gc.unfreeze()


def end_now(code: int) -> None:
    """End the process with `code` once its output is out, without freeing the model.

    The interpreter's own exit collects every object it still holds: for a loaded model, a
    million pyecore objects in reference cycles, 0.5 s at 10k nodes and 5-10 s at 200k, after
    the command has said everything. The exit handlers still run (temporary folders, logging);
    what is skipped is only the freeing, which the operating system does at once. A thread or
    child process still running gets the ordinary exit, which waits for it.
    """
    if not _can_end_now():
        return
    atexit._run_exitfuncs()  # what the interpreter's exit would run, in the same order
    _flushed()
    os._exit(code)


_MAIN = threading.main_thread()


def _can_end_now() -> bool:
    """No thread or child process still running, and the output flushed."""
    if any(t.is_alive() and not t.daemon for t in threading.enumerate() if t is not _MAIN):
        return False
    multiprocessing = sys.modules.get("multiprocessing")
    if multiprocessing is not None and multiprocessing.active_children():
        return False
    return _flushed()  # False: a closed pipe or stream, which the ordinary exit reports


def _flushed() -> bool:
    """Flush stdout and stderr; False if either cannot take it."""
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except (OSError, ValueError):
        return False
    return True


def commands() -> dict[str, click.Command]:
    """Every top-level command, imported now (for documentation and tests)."""
    ctx = click.Context(cli)
    found = {name: cli.get_command(ctx, name) for name in cli.list_commands(ctx)}
    return {name: command for name, command in found.items() if command is not None}
