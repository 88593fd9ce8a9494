"""The editor protocol carries a route position both ways: what the page receives it can send
back unchanged, and a route it cannot be is refused with the reason."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.editor.errors import OperationError
from sceml.editor.values import position_from_json, position_to_json
from sceml.importer import import_file
from sceml.model import graph
from sceml.model.compare import differences

ROUTES = Path(__file__).parents[1] / "importer" / "files" / "route-positions.xosc"


def _ego_start() -> object:
    root = graph.root_node(import_file(ROUTES).scenario)
    return next(a for a in root.actors if a.name == "Ego").startPosition


def test_a_route_position_goes_to_the_page_and_back_unchanged() -> None:
    start = _ego_start()
    sent = position_to_json(start)
    assert sent is not None
    assert (sent["type"], sent["routeName"], sent["laneId"]) == ("route", "KeepRight", -2)
    assert [w["routeStrategy"] for w in sent["waypoints"]] == ["shortest", "fastest"]
    assert sent["waypoints"][1]["position"]["s"] == {"type": "value", "value": 900.0}
    back = position_from_json(sent)
    assert differences(start, back) == []


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"waypoints": []}, "two or more"),
        ({"laneId": 1.5}, "'laneId' must be a whole number"),
    ],
)
def test_a_route_the_model_cannot_hold_is_refused(change: dict[str, object], message: str) -> None:
    sent = position_to_json(_ego_start())
    assert sent is not None
    with pytest.raises(OperationError, match=message):
        position_from_json({**sent, **change})


def test_a_waypoint_relative_to_an_actor_is_refused() -> None:
    sent = position_to_json(_ego_start())
    assert sent is not None
    relative = {"type": "relativeWorld", "entity": "Ego", "dx": None, "dy": None, "dz": None}
    sent["waypoints"][0] = {"routeStrategy": "shortest", "position": relative}
    with pytest.raises(OperationError):
        position_from_json(sent, participants={})
