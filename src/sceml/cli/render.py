"""`sceml render FILE -o OUT`: draw a scenario or library module as SVG, PNG or PDF."""

from __future__ import annotations

from pathlib import Path
from typing import cast

import click

import scemlmodel as scm

from ..errors import SceMLError
from ..files.writing import write_atomically
from ..model.documents import Document
from ..model.loading import broken_references, load, unresolved_references
from ..model.locating import model_path
from ..render import FORMATS, MAX_DIAGRAM_NODES, ModuleChoiceError, View, diagram, to_bytes
from ..render.flow import Modules
from .common import SceMLCommand, allow_option, exit_if_broken, input_file, output_file


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
@input_file()
@output_file("File to write; its suffix (.svg, .png or .pdf) chooses the format.")
@click.option(
    "--view",
    type=click.Choice(["flow", "bt", "map"]),
    default="flow",
    show_default=True,
    help="flow: the SceML notation; bt: the same scenario as a behavior tree; map: the start "
    "situation from above on the scenario's OpenDRIVE map (lanes, actors with heading and size, "
    "destinations, waypoints, condition radii; logical ranges shaded).",
)
@click.option(
    "--extent",
    type=click.Choice(["scenario", "map"]),
    default="scenario",
    show_default=True,
    help="For --view map: scenario shows what the scenario uses (actors, targets, radii) with "
    "15 m around it and at least the junction; map shows every road.",
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
@click.option(
    "--max-nodes",
    type=click.IntRange(min=1),
    default=MAX_DIAGRAM_NODES,
    show_default=True,
    metavar="N",
    help="Refuse (exit 1, nothing written) a flow or behavior-tree diagram with more boxes than "
    "N: Graphviz needs about 3 s for 5,000 and runs out of memory near 50,000.",
)
@click.option(
    "--diff",
    "old",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    default=None,
    metavar="OLD",
    help="Mark what changed since scenario OLD (flow view): added, changed and removed nodes "
    "and flows, by colour and by sign, with a legend (as `sceml diff --format html`).",
)
@allow_option
def render(
    file: Path,
    output: Path,
    view: str,
    modules: str,
    legend: bool,
    module: str | None,
    extent: str,
    max_nodes: int,
    old: Path | None,
    allow: tuple[Path, ...],
) -> None:
    """Draw FILE, a scenario or a module library (.xmi), as a diagram.

    Exits 0 when the diagram is written, 1 when it is written but a module use's definition
    cannot be loaded (drawn as broken), 2 for usage errors or unreadable input. The map view
    needs a scenario whose map is an OpenDRIVE (.xodr) file: a simulator town, no map, or a map
    file that cannot be read exits 2 and writes nothing.
    """
    fmt = output_format(output)
    if old is not None:
        _render_diff(old, file, output, fmt, view)
        click.echo(f"wrote {output}")
        return
    document = load(file, allow=allow)
    _refuse_broken_actors(document)
    if view == "map":
        _render_map(document, output, fmt, extent)
    else:
        _render_diagram(document, output, fmt, view, modules, legend, module, max_nodes)
    click.echo(f"wrote {output}")
    # The diagram draws a broken module use as such; the exit status still says it is broken.
    exit_if_broken(list(broken_references(document)))


def _refuse_broken_actors(document: Document) -> None:
    # A module use whose definition cannot be loaded is drawn as broken (and exits 1 after);
    # any other reference to another file that cannot be loaded (a hand-edited referenceActor)
    # leaves nothing to draw it by, and is refused before anything is written.
    for holder, _href, reason in unresolved_references(document.root, through_files=True):
        if not isinstance(holder, scm.ModuleUse):
            raise SceMLError(
                reason,
                file=document.file_of(holder) or document.path,
                line=document.line_of(holder),
                element=model_path(holder),
            )


def _render_diagram(
    document: Document,
    output: Path,
    fmt: str,
    view: str,
    modules: str,
    legend: bool,
    module: str | None,
    max_nodes: int,
) -> None:
    """The flow or behavior-tree diagram, through Graphviz."""
    try:
        graph = diagram(
            document.root,
            view=cast(View, view),
            modules=cast(Modules, modules),
            legend=legend,
            module=module,
            max_nodes=max_nodes,
        )
        write_atomically(output, to_bytes(graph, fmt))
    except ModuleChoiceError as error:  # exit 2, at the file's model (the library or scenario)
        error.file, error.line = str(document.path), document.line_of(document.root)
        raise


def _render_diff(old: Path, new: Path, output: Path, fmt: str, view: str) -> None:
    """The new flow diagram with the changes since `old` marked (sceml.diff.picture)."""
    if view != "flow":
        raise click.UsageError("--diff draws the flow view")
    from ..diff import compare_files
    from ..diff.picture import diff_picture

    write_atomically(output, diff_picture(compare_files(old, new), fmt))


def _render_map(document: Document, output: Path, fmt: str, extent: str) -> None:
    """The map view; what it could not place is said on standard error."""
    if not isinstance(document.root, scm.Scenario):
        raise ModuleChoiceError(
            "the map view draws scenarios, not module libraries",
            file=document.path,
            line=document.line_of(document.root),
        )
    # matplotlib is loaded only when a map is drawn: the other commands start faster without it.
    from ..render.mapview import Extent, map_view

    picture = map_view(document.root, document.path, fmt, extent=cast(Extent, extent))
    write_atomically(output, picture.data)
    for note in picture.notes:
        click.echo(f"Note: {note}", err=True)
