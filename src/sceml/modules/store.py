"""Module operations on files: flatten a scenario file, extract into a library file, atomically."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from pyecore.ecore import EObject
from pyecore.resources import URI

import scemlmodel as scm

from ..errors import SaveError
from ..files.safefiles import output_target, reading_roots
from ..files.writing import make_folder, remove_folders
from ..model.documents import new_resource_set
from ..model.loading import broken_references, load_library, load_scenario
from ..model.saving import save
from .errors import ExtractError
from .extract import RoleSpec, extract
from .flatten import expand


@dataclass
class FlattenReport:
    """What `flatten_file` did."""

    output: Path
    expanded: list[str]
    nodes: int


@dataclass
class ExtractReport:
    """What `extract_file` did."""

    scenario: Path
    library: Path
    module: str
    use: str
    roles: dict[str, str]
    parameters: int
    created_library: bool


def flatten_file(
    path: str | Path, output: str | Path, *, allowed_roots: Iterable[str | Path] = ()
) -> FlattenReport:
    """Flatten the scenario in `path` and save it, atomically, to `output`.

    Referenced libraries are read from `reading_roots(path, allowed_roots)`.
    """
    path, output = Path(path), Path(output)
    document = load_scenario(path, allow=allowed_roots)
    # Every reference to another file is tried first, a node's referenceActor as much as a
    # module's definition: each failure is told at its line, none in pyecore's words mid-way.
    for error in broken_references(document):
        raise error
    flattened = expand(document.root)
    save(flattened.scenario, output, origin=path)
    return FlattenReport(output, flattened.expanded, len(flattened.scenario.nodes))


def extract_file(
    path: str | Path,
    node_names: Sequence[str],
    name: str,
    library_path: str | Path,
    *,
    output: str | Path | None = None,
    roles: Mapping[str, RoleSpec] | None = None,
    parametrize: bool = False,
    allowed_roots: Iterable[str | Path] = (),
) -> ExtractReport:
    """Extract nodes of the scenario in `path` into module `name` of the library file.

    The library is created if it does not exist. The scenario is saved to `output` (default:
    in place). Nothing is written unless both files can be.
    """
    path, library_path = Path(path).resolve(), Path(library_path).resolve()
    target = Path(output).resolve() if output is not None else path
    resource_set = new_resource_set(reading_roots(path, [library_path.parent, *allowed_roots]))
    scenario = load_scenario(path, resource_set=resource_set).root
    created = not library_path.exists()
    if created:
        library = scm.Library(name=library_path.stem)
        resource_set.create_resource(URI(str(library_path))).append(library)
    else:
        library = load_library(library_path, resource_set=resource_set).root
    try:
        use = extract(scenario, node_names, name, library, roles=roles, parametrize=parametrize)
    except ExtractError as error:
        error.file = error.file or str(path)
        raise
    save_together([(library, library_path), (scenario, target)])
    definition = use.definition
    return ExtractReport(
        scenario=target,
        library=library_path,
        module=name,
        use=str(use.name),
        roles={str(b.role): str(b.actor.name) for b in use.bindings},
        parameters=len(definition.parameters),
        created_library=created,
    )


def save_together(models: Sequence[tuple[EObject, Path]]) -> None:
    """Save several models so that either all files are replaced or none is.

    Each model is first saved to a temporary file beside its target (so relative references come
    out right), then the files are renamed in the given order. Put a library before the scenario
    that uses it: if the second rename failed, the scenario would still be the old one.
    """
    temporaries: list[Path] = []
    created: list[Path] = []
    done = False
    try:
        replaced = [output_target(target) for _, target in models]
        for (root, target), real in zip(models, replaced, strict=True):
            created += make_folder(real.parent, target=target)
            try:
                handle, name = tempfile.mkstemp(
                    prefix=f".{real.name}.", suffix=".tmp", dir=real.parent
                )
            except OSError as error:
                raise SaveError(f"cannot write: {error.strerror}", file=target) from None
            os.close(handle)
            temporaries.append(Path(name))
            save(root, name)
        for temporary, (_, target), real in zip(temporaries, models, replaced, strict=True):
            try:
                os.replace(temporary, real)
            except OSError as error:
                raise SaveError(f"cannot write: {error.strerror}", file=target) from None
        done = True
    finally:
        for temporary in temporaries:
            with contextlib.suppress(FileNotFoundError):
                temporary.unlink()
        if not done:
            remove_folders(created)
