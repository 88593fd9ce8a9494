"""Which files a model names (module libraries, its map), and which of them a copy written
into another folder could no longer read by the reading rule (`sceml.files.safefiles.reading_roots`).

`concretize` writes where it is told; a library or map that the new file's folder and project
root do not hold is refused when the file is read back, unless `--allow` names its folder. The
writer warns about it when it writes, not the reader later.
"""

from __future__ import annotations

from pathlib import Path

from pyecore.ecore import EObject

import scemlmodel as scm

from ..files.safefiles import is_inside, reading_roots
from ..maps.reference import map_reference
from .graph import root_node
from .traversal import all_contents


def named_files(model: EObject, origin: str | Path | None) -> list[Path]:
    """The library files `model`'s module uses name and the map file its root names (relative
    to `origin`, the file it was read from), each once, in the order met."""
    found: list[Path] = []
    for obj in [model, *all_contents(model)]:
        if isinstance(obj, scm.ModuleUse) and obj.definition is not None:
            resource = obj.definition.eResource
            if resource is not None:
                found.append(Path(resource.uri.normalize()))
    root = root_node(model) if isinstance(model, scm.Scenario) else None
    reference = map_reference(root.map if root is not None else None, origin, roots=())
    needed = None if reference is None else reference.path or reference.scenery
    if needed is not None:
        found.append(needed)
    return list(dict.fromkeys(path.resolve() for path in found))


def unreadable_from(
    model: EObject, origin: str | Path | None, destination: str | Path
) -> list[Path]:
    """The files `model` names that a command reading it from `destination` may not read
    without `--allow` (outside its folder and project root)."""
    roots = reading_roots(destination)
    return [path for path in named_files(model, origin) if not is_inside(path, roots)]
