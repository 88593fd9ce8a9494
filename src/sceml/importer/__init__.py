"""OpenSCENARIO 1.0-1.3 to SceML (SPEC §13): `sceml import` and its Python API.

- `import_file(path, *, map_path=None)` returns `Imported(scenario, report)`: a concrete
  scenario in memory and the `ImportReport` of what was mapped, kept opaque, guessed or not
  represented;
- `import_to_file(path, output, *, map_path=None)` also saves it (atomically, `sceml.io.save`).

Input that cannot be used (malformed XML, another version, an XSD violation, a missing catalog,
a dangling reference, a circular trigger) raises `XoscImportError` with file and line, before
anything is written. The stages: `reading` (parse, version, XSD), `catalogs`, `parameters`,
`entities`, `init`, `storyboard` (events, `triggers`, `conditions`, `actions`, `markers`),
`ending` (StopTrigger), `report`. docs/import.md says what maps to what.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import scemlmodel as scm

from .. import io
from ..build import ScenarioBuilder
from . import catalogs, markers, parameters
from .context import Build
from .ending import read_stop
from .entities import read_entities
from .errors import XoscImportError
from .init import read_init
from .markers import marker_name
from .overlaps import separate
from .reading import Source, read
from .report import ImportReport
from .storyboard import Storyboard

__all__ = ["ImportReport", "Imported", "XoscImportError", "import_file", "import_to_file"]


@dataclass(frozen=True)
class Imported:
    """An imported scenario and its report."""

    scenario: scm.Scenario
    report: ImportReport


def import_file(path: str | Path, *, map_path: str | Path | None = None) -> Imported:
    """Read an OpenSCENARIO file into a concrete SceML scenario (nothing is written).

    `map_path` names the OpenDRIVE file to use instead of the file's LogicFile.
    """
    source = read(path)
    report = ImportReport(str(source.path), source.version)
    report.catalog_entries = catalogs.resolve(source)
    report.parameters = {k: v for k, v in parameters.resolve(source).items() if k != markers.MARKER}
    build = _start(source, report, map_path)
    _variables(build)
    read_entities(build)
    read_init(build)
    storyboard = Storyboard(build)
    storyboard.collect()
    storyboard.run()
    separate(build)
    read_stop(build, storyboard)
    return Imported(build.scenario, report)


def import_to_file(
    path: str | Path, output: str | Path, *, map_path: str | Path | None = None
) -> Imported:
    """Import `path` and save the scenario as `output` (atomically; map path relative to it)."""
    imported = import_file(path, map_path=map_path)
    io.save(imported.scenario, output, origin=Path(path))
    return imported


def _start(source: Source, report: ImportReport, map_path: str | Path | None) -> Build:
    header = source.root.find("FileHeader")
    assert header is not None  # the XSD requires it
    logic = source.root.find("RoadNetwork/LogicFile")
    given = None if logic is None else logic.get("filepath")
    if map_path is not None:
        given = Path(
            os.path.relpath(Path(map_path).resolve(), source.path.parent.resolve())
        ).as_posix()
    builder = ScenarioBuilder(
        "",
        map=given,
        level="concrete",
        date=header.get("date"),
        description=header.get("description"),
    )
    builder.root.scenarioName = None
    builder.root.author = header.get("author")
    build = Build(source, report, builder.scenario, builder.root, builder.end, builder)
    for node in (builder.root, builder.end):
        build.name(str(node.name))
    build.marker = marker_name(source.root)
    build.road_map = _map(build, given)
    if build.from_sceml:
        report.add("mapped", "a SceML export: its marker events are folded back into their nodes")
    return build


def _map(build: Build, given: str | None):  # type: ignore[no-untyped-def]
    """The OpenDRIVE map for turn geometry, or None (the report says so)."""
    if not given or not given.lower().endswith(".xodr"):
        build.report.add(
            "guessed", f"map {given!r} is no OpenDRIVE file: turns are read from headings"
        )
        return None
    from ..maps import MapError, load_map

    path = build.source.path.parent / given
    try:
        return load_map(path)
    except (MapError, OSError) as error:
        build.report.add(
            "guessed", f"map {path} cannot be read ({error}): turns are read from headings"
        )
        return None


def _variables(build: Build) -> None:
    """Variables (1.2+) have no SceML counterpart; opaque nodes that use them need them."""
    for declaration in build.source.root.iterfind("VariableDeclarations/VariableDeclaration"):
        if declaration.get("name") != markers.MARKER:
            build.report.add(
                "not represented",
                f"variable {declaration.get('name')!r} (SceML has no variables; an exported "
                "opaque node that uses it will not find it)",
                build.where(declaration),
            )
