"""The `sceml` command line: one module per subcommand, registered on one click group.

A command's module (and what it imports: numpy for sampling, Jinja2 for export, graphviz for
drawing) is imported only when that command runs, or when `--help` lists them all: starting
`sceml validate` should cost the validator, not the whole toolchain.
"""

from __future__ import annotations

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
    """Console-script entry point."""
    cli()


def commands() -> dict[str, click.Command]:
    """Every top-level command, imported now (for documentation and tests)."""
    ctx = click.Context(cli)
    found = {name: cli.get_command(ctx, name) for name in cli.list_commands(ctx)}
    return {name: command for name, command in found.items() if command is not None}
