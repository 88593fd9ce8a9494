"""A small typed API for building scenarios and module libraries in code, without pyecore plumbing.

b = ScenarioBuilder("UIS1", map="../maps/intersection.xodr", level="concrete")
ego = b.actor("Car", "ego", ego=True, start=world(10, -30, h=1.57), speed=8)
turn = b.add("TurnRight", ego, destination=world(30, 5))
b.chain(b.root, turn, b.end)
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from typing import cast

from pyecore.ecore import EObject

import scemlmodel as scm

from ..errors import BuildError
from . import catalog
from .copying import detached
from .graph import DEFAULT_LEVEL
from .params import ParameterInput, as_parameter


def world(
    x: ParameterInput, y: ParameterInput, z: ParameterInput = 0.0, h: ParameterInput = 0.0
) -> scm.WorldPosition:
    """A world position (m, m, m, rad)."""
    return scm.WorldPosition(
        x=as_parameter(x), y=as_parameter(y), z=as_parameter(z), h=as_parameter(h)
    )


def lane(
    road_id: str | int,
    lane_id: int,
    s: ParameterInput,
    offset: ParameterInput = 0.0,
    h: ParameterInput | None = None,
) -> scm.LanePosition:
    """A lane position: road, lane, distance along the road and lateral offset (m) and, when
    given, the heading relative to the lane's direction of traffic (rad)."""
    return scm.LanePosition(
        roadId=str(road_id),
        laneId=int(lane_id),
        s=as_parameter(s),
        offset=as_parameter(offset),
        h=None if h is None else as_parameter(h),
    )


def road(
    road_id: str | int, s: ParameterInput, t: ParameterInput = 0.0, h: ParameterInput | None = None
) -> scm.RoadPosition:
    """A road position: distance along the road's reference line, lateral t (m, positive to the
    left) and, when given, the heading relative to the road (rad)."""
    return scm.RoadPosition(
        roadId=str(road_id),
        s=as_parameter(s),
        t=as_parameter(t),
        h=None if h is None else as_parameter(h),
    )


def relative_lane(
    entity: scm.Participant | None,
    d_lane: int = 0,
    ds: ParameterInput = 0.0,
    offset: ParameterInput = 0.0,
) -> scm.RelativeLanePosition:
    """d_lane lanes left (negative: right) of the entity's lane, ds on along the road, offset
    from that lane's centre, from where the entity is when the position is used."""
    return scm.RelativeLanePosition(
        entity=entity, dLane=int(d_lane), ds=as_parameter(ds), offset=as_parameter(offset)
    )


def relative_road(
    entity: scm.Participant | None, ds: ParameterInput = 0.0, dt: ParameterInput = 0.0
) -> scm.RelativeRoadPosition:
    """ds along and dt across the road (m, positive to the left) from the entity."""
    return scm.RelativeRoadPosition(entity=entity, ds=as_parameter(ds), dt=as_parameter(dt))


def relative_object(
    entity: scm.Participant | None,
    dx: ParameterInput = 0.0,
    dy: ParameterInput = 0.0,
    dz: ParameterInput = 0.0,
    h: ParameterInput | None = None,
) -> scm.RelativeObjectPosition:
    """dx ahead, dy left, dz above the entity in its own frame; h turns from its heading."""
    return scm.RelativeObjectPosition(
        entity=entity,
        dx=as_parameter(dx),
        dy=as_parameter(dy),
        dz=as_parameter(dz),
        h=None if h is None else as_parameter(h),
    )


def relative_world(
    entity: scm.Participant | None,
    dx: ParameterInput = 0.0,
    dy: ParameterInput = 0.0,
    dz: ParameterInput = 0.0,
) -> scm.RelativeWorldPosition:
    """dx, dy, dz in world axes from the entity (heading the entity's)."""
    return scm.RelativeWorldPosition(
        entity=entity, dx=as_parameter(dx), dy=as_parameter(dy), dz=as_parameter(dz)
    )


def controller(
    name: str, controller_type: str | None = None, properties: dict[str, str] | None = None
) -> scm.Controller:
    """A controller for an actor (`actor(..., controller=...)`) or an AssignController."""
    made = scm.Controller(name=name, controllerType=controller_type)
    for key, value in (properties or {}).items():
        made.properties.append(scm.Property(name=key, value=value))
    return made


def activation(
    *,
    lateral: bool | None = None,
    longitudinal: bool | None = None,
    lighting: bool | None = None,
    animation: bool | None = None,
) -> scm.ControllerActivation:
    """Which controller domains to switch on (True) or off (False); None leaves one as it is."""
    return scm.ControllerActivation(
        lateral=lateral, longitudinal=longitudinal, lighting=lighting, animation=animation
    )


def override(kind: str, value: float = 0.0, *, active: bool = True) -> scm.ControllerOverride:
    """One input of an OverrideController: throttle, brake, clutch, parkingBrake,
    steeringWheel or gear."""
    literal = scm.ControllerOverrideKind.getEEnumLiteral(kind)
    if literal is None:
        options = ", ".join(str(item.name) for item in scm.ControllerOverrideKind.eLiterals)
        raise BuildError(f"unknown override {kind!r}; choose one of: {options}")
    return scm.ControllerOverride(kind=literal, value=float(value), active=active)


def _kind_class(kind: str | type, base: str) -> type:
    name = catalog.class_name(kind)
    cls = getattr(scm, name, None)
    if cls is None or not catalog.is_kind_of(name, base) or cls.eClass.abstract:
        options = ", ".join(c.__name__ for c in catalog.concrete_subclasses(base))
        raise BuildError(f"unknown {base} kind {name!r}; choose one of: {options}")
    return cast(type, cls)


class GraphBuilder:
    """Adds nodes and flows to a graph (a scenario or a module definition)."""

    def __init__(self, graph: scm.Graph) -> None:
        self.graph = graph
        self._counts: Counter[str] = Counter(
            node.eClass.name for node in graph.nodes if isinstance(node, scm.ModuleElement)
        )

    def _auto_name(self, kind: str) -> str:
        self._counts[kind] += 1
        return f"{kind}_{self._counts[kind]}"

    def _adopt(self, node: scm.GraphElement) -> scm.GraphElement:
        self.graph.nodes.append(node)
        return node

    def add(
        self,
        kind: str | type,
        actor: scm.Participant | None,
        *,
        target: scm.Participant | None = None,
        name: str | None = None,
        **parameters: object,
    ) -> scm.ActionNode:
        """Add a maneuver or condition performed by `actor` (None for a global kind such as
        SetParameter, which no actor performs).

        Numeric parameters take numbers or parameter values (see `sceml.model.params`); positions take
        `world(...)` or `lane(...)`; other attributes (e.g. `direction="right"`) take their literal.
        """
        cls = _kind_class(kind, "ActionNode")
        if (actor is None) == catalog.performed_by_actor(cls):
            needs = "needs a reference actor" if actor is None else "is performed by no actor"
            raise BuildError(f"{cls.__name__} {needs}")
        node = cls(name=name or self._auto_name(cls.__name__))
        node.referenceActor = actor
        if target is not None:
            node.targetActor = target
        numeric = {spec.name for spec in catalog.parameters(cls)}
        for key, given in parameters.items():
            feature = node.eClass.findEStructuralFeature(key)
            if feature is None:
                raise BuildError(f"{cls.__name__} has no parameter {key!r}")
            if key in numeric:
                node.eSet(key, as_parameter(given))
            elif feature.many:
                node.eGet(key).extend(detached(item) for item in given)  # type: ignore[attr-defined]
            elif hasattr(feature.eType, "getEEnumLiteral"):
                literal = feature.eType.getEEnumLiteral(str(given))
                if literal is None:
                    raise BuildError(f"{cls.__name__}.{key} does not accept {given!r}")
                node.eSet(key, literal)
            elif isinstance(given, EObject):
                node.eSet(key, detached(given))
            else:
                node.eSet(key, given)
        self._adopt(node)
        return node

    def join_all(
        self, *predecessors: scm.GraphElement, name: str | None = None
    ) -> scm.JoinAllFinished:
        """A join that finishes when all predecessors have; flows from each are added."""
        join = scm.JoinAllFinished(name=name or self._auto_name("JoinAllFinished"))
        self._adopt(join)
        for node in predecessors:
            self.flow(node, join)
        return join

    def join_one(
        self, *predecessors: scm.GraphElement, name: str | None = None
    ) -> scm.JoinOneFinished:
        """A join that finishes when the first predecessor has; flows from each are added."""
        join = scm.JoinOneFinished(name=name or self._auto_name("JoinOneFinished"))
        self._adopt(join)
        for node in predecessors:
            self.flow(node, join)
        return join

    def use(
        self,
        definition: scm.ModuleDefinition,
        bindings: Mapping[str, scm.Participant],
        overrides: Mapping[str, ParameterInput] | None = None,
        *,
        name: str | None = None,
    ) -> scm.ModuleUse:
        """Use a module definition, binding each of its roles to an actor (or outer role)."""
        use = scm.ModuleUse(name=name or self._auto_name(str(definition.name)))
        use.definition = definition
        for role, actor in bindings.items():
            use.bindings.append(scm.RoleBinding(role=role, actor=actor))
        for parameter, given in (overrides or {}).items():
            use.overrides.append(
                scm.ParameterOverride(parameter=parameter, value=as_parameter(given))
            )
        self._adopt(use)
        return use

    def flow(self, source: scm.GraphElement, target: scm.GraphElement) -> scm.Flow:
        """A flow: `target` is activated when `source` has finished."""
        flow = scm.Flow(source=source, target=target)
        self.graph.flows.append(flow)
        return flow

    def chain(self, *nodes: scm.GraphElement) -> None:
        """Flows from each node to the next."""
        for source, target in zip(nodes, nodes[1:], strict=False):
            self.flow(source, target)


class ScenarioBuilder(GraphBuilder):
    """Builds a Scenario with its root node, end node and actors."""

    def __init__(
        self,
        name: str,
        *,
        map: str | None = None,
        level: str = DEFAULT_LEVEL,
        max_duration: ParameterInput | None = None,
        date: str | None = None,
        description: str | None = None,
        end_policy: str = "joinAll",
    ) -> None:
        super().__init__(scm.Scenario())
        self.root = scm.RootNode(name="Root", scenarioName=name, map=map, date=date)
        self.root.description = description
        self.root.level = scm.AbstractionLevel.getEEnumLiteral(level)
        if self.root.level is None:
            raise BuildError(f"unknown abstraction level {level!r}")
        if max_duration is not None:
            self.root.maxDuration = as_parameter(max_duration)
        self.end = scm.EndNode(name="End", policy=scm.JoinPolicy.getEEnumLiteral(end_policy))
        self._adopt(self.root)
        self._adopt(self.end)

    @property
    def scenario(self) -> scm.Scenario:
        """The scenario built so far."""
        return self.graph

    def environment(
        self,
        *,
        time_of_day: str = "12:00:00",
        cloud_state: str = "free",
        precipitation: str = "dry",
        precipitation_intensity: ParameterInput | None = None,
        fog_visual_range: ParameterInput | None = None,
    ) -> scm.Environment:
        """Set the environment of the root node."""
        environment = scm.Environment(
            timeOfDay=time_of_day,
            cloudState=scm.CloudState.getEEnumLiteral(cloud_state),
            precipitation=scm.PrecipitationType.getEEnumLiteral(precipitation),
        )
        if precipitation_intensity is not None:
            environment.precipitationIntensity = as_parameter(precipitation_intensity)
        if fog_visual_range is not None:
            environment.fogVisualRange = as_parameter(fog_visual_range)
        self.root.environment = environment
        return environment

    def actor(
        self,
        kind: str | type,
        name: str,
        *,
        ego: bool = False,
        start: scm.Position | None = None,
        speed: ParameterInput | None = None,
        model: str | None = None,
        controller: scm.Controller | None = None,
        activation: scm.ControllerActivation | None = None,
        **dimensions: ParameterInput,
    ) -> scm.Actor:
        """Add an actor of a kind (Car, Bicycle, Pedestrian, ...) to the root node, optionally
        with the controller it starts with and the domains switched on at the start."""
        cls = _kind_class(kind, "Actor")
        actor = cls(name=name, isEgo=ego, model=model)
        if controller is not None:
            actor.controller = detached(controller)
        if activation is not None:
            actor.controllerActivation = detached(activation)
        if start is not None:
            actor.startPosition = detached(start)
        if speed is not None:
            actor.initialSpeed = as_parameter(speed)
        for key, given in dimensions.items():
            if key not in ("length", "width", "height"):
                raise BuildError(f"actors have no parameter {key!r}")
            actor.eSet(key, as_parameter(given))
        self.root.actors.append(actor)
        return actor

    def declare(
        self, name: str, value: object, *, type: str = "double", variable: bool = False
    ) -> scm.Declaration:
        """Declare a parameter (or a 1.2+ variable) the global nodes read and change."""
        kind = scm.DeclarationType.getEEnumLiteral(type)
        if kind is None:
            raise BuildError(f"unknown declaration type {type!r}")
        text = str(value).lower() if isinstance(value, bool) else str(value)
        declaration = scm.Declaration(name=name, type=kind, value=text, variable=variable)
        self.root.declarations.append(declaration)
        return declaration


class ModuleBuilder(GraphBuilder):
    """Builds a module definition: roles, parameters and a graph from in-port to out-port."""

    def __init__(self, definition: scm.ModuleDefinition) -> None:
        super().__init__(definition)
        self.definition = definition
        self.in_port = scm.InPort(name="In")
        self.out_port = scm.OutPort(name="Out")
        self._adopt(self.in_port)
        self._adopt(self.out_port)

    def role(self, name: str, *kinds: str) -> scm.ActorRole:
        """Declare an actor role and the actor kinds it accepts (e.g. "Bicycle", "Pedestrian")."""
        role = scm.ActorRole(name=name)
        for kind in kinds:
            literal = scm.ActorKind.getEEnumLiteral(kind)
            if literal is None:
                raise BuildError(f"unknown actor kind {kind!r}")
            role.allowedKinds.append(scm.AllowedKind(kind=literal))
        self.definition.roles.append(role)
        return role

    def parameter(
        self, name: str, unit: str = "", default: ParameterInput | None = None
    ) -> scm.ModuleParameter:
        """Declare a module parameter; pass it as a node parameter to refer to it."""
        declared = scm.ModuleParameter(name=name, unit=unit)
        if default is not None:
            declared.default = as_parameter(default)
        self.definition.parameters.append(declared)
        return declared


class LibraryBuilder:
    """Builds a module library."""

    def __init__(self, name: str, description: str | None = None) -> None:
        self.library = scm.Library(name=name, description=description)

    def module(self, name: str, description: str | None = None) -> ModuleBuilder:
        """Start a new module definition in the library."""
        definition = scm.ModuleDefinition(name=name, description=description)
        self.library.modules.append(definition)
        return ModuleBuilder(definition)


def node_named(graph: scm.Graph, name: str) -> scm.GraphElement:
    """The node of a graph with this name; KeyError lists the names there are."""
    for node in graph.nodes:
        if node.name == name:
            return node
    raise KeyError(f"no node {name!r}; nodes are: {', '.join(str(n.name) for n in graph.nodes)}")


def actor_named(scenario: scm.Scenario, name: str) -> scm.Actor:
    """The actor of a scenario with this name."""
    for node in scenario.nodes:
        if isinstance(node, scm.RootNode):
            for actor in node.actors:
                if actor.name == name:
                    return actor
    raise KeyError(f"no actor {name!r}")


__all__ = [
    "GraphBuilder",
    "LibraryBuilder",
    "ModuleBuilder",
    "ScenarioBuilder",
    "actor_named",
    "lane",
    "node_named",
    "world",
]
