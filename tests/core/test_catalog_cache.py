"""The catalog caches per metaclass, never per model object: asking about a node keeps it alive
no longer than the model does (issue 14)."""

from __future__ import annotations

import gc
import weakref

import pytest

import scemlmodel as scm
from sceml.model import catalog


@pytest.mark.parametrize(
    "question",
    [
        catalog.parameters,
        catalog.category,
        catalog.complexity,
        catalog.needs_target,
        catalog.actor_dimensions,
    ],
    ids=lambda f: f.__name__,
)
def test_asking_about_an_object_does_not_keep_it(question: object) -> None:
    node = scm.Car() if question is catalog.actor_dimensions else scm.Accelerate()
    answer = question(node)  # type: ignore[operator]
    assert answer == question(node.eClass.name)  # type: ignore[operator]
    alive = weakref.ref(node)
    del node
    gc.collect()
    assert alive() is None


def test_answers_are_cached_per_class() -> None:
    assert catalog.parameters(scm.Accelerate()) is catalog.parameters("Accelerate")
