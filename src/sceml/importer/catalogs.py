"""Catalog references replaced by the entries they name (vehicles, pedestrians, controllers,
maneuvers, any catalog), read from catalog folders found as esmini finds them.

A CatalogLocations `Directory` is read relative to the scenario's folder, then relative to each
`--catalog-path` folder, and each `--catalog-path` folder is searched too. `catalogName` and
`entryName` may be `$parameters` or `${expressions}`; they are resolved in the reference's scope
(`parameters.values_at`). A reference's ParameterAssignments become the copied entry's
declaration values, so the entry is then resolved in place like any other element
(`parameters.py`).

Only regular files inside the allowed folders (`reading_roots`: the scenario's folder, its
project root, `--allow` and `--catalog-path` folders) are read, and resolution is bounded: an
entry that refers to itself (directly or through others) would otherwise grow the tree
exponentially.
"""

from __future__ import annotations

import copy
from collections.abc import Sequence
from pathlib import Path

from lxml import etree

from ..files.safefiles import reading_roots
from ..xosc import schema
from .parameters import declared_name, value_of, values_at
from .reading import CATALOG_ENTRY, ORIGIN, Source
from .report import ImportReport

#: Rounds of resolution: an entry may refer to another catalog's entry this deep.
MAX_DEPTH = 8
#: References resolved in one import, and elements copied from catalogs: beyond them the
#: catalogs are taken to refer to themselves (a self-reference bomb), not to be a scenario.
MAX_REFERENCES = 10_000
MAX_COPIED_ELEMENTS = 1_000_000


def resolve(
    source: Source,
    search: Sequence[Path] = (),
    roots: Sequence[Path] | None = None,
    report: ImportReport | None = None,
) -> list[str]:
    """Replace every CatalogReference in the tree; returns 'catalog/entry' of each one used.

    `search` are the `--catalog-path` folders; `roots` the folders files may be read from
    (default: `reading_roots` of the scenario with `search`); `report` gets the guesses.
    """
    if roots is None:
        roots = reading_roots(source.path, search)
    catalogs = _Catalogs(source, search, roots)
    used: list[str] = []
    copied = 0
    for _ in range(MAX_DEPTH):
        references = list(source.root.iter("CatalogReference"))
        if not references:
            return used
        for reference in references:
            if len(used) >= MAX_REFERENCES or copied > MAX_COPIED_ELEMENTS:
                raise source.error(
                    f"catalog entries refer to each other too often (over {MAX_REFERENCES:,} "
                    f"references or {MAX_COPIED_ELEMENTS:,} copied elements): refused as a "
                    "self-reference bomb",
                    reference,
                )
            values = values_at(source, reference)
            catalog_name = value_of(source, reference, "catalogName", values)
            entry_name = value_of(source, reference, "entryName", values)
            path, entry = catalogs.entry(reference, catalog_name, entry_name)
            copied += sum(1 for _ in entry.iter())
            _assign(reference, entry)
            entry.set(ORIGIN, str(path))
            parent = reference.getparent()
            assert parent is not None
            if parent.tag == "ScenarioObject":
                # An entity: its actor keeps the entry, for a re-export that refers to it.
                entry.set(CATALOG_ENTRY, entry_name)
            parent.replace(reference, entry)
            used.append(f"{catalog_name}/{entry_name}")
            for message, where in catalogs.guesses:
                if report is not None:
                    report.add("guessed", message, source.where(where))
            catalogs.guesses.clear()
    left = next(source.root.iter("CatalogReference"), None)
    if left is None:
        return used
    raise source.error(
        f"catalog entries refer to each other more than {MAX_DEPTH} deep (a loop?)", left
    )


def _assign(reference: etree._Element, entry: etree._Element) -> None:
    """The reference's parameter assignments as the entry's declaration values."""
    assignments = {
        str(a.get("parameterRef")).removeprefix("$"): str(a.get("value"))
        for a in reference.iter("ParameterAssignment")
    }
    declarations = entry.find("ParameterDeclarations")
    if declarations is None:
        return
    for declaration in declarations.iterchildren("ParameterDeclaration"):
        name = declared_name(declaration)
        if name in assignments:
            declaration.set("value", assignments[name])


class _Catalogs:
    """The catalog files of the folders to search, read once each."""

    def __init__(self, source: Source, search: Sequence[Path], roots: Sequence[Path]) -> None:
        self.source = source
        self.roots = [root.resolve() for root in roots]
        #: (folder, the element that named it, or None for a --catalog-path folder).
        self.folders: list[tuple[Path, etree._Element | None]] = []
        locations = source.root.find("CatalogLocations")
        for directory in [] if locations is None else locations.iter("Directory"):
            named = str(directory.get("path", ""))
            candidates = [source.path.parent / named, *(Path(base) / named for base in search)]
            found = next((c for c in candidates if c.is_dir()), candidates[0])
            self.folders.append((Path(found), directory))
        self.folders.extend((Path(folder), None) for folder in search)
        self._read: list[tuple[str, Path, etree._Element]] | None = None
        #: Entries found in another catalog than the one named: (message, reference).
        self.guesses: list[tuple[str, etree._Element]] = []

    def _catalogs(self) -> list[tuple[str, Path, etree._Element]]:
        """(catalog name, file, Catalog element) of every catalog file, in search order."""
        if self._read is None:
            self._read = []
            for folder, named_by in self.folders:
                self._check_inside(folder, named_by)
                for path in sorted(folder.glob("*.xosc")) if folder.is_dir() else []:
                    self._add(path)
        return self._read

    def _check_inside(self, folder: Path, named_by: etree._Element | None) -> None:
        if any(_is_within(folder, root) for root in self.roots):
            return
        raise self.source.error(
            f"the catalog folder {folder} is outside the folders the import may read "
            f"({', '.join(str(r) for r in self.roots)}); allow it with --allow or "
            "--catalog-path",
            named_by,
        )

    def _add(self, path: Path) -> None:
        assert self._read is not None
        real = path.resolve()
        # Only regular files inside the allowed folders: a link to a device, a FIFO or a file
        # elsewhere is passed over (its content is never read nor echoed).
        if not real.is_file() or not any(_is_within(real, root) for root in self.roots):
            return
        if any(known == path for _, known, _ in self._read):
            return
        try:
            catalog = schema.parse_file(real).getroot().find("Catalog")
        except (OSError, schema.SchemaError) as error:
            raise self.source.error(f"cannot read the catalog file {path}: {error}") from None
        if catalog is not None:
            self._read.append((str(catalog.get("name")), path, catalog))

    def entry(
        self, reference: etree._Element, catalog_name: str, entry_name: str
    ) -> tuple[Path, etree._Element]:
        """The catalog file and a fresh copy of the entry a reference names.

        Like esmini, an entry that the catalog of that name lacks (or a catalog name no file
        declares) is looked for in every catalog file of the folders (reported as guessed).
        """
        catalogs = self._catalogs()
        named = [(path, catalog) for name, path, catalog in catalogs if name == catalog_name]
        others = [(path, catalog) for name, path, catalog in catalogs if name != catalog_name]
        for index, (path, catalog) in enumerate([*named, *others]):
            found = _find(catalog, entry_name)
            if found is None:
                continue
            if index >= len(named):
                self.guesses.append(
                    (
                        f"catalog {catalog_name!r} has no entry {entry_name!r}: taken from "
                        f"{path} (catalog {catalog.get('name')!r}), as esmini does",
                        reference,
                    )
                )
            return path, found
        if not named:
            where = ", ".join(str(f) for f, _ in self.folders) or "no CatalogLocations"
            missing = [str(f) for f, _ in self.folders if not f.is_dir()]
            why = f"; missing folder {', '.join(missing)}" if missing else ""
            raise self.source.error(
                f"catalog {catalog_name!r} not found (looked in: {where}){why}; more folders "
                "with --catalog-path",
                reference,
            )
        raise self.source.error(
            f"catalog {catalog_name!r} ({named[0][0]}) has no entry {entry_name!r}", reference
        )


def _find(catalog: etree._Element, entry_name: str) -> etree._Element | None:
    for candidate in catalog:
        if isinstance(candidate.tag, str) and candidate.get("name") == entry_name:
            return copy.deepcopy(candidate)
    return None


def _is_within(path: Path, root: Path) -> bool:
    return path.resolve().is_relative_to(root)
