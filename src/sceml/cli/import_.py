"""`sceml import FILE.xosc -o FILE.xmi [--distribution PVD.xosc]`: recover a SceML graph from an
OpenSCENARIO file (logical where a ParameterValueDistribution varies it)."""

from __future__ import annotations

from pathlib import Path

import click

from ..diagnostics import Severity
from ..files.safefiles import reading_roots
from ..importer import import_to_file
from ..importer.verdict import judge
from ..model.loading import load_scenario
from ..validation import validate
from .common import SceMLCommand, allow_option, echo_diagnostics, input_file, output_file


@click.command(cls=SceMLCommand)
@input_file()
@output_file(
    "The scenario to write (atomically; nothing is written when the input cannot be used).",
    metavar="OUT.xmi",
)
@click.option(
    "--map",
    "map_path",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    help="OpenDRIVE file to use instead of the file's LogicFile (for the map and turn geometry).",
)
@click.option(
    "--distribution",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    metavar="PVD.xosc",
    help="A ParameterValueDistribution (1.1+): the parameters it varies become ranges and "
    "distributions, and the scenario logical.",
)
@click.option(
    "--catalog-path",
    "catalog_paths",
    multiple=True,
    type=click.Path(exists=True, file_okay=False, path_type=Path),
    metavar="DIR",
    help="Another folder to find catalogs in, as esmini's --path: searched itself, and the "
    "file's CatalogLocations are also tried relative to it; repeatable. Read even when "
    "outside the allowed folders.",
)
@allow_option
@click.option(
    "--report", "show_report", is_flag=True, help="Print what was mapped, kept opaque and guessed."
)
@click.option(
    "--strict",
    is_flag=True,
    help="Exit 1 on any validation error, the original's too (a speed above the kind's limit, "
    "a position the map lacks).",
)
def import_command(
    file: Path,
    output: Path,
    map_path: Path | None,
    distribution: Path | None,
    catalog_paths: tuple[Path, ...],
    allow: tuple[Path, ...],
    show_report: bool,
    strict: bool,
) -> None:
    """Import the OpenSCENARIO 1.0-1.3 FILE as a SceML scenario OUT.

    The scenario is concrete, or logical with a ParameterValueDistribution: given with
    --distribution, or as FILE itself (then the scenario its ScenarioFile names is read).
    Each place a distributed `$parameter` fills becomes its range or distribution; what SceML
    cannot represent keeps the declared value and is reported.

    Entities become actors, Init their start and speed, events maneuver nodes, start triggers
    flows, conditions and joins, the StopTrigger the end node. What has no SceML kind is kept as
    an opaque node with its XML and line (docs/import.md). Catalogs are found as esmini finds
    them: CatalogLocations relative to FILE, then relative to each --catalog-path. Files FILE
    names (catalogs, LogicFile, a distribution's ScenarioFile) are read only from FILE's
    folder, its project root, --allow and --catalog-path folders.

    The scenario is validated after it is written. Errors of rules that judge a value as the
    file states it against the world (a speed or rate above the actor kind's limit, a position
    on a lane the map lacks) are the original's too: the import copied the value as written,
    and they are listed under "the original has these too" without failing the import. Any
    other error (an actor with no start, a lost construct) means the model is not what FILE
    means. Exit 0 when the model means what FILE means; 1 when the import caused an error, or
    with --strict on any error; 2 when FILE cannot be used.
    """
    imported = import_to_file(
        file,
        output,
        map_path=map_path,
        distribution=distribution,
        catalog_paths=catalog_paths,
        allow=allow,
    )
    if show_report:
        click.echo(imported.report.text(), nl=False)
    counts = imported.report.counts()
    nodes = len(imported.scenario.nodes)
    logical = f"; {len(imported.report.logical)} places logical" if imported.report.logical else ""
    click.echo(
        f"{output}: {nodes} nodes from {imported.report.file} (OpenSCENARIO "
        f"{imported.report.version}); {counts['opaque']} kept opaque, {counts['guessed']} "
        f"guessed{logical}"
    )
    # The written model names the map the import may read (inside the input's folders, --allow
    # and --catalog-path, or the --map given): validating it reads that map again. A LogicFile
    # outside them the import did not open, and the validation does not open it either.
    given_map = [] if map_path is None else [map_path.resolve().parent]
    document = load_scenario(
        output, allow=[*reading_roots(file), *allow, *catalog_paths, *given_map]
    )
    verdict = judge(validate(document.root, document=document))
    echo_diagnostics([d for d in verdict.own if d.severity is not Severity.INFO], document, output)
    if verdict.originals:
        click.echo(
            f"the original has these too ({len(verdict.originals)}: values {file.name} states, "
            "copied as written; they do not fail the import"
            + ("" if strict else ", --strict makes them")
            + "):",
            err=True,
        )
        echo_diagnostics(verdict.originals, document, output)
    code = verdict.exit_code(strict=strict)
    if code:
        raise click.exceptions.Exit(code)
