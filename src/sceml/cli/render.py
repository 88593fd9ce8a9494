"""`sceml render FILE -o OUT`: draw a scenario or library module as SVG, PNG or PDF."""

from __future__ import annotations

from pathlib import Path
from typing import cast

import click

from ..io import load, model_path, unresolved_references, write_atomically
from ..render import FORMATS, ModuleChoiceError, View, diagram, to_bytes
from ..render.flow import Modules
from .common import SceMLCommand, allow_option


def output_format(path: Path) -> str:
    """The format named by an output file's suffix; a usage error for any other suffix."""
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise click.BadParameter(
            f"cannot tell the format from {path.name!r}; use a .svg, .png or .pdf file",
            param_hint="'-o' / '--output'",
        )
    return fmt


@click.command(cls=SceMLCommand)
@click.argument("file", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--output",
    required=True,
    type=click.Path(dir_okay=False, path_type=Path),
    help="File to write; its suffix (.svg, .png or .pdf) chooses the format.",
)
@click.option(
    "--view",
    type=click.Choice(["flow", "bt"]),
    default="flow",
    show_default=True,
    help="flow: the SceML notation; bt: the same scenario as a behavior tree.",
)
@click.option(
    "--modules",
    type=click.Choice(["collapsed", "expanded"]),
    default="collapsed",
    show_default=True,
    help="Draw each module use as one box, or as a frame with its nodes and in/out ports.",
)
@click.option("--legend", is_flag=True, help="Add the notation's legend beside the diagram.")
@click.option(
    "--module",
    "module",
    metavar="NAME",
    default=None,
    help="For a module library: the module definition to draw (required there).",
)
@allow_option
def render(
    file: Path,
    output: Path,
    view: str,
    modules: str,
    legend: bool,
    module: str | None,
    allow: tuple[Path, ...],
) -> None:
    """Draw FILE, a scenario or a module library (.xmi), as a diagram.

    Exits 0 when the diagram is written, 1 when it is written but a module use's definition
    cannot be loaded (drawn as broken), 2 for usage errors or unreadable input.
    """
    fmt = output_format(output)
    try:
        document = load(file, allow=allow)
        root = document.root
        graph = diagram(
            root,
            view=cast(View, view),
            modules=cast(Modules, modules),
            legend=legend,
            module=module,
        )
        write_atomically(output, to_bytes(graph, fmt))
    except ModuleChoiceError as error:
        raise click.UsageError(error.message) from None
    click.echo(f"wrote {output}")
    # The diagram draws a broken module use as such; the exit status still says it is broken.
    broken = list(unresolved_references(root))
    for holder, _href, reason in broken:
        line = document.line_of(holder)
        where = f"{file}:{line}" if line else str(file)
        click.echo(f"Error: {where}: {reason} ({model_path(holder)})", err=True)
    if broken:
        raise SystemExit(1)
