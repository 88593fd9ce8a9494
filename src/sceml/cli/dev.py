"""`sceml dev ...`: commands for people who change SceML itself."""

from __future__ import annotations

from pathlib import Path

import click

from ..regenerate import generate, project_root


@click.group()
def dev() -> None:
    """Developer commands (need a source checkout and `pip install -e .[dev]`)."""


@dev.command("generate")
@click.option(
    "--check",
    is_flag=True,
    help="Do not write; exit 1 if generated/ differs from a fresh generation.",
)
@click.option(
    "--root",
    type=click.Path(file_okay=False, path_type=Path),
    default=None,
    help="Source checkout to work on (default: the one this sceml is installed from).",
)
def generate_command(check: bool, root: Path | None) -> None:
    """Regenerate generated/ from metamodel/*.ecore with pyecoregen."""
    root = root or project_root()
    differences = generate(root, check=check)
    if check and differences:
        for name in differences:
            click.echo(f"generated/{name} differs from a fresh generation", err=True)
        raise SystemExit(1)
    click.echo("generated/ is up to date" if check else "generated/ regenerated")


@dev.command("class-diagram")
@click.option(
    "-o",
    "--out",
    type=click.Path(file_okay=False, path_type=Path),
    default=Path("docs/metamodel"),
    show_default=True,
    help="Folder for <view>.svg and <view>.png, one per view of the metamodel.",
)
def class_diagram_command(out: Path) -> None:
    """Draw the metamodel's class diagrams (graph, actions, actors, values) from the .ecore."""
    from ..classdiagram import VIEWS, class_diagram
    from ..io import write_atomically

    for view in VIEWS:
        graph = class_diagram(view)
        for suffix in ("svg", "png"):
            target = out / f"{view}.{suffix}"
            write_atomically(target, graph.pipe(format=suffix))
            click.echo(target)
