"""Validating or flattening again and again leaves the model as it found it.

pyecore records each reference without an opposite in the object referred to (`_inverse_rels`).
The copies a module expansion makes name the scenario's actors and the library's parameters and
definitions; unless the expansion forgets them, every validation (the editor runs one after each
edit) would leave its copies reachable from the model, which would grow without bound.
"""

from __future__ import annotations

from pathlib import Path

from pyecore.ecore import EObject

from sceml.model.loading import load
from sceml.model.traversal import all_contents
from sceml.modules import expand
from sceml.validation import validate

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _links(*roots: EObject) -> int:
    """How many references other objects have recorded in everything below `roots`."""
    return sum(len(obj._inverse_rels) for root in roots for obj in (root, *all_contents(root)))


def test_repeated_validation_records_nothing_in_the_scenario_or_its_library() -> None:
    document = load(EXAMPLES / "overtaking-concrete.xmi")  # a module used three deep
    validate(document.root, document=document)  # loads the library
    library = next(
        r for r in document.resource_set.resources.values() if r is not document.resource
    )
    before = _links(document.root), _links(library.contents[0])
    for _ in range(4):
        validate(document.root, document=document)
    assert (_links(document.root), _links(library.contents[0])) == before


def test_repeated_flattening_records_nothing_in_the_scenario_or_its_library() -> None:
    document = load(EXAMPLES / "uis2-concrete.xmi")
    expand(document.root)
    library = next(
        r for r in document.resource_set.resources.values() if r is not document.resource
    )
    before = _links(document.root), _links(library.contents[0])
    flats = [expand(document.root) for _ in range(4)]  # kept alive: only dropped copies forget
    assert (_links(document.root), _links(library.contents[0])) == before
    assert all(len(flat.scenario.nodes) == len(flats[0].scenario.nodes) for flat in flats)
