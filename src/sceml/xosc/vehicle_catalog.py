"""A folder of OpenSCENARIO vehicle catalogs, as the root node's `vehicleCatalog` names it
(release 1.5): its entries and the values each says, for the export (which writes an actor as a
CatalogReference where the entry says what the actor is) and for validation.

Files are read only inside the allowed folders (the reading rule of the import: `--allow`),
regular files only, each parsed safely (`schema.parse_file`). An entry's values are its own
attributes with its ParameterDeclarations' defaults resolved (`$name` and `${expression}`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from ..importer.expressions import ExpressionError, evaluate
from . import schema

#: The attributes of a Vehicle entry that an actor's values are compared with, by the name the
#: export's entity uses for them.
ENTRY_NUMBERS = {
    "x": ("BoundingBox/Center", "x"),
    "length": ("BoundingBox/Dimensions", "length"),
    "width": ("BoundingBox/Dimensions", "width"),
    "height": ("BoundingBox/Dimensions", "height"),
    "maxSpeed": ("Performance", "maxSpeed"),
    "maxAcceleration": ("Performance", "maxAcceleration"),
    "maxDeceleration": ("Performance", "maxDeceleration"),
}


@dataclass(frozen=True)
class EntryValue:
    """One compared value of an entry: the number it means, and the parameter it is read from
    when the attribute is a plain `$name` (a reference may assign that one)."""

    number: float | None
    parameter: str | None


@dataclass(frozen=True)
class CatalogEntry:
    """A Vehicle entry: the catalog that holds it and the values it says."""

    catalog: str
    file: Path
    category: str
    values: dict[str, EntryValue]
    #: Whether the entry tows a trailer of its own (an inline Trailer or a TrailerRef that
    #: names an entity with its defaults).
    tows: bool


@dataclass
class VehicleCatalogFolder:
    """The catalog files of one folder, read once; `problem` says why none can be read."""

    folder: Path
    roots: Sequence[Path] | None = None
    problem: str | None = None
    _entries: dict[str, CatalogEntry] | None = field(default=None, repr=False)

    def entry(self, name: str) -> CatalogEntry | None:
        """The Vehicle entry of that name (the first catalog file, by name, that has it)."""
        return self._read().get(name)

    def _read(self) -> dict[str, CatalogEntry]:
        if self._entries is not None:
            return self._entries
        self._entries = {}
        self.problem = _folder_problem(self.folder, self.roots)
        if self.problem is not None:
            return self._entries
        for path in sorted(self.folder.glob("*.xosc")):
            real = path.resolve()
            if not real.is_file() or not _inside(real, self.roots):
                continue  # a link to a device, a FIFO or a file elsewhere is never read
            try:
                catalog = schema.parse_file(real).getroot().find("Catalog")
            except (OSError, schema.SchemaError) as error:
                self.problem = f"cannot read the catalog file {path}: {error}"
                continue
            for vehicle in [] if catalog is None else catalog.iterchildren("Vehicle"):
                name = str(vehicle.get("name"))
                if name not in self._entries:
                    self._entries[name] = _entry(str(catalog.get("name")), path, vehicle)
        return self._entries


def _folder_problem(folder: Path, roots: Sequence[Path] | None) -> str | None:
    if not _inside(folder, roots):
        shown = ", ".join(str(r) for r in roots or ())
        return (
            f"the vehicle catalog folder {folder} is outside the folders files may be read "
            f"from ({shown}); allow it with --allow"
        )
    if not folder.is_dir():
        return f"the vehicle catalog folder {folder} does not exist"
    return None


def _inside(path: Path, roots: Sequence[Path] | None) -> bool:
    return roots is None or any(path.resolve().is_relative_to(r.resolve()) for r in roots)


def _entry(catalog: str, path: Path, vehicle: etree._Element) -> CatalogEntry:
    defaults = _defaults(vehicle)
    values = {
        key: _value(vehicle.find(where), attribute, defaults)
        for key, (where, attribute) in ENTRY_NUMBERS.items()
    }
    trailer = vehicle.find("Trailer")
    reference = None if trailer is None else trailer.find("TrailerRef")
    named = "" if reference is None else _text(str(reference.get("entityRef", "")), defaults)
    tows = trailer is not None and (trailer.find("Trailer") is not None or bool(named))
    category = _text(str(vehicle.get("vehicleCategory", "")), defaults)
    return CatalogEntry(catalog, path, category, values, tows)


def _defaults(vehicle: etree._Element) -> dict[str, str]:
    """The entry's parameters with their declared values, in order (a later one may use an
    earlier one); a value that cannot be computed is left out."""
    values: dict[str, str] = {}
    for declaration in vehicle.iterfind("ParameterDeclarations/ParameterDeclaration"):
        name = str(declaration.get("name", "")).removeprefix("$")
        try:
            values[name] = _text(str(declaration.get("value", "")), values)
        except (ExpressionError, KeyError):
            continue
    return values


def _text(text: str, values: dict[str, str]) -> str:
    """An attribute's text with a `$name` or `${expression}` resolved."""
    if text.startswith("${") and text.endswith("}"):
        return repr(evaluate(text[2:-1], values))
    if text.startswith("$"):
        return values[text[1:]]
    return text


def _value(element: etree._Element | None, attribute: str, defaults: dict[str, str]) -> EntryValue:
    text = None if element is None else element.get(attribute)
    if text is None:
        return EntryValue(None, None)
    parameter = text[1:] if text.startswith("$") and not text.startswith("${") else None
    try:
        return EntryValue(float(_text(text, defaults)), parameter)
    except (ExpressionError, KeyError, ValueError):
        return EntryValue(None, parameter)
