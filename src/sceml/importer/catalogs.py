"""Catalog references replaced by the entries they name (vehicles, pedestrians, controllers,
maneuvers, any catalog), read from the folders the file's CatalogLocations name.

A reference's ParameterAssignments become the copied entry's declaration values, so the entry is
then resolved in place like any other element (`parameters.py`).
"""

from __future__ import annotations

import copy
from pathlib import Path

from lxml import etree

from .. import schema
from .reading import ORIGIN, Source


def resolve(source: Source) -> list[str]:
    """Replace every CatalogReference in the tree; returns 'catalog/entry' of each one used."""
    catalogs = _Catalogs(source)
    used: list[str] = []
    # Entries may refer to other catalogs, so repeat until none is left (bounded: no loops).
    for _ in range(10):
        references = list(source.root.iter("CatalogReference"))
        if not references:
            return used
        for reference in references:
            entry = catalogs.entry(reference)
            _assign(reference, entry)
            entry.set(ORIGIN, catalogs.file_of(reference))
            parent = reference.getparent()
            assert parent is not None
            parent.replace(reference, entry)
            used.append(f"{reference.get('catalogName')}/{reference.get('entryName')}")
    raise source.error("catalog entries refer to each other in a loop")


def _assign(reference: etree._Element, entry: etree._Element) -> None:
    """The reference's parameter assignments as the entry's declaration values."""
    assignments = {
        str(a.get("parameterRef")): str(a.get("value"))
        for a in reference.iter("ParameterAssignment")
    }
    declarations = entry.find("ParameterDeclarations")
    if declarations is None:
        return
    for declaration in declarations.iterchildren("ParameterDeclaration"):
        name = declaration.get("name")
        if name in assignments:
            declaration.set("value", assignments[name])


class _Catalogs:
    """The catalog files of the folders CatalogLocations names, read once each."""

    def __init__(self, source: Source) -> None:
        self.source = source
        self.folders: list[Path] = []
        locations = source.root.find("CatalogLocations")
        for directory in [] if locations is None else locations.iter("Directory"):
            self.folders.append((source.path.parent / str(directory.get("path", ""))).resolve())
        self._read: dict[str, tuple[Path, etree._Element]] | None = None
        self._files: dict[str, str] = {}

    def _catalogs(self) -> dict[str, tuple[Path, etree._Element]]:
        if self._read is None:
            self._read = {}
            for folder in self.folders:
                for path in sorted(folder.glob("*.xosc")) if folder.is_dir() else []:
                    self._add(path)
        return self._read

    def _add(self, path: Path) -> None:
        assert self._read is not None
        try:
            catalog = schema.parse_file(path).getroot().find("Catalog")
        except (OSError, schema.SchemaError) as error:
            raise self.source.error(f"cannot read the catalog file {path}: {error}") from None
        if catalog is not None:
            self._read.setdefault(str(catalog.get("name")), (path, catalog))

    def entry(self, reference: etree._Element) -> etree._Element:
        """A fresh copy of the entry a reference names."""
        catalog_name, entry_name = reference.get("catalogName"), reference.get("entryName")
        found = self._catalogs().get(str(catalog_name))
        if found is None:
            where = ", ".join(str(f) for f in self.folders) or "no CatalogLocations"
            missing = [str(f) for f in self.folders if not f.is_dir()]
            why = f"; missing folder {', '.join(missing)}" if missing else ""
            raise self.source.error(
                f"catalog {catalog_name!r} not found (looked in: {where}){why}", reference
            )
        path, catalog = found
        for candidate in catalog:
            if isinstance(candidate.tag, str) and candidate.get("name") == entry_name:
                self._files[_key(reference)] = str(path)
                return copy.deepcopy(candidate)
        raise self.source.error(
            f"catalog {catalog_name!r} ({path}) has no entry {entry_name!r}", reference
        )

    def file_of(self, reference: etree._Element) -> str:
        """The catalog file the reference was resolved from."""
        return self._files[_key(reference)]


def _key(reference: etree._Element) -> str:
    return f"{reference.get('catalogName')}/{reference.get('entryName')}"
