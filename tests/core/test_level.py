"""The scenario's abstraction level has one reading (model.graph), and the stages agree on it."""

from __future__ import annotations

import pytest

import scemlmodel as scm
from sceml.export.checks import level_problems
from sceml.model.build import ScenarioBuilder
from sceml.model.graph import level_text, root_level, root_node, scenario_level
from sceml.model.info import summarize
from sceml.render.labels import root_lines
from sceml.validation.context import Context
from sceml.validation.limits import Limits


@pytest.mark.parametrize("level", ["functional", "logical", "concrete"])
def test_the_level_is_the_root_nodes(level: str) -> None:
    scenario = ScenarioBuilder("S", level=level).scenario
    assert scenario_level(scenario) == level
    assert level_text(scenario) == level
    assert summarize(scenario).level == level
    assert Context(scenario, None, Limits()).level_of(scenario) == level


def test_a_level_set_to_nothing_is_the_metamodels_default() -> None:
    scenario = ScenarioBuilder("S", level="concrete").scenario
    root = root_node(scenario)
    assert root is not None
    root.level = None
    # RootNode.level defaults to functional in metamodel/scemlmodel.ecore.
    assert root_level(root) == "functional" == scenario_level(scenario)
    assert root_lines(root, scenario)[0] == "level: functional"
    assert [d.message for d in level_problems(scenario)] == [
        "a functional scenario cannot be exported; refine it to concrete first"
    ]


def test_a_scenario_without_a_root_node_has_no_level() -> None:
    scenario = scm.Scenario()
    assert scenario_level(scenario) is None
    assert level_text(scenario) == "?"
    assert summarize(scenario).level is None
    assert Context(scenario, None, Limits()).level_of(scenario) is None
