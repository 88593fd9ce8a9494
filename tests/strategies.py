"""Hypothesis strategies that draw random valid SceML scenarios, for property tests of every stage.

Public API (keep it small; other test packages import it):

    scenarios(level="concrete", *, max_nodes=8, max_actors=4, kinds=None)
        -> SearchStrategy[scemlmodel.Scenario]

What a drawn scenario guarantees, at every level:

- one RootNode named `Root` and one EndNode named `End` (policy joinAll or joinOne);
- 1 to `max_actors` actors with unique names; the first, `ego`, is the only ego (a Car);
- a series-parallel DAG: the root forks into one or more branches, a branch may fork again and
  every fork is merged by a JoinAllFinished or JoinOneFinished with at least two inputs; every
  node is reachable from the root and reaches the end, and only joins and the end merge;
- every action node has a reference actor, and a different target actor where its kind needs one;
- no two maneuvers of the same actor and overlapping category (composite overlaps both
  longitudinal and lateral) can run at the same time, in the order sceml.validation uses (a
  join-one is ordered after a node only when all of its predecessors are);
- node names come from the builder: `<Kind>_<n>`.

Per level:

- `concrete`: every required parameter has a Value, optional ones sometimes; every actor has a
  start position and an initial speed; positions are the lane and world positions of
  maps/positions.json (real lanes of maps/intersection.xodr), vehicles on driving lanes, bikes
  and pedestrians on sidewalks; speeds stay plausible per actor kind.
- `logical`: like concrete, but at least one parameter holds a range or a distribution.
- `functional`: graph, actors and kinds only; parameters and positions may be missing.

`kinds` restricts the action node kinds drawn (names such as "Accelerate"); conditions are
always allowed because they are the fallback where a maneuver would break the simultaneity rule.

Import it from a test with `from strategies import scenarios` when `tests/` is on sys.path, or
load it by file path (see `load_strategies` in tests/export/conftest.py).
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from hypothesis import strategies as st

import scemlmodel as scm
from sceml.model import catalog
from sceml.model.build import ScenarioBuilder, lane, world
from sceml.model.params import normal, span, uniform

POSITIONS = Path(__file__).resolve().parents[1] / "maps" / "positions.json"
MAP = "../maps/intersection.xodr"
DATE = "2026-01-01T00:00:00"

VEHICLES = ("Car", "Van", "Truck", "Bus", "Motorcycle")
VULNERABLE = ("Bicycle", "Pedestrian")
#: Highest speed (m/s) drawn per actor kind, well inside any sensible plausibility limit.
MAX_SPEED = {"Pedestrian": 2.0, "Bicycle": 6.0}
VEHICLE_MAX_SPEED = 15.0

MANEUVERS = (
    "Accelerate",
    "Decelerate",
    "Stop",
    "KeepVelocity",
    "DriveDistance",
    "Follow",
    "Approach",
    "LaneChange",
    "TurnLeft",
    "TurnRight",
    "Cross",
    "FollowTrajectory",
    "Overtake",
)
CONDITIONS = (
    "InLocationRadius",
    "InVehicleRadius",
    "TimeElapsed",
    "SpeedCondition",
    "TimeToCollision",
)
#: Kinds a pedestrian or bike performs; the rest are driving maneuvers.
VULNERABLE_MANEUVERS = ("Accelerate", "Decelerate", "Stop", "KeepVelocity", "Cross")


@cache
def _positions() -> dict:
    return json.loads(POSITIONS.read_text(encoding="utf-8"))


def _points(vulnerable: bool) -> list[dict]:
    """Reference points on driving lanes (vehicles) or sidewalks (bikes, pedestrians)."""
    points = []
    for scenario in ("uis1", "uis2"):
        for key, point in _positions()[scenario].items():
            on_sidewalk = key.startswith(("bike", "pedestrian"))
            if on_sidewalk == vulnerable and point not in points:
                points.append(point)
    return points


@dataclass
class _Shape:
    """The abstract DAG: node ids are ints, 0 is the root, 1 the end; joins are named by policy."""

    joins: dict[int, str] = field(default_factory=dict)
    actions: list[int] = field(default_factory=list)
    flows: list[tuple[int, int]] = field(default_factory=list)
    count: int = 2

    def new(self) -> int:
        self.count += 1
        return self.count - 1


def _chain(draw: st.DrawFn, shape: _Shape, start: int, budget: list[int], depth: int) -> int:
    """Append a non-empty sequence of actions and parallel blocks after `start`; return its last node."""
    current = start
    first = True
    while first or (budget[0] > 0 and draw(st.booleans())):
        first = False
        if depth < 2 and budget[0] >= 3 and draw(st.integers(0, 3)) == 0:
            branches = draw(st.integers(2, min(3, budget[0] - 1)))
            budget[0] -= branches + 1
            ends = []
            for _ in range(branches):
                budget[0] += 1  # each branch re-spends its first node inside _chain
                ends.append(_chain(draw, shape, current, budget, depth + 1))
            join = shape.new()
            shape.joins[join] = draw(st.sampled_from(("JoinAllFinished", "JoinOneFinished")))
            shape.flows.extend((end, join) for end in ends)
            current = join
        else:
            node = shape.new()
            budget[0] -= 1
            shape.actions.append(node)
            shape.flows.append((current, node))
            current = node
    return current


def _draw_shape(draw: st.DrawFn, max_nodes: int) -> _Shape:
    shape = _Shape()
    budget = [max(1, max_nodes)]
    branches = draw(st.integers(1, max(1, min(3, budget[0]))))
    for _ in range(branches):
        end_of_branch = _chain(draw, shape, 0, budget, 0)
        shape.flows.append((end_of_branch, 1))
        if budget[0] <= 0:
            break
    return shape


def _ordered_after(shape: _Shape) -> dict[int, set[int]]:
    """For each node, the nodes it can only be activated after (itself included).

    The simultaneity rule's order: a join-one finishes with its first predecessor, so it is
    ordered after a node only when all of its predecessors are; others when any predecessor is.
    """
    before: dict[int, list[int]] = {}
    for source, target in shape.flows:
        before.setdefault(target, []).append(source)
    after: dict[int, set[int]] = {}

    def visit(node: int) -> set[int]:
        if node not in after:
            inherited = [visit(p) for p in before.get(node, [])]
            if shape.joins.get(node) == "JoinOneFinished":
                combined = set.intersection(*inherited) if inherited else set()
            else:
                combined = set().union(*inherited)
            after[node] = combined | {node}
        return after[node]

    for node in range(shape.count):
        visit(node)
    return after


def _overlap(first: str, second: str) -> bool:
    categories = {catalog.category(first), catalog.category(second)}
    return "condition" not in categories and (len(categories) == 1 or "composite" in categories)


def _allowed(actor_kind: str, kinds: Sequence[str], has_other_actor: bool) -> list[str]:
    pool = [
        k for k in kinds if actor_kind not in VULNERABLE or k in VULNERABLE_MANEUVERS + CONDITIONS
    ]
    return [k for k in pool if has_other_actor or not catalog.needs_target(k)]


def _speed(draw: st.DrawFn, actor_kind: str, low: float = 0.5) -> float:
    top = MAX_SPEED.get(actor_kind, VEHICLE_MAX_SPEED)
    return draw(st.integers(int(low * 2), int(top * 2))) / 2


def _position(draw: st.DrawFn, actor_kind: str, prefer_lane: bool = True) -> scm.Position:
    point = draw(st.sampled_from(_points(actor_kind in VULNERABLE)))
    if prefer_lane and draw(st.booleans()):
        return lane(point["roadId"], point["laneId"], point["s"], point["offset"])
    return world(point["x"], point["y"], h=point["h"])


def _parameters(draw: st.DrawFn, kind: str, actor_kind: str) -> dict[str, object]:
    """Values for every required parameter of `kind`, and for some optional ones."""
    positive = st.integers(2, 40).map(lambda v: v / 2)
    chosen: dict[str, object] = {}
    for spec in catalog.parameters(kind):
        if not spec.required and not draw(st.booleans()):
            continue
        if spec.unit == "m/s3":
            continue  # jerks (a Follow's limits) cannot be said before OpenSCENARIO 1.2
        if spec.unit == "m/s":
            chosen[spec.name] = _speed(draw, actor_kind)
        elif spec.unit == "m/s2":
            # 3 m/s2 is the lowest acceleration limit of any kind (pedestrians, bikes, trucks).
            chosen[spec.name] = draw(st.integers(1, 6)) / 2
        elif spec.unit == "s":
            chosen[spec.name] = draw(positive)
        elif spec.name in ("distance", "laneChangeDistance"):
            chosen[spec.name] = draw(st.integers(10, 60).map(float))
        else:
            chosen[spec.name] = draw(positive)
    if kind in ("TurnLeft", "TurnRight", "Cross"):
        chosen["destination"] = _position(draw, actor_kind)
    if kind == "InLocationRadius":
        chosen["position"] = _position(draw, actor_kind)
    if kind == "FollowTrajectory":
        chosen["waypoints"] = [
            _position(draw, actor_kind, prefer_lane=False) for _ in range(draw(st.integers(2, 3)))
        ]
    if kind == "LaneChange" and "duration" in chosen:
        chosen.pop("distance", None)  # given in time or by distance, not both (SCEML-P010)
    if kind in ("LaneChange", "Overtake"):
        chosen["direction" if kind == "LaneChange" else "side"] = draw(
            st.sampled_from(("left", "right"))
        )
    if kind in ("SpeedCondition", "TimeToCollision"):
        chosen["rule"] = draw(st.sampled_from(("greaterThan", "lessThan")))
    return chosen


def _loosen(draw: st.DrawFn, scenario: scm.Scenario) -> None:
    """Turn one to three non-zero Values into ranges or distributions (logical level).

    Each spans [low, value] with low below the value, so no sample exceeds what the concrete
    value already respected (speed and rate limits) and positive quantities stay positive.
    """
    values = [o for o in scenario.eAllContents() if isinstance(o, scm.Value) and o.value != 0]
    picked = draw(st.lists(st.sampled_from(values), min_size=1, max_size=3, unique_by=id))
    for held in picked:
        high = float(held.value)
        low = high * 0.5 if high > 0 else high * 1.5 - 1.0
        shape = draw(st.sampled_from(("range", "uniform", "normal")))
        if shape == "range":
            loose: scm.ParameterValue = span(low, high, (high - low) / 2)
        elif shape == "uniform":
            loose = uniform(low, high)
        else:
            loose = normal((low + high) / 2, (high - low) / 4, low, high)
        held.eContainer().eSet(held.eContainmentFeature(), loose)


def _thin(draw: st.DrawFn, scenario: scm.Scenario) -> None:
    """Drop parameters and positions at random (functional level)."""
    for obj in [o for o in scenario.eAllContents() if isinstance(o, scm.Value | scm.Position)]:
        if obj.eContainer() is not None and draw(st.booleans()):
            container, feature = obj.eContainer(), obj.eContainmentFeature()
            if feature.many:
                container.eGet(feature).remove(obj)
            else:
                container.eSet(feature, None)


@st.composite
def _scenarios(
    draw: st.DrawFn, level: str, max_nodes: int, max_actors: int, kinds: tuple[str, ...]
) -> scm.Scenario:
    shape = _draw_shape(draw, max_nodes)
    actor_kinds = ["Car"] + draw(
        st.lists(st.sampled_from(VEHICLES + VULNERABLE), max_size=max(0, max_actors - 1))
    )
    builder = ScenarioBuilder(
        "Random",
        map=MAP,
        level="functional" if level == "functional" else "concrete",
        date=DATE,
        max_duration=draw(st.integers(10, 120).map(float)),
        end_policy=draw(st.sampled_from(("joinAll", "joinOne"))),
    )
    builder.environment()
    actors = [
        builder.actor(
            kind,
            "ego" if index == 0 else f"{kind.lower()}{index}",
            ego=index == 0,
            start=_position(draw, kind),
            speed=_speed(draw, kind, low=0.0),
        )
        for index, kind in enumerate(actor_kinds)
    ]
    _populate(draw, builder, shape, actors, kinds)
    scenario = builder.scenario
    if level == "logical":
        builder.root.level = scm.AbstractionLevel.logical
        _loosen(draw, scenario)
    elif level == "functional":
        _thin(draw, scenario)
    return scenario


def _populate(
    draw: st.DrawFn,
    builder: ScenarioBuilder,
    shape: _Shape,
    actors: list[scm.Actor],
    kinds: tuple[str, ...],
) -> None:
    """Create the nodes of `shape` in order, choosing kinds that keep the simultaneity rule."""
    after = _ordered_after(shape)
    made: dict[int, scm.GraphElement] = {0: builder.root, 1: builder.end}
    chosen: dict[int, tuple[int, str]] = {}
    for node in range(2, shape.count):
        if node in shape.joins:
            made[node] = getattr(builder, _JOIN_METHODS[shape.joins[node]])()
            continue
        index = draw(st.integers(0, len(actors) - 1))
        actor_kind = actors[index].eClass.name
        clashes = {
            kind
            for other, (other_index, kind) in chosen.items()
            if other_index == index and other not in after[node] and node not in after[other]
        }
        pool = _allowed(actor_kind, kinds, len(actors) > 1)
        pool = [k for k in pool if not any(_overlap(k, c) for c in clashes)]
        kind = draw(st.sampled_from(pool))
        chosen[node] = (index, kind)
        target = None
        if catalog.needs_target(kind):
            others = [a for a in actors if a is not actors[index]]
            target = draw(st.sampled_from(others))
        parameters = _parameters(draw, kind, actor_kind)
        made[node] = builder.add(kind, actors[index], target=target, **parameters)
    for source, target_id in shape.flows:
        builder.flow(made[source], made[target_id])


_JOIN_METHODS = {"JoinAllFinished": "join_all", "JoinOneFinished": "join_one"}


def scenarios(
    level: str = "concrete",
    *,
    max_nodes: int = 8,
    max_actors: int = 4,
    kinds: Sequence[str] | None = None,
) -> st.SearchStrategy[scm.Scenario]:
    """Random valid scenarios of an abstraction level (see the module docstring for guarantees)."""
    if level not in ("functional", "logical", "concrete"):
        raise ValueError(f"unknown abstraction level {level!r}")
    allowed = tuple(kinds) if kinds is not None else MANEUVERS
    unknown = set(allowed) - set(MANEUVERS) - set(CONDITIONS)
    if unknown:
        raise ValueError(f"unknown node kinds: {sorted(unknown)}")
    pool = tuple(dict.fromkeys((*allowed, *CONDITIONS)))
    return _scenarios(level, max(1, max_nodes), max(1, max_actors), pool)
