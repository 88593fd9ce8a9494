"""A loaded model file (`Document`) and the resource sets SceML reads files into."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pyecore.ecore import EObject
from pyecore.resources import ResourceSet
from pyecore.resources.xmi import XMIResource

import scemlmodel as scm

from .xmiresource import SafeXMIResource


def new_resource_set(
    allowed_roots: Iterable[str | Path] | None = None,
    max_bytes: int | None = None,
    read_only: bool = False,
) -> ResourceSet:
    """A fresh resource set that knows the SceML metamodel and reads files safely.

    `allowed_roots`, when given, are the only folders files may be read from, cross-file
    references included. `max_bytes` limits each file's size (default: `max_bytes_limit()`).
    With `read_only`, the files are read into `sceml.model.lightobjects`' lighter objects, which
    refuse any change (for commands that only read a model, such as `sceml validate`).
    """
    resource_set = ResourceSet()
    resource_set.metamodel_registry[scm.nsURI] = scm
    resource_set.resource_factory["xmi"] = SafeXMIResource
    resource_set.resource_factory["*"] = SafeXMIResource
    resource_set.sceml_allowed_roots = (
        None if allowed_roots is None else [Path(r).resolve() for r in allowed_roots]
    )
    resource_set.sceml_max_bytes = max_bytes
    resource_set.sceml_read_only = read_only
    return resource_set


@dataclass
class Document:
    """A loaded model file: its root object and where each element was written."""

    path: Path
    root: EObject
    resource: XMIResource
    resource_set: ResourceSet = field(repr=False)

    def line_of(self, obj: EObject) -> int | None:
        """The line of the element `obj` was read from in this file, if it was read from it."""
        # Lines are those of the file as it was read: an object made since has none, and one
        # moved since keeps the line it was read from.
        lines = getattr(obj.eResource, "sceml_lines", None) if obj.eResource else None
        return lines.get(obj) if lines is not None else None

    @property
    def migration(self) -> Any:
        """How this file was migrated from an older metamodel release (a
        `sceml.migrations.Report`), or None when it was saved with the current one."""
        return getattr(self.resource, "sceml_migration", None)

    def migrations(self) -> list[Any]:
        """The migration reports of this file and of every file it has loaded since (libraries)."""
        # A resource set may hold one file under two URIs; each file is reported once.
        found: dict[Path, Any] = {}
        for resource in self.resource_set.resources.values():
            report = getattr(resource, "sceml_migration", None)
            if report is not None:
                found.setdefault(Path(report.file).resolve(), report)
        return list(found.values())

    @property
    def allowed_roots(self) -> list[Path] | None:
        """The folders files this model names (libraries, maps) may be read from; None: any."""
        return allowed_roots_of(self.root)

    def file_of(self, obj: EObject) -> Path | None:
        """The file an object was read from (a library, for module internals)."""
        resource = obj.eResource
        return Path(resource.uri.normalize()) if resource is not None else None

    def where(self, obj: EObject) -> tuple[str, int | None]:
        """Where a diagnostic about `obj` points: this file as the user named it, or the library
        a module internal was read from, and the line of its element (the one rule of locating,
        for validation's findings and every command's diagnostics)."""
        other = obj.eResource is not None and obj.eResource is not self.resource
        found = self.file_of(obj) if other else None
        return str(found or self.path), self.line_of(obj)


def allowed_roots_of(obj: EObject) -> list[Path] | None:
    """The folders the files `obj`'s model names may be read from, as it was loaded (`load`'s
    allowed roots); None for a model that was not loaded with them (built in Python)."""
    resource = obj.eResource
    resource_set = resource.resource_set if resource is not None else None
    roots: list[Path] | None = getattr(resource_set, "sceml_allowed_roots", None)
    return roots
