"""`sceml export FILE -o OUT.xosc`: write a concrete scenario as OpenSCENARIO 1.0-1.3."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import SceMLError
from ..export import ExportError, build_xosc
from ..export.checks import split_implausible
from ..export.versions import VERSIONS
from ..export.writer import header_date
from ..files.writing import write_atomically
from ..model.loading import load_scenario
from ..xosc.profiles import PROFILES, default_version
from .common import Parsed, SceMLCommand, allow_option, echo_diagnostics, input_file, output_file


@click.command(cls=SceMLCommand)
@input_file()
@output_file("The .xosc file to write (atomically; an existing file is only replaced on success).")
@click.option(
    "--osc-version",
    type=click.Choice(VERSIONS),
    help="OpenSCENARIO version to write. Default: 1.3, or 1.0 with the carla profile (the only "
    "version scenario_runner reads).",
)
@click.option(
    "--profile",
    type=click.Choice(PROFILES),
    default="generic",
    show_default=True,
    help="generic: any OpenSCENARIO player (e.g. esmini); carla: what CARLA scenario_runner reads.",
)
@click.option(
    "--date",
    type=Parsed("ISO", header_date),
    help="FileHeader date (ISO 8601), e.g. 2026-01-01T00:00:00; default: the root node's date.",
)
@click.option(
    "--town",
    metavar="NAME",
    help="CARLA town written as LogicFile (e.g. Town03); required by the carla profile unless "
    "the model's map already is a town name.",
)
@click.option(
    "--map",
    "map_path",
    type=click.Path(dir_okay=False, path_type=Path),
    help="OpenDRIVE file to refer to instead of the model's map (written relative to OUTPUT).",
)
@click.option(
    "--allow-implausible",
    is_flag=True,
    help="Write the scenario even when its only errors are plausibility limits (SCEML-L001 to "
    "L005: a speed or rate above what its actor kind can reach, e.g. a pedestrian at 8 m/s), "
    "each printed as a warning. For a model that states such values on purpose, as an imported "
    "file that has them does; players run them as stated. Other errors still refuse.",
)
@allow_option
def export(
    file: Path,
    output: Path,
    osc_version: str | None,
    profile: str,
    date: str | None,
    town: str | None,
    map_path: Path | None,
    allow_implausible: bool,
    allow: tuple[Path, ...],
) -> None:
    """Export the concrete scenario FILE to OpenSCENARIO.

    Module uses are flattened first. Functional and logical scenarios, invalid models and nodes
    the chosen version or profile cannot express are refused with their diagnostics (exit 1);
    the output is checked against the official XSD before it is written.
    """
    osc_version = osc_version or default_version(profile)
    document = load_scenario(file, allow=allow)
    try:
        written = build_xosc(
            document.root,
            version=osc_version,
            profile=profile,
            date=date,
            source_path=file,
            map_path=map_path,
            output_path=output,
            town=town,
            allow_implausible=allow_implausible,
        )
    except ExportError as error:
        if not error.diagnostics:
            raise
        # Each problem once, located; then only the verdict, which would otherwise repeat one.
        echo_diagnostics(error.diagnostics, document, file)
        count = len(error.diagnostics)
        refusing, _ = split_implausible(error.diagnostics)
        # Only limits the model states itself: say how to write it anyway.
        hint = "" if refusing else " (plausibility limits only: --allow-implausible writes it)"
        raise SceMLError(
            f"not exported: {count} problem{'s' if count != 1 else ''}{hint}", file=file
        ) from None
    write_atomically(output, written.data)
    echo_diagnostics(written.allowed, document, file)
    click.echo(f"{output}: OpenSCENARIO {osc_version} ({profile})")
