"""OpenSCENARIO 1.0-1.3 to SceML (SPEC §13): `sceml import` and its Python API.

- `import_file(path, *, map_path=None, distribution=None)` returns `Imported(scenario, report)`:
  a concrete scenario in memory and the `ImportReport` of what was mapped, kept opaque, guessed
  or not represented; with a ParameterValueDistribution (`distribution`, or `path` itself being
  one, which names its scenario) the scenario is logical where the distribution varies it;
- `import_to_file(path, output, *, map_path=None, distribution=None)` also saves it
  (atomically, `sceml.model.saving.save`).

Input that cannot be used (malformed XML, another version, an XSD violation, a missing catalog,
a dangling reference, a circular trigger) raises `XoscImportError` with file and line, before
anything is written. The stages: `reading` (parse, version, XSD), `catalogs`, `parameters`,
`entities`, `init`, `storyboard` (events, `triggers`, `conditions`, `actions`, `markers`),
`ending` (StopTrigger), `report`; with a distribution `distribution` (reading it), `traced`
(following its parameters into values) and `logical` (placing it). docs/import.md says what maps
to what.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import scemlmodel as scm

from ..files.safefiles import reading_roots
from ..model.build import ScenarioBuilder
from ..model.saving import save
from . import catalogs, markers, parameters
from .context import Build
from .distribution import Distribution, read_distribution
from .ending import read_stop
from .entities import read_entities
from .errors import BadValue, XoscImportError
from .init import read_init
from .logical import apply_distribution
from .markers import marker_name
from .overlaps import separate
from .reading import Source, is_distribution, load, read, scenario_source
from .report import ImportReport
from .storyboard import Storyboard
from .unplaced import start_on_first_trajectory

__all__ = ["ImportReport", "Imported", "XoscImportError", "import_file", "import_to_file"]


@dataclass(frozen=True)
class Imported:
    """An imported scenario and its report."""

    scenario: scm.Scenario
    report: ImportReport


def import_file(
    path: str | Path,
    *,
    map_path: str | Path | None = None,
    distribution: str | Path | None = None,
    catalog_paths: Sequence[str | Path] = (),
    allow: Sequence[str | Path] = (),
) -> Imported:
    """Read an OpenSCENARIO file into a SceML scenario (nothing is written).

    `map_path` names the OpenDRIVE file to use instead of the file's LogicFile. `distribution`
    names a ParameterValueDistribution whose parameters make the scenario logical; when `path`
    is itself one, the scenario its ScenarioFile names is imported with it. `catalog_paths`
    are more folders to find catalogs in (esmini's `--path`); files the scenario names are read
    only inside `reading_roots` of it, `allow` and `catalog_paths`.
    """
    search = [Path(folder) for folder in catalog_paths]
    extra = [*search, *(Path(folder) for folder in allow)]
    source, varied = _sources(
        Path(path), None if distribution is None else Path(distribution), extra
    )
    roots = reading_roots(source.path, extra)
    report = ImportReport(str(source.path), source.version)
    report.catalog_entries = catalogs.resolve(source, search, roots, report)
    resolved = parameters.resolve(source, () if varied is None else varied.specs)
    report.parameters = {k: v for k, v in resolved.top.items() if k != markers.MARKER}
    try:
        return _build(source, report, varied, resolved, map_path, roots)
    except BadValue as error:
        raise source.error(str(error), error.element) from None


def _build(
    source: Source,
    report: ImportReport,
    varied: Distribution | None,
    resolved: parameters.Resolved,
    map_path: str | Path | None,
    roots: Sequence[Path],
) -> Imported:
    """Every stage after reading, catalogs and parameters."""
    build = _start(source, report, map_path, roots)
    if varied is not None and varied.scenario.resolve() != source.path.resolve():
        report.add(
            "guessed",
            f"the distribution names {varied.scenario}; applied to {source.path} as asked",
            varied.where(varied.scenario_line),
        )
    _variables(build)
    read_entities(build)
    read_init(build)
    storyboard = Storyboard(build)
    storyboard.collect()
    storyboard.run()
    start_on_first_trajectory(build)
    separate(build)
    read_stop(build, storyboard)
    if varied is not None:
        apply_distribution(build, varied, resolved.uses)
    return Imported(build.scenario, report)


def import_to_file(
    path: str | Path,
    output: str | Path,
    *,
    map_path: str | Path | None = None,
    distribution: str | Path | None = None,
    catalog_paths: Sequence[str | Path] = (),
    allow: Sequence[str | Path] = (),
) -> Imported:
    """Import `path` and save the scenario as `output` (atomically; map path relative to it)."""
    imported = import_file(
        path,
        map_path=map_path,
        distribution=distribution,
        catalog_paths=catalog_paths,
        allow=allow,
    )
    save(imported.scenario, output, origin=Path(imported.report.file))
    return imported


def _sources(
    path: Path, distribution: Path | None, allow: Sequence[Path]
) -> tuple[Source, Distribution | None]:
    """The scenario to import and the distribution to apply (either file may be the PVD)."""
    tree, version = load(path)
    if not is_distribution(tree):
        source = scenario_source(path, tree, version)
        if distribution is None:
            return source, None
        pvd_tree, pvd_version = load(distribution)
        if not is_distribution(pvd_tree):
            raise XoscImportError(
                "the file given as the distribution is no ParameterValueDistribution",
                file=distribution,
                line=pvd_tree.getroot().sourceline,
            )
        return source, read_distribution(distribution, pvd_tree, pvd_version)
    if distribution is not None:
        raise XoscImportError(
            "the file is itself a ParameterValueDistribution; give the scenario, or drop "
            "the distribution option",
            file=path,
            line=tree.getroot().sourceline,
        )
    varied = read_distribution(path, tree, version)
    if not _inside(varied.scenario, reading_roots(path, allow)):
        # Its name only: an outside file is neither read nor described.
        raise XoscImportError(
            f"the ScenarioFile {varied.scenario} is outside the folders the import may read; "
            "allow its folder with --allow",
            file=path,
            line=varied.scenario_line,
        )
    if not varied.scenario.is_file():
        raise XoscImportError(
            f"the ScenarioFile {varied.scenario.name!r} does not exist ({varied.scenario})",
            file=path,
            line=varied.scenario_line,
        )
    return read(varied.scenario), varied


def _inside(path: Path, roots: Sequence[Path]) -> bool:
    real = path.resolve()
    return any(real.is_relative_to(root) for root in roots)


def _start(
    source: Source, report: ImportReport, map_path: str | Path | None, roots: Sequence[Path]
) -> Build:
    header = source.root.find("FileHeader")
    assert header is not None  # the XSD requires it
    logic = source.root.find("RoadNetwork/LogicFile")
    given = None if logic is None else logic.get("filepath")
    scenery = source.root.find("RoadNetwork/SceneGraphFile")
    if not given and scenery is not None and scenery.get("filepath"):
        # A place with no roads (esmini's parking lot): the scene graph is the map, and every
        # position is a world position.
        given = scenery.get("filepath")
        report.add("mapped", f"the scene graph {given!r} (no road network) as the map")
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
    build.road_map = _map(build, given, roots if map_path is None else None)
    if build.from_sceml:
        report.add("mapped", "a SceML export: its marker events are folded back into their nodes")
    return build


def _map(build: Build, given: str | None, roots: Sequence[Path] | None):  # type: ignore[no-untyped-def]
    """The OpenDRIVE map for turn geometry, or None (the report says so).

    A LogicFile outside `roots` is not opened (the model keeps its path); a `--map` given by
    the user is read wherever it is.
    """
    if not given or not given.lower().endswith(".xodr"):
        build.report.add(
            "guessed", f"map {given!r} is no OpenDRIVE file: turns are read from headings"
        )
        return None
    from ..maps import MapError, load_map

    path = build.source.path.parent / given
    if roots is not None and not _inside(path, roots):
        build.report.add(
            "guessed",
            f"map {given} is outside the folders the import may read, so it is not opened "
            "(--allow its folder, or --map): turns are read from headings",
        )
        return None
    if not path.resolve().is_file():
        # A device or FIFO would never end; a missing map is the validator's to report.
        build.report.add(
            "guessed", f"map {path} cannot be read (no regular file): turns are read from headings"
        )
        return None
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
