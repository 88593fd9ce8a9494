"""The comparison of the import tests: a scenario's behaviour in a name-free canonical form.

Two scenarios are equal when they have the same actors (kind, ego, start, initial speed, box,
model) and, node by node, the same kind, actors and values, waiting for the same predecessors.
Values are compared as a concrete scenario uses them (its own value, else the language default),
rounded to the microunit the export writes; a range or distribution (a logical import) is
compared as the distribution it samples (`sceml.levels.space.dimension`): its levels with their
relative weights, or its kind and parameters, so that a Range with a step and the equally
weighted set a stochastic ParameterValueDistribution writes for it are equal. What an export cannot carry is left out on purpose,
each for a stated reason below; node names are left out (the export makes them safe for
OpenSCENARIO, so `a.b` comes back as `a_b`).
"""

from __future__ import annotations

import hashlib
from collections import Counter
from collections.abc import Callable

import pytest
from pyecore.ecore import EAttribute, EObject, EReference

import scemlmodel as scm
from sceml.export.names import sanitize
from sceml.levels.space import dimension
from sceml.model import catalog, graph, params

#: Not behaviour: where the file is (map, vehicleCatalog: paths relative to it), what the header says (date, description, author),
#: how the editor draws it (diagramPosition), the name.
SKIPPED = {
    "name",
    "map",
    "vehicleCatalog",
    "date",
    "description",
    "author",
    "diagramPosition",
    "incoming",
    "outgoing",
}


def _number(owner: EObject, feature: str) -> str:
    held = owner.eGet(feature)
    if held is None and any(s.name == feature and s.optional for s in catalog.parameters(owner)):
        return "unset"  # unset has a meaning of its own (a light's intensity: the player's)
    if isinstance(held, scm.ParameterValue) and not isinstance(held, scm.Value):
        return _spread(held)
    if held is None and catalog.parameter(owner, feature).optional:
        return "unset"  # an optional value (an actor's own maxSpeed, release 1.4) not stated
    return f"{params.concrete(owner, feature):.6f}"


def _spread(held: scm.ParameterValue) -> str:
    """A range or distribution as what it samples."""
    dim = dimension(feature_path(held), held)
    if dim.is_set:
        total = sum(dim.weights)
        levels = ",".join(
            f"{v:.6f}:{w / total:.6f}" for v, w in zip(dim.levels, dim.weights, strict=True)
        )
        return f"set({levels})"
    if dim.kind == "uniform":
        return f"uniform({dim.low:.6f},{dim.high:.6f})"
    return f"normal({dim.mean:.6f},{dim.sd:.6f},{dim.low:.6f},{dim.high:.6f})"


def feature_path(held: EObject) -> str:
    """Where a value is, for messages."""
    owner, feature = held.eContainer(), held.eContainmentFeature()
    return f"{getattr(owner, 'name', owner.eClass.name)}.{getattr(feature, 'name', '?')}"


def _position(position: EObject | None, heading: bool = True) -> str:
    if position is None:
        return "-"
    if isinstance(position, scm.RoutePosition):
        # Its route and place on it, every feature compared (the waypoints' positions included).
        return f"route({_content(position)})"
    if isinstance(position, scm.LanePosition):
        turned = "" if position.h is None else f",h={_number(position, 'h')}"
        return f"lane({position.roadId},{position.laneId},{_number(position, 's')},{_number(position, 'offset')}{turned})"
    # Trajectory vertices are written without a heading (docs/openscenario-mapping.md, issue 13),
    # so a Cross destination and FollowTrajectory waypoints come back without one.
    h = _number(position, "h") if heading else "*"
    return f"world({_number(position, 'x')},{_number(position, 'y')},{_number(position, 'z')},{h})"


def _content(obj: EObject) -> str:
    numeric = {spec.name for spec in catalog.parameters(obj)} if _annotated(obj) else set()
    parts = []
    for feature in obj.eClass.eAllStructuralFeatures():
        name = str(feature.name)
        if feature.derived or feature.transient:
            continue
        # A controller's name picks what drives the actor, a property's names its setting.
        if name in SKIPPED and not (
            name == "name" and isinstance(obj, scm.Controller | scm.Property)
        ):
            continue
        if name == "referenceActor" and isinstance(obj, scm.TimeElapsed):
            # A wait does nothing to its actor, and the export writes it as a delay in its
            # successor's trigger (`xosc.flows.inlined`), which names no actor.
            continue
        held = obj.eGet(feature)
        if name in numeric:
            parts.append(f"{name}={_number(obj, name)}")
        elif isinstance(feature, EAttribute):
            value = getattr(held, "name", held)
            if name == "model" and isinstance(obj, scm.Actor):
                value = _model(obj)
            if name == "scenarioName":
                value = sanitize(held, "Scenario")
            parts.append(f"{name}={value}")
        elif isinstance(feature, EReference) and feature.containment:
            items = list(held) if feature.many else [held]
            heading = not isinstance(obj, scm.Cross | scm.FollowTrajectory)
            texts = [
                _position(item, heading)
                if isinstance(item, scm.Position | type(None))
                else _content(item)
                for item in items
            ]
            parts.append(f"{name}=[{'|'.join(texts)}]")
        elif isinstance(feature, EReference):
            parts.append(f"{name}={getattr(held, 'name', None)}")
    return ";".join(parts)


def _annotated(obj: EObject) -> bool:
    try:
        catalog.parameters(obj)
    except KeyError:
        return False
    return True


def _model(actor: scm.Actor) -> str | None:
    """The export writes the category (or `pedestrian`) when an actor has no model."""
    return actor.model or None


def _waits_for_one(node: EObject) -> bool:
    if isinstance(node, scm.EndNode):
        return node.policy is scm.JoinPolicy.joinOne
    return isinstance(node, scm.JoinOneFinished)


def _merged(node: EObject) -> bool:
    """A join that only feeds one node waiting the same way (all, or one, of its inputs): it
    means nothing of its own. The export writes it into that node's trigger
    (`xosc.flows.inlined`), so the import reads its inputs as the node's own; the two
    graphs mean the same (SPEC §3) and compare equal."""
    after = graph.successors(node)
    if len(after) != 1:
        return False
    if isinstance(node, scm.JoinAllFinished):
        return not _waits_for_one(after[0])
    return isinstance(node, scm.JoinOneFinished) and _waits_for_one(after[0])


def _waits_for(node: EObject) -> list[EObject]:
    """The node's predecessors, with merged joins replaced by their own."""
    found = []
    for before in graph.predecessors(node):
        found.extend(_waits_for(before) if _merged(before) else [before])
    return found


def canonical_form(scenario: scm.Scenario) -> Counter[str]:
    """Each node as kind + content + the keys of its predecessors (names left out)."""
    keys: dict[EObject, str] = {}

    def key(node: EObject) -> str:
        if node not in keys:
            before = sorted(key(p) for p in _waits_for(node))
            text = f"{node.eClass.name}[{_content(node)}]<-({','.join(before)})"
            keys[node] = hashlib.sha256(text.encode()).hexdigest()[:16]
        return keys[node]

    return Counter(key(node) for node in scenario.nodes if not _merged(node))


def readable_form(scenario: scm.Scenario) -> list[str]:
    """The same form as text, for a readable assertion diff."""
    lines = []
    for node in scenario.nodes:
        if _merged(node):
            continue
        before = sorted(str(p.eClass.name) for p in _waits_for(node))
        lines.append(f"{node.eClass.name}[{_content(node)}] <- {before}")
    return sorted(lines)


def assert_same(original: scm.Scenario, imported: scm.Scenario) -> None:
    """Fail with the nodes one scenario has and the other lacks."""
    if canonical_form(original) != canonical_form(imported):
        missing = sorted(set(readable_form(original)) - set(readable_form(imported)))
        extra = sorted(set(readable_form(imported)) - set(readable_form(original)))
        pytest.fail("lost:\n" + "\n".join(missing) + "\ngained:\n" + "\n".join(extra))


@pytest.fixture
def canonical() -> Callable[[scm.Scenario], Counter[str]]:
    """The canonical form function."""
    return canonical_form


@pytest.fixture
def same() -> Callable[[scm.Scenario, scm.Scenario], None]:
    """Asserts that two scenarios behave the same (equal canonical forms)."""
    return assert_same
