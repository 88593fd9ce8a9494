"""`sceml dev ...`: commands for people who change SceML itself."""

from __future__ import annotations

from pathlib import Path

import click

from ..dev.regenerate import generate, project_root


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


@dev.command("check-release")
@click.option(
    "--root",
    type=click.Path(file_okay=False, path_type=Path),
    default=None,
    help="Source checkout to work on (default: the one this sceml is installed from).",
)
def check_release_command(root: Path | None) -> None:
    """Refuse a breaking change to the metamodel that no migration step covers (what CI runs).

    Compares metamodel/scemlmodel.ecore with the newest release kept in metamodel/history/.
    A class or feature removed or renamed, a type changed, a multiplicity narrowed or a required
    feature added breaks files saved with that release: it needs a new release (the version in
    the nsURI raised) and a step in metamodel/migrations/ with an operation that migrates it.
    Additive changes pass. Exit 1 naming each change that is not covered.
    """
    from ..migrations import History, check_release

    root = root or project_root()
    result = check_release(History(root / "metamodel"))
    for note in result.notes:
        click.echo(f"note: {note}", err=True)
    for problem in result.problems:
        click.echo(f"metamodel: {problem}", err=True)
    if result.problems:
        raise SystemExit(1)
    click.echo(
        f"metamodel release {result.current}: files of release {result.last_release} and "
        "earlier load (every breaking change has its migration)"
    )


@dev.command("release")
@click.option(
    "--root",
    type=click.Path(file_okay=False, path_type=Path),
    default=None,
    help="Source checkout to work on (default: the one this sceml is installed from).",
)
def release_command(root: Path | None) -> None:
    """Keep the current metamodel as a release in metamodel/history/<version>/.

    Copies the .ecore, the examples and the module library saved with it, their map, and their
    OpenSCENARIO exports, as test material that never changes. Run it once per release, after
    `sceml dev check-release` passes; it refuses a version that is already kept.
    """
    from ..dev.release import keep_release

    root = root or project_root()
    folder = keep_release(root)
    click.echo(f"kept release in {folder}")


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
    from ..dev.classdiagram import VIEWS, class_diagram
    from ..files.writing import write_atomically

    for view in VIEWS:
        graph = class_diagram(view)
        for suffix in ("svg", "png"):
            target = out / f"{view}.{suffix}"
            write_atomically(target, graph.pipe(format=suffix))
            click.echo(target)
