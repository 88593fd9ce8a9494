"""A folder of OpenSCENARIO vehicle catalogs, as the root node's `vehicleCatalog` names it
(release 1.5): its entries, the values each says, and whether an entry says an actor, for the
export (which writes an actor as a CatalogReference where it does) and for validation (which
warns where it does not, SCEML-A011).

A reference says the actor when the entry's category and each value the export would write in
place (box centre and dimensions, performance) equal the actor's, or differ in an attribute
that is a plain `$parameter` of the entry (then assigned).

Files are read only inside the allowed folders (the reading rule of the import: `--allow`),
regular files only, each parsed safely (`schema.parse_file`). An entry's values are its own
attributes with its ParameterDeclarations' defaults resolved (`$name` and `${expression}`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

import scemlmodel as scm

from ..files.safefiles import reading_roots
from ..model import params
from ..model.documents import allowed_roots_of
from ..model.kind_performance import VEHICLE_CATEGORIES, own_performance
from . import schema
from .expressions import ExpressionError, evaluate

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


#: Two values are the same when they differ by less than this (m, m/s, m/s2): the entry's text
#: and the model's double may round differently.
TOLERANCE = 1e-6


@dataclass(frozen=True)
class Reference:
    """A CatalogReference: the catalog's name, the entry, and its ParameterAssignments."""

    catalog: str
    entry: str
    assignments: tuple[tuple[str, str], ...]


def actor_values(actor: scm.Actor) -> dict[str, float]:
    """The values the export writes in place for a vehicle, by the names the entry's are kept
    under (`vehicle_catalog.ENTRY_NUMBERS`)."""
    max_speed, max_acceleration, max_deceleration = own_performance(actor)
    return {
        "x": params.concrete(actor, "boxCenterX"),
        "length": params.concrete(actor, "length"),
        "width": params.concrete(actor, "width"),
        "height": params.concrete(actor, "height"),
        "maxSpeed": max_speed,
        "maxAcceleration": max_acceleration,
        "maxDeceleration": max_deceleration,
    }


def compare(actor: scm.Actor, entry: CatalogEntry) -> tuple[Reference | None, list[str]]:
    """The reference that says the actor, or None and what a reference cannot say."""
    unsaid: list[str] = []
    category = VEHICLE_CATEGORIES.get(actor.eClass.name)
    if category != entry.category:
        unsaid.append(f"vehicleCategory {entry.category} (the actor is a {actor.eClass.name})")
    if actor.trailer is not None or entry.tows:
        unsaid.append("a trailer (written in place with its tower)")
    assignments: list[tuple[str, str]] = []
    for key, value in actor_values(actor).items():
        said = entry.values[key]
        if said.number is not None and abs(said.number - value) <= TOLERANCE:
            continue
        if said.parameter is not None:
            assignments.append((said.parameter, _number(value)))
        else:
            stated = "nothing" if said.number is None else _number(said.number)
            unsaid.append(f"{key} {_number(value)} (the entry says {stated})")
    if unsaid:
        return None, unsaid
    return Reference(entry.catalog, str(actor.catalogEntry), tuple(assignments)), []


def catalog_folder(
    root: scm.RootNode, source_path: str | Path | None, *, roots: list[Path] | None = None
) -> VehicleCatalogFolder | None:
    """The root node's vehicle catalog folder (relative to the model file, as `map` is), read
    only inside the folders the model may read from; None when it names none, or is relative
    and the model has no file."""
    text = (root.vehicleCatalog or "").strip()
    if not text:
        return None
    folder = Path(text)
    if not folder.is_absolute():
        if source_path is None:
            return None
        folder = Path(source_path).resolve().parent / folder
    if roots is None:
        roots = allowed_roots_of(root)
    if roots is None and source_path is not None:
        roots = reading_roots(source_path)
    return VehicleCatalogFolder(folder, roots)


def _number(value: float) -> str:
    """A number as OpenSCENARIO text, as the export writes it (`export.values.number`)."""
    return repr(float(value))
