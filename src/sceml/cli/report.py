"""`sceml report FILE -o OUT.html`: one self-contained review page for a scenario or library."""

from __future__ import annotations

from pathlib import Path
from typing import cast

import click

from ..diagnostics import Severity
from ..files.writing import write_atomically
from ..model.loading import load
from ..render.flow import Modules
from ..review.figures import report_figures
from ..review.page import build_report
from ..validation import validate
from .common import SceMLCommand, allow_option, input_file, output_file


@click.command(cls=SceMLCommand)
@input_file()
@output_file("HTML file to write (.html).")
@click.option(
    "--modules",
    type=click.Choice(["collapsed", "expanded"]),
    default="expanded",
    show_default=True,
    help="Draw module uses as one box, or expanded so diagnostics inside them can be shown.",
)
@allow_option
def report(file: Path, output: Path, modules: str, allow: tuple[Path, ...]) -> None:
    """Write a review report of FILE: diagram, map view, validation diagnostics, actors and
    parameters.

    The map view (as `sceml render --view map` draws it) is included when the scenario's map is
    a readable OpenDRIVE file; otherwise the page says why there is none.

    Clicking a diagnostic in the page highlights its element in the diagram. Exits 0 when the
    model has no errors, 1 when it has errors (the report is written either way), 2 for usage
    errors or unreadable input.
    """
    if output.suffix.lower() not in (".html", ".htm"):
        raise click.BadParameter("the report is HTML; name a .html file", param_hint="'-o'")
    document = load(file, allow=allow)
    diagnostics = validate(document.root, document=document)
    html = build_report(
        document, diagnostics, modules=cast(Modules, modules), figures=report_figures(document)
    )
    write_atomically(output, html.encode("utf-8"))
    errors = sum(d.severity == Severity.ERROR for d in diagnostics)
    click.echo(
        f"wrote {output}" + (f" ({errors} error{'s' if errors != 1 else ''})" if errors else "")
    )
    if errors:
        raise SystemExit(1)
