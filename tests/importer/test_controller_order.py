"""The order of Init controller activations and speeds survives the round trip (issue 24,
`cut-in_interactive`, `distance_test`): players' controllers take over at the speed the actor
has when they are activated, so a speed set after the activation must be written after it
again, and further activations add their domains to the earlier ones.

`files/controller-first.xosc` is written by hand; esmini 3.6 plays it with the ego standing
still at x = 20 m (its interactive driver took over at 0 m/s) and the target at 15 m/s. Before,
the export set the ego's speed first and its driver drove off at 20 m/s (240 m off at 12 s)."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import build_xosc, export_to_file
from sceml.importer import import_file
from sceml.model import graph, params

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "controller-first.xosc"


@pytest.fixture(scope="module")
def imported() -> scm.Scenario:
    return import_file(SOURCE).scenario


@pytest.fixture(scope="module")
def exported(imported: scm.Scenario) -> etree._Element:
    return build_xosc(imported, version="1.1", source_path=SOURCE).tree.getroot()


def actor(scenario: scm.Scenario, name: str) -> scm.Actor:
    return next(a for a in graph.actors(scenario) if a.name == name)


def init_order(document: etree._Element, entity: str) -> list[str]:
    """The Init actions of an entity in document order: `speed:<m/s>`, `activate:<domains on>`."""
    order = []
    for private in document.iterfind(f"Storyboard/Init/Actions/Private[@entityRef='{entity}']"):
        for action in private.iterfind("PrivateAction"):
            activate = action.find(".//ActivateControllerAction")
            target = action.find("LongitudinalAction/SpeedAction//AbsoluteTargetSpeed")
            if target is not None:
                order.append(f"speed:{float(target.get('value')):g}")
            elif activate is not None:
                on = sorted(k for k, v in activate.attrib.items() if v == "true")
                order.append(f"activate:{','.join(on)}")
    return order


def test_two_init_activations_add_up(imported: scm.Scenario) -> None:
    activation = actor(imported, "Ego").controllerActivation
    assert (activation.longitudinal, activation.lateral) == (True, True)
    assert (activation.lighting, activation.animation) == (None, None)


def test_a_speed_after_the_activation_is_a_speed_change_from_the_start(
    imported: scm.Scenario,
) -> None:
    ego = actor(imported, "Ego")
    assert ego.initialSpeed is None  # the driver took over at 0 m/s
    (speed,) = [n for n in imported.nodes if isinstance(n, scm.Accelerate)]
    assert speed.referenceActor is ego
    assert params.concrete(speed, "targetSpeed") == 20.0
    assert graph.predecessors(speed) == [imported.nodes[0]]


def test_a_speed_before_the_activation_stays_the_initial_speed(imported: scm.Scenario) -> None:
    target = actor(imported, "Target")
    assert params.concrete(target, "initialSpeed") == 15.0
    assert target.controllerActivation.longitudinal is True


def test_the_export_activates_and_sets_speeds_in_the_original_order(
    exported: etree._Element,
) -> None:
    # The ego's driver takes over at rest (the export writes every actor's initial speed).
    assert init_order(exported, "Ego") == ["speed:0", "activate:lateral,longitudinal"]
    assert init_order(exported, "Target") == ["speed:15", "activate:longitudinal"]
    # The ego's speed: a story event at the start, after the Init activation.
    speeds = [
        event
        for event in exported.iter("Event")
        if event.find(".//SpeedAction//AbsoluteTargetSpeed[@value='20.0']") is not None
    ]
    (clock,) = [c for e in speeds for c in e.iterfind(".//SimulationTimeCondition")]
    assert (clock.get("value"), clock.get("rule")) == ("0.0", "greaterOrEqual")


def test_the_export_imports_back_as_the_same_scenario(tmp_path: Path, same) -> None:
    first = import_file(SOURCE).scenario
    exported = tmp_path / SOURCE.name
    export_to_file(first, exported, version="1.1", source_path=SOURCE)
    # The file sets no environment; the export writes SceML's default one, which reads back.
    first.nodes[0].environment = scm.Environment()
    same(first, import_file(exported, allow=[FILES]).scenario)
