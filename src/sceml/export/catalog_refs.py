"""An actor read from a vehicle catalog entry (`Actor.catalogEntry`, release 1.5) written as a
CatalogReference to it, and the scenario's CatalogLocations.

esmini fills a swarm from the vehicle catalogs it has loaded, and loads one only for a
reference that names it: written in place, every swarm vehicle would be a copy of the ego.
Whether an entry says the actor is `xosc.vehicle_catalog.compare`'s to judge (validation warns
with the same judgement, SCEML-A011).
"""

from __future__ import annotations

import os
from pathlib import Path, PurePosixPath
from typing import Any

import scemlmodel as scm

from ..xosc.vehicle_catalog import Reference, VehicleCatalogFolder, compare
from .context import Context


def reference_for(ctx: Context, actor: scm.Actor, written: dict[str, Any]) -> Reference | None:
    """The CatalogReference that says the actor, or None: it is written in place (`written`,
    the in-place entity). A value the caller's parameter hook names (`$name`) stays in place."""
    if ctx.vehicle_catalog is None or not actor.catalogEntry:
        return None
    entry = ctx.vehicle_catalog.entry(actor.catalogEntry)
    values = [*written["bbox"].values(), *written["performance"].values()]
    if entry is None or any(str(v).startswith("$") for v in values):
        return None
    reference, _ = compare(actor, entry)
    return reference


def catalog_location(folder: VehicleCatalogFolder, output_path: str | Path | None) -> str:
    """The CatalogLocations Directory of the folder: relative to the output's folder (as the
    LogicFile is), absolute without an output path."""
    target = folder.folder.resolve()
    if output_path is None:
        return target.as_posix()
    relative = os.path.relpath(target, Path(output_path).resolve().parent)
    return PurePosixPath(*Path(relative).parts).as_posix()
