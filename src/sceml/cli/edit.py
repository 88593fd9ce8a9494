"""`sceml edit [FILE]`: open a scenario (or a library module) in the browser-based editor."""

from __future__ import annotations

import contextlib
from pathlib import Path

import click

import scemlmodel as scm

from ..model.graph import DEFAULT_LEVEL
from .common import SceMLCommand


@click.command(cls=SceMLCommand)
@click.argument("file", required=False, type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "--port",
    type=click.IntRange(1, 65535),
    default=None,
    help="Port on 127.0.0.1 (default: a free one).",
)
@click.option("--no-browser", is_flag=True, help="Do not open a browser; just print the URL.")
@click.option("--read-only", is_flag=True, help="Let reviewers look: every change is refused.")
@click.option(
    "--level",
    type=click.Choice([level.name for level in scm.AbstractionLevel.eLiterals]),
    default=DEFAULT_LEVEL,
    show_default=True,
    help="Abstraction level of a new scenario (when FILE does not exist yet).",
)
@click.option(
    "--library",
    "libraries",
    multiple=True,
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    help="Another module library to offer in the palette; repeatable. Always offered: the "
    "libraries the scenario uses and the *.xmi files in a library/ folder beside it.",
)
@click.option(
    "--module", default=None, metavar="NAME", help="For a library FILE: the module to edit."
)
@click.option(
    "--allow",
    "allow",
    multiple=True,
    type=click.Path(file_okay=False, path_type=Path),
    help="Another folder the editor may open, save and export into (and module libraries "
    "may be read from); repeatable. Always allowed: FILE's folder and its project root (the "
    "nearest folder above with .git, .hg, .svn or .sceml-root), with their subfolders.",
)
def edit(
    file: Path | None,
    port: int | None,
    no_browser: bool,
    read_only: bool,
    level: str,
    libraries: tuple[Path, ...],
    module: str | None,
    allow: tuple[Path, ...],
) -> None:
    """Edit FILE, a scenario (.xmi), in the browser; a missing FILE starts a new scenario.

    The server runs on 127.0.0.1 until Ctrl-C, `kill` or a closed terminal. Every edit is
    logged beside the file (.NAME.journal) before it is answered, and the whole unsaved model
    is copied there (.NAME.recovered.xmi) when the edits pause and when the server stops; its
    path is printed. If the server was killed, the next `sceml edit FILE` offers to restore the
    copy with the logged edits replayed.

    Files are opened, saved and exported only inside FILE's folder, its project root and the
    --allow folders.
    """
    from ..editor import EditorSession, SessionOptions
    from ..editor.server import serve

    target = file or Path("untitled.xmi")
    if not target.exists():
        # Refuse now rather than at the first save, after the user has drawn a whole scenario.
        if read_only:
            raise click.UsageError(f"{target} does not exist: there is nothing to review")
        if not target.resolve().parent.is_dir():
            raise click.UsageError(f"cannot create {target}: folder {target.parent} does not exist")
    options = SessionOptions(
        read_only=read_only, level=level, libraries=list(libraries), allow=list(allow)
    )
    session = EditorSession(options)
    session.open(target, module=module)
    offer = session.recovery_offer
    if offer is not None:
        logged = f" and {len(offer.entries)} logged changes" if offer.entries else ""
        click.echo(
            f"unsaved changes of an earlier run are in {offer.shown}{logged}; "
            "the page offers to restore them",
            err=True,
        )
        if offer.problem is not None:
            click.echo(f"the change log cannot be used: {offer.problem}", err=True)
    result = serve(
        session,
        port=port,
        open_browser=not no_browser,
        announce=lambda url: click.echo(f"SceML editor: {url} (Ctrl-C to stop)"),
    )
    if result.recovered is not None:
        # After a SIGHUP the terminal may be gone: the copy is written either way.
        with contextlib.suppress(OSError):
            click.echo(f"unsaved changes were written to {result.recovered}", err=True)
