"""Semantic round trip: the triggers of the .xosc say exactly which node waits for which.

From the exported file alone, each node's activation event's StartTrigger is read back as
ConditionGroups (OR) of the nodes whose finish events it waits for (AND). That must equal the
SceML graph's predecessor structure: one group of all predecessors for ordinary nodes and
join-all, one group per predecessor for join-one; likewise for the StopTrigger and the end node.
"""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree
from strategies import scenarios

import scemlmodel as scm
from sceml.export import build_xosc
from sceml.export.names import SEPARATOR, sanitize
from sceml.model import graph
from sceml.model.loading import load_scenario
from sceml.modules.flatten import flatten

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
ROOT = "Root"

Structure = list[frozenset[str]]


def expected_groups(node: scm.GraphElement) -> Structure:
    """What the SceML graph says `node` waits for."""
    before = [
        ROOT if isinstance(p, scm.RootNode) else sanitize(p.name) for p in graph.predecessors(node)
    ]
    one = isinstance(node, scm.JoinOneFinished) or (
        isinstance(node, scm.EndNode) and node.policy is scm.JoinPolicy.joinOne
    )
    groups = [frozenset([name]) for name in before] if one else [frozenset(before)]
    return sorted(groups, key=sorted)


def finish_events(root: etree._Element) -> dict[str, str]:
    """Node name -> its last event in document order (the one successors must wait for)."""
    last: dict[str, str] = {}
    for event in root.iter("Event"):
        last[event.get("name").split(SEPARATOR)[0]] = event.get("name")
    return last


def read_groups(trigger: etree._Element, finishes: dict[str, str]) -> Structure:
    """The nodes each ConditionGroup of a trigger waits for; checks refs hit finish events."""
    groups = []
    for group in trigger.iter("ConditionGroup"):
        waited: set[str] = set()
        for state in group.iter("StoryboardElementStateCondition"):
            assert state.get("state") == "completeState"
            ref = state.get("storyboardElementRef")
            node = ref.split(SEPARATOR)[0]
            assert finishes[node] == ref, f"{ref} is not the finish event of {node}"
            waited.add(node)
        if group.find(".//SimulationTimeCondition") is not None and not waited:
            waited.add(ROOT)
        groups.append(frozenset(waited))
    return sorted(groups, key=sorted)


def check_round_trip(scenario: scm.Scenario, version: str) -> None:
    flat = flatten(scenario)
    document = build_xosc(scenario, version=version, date="2026-01-01T00:00:00")
    tree = etree.fromstring(document.data)
    finishes = finish_events(tree)
    events = {event.get("name"): event for event in tree.iter("Event")}
    end = graph.end_node(flat)
    for node in flat.nodes:
        if isinstance(node, scm.RootNode | scm.EndNode):
            continue
        event = events[sanitize(node.name)]
        assert read_groups(event.find("StartTrigger"), finishes) == expected_groups(node), node.name
    stop = tree.find("Storyboard/StopTrigger")
    groups = read_groups(stop, finishes)
    # The extra group is the maximum duration (SimulationTimeCondition only).
    assert frozenset([ROOT]) in groups
    groups.remove(frozenset([ROOT]))
    assert groups == expected_groups(end)


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(scenarios("concrete", max_nodes=10), st.sampled_from(["1.0", "1.1", "1.2", "1.3"]))
def test_triggers_rebuild_the_predecessor_structure(scenario: scm.Scenario, version: str) -> None:
    check_round_trip(scenario, version)


def test_round_trip_holds_for_the_flattened_examples() -> None:
    for name in ("uis1", "uis2"):
        check_round_trip(load_scenario(EXAMPLES / f"{name}-concrete.xmi").root, "1.3")
