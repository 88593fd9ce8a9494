"""An actor read from a vehicle catalog entry (`Actor.catalogEntry`, release 1.5) written as a
CatalogReference to it, and the scenario's CatalogLocations.

esmini fills a swarm from the vehicle catalogs it has loaded, and loads one only for a
reference that names it: written in place, every swarm vehicle would be a copy of the ego.

A reference is written only where it says the actor: the entry's category and each value the
export would write in place (box centre and dimensions, performance) equal the actor's, or
differ in an attribute that is a plain `$parameter` of the entry (then assigned). Otherwise the
actor is written in place, as before release 1.5, and validation warns (`unsaid`).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

import scemlmodel as scm

from ..files.safefiles import reading_roots
from ..model import params
from ..model.documents import allowed_roots_of
from ..xosc.vehicle_catalog import CatalogEntry, VehicleCatalogFolder
from .entities import VEHICLE_CATEGORIES, own_performance
from .values import number

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
            assignments.append((said.parameter, number(value)))
        else:
            stated = "nothing" if said.number is None else number(said.number)
            unsaid.append(f"{key} {number(value)} (the entry says {stated})")
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


def catalog_location(folder: VehicleCatalogFolder, output_path: str | Path | None) -> str:
    """The CatalogLocations Directory of the folder: relative to the output's folder (as the
    LogicFile is), absolute without an output path."""
    target = folder.folder.resolve()
    if output_path is None:
        return target.as_posix()
    relative = os.path.relpath(target, Path(output_path).resolve().parent)
    return PurePosixPath(*Path(relative).parts).as_posix()
