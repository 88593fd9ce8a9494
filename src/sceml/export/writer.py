"""Export entry points: refuse what cannot be exported, map, render, validate, write atomically."""

from __future__ import annotations

import os
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path, PurePosixPath

from lxml import etree

import scemlmodel as scm

from ..diagnostics import Diagnostic
from ..errors import ArgumentError, SceMLError
from ..files.writing import write_atomically
from ..maps.reference import is_town_name
from ..model import graph
from ..model.documents import allowed_roots_of
from ..modules.flatten import expand
from ..xosc import schema
from ..xosc.profiles import DEFAULT_VERSION
from ..xosc.support import unsupported_reason
from ..xosc.vehicle_catalog import catalog_folder
from . import checks
from .catalog_refs import catalog_location
from .render import render_tree, serialise
from .values import ParameterHook
from .viewmodel import MappingError, Options, build_view

#: FileHeader date when neither the caller nor the model gives one: output stays deterministic.
EPOCH = "1970-01-01T00:00:00"


class ExportError(SceMLError):
    """The scenario cannot be exported; `diagnostics` says why, element by element."""

    exit_code = 1

    def __init__(
        self, message: str, diagnostics: list[Diagnostic] | None = None, **where: object
    ) -> None:
        super().__init__(message, **where)  # type: ignore[arg-type]
        self.diagnostics = list(diagnostics or [])


class InvalidOutputError(SceMLError):
    """Internal error: the generated document fails its XSD; nothing is written."""

    exit_code = 1


@dataclass(frozen=True)
class XoscDocument:
    """An exported document: the bytes to write and the validated lxml tree they came from."""

    data: bytes
    tree: etree._ElementTree
    #: SceML node name -> (its first event, its finish event).
    events_of: dict[str, tuple[str, str]]
    #: The plausibility limits the model breaks and the export wrote anyway (allow_implausible),
    #: as warnings; empty otherwise.
    allowed: tuple[Diagnostic, ...] = ()


def build_xosc(
    scenario: scm.Scenario,
    *,
    version: str = DEFAULT_VERSION,
    profile: str = "generic",
    date: str | None = None,
    source_path: str | Path | None = None,
    map_path: str | Path | None = None,
    output_path: str | Path | None = None,
    parameters: ParameterHook | None = None,
    town: str | None = None,
    check_model: bool = True,
    allow_implausible: bool = False,
) -> XoscDocument:
    """Map a concrete scenario to OpenSCENARIO bytes and tree, validated against the XSD.

    Raises ExportError (with diagnostics) for anything that cannot be exported and
    InvalidOutputError if the result fails the schema (a bug in the mapping).
    `allow_implausible` writes a model whose plausibility limits (SCEML-L) are its only errors:
    a speed or rate above its actor kind's is what the scenario states, which players run as
    stated; they come back as the document's `allowed` warnings.
    """
    request = unsupported_reason("RootNode", version, profile)
    if request is not None:
        raise ExportError(request, [checks.error(checks.PROFILE, request)], file=source_path)
    _refuse(checks.level_problems(scenario), source_path)
    flattened = (
        expand(scenario) if any(isinstance(n, scm.ModuleUse) for n in scenario.nodes) else None
    )
    flat = flattened.scenario if flattened is not None else scenario
    allowed: list[Diagnostic] = []
    if check_model:
        problems = checks.model_problems(scenario)
        if allow_implausible:
            problems, allowed = checks.split_implausible(problems)
        _refuse(problems, source_path)
    problems = checks.expressibility_problems(flat, version, profile)
    _refuse(checks.traced(problems, flattened), source_path)
    root = graph.root_node(flat)
    assert root is not None  # level_problems refused scenarios without one
    catalog = catalog_folder(root, source_path, roots=allowed_roots_of(scenario))
    options = Options(
        version=version,
        profile=profile,
        date=_file_header_date(date, root, source_path),
        logic_file=logic_file(root.map, source_path, map_path, output_path, town),
        parameters=parameters,
        vehicle_catalog=catalog,
        catalog_location="" if catalog is None else catalog_location(catalog, output_path),
    )
    try:
        view = build_view(flat, options)
    except (ValueError, MappingError) as problem:
        message = problem.message if isinstance(problem, SceMLError) else str(problem)
        raise ExportError(f"cannot map the scenario: {message}", file=source_path) from None
    tree = render_tree(view)
    issues = schema.validate_tree(tree, version)
    if issues:
        details = "; ".join(str(issue) for issue in issues[:5])
        raise InvalidOutputError(
            f"internal error: the OpenSCENARIO {version} output fails its XSD: {details}"
        )
    return XoscDocument(serialise(tree), tree, view.events_of, tuple(allowed))


def export(scenario: scm.Scenario, **options: object) -> etree._ElementTree:
    """The exported document as a validated lxml tree (see `build_xosc` for the options)."""
    return build_xosc(scenario, **options).tree  # type: ignore[arg-type]


def export_to_file(scenario: scm.Scenario, path: str | Path, **options: object) -> Path:
    """Export and write atomically; a refused or failed export leaves any existing file as it was."""
    path = Path(path)
    options.setdefault("output_path", path)
    document = build_xosc(scenario, **options)  # type: ignore[arg-type]
    write_atomically(path, document.data)
    return path


def _refuse(problems: list[Diagnostic], source_path: str | Path | None) -> None:
    if not problems:
        return
    first = problems[0]
    more = f" (and {len(problems) - 1} more)" if len(problems) > 1 else ""
    raise ExportError(
        f"cannot export: [{first.code}] {first.message}{more}",
        problems,
        file=source_path,
        element=first.path,
    )


def _file_header_date(date: str | None, root: scm.RootNode, source_path: str | Path | None) -> str:
    """The FileHeader date: the caller's, else the root node's, else the epoch."""
    if date:
        return header_date(date)
    try:
        return header_date(root.date or EPOCH)
    except ArgumentError as error:
        raise ExportError(f"the root node's {error.message}", file=source_path) from None


def header_date(text: str) -> str:
    """A FileHeader date (xsd:dateTime, to the second) from ISO 8601 text; ArgumentError if not."""
    try:
        parsed = datetime.fromisoformat(text)
    except ValueError:
        raise ArgumentError(
            f"date {text!r} is not an ISO 8601 date, e.g. 2026-01-01T12:00:00"
        ) from None
    return parsed.isoformat(timespec="seconds")


def logic_file(
    map_text: str | None,
    source_path: str | Path | None,
    map_path: str | Path | None,
    output_path: str | Path | None,
    town: str | None,
) -> str:
    """The LogicFile filepath: a town name as given, or the map file relative to the output.

    Every profile writes the scenario's own .xodr as it is: CARLA's scenario_runner loads a
    LogicFile that ends in .xodr as a standalone OpenDRIVE world.

    The model's map is relative to the scenario file (`source_path`); `map_path` overrides it
    (relative to the working directory). Without an output path the file is written as the
    model gives it.
    """
    if town:
        return town
    if map_path is not None:
        target: Path | None = Path(map_path).resolve()
    elif map_text and not is_town_name(map_text) and source_path is not None:
        target = (Path(source_path).resolve().parent / map_text).resolve()
    else:
        target = None
    if target is None:
        return map_text or ""
    if output_path is None:
        return target.as_posix() if map_path is not None else str(map_text)
    relative = os.path.relpath(target, Path(output_path).resolve().parent)
    return PurePosixPath(*Path(relative).parts).as_posix()
