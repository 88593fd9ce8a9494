"""Which vehicle catalog entry an actor was read from (release 1.5: `Actor.catalogEntry`, and
the folder as `RootNode.vehicleCatalog`), so that its export refers to the entry again.

esmini draws a swarm's vehicles from the vehicle catalogs it has loaded, and it loads a catalog
only for a CatalogReference that names it: a re-export that wrote every entity in place would
fill the swarm with copies of the ego.

One folder per scenario: an actor read from a catalog file of another folder than the first
one's stays in place (the report says so). A vehicle entry with a trailer of its own stays in
place too: its trailer is an actor of the model, written in place by its tower.
"""

from __future__ import annotations

import os
from pathlib import Path, PurePosixPath

from lxml import etree

import scemlmodel as scm

from .context import Build
from .reading import CATALOG_ENTRY, ORIGIN


def keep_catalog_entry(build: Build, actor: scm.Actor, body: etree._Element) -> None:
    """Set the actor's catalogEntry (and the root's vehicleCatalog) when `body`, a Vehicle,
    was copied from a catalog entry into its ScenarioObject."""
    entry = body.get(CATALOG_ENTRY)
    origin = body.get(ORIGIN)
    if body.tag != "Vehicle" or entry is None or origin is None:
        return
    if _tows(body):
        build.report.add(
            "guessed",
            f"entity {actor.name!r}: catalog entry {entry!r} tows a trailer; written in place "
            "on export, the trailer with it",
            build.where(body),
        )
        return
    folder = _relative_folder(Path(origin).parent, build.source.path.parent)
    if build.root.vehicleCatalog is None:
        build.root.vehicleCatalog = folder
    elif build.root.vehicleCatalog != folder:
        build.report.add(
            "guessed",
            f"entity {actor.name!r}: catalog entry {entry!r} is in {folder}, not in the "
            f"scenario's vehicle catalog folder {build.root.vehicleCatalog}; written in place "
            "on export",
            build.where(body),
        )
        return
    actor.catalogEntry = entry
    build.report.add(
        "mapped",
        f"entity {actor.name!r}: vehicle catalog entry {entry!r} in {folder}",
        build.where(body),
    )


def _tows(body: etree._Element) -> bool:
    """Whether the Vehicle tows a trailer: an inline one, or a TrailerRef that names an entity
    (esmini's catalog cars have an empty one by default)."""
    trailer = body.find("Trailer")
    if trailer is None:
        return False
    reference = trailer.find("TrailerRef")
    return trailer.find("Trailer") is not None or bool(
        reference is not None and reference.get("entityRef")
    )


def _relative_folder(folder: Path, scenario_folder: Path) -> str:
    """`folder` relative to the scenario's folder, as the file names it: links are not
    followed, so a catalog laid over another tree keeps the path people see."""
    relative = os.path.relpath(os.path.abspath(folder), os.path.abspath(scenario_folder))
    return PurePosixPath(*Path(relative).parts).as_posix()
