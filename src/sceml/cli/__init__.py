"""The `sceml` command line: one module per subcommand, registered on one click group."""

from __future__ import annotations

import click

from .. import __version__
from .check_xosc import check_xosc
from .common import SceMLGroup
from .concretize import concretize
from .dev import dev
from .edit import edit
from .export import export
from .export_logical import export_distribution_command
from .flatten import flatten
from .info import info
from .module import module
from .promote import promote
from .render import render
from .report import report
from .sample import sample
from .validate import validate


@click.group(cls=SceMLGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="sceml")
def cli() -> None:
    """SceML: model, check, draw and export driving scenarios.

    Scenarios are XMI files in the SceML notation: a root node with actors and map, maneuver and
    condition nodes joined by flows, joins, an end node, and modules from libraries.
    """


cli.add_command(info)
cli.add_command(validate)
cli.add_command(render)
cli.add_command(report)
cli.add_command(export)
cli.add_command(check_xosc)
cli.add_command(concretize)
cli.add_command(promote)
cli.add_command(sample)
cli.add_command(export_distribution_command)
cli.add_command(module)
cli.add_command(flatten)
cli.add_command(dev)
cli.add_command(edit)


def main() -> None:
    """Console-script entry point."""
    cli()
