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
from trigger_waits import ROOT, Structure, expected_groups, waited

import scemlmodel as scm
from sceml.export import build_xosc
from sceml.export.names import SEPARATOR, sanitize
from sceml.model import graph
from sceml.model.loading import load_scenario
from sceml.modules.flatten import flatten
from sceml.xosc.flows import inlined

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def finish_events(root: etree._Element) -> dict[str, str]:
    """Node name -> its last event in document order (the one successors must wait for)."""
    last: dict[str, str] = {}
    for event in root.iter("Event"):
        last[event.get("name").split(SEPARATOR)[0]] = event.get("name")
    return last


def read_groups(trigger: etree._Element, finishes: dict[str, str], owns: set[str]) -> Structure:
    """The nodes each ConditionGroup of a trigger waits for (their finish events, the start, an
    inlined node's own condition named in `owns`), each with its condition's delay, and LIMIT
    for the maximum duration; equal groups counted once."""
    groups = set()
    for group in trigger.iter("ConditionGroup"):
        members: set[str] = set()
        for condition in group.iter("Condition"):
            delay = float(condition.get("delay"))
            state = condition.find(".//StoryboardElementStateCondition")
            clock = condition.find(".//SimulationTimeCondition")
            if condition.get("name") in owns:
                members.add(waited(str(condition.get("name")), delay))
            elif state is not None:
                assert state.get("state") == "completeState"
                ref = state.get("storyboardElementRef")
                node = ref.split(SEPARATOR)[0]
                assert finishes[node] == ref, f"{ref} is not the finish event of {node}"
                members.add(waited(node, delay))
            elif clock is not None:
                limit = float(clock.get("value", "0")) > 0
                members.add("LIMIT" if limit else waited(ROOT, delay))
        groups.add(frozenset(members))
    return sorted(groups, key=sorted)


def check_round_trip(scenario: scm.Scenario, version: str) -> None:
    flat = flatten(scenario)
    inline = inlined(flat.nodes)
    document = build_xosc(scenario, version=version, date="2026-01-01T00:00:00")
    tree = etree.fromstring(document.data)
    finishes = finish_events(tree)
    events = {event.get("name"): event for event in tree.iter("Event")}
    owns = {sanitize(n.name) for n in inline}
    end = graph.end_node(flat)
    for node in flat.nodes:
        if isinstance(node, scm.RootNode | scm.EndNode):
            continue
        if node in inline:
            assert sanitize(node.name) not in events, f"{node.name} is inlined: no event"
            continue
        event = events[sanitize(node.name)]
        assert read_groups(event.find("StartTrigger"), finishes, owns) == expected_groups(
            node, inline, delays=True
        ), node.name
    stop = tree.find("Storyboard/StopTrigger")
    groups = read_groups(stop, finishes, owns)
    # The extra group is the maximum duration (SimulationTimeCondition only).
    assert frozenset(["LIMIT"]) in groups
    groups.remove(frozenset(["LIMIT"]))
    assert groups == expected_groups(end, inline, delays=True)


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
