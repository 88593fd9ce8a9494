"""`sceml concretize FILE --set PATH=VALUE ... -o OUT`: fix a scenario's parameters to values."""

from __future__ import annotations

from pathlib import Path

import click

import scemlmodel as scm

from ..diagnostics import Severity
from ..levels.checks import validate_model
from ..levels.concretize import concretize as make_concrete
from ..levels.concretize import parse_assignment
from ..model.documents import Document
from ..model.loading import broken_references, load_scenario
from ..model.reach import unreadable_from
from ..model.saving import save
from .common import Parsed, SceMLCommand, allow_option, echo_diagnostics, input_file, output_file


@click.command(cls=SceMLCommand)
@input_file()
@click.option(
    "--set",
    "assignments",
    multiple=True,
    type=Parsed("PATH=VALUE", parse_assignment),
    help="Give a parameter a value in SI units, e.g. ego.Accelerate_1.targetSpeed=12. Repeatable. "
    "Paths are listed when an unknown one is given (see docs/levels.md).",
)
@output_file("Where to write the concrete scenario (.xmi); written atomically.", metavar="OUT")
@allow_option
def concretize(
    file: Path, assignments: tuple[tuple[str, float], ...], output: Path, allow: tuple[Path, ...]
) -> None:
    """Make FILE concrete: set the given parameters, then check that nothing is left open.

    Every range or distribution must get a value, and every required parameter without a
    language default must be set. The result is validated and written to OUT; exit 1 when it
    has errors (it is written anyway, so that it can be inspected).
    """
    document = load_scenario(file, allow=allow)
    _refuse_unresolved(document)
    result = make_concrete(document.root, dict(assignments))
    save(result, output, origin=file)
    click.echo(f"wrote {output}")
    for named in unreadable_from(result, file, output):
        click.echo(
            f"Warning: {output} names {named}, outside its folder and project root: commands "
            f"that read it will refuse it unless given --allow {named.parent}",
            err=True,
        )
    report_validation(result, output)


def report_validation(model: scm.Scenario, output: Path) -> None:
    """Show the validation findings of a written model; exit 1 when there are errors."""
    found = validate_model(model)
    echo_diagnostics(found, file=output)
    if any(d.severity >= Severity.ERROR for d in found):
        raise click.exceptions.Exit(1)


def _refuse_unresolved(document: Document) -> None:
    # The copy concretize works on has no file, so report a broken reference here, located.
    for error in broken_references(document):
        raise error
