"""Catalog rules (release 1.5): an actor read from a vehicle catalog entry can be exported as a
reference to it.

The export writes an actor with a `catalogEntry` as a CatalogReference into the root node's
`vehicleCatalog` folder where the entry says what the actor is, and in place otherwise (as
before release 1.5). Writing it in place still plays the actor, but not what a player draws
from the catalogs a scenario refers to (esmini's swarm traffic): a warning, never an error.
"""

from __future__ import annotations

from collections.abc import Iterator

import scemlmodel as scm

from ..diagnostics import Severity
from ..model.graph import root_node
from ..xosc.vehicle_catalog import catalog_folder, compare
from .context import Context
from .reads import SELF, Aspect, Reads
from .registry import Finding, constraint

WARNING = Severity.WARNING


@constraint(
    "SCEML-A011",
    WARNING,
    "Actor",
    "an actor's catalogEntry (release 1.5) is an entry of the root node's vehicleCatalog "
    "folder that says the actor (category, box, performance), or the export writes the actor "
    "in place instead of as a CatalogReference",
    source="SPEC §6 (release 1.5)",
    # the actor's entry and values; the root node's vehicleCatalog
    reads=Reads(SELF, Aspect.SETTINGS | Aspect.CAST),
)
def catalog_entry_is_found(actor: scm.Actor, context: Context) -> Iterator[Finding]:
    if not actor.catalogEntry:
        return
    scenario = context.home(actor)
    root = root_node(scenario) if isinstance(scenario, scm.Scenario) else None
    if root is None:
        return  # a module's actor, or no root node (SCEML-S001 says so)
    who = f"actor {actor.name!r}: catalog entry {actor.catalogEntry!r}"
    if not (root.vehicleCatalog or "").strip():
        yield actor, f"{who}, but the root node names no vehicleCatalog; exported in place"
        return
    file = context.document.path if context.document is not None else None
    folder = catalog_folder(root, file)
    if folder is None:
        # A model built or imported in memory has no folder for a relative path to start from
        # (the working directory is an accident): checked once it is saved, as the map is.
        return
    entry = folder.entry(actor.catalogEntry)
    if folder.problem is not None and entry is None:
        yield actor, f"{who}: {folder.problem}; exported in place"
        return
    if entry is None:
        yield (
            actor,
            f"{who}: no catalog file in {folder.folder} has a Vehicle of that name; exported "
            "in place",
        )
        return
    _, unsaid = compare(actor, entry)
    if unsaid:
        yield (
            actor,
            f"{who} in {entry.file} cannot say {'; '.join(unsaid)} (not a parameter of the "
            "entry); exported in place",
        )
