"""`sceml extract RECORDING -o OUT.xmi --map MAP.xodr`: a recorded drive as a SceML scenario."""

from __future__ import annotations

import json
import os
from dataclasses import replace
from pathlib import Path

import click

from ..diagnostics import Severity
from ..errors import ArgumentError
from ..model.loading import load_scenario
from ..model.saving import save
from ..validation import validate
from .common import Parsed, SceMLCommand, echo_diagnostics, input_file, output_file


def _origin(text: str) -> tuple[float, float]:
    try:
        lat, lon = (float(v) for v in text.split(","))
    except ValueError:
        raise ArgumentError(f"expected LAT,LON in degrees, got {text!r}") from None
    return lat, lon


def _actor(text: str) -> object:
    from ..extract import parse_actor

    return parse_actor(text)


@click.command(cls=SceMLCommand)
@input_file("recording")
@output_file(
    "The scenario to write (atomically; nothing is written when the recording cannot be used).",
    metavar="OUT.xmi",
)
@click.option(
    "--map",
    "map_path",
    required=True,
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    metavar="MAP.xodr",
    help="The OpenDRIVE map the recording was driven on; the scenario names it relative to OUT.",
)
@click.option(
    "--input-format",
    type=click.Choice(["auto", "sceml", "esmini", "osc-generator"]),
    default="auto",
    show_default=True,
    help="The recording's format: sceml simulate --csv, esmini --csv_logger, OSC-Generator's "
    "CSV; auto tells it by the header.",
)
@click.option(
    "--actor",
    "actor_specs",
    multiple=True,
    type=Parsed("NAME=KIND[:LxW]", _actor),
    metavar="NAME=KIND[:LxW]",
    help="An actor's kind (Car, Truck, Bicycle, Pedestrian, ...) and box size in metres, where "
    "the recording does not say (repeatable).",
)
@click.option("--ego", help="The ego's name [default: the recording's ego, else its first actor].")
@click.option("--name", default=None, help="The scenario's name [default: OUT's stem].")
@click.option(
    "--geo-origin",
    type=Parsed("LAT,LON", _origin),
    default="0,0",
    show_default=True,
    metavar="LAT,LON",
    help="For OSC-Generator's geographic positions: the latitude and longitude of the map's "
    "(0, 0).",
)
@click.option(
    "--smoothing", type=click.FloatRange(min=0.1), help="Smoothing window in s [default: 1.0]."
)
@click.option(
    "--accel-threshold",
    type=click.FloatRange(min=0.01),
    help="Acceleration (m/s²) that marks a speed change [default: 0.4].",
)
@click.option(
    "--turn-angle",
    type=click.FloatRange(min=0.05),
    help="Heading change (rad) that makes a turn [default: 0.52, 30°].",
)
@click.option(
    "--vehicle-radius",
    type=click.FloatRange(min=0.5),
    help="Largest radius (m) of an inferred InVehicleRadius [default: 22].",
)
@click.option(
    "--tolerance",
    type=click.FloatRange(min=0.1),
    help="Arrival tolerance (m) of turns and crossings [default: 2].",
)
@click.option(
    "--sharp-bend",
    type=click.FloatRange(min=0.05),
    help="Bend (rad) after a set-off from standing from which the set-off is fitted to the raw "
    "positions, the bend pinning the ramp's end [default: 0.5].",
)
@click.option(
    "--start-rate",
    type=click.FloatRange(min=0.1),
    help="Rate (m/s²) taken for a speed change under way when a noisy recording starts, whose "
    "length the noise leaves open [default: 2].",
)
@click.option(
    "--start-significance",
    type=click.FloatRange(min=0.5),
    help="How many times the noise's variance a change under way at a noisy recording's start "
    "must explain beyond a steady speed to count [default: 9].",
)
@click.option("--no-replay", is_flag=True, help="Skip the replay in the preview.")
@click.option("--report", "show_report", is_flag=True, help="Print what was found and why.")
@click.option(
    "--format",
    "report_format",
    type=click.Choice(["text", "json"]),
    default="text",
    show_default=True,
    help="The report's format.",
)
def extract_command(
    recording: Path,
    output: Path,
    map_path: Path,
    input_format: str,
    actor_specs: tuple[object, ...],
    ego: str | None,
    name: str | None,
    geo_origin: tuple[float, float],
    smoothing: float | None,
    accel_threshold: float | None,
    turn_angle: float | None,
    vehicle_radius: float | None,
    tolerance: float | None,
    sharp_bend: float | None,
    start_rate: float | None,
    start_significance: float | None,
    no_replay: bool,
    show_report: bool,
    report_format: str,
) -> None:
    """Extract a concrete SceML scenario from the recorded drive RECORDING.

    Each actor's trajectory is smoothed and cut into maneuvers (Accelerate, Decelerate, Stop,
    DriveDistance for a speed that jumps from standing, KeepVelocity, LaneChange, TurnLeft,
    TurnRight, Cross) with their parameters. When a
    maneuver started later than the one before it finished, the condition that first held
    then becomes a node before it: another actor within a radius (InVehicleRadius), another
    actor at a place (InLocationRadius), another actor's speed (SpeedCondition), else a time.
    The scenario is replayed in the preview and compared with the recording, saved, and
    validated: exit 1 when it has errors, 2 when the recording cannot be used.
    docs/extract.md explains the thresholds and what cannot be told from a recording.
    """
    from ..extract import ActorSpec, Thresholds, extract, read_recording
    from ..extract.report import report_data, report_lines
    from ..maps import load_map

    settings = {
        "smoothing_window": smoothing,
        "accel_threshold": accel_threshold,
        "turn_angle": turn_angle,
        "vehicle_radius": vehicle_radius,
        "arrival_tolerance": tolerance,
        "sharp_bend": sharp_bend,
        "start_rate": start_rate,
        "start_significance": start_significance,
    }
    thresholds = replace(Thresholds(), **{k: v for k, v in settings.items() if v is not None})
    recorded = read_recording(
        recording, None if input_format == "auto" else input_format, geo_origin=geo_origin
    )
    reference = Path(os.path.relpath(map_path.resolve(), output.resolve().parent)).as_posix()
    found = extract(
        recorded,
        load_map(map_path),
        map_reference=reference,
        name=name or output.stem,
        thresholds=thresholds,
        actors=[spec for spec in actor_specs if isinstance(spec, ActorSpec)],
        ego=ego,
        check_replay=not no_replay,
    )
    save(found.scenario, output)
    if show_report and report_format == "json":
        click.echo(json.dumps(report_data(found), indent=2))
    elif show_report:
        for line in report_lines(found):
            click.echo(line)
    fit = "" if found.replay is None else f"; replay within {found.replay.largest:.2f} m"
    click.echo(
        f"{output}: {len(found.actors)} actors, "
        f"{sum(len(a.maneuvers) for a in found.actors)} maneuvers, "
        f"{len(found.inferred)} inferred conditions{fit}",
        err=show_report and report_format == "json",
    )
    # The user named the map with --map: validating the written scenario may read it there.
    document = load_scenario(output, allow=[map_path.resolve().parent])
    diagnostics = validate(document.root, document=document)
    echo_diagnostics([d for d in diagnostics if d.severity is not Severity.INFO], document, output)
    if any(d.severity is Severity.ERROR for d in diagnostics):
        raise click.exceptions.Exit(1)
