"""Diff fixtures: a copy of UIS2 (logical) and a way to save an edited version beside it."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.model.loading import load_scenario
from sceml.model.saving import save

Edit = Callable[[scm.Scenario], None]


@pytest.fixture
def uis2(examples_copy: Path) -> Path:
    """A private copy of examples/uis2-logical.xmi (its library and map beside it)."""
    return examples_copy / "uis2-logical.xmi"


@pytest.fixture
def edited(uis2: Path) -> Callable[..., Path]:
    """`edited(edit, name="new.xmi", base=uis2)`: load base, apply `edit`, save as `name` beside it."""

    def make(edit: Edit, name: str = "new.xmi", base: Path | None = None) -> Path:
        source = base or uis2
        document = load_scenario(source)
        assert isinstance(document.root, scm.Scenario)
        edit(document.root)
        return save(document.root, source.with_name(name))

    return make


def node(scenario: scm.Scenario, name: str) -> scm.GraphElement:
    """The scenario's node called `name`."""
    return next(n for n in scenario.nodes if n.name == name)


def actor(scenario: scm.Scenario, name: str) -> scm.Actor:
    """The scenario's actor called `name`."""
    root = node(scenario, "Root")
    return next(a for a in root.actors if a.name == name)
