"""The view model: every decision about the OpenSCENARIO document, made before any template runs.

`build_view` turns a flattened, concrete scenario into plain data (dicts, lists, small
dataclasses) that the templates only loop over: names, the trigger structure of SPEC §7,
version differences (via `versions.Traits`) and profile differences.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

import scemlmodel as scm

from ..errors import SceMLError
from ..maps.reference import is_scenery_file
from ..model import graph
from ..xosc.flows import inlined
from ..xosc.profiles import DEFAULT_VERSION
from .actions import PLANNERS
from .context import Context, Event, node_name
from .entities import entity, init_actions, towed_first, written_in_place
from .environment import environment
from .global_kinds import declarations
from .names import NameTable, sanitize
from .triggers import Finish, Group, activation, simulation_started, simulation_time_over
from .values import ParameterHook, Values
from .versions import traits

if TYPE_CHECKING:
    from ..xosc.vehicle_catalog import VehicleCatalogFolder


class MappingError(SceMLError):
    """A node cannot be written in the chosen version and profile."""


@dataclass
class Options:
    """What the caller decided: version, profile, header date, map text, parameter hook."""

    version: str = DEFAULT_VERSION
    profile: str = "generic"
    date: str = "1970-01-01T00:00:00"
    logic_file: str = ""
    parameters: ParameterHook | None = None
    #: The root node's vehicle catalog (release 1.5), where actors read from it are referred
    #: to, and its CatalogLocations Directory relative to the output.
    vehicle_catalog: VehicleCatalogFolder | None = None
    catalog_location: str = ""


@dataclass
class View:
    """Everything the main template needs."""

    traits: Any
    header: dict[str, str]
    marker: dict[str, str]
    parameters: list[Any]
    logic_file: str
    #: The RoadNetwork element that names the map: a scene graph with no roads, or the usual
    #: LogicFile (OpenDRIVE or a simulator town).
    road_network: str
    entities: list[dict[str, Any]]
    #: CatalogLocations' VehicleCatalog Directory; empty when no entity is a catalog reference.
    vehicle_catalog: str
    environment: dict[str, Any]
    privates: list[dict[str, Any]]
    story: str
    act: str
    act_start: list[Group]
    groups: list[dict[str, Any]]
    stop: list[Group]
    #: The root's declarations (`global_kinds.declarations`): parameters and variables.
    declared: dict[str, list[dict[str, Any]]] = field(default_factory=dict)
    #: node name -> (first event, finish event) of every node that has events (an inlined node
    #: has none: `xosc.flows.inlined`); not rendered, for callers and tests.
    events_of: dict[str, tuple[str, str]] = field(default_factory=dict)


def build_view(scenario: scm.Scenario, options: Options) -> View:
    """The view model of a flattened concrete scenario."""
    root, end = graph.root_node(scenario), graph.end_node(scenario)
    if root is None or end is None:
        raise MappingError("the scenario needs a root node and an end node")
    names = NameTable()
    actors = list(root.actors)
    ctx = Context(
        traits=traits(options.version),
        profile=options.profile,
        values=Values(options.parameters),
        names=names,
        ego="",
        marker="",
        vehicle_catalog=options.vehicle_catalog,
    )
    for actor in actors:
        ctx.entity_names[actor] = names.claim(sanitize(actor.name, "actor"))
    ego = next((a for a in actors if a.isEgo), actors[0] if actors else None)
    if ego is None:
        raise MappingError("the scenario has no actors")
    ctx.ego = ctx.entity(ego)
    order, cyclic = graph.topological_order(scenario)
    if cyclic:
        raise MappingError("the graph has a cycle", element=sorted(n.name for n in cyclic)[0])
    nodes = [n for n in order if not isinstance(n, scm.RootNode | scm.EndNode)]
    for node in nodes:
        ctx.event_names[node] = names.claim(node_name(node))
    ctx.marker = names.claim("SceML_marker")
    ctx.inline = inlined(scenario.nodes)
    events, finishes = _plan(ctx, nodes)
    story = names.claim(sanitize(root.scenarioName, "Scenario"))
    act = names.claim(f"{story}_Act")
    groups = _groups(ctx, actors, events)
    stop = activation(
        [finishes.get(p) for p in graph.predecessors(end)], graph.finishes_with_first(end), "End"
    )
    max_duration = ctx.values.text(root, "maxDuration")
    stop = _unique(names, [*stop, [simulation_time_over(max_duration, "End")]])
    env = environment(ctx, root, options.date)
    # A towed actor without a start is written inside its tower's Trailer, with no Init.
    placed = [actor for actor in actors if not written_in_place(actor)]
    entities = [entity(ctx, actor) for actor in towed_first(placed)]
    privates = [init_actions(ctx, actor) for actor in placed]
    # Declarations are complete only now that every value has been written.
    return View(
        traits=ctx.traits,
        header=_header(root, options.date),
        marker={"name": ctx.marker, "type": "string", "value": "none"},
        parameters=sorted(ctx.values.declarations.values(), key=lambda spec: spec.name),
        logic_file=options.logic_file,
        road_network="SceneGraphFile" if is_scenery_file(options.logic_file) else "LogicFile",
        entities=entities,
        vehicle_catalog=(
            options.catalog_location if any(e.get("reference") for e in entities) else ""
        ),
        environment=env,
        privates=privates,
        story=story,
        act=act,
        act_start=_unique(names, [[simulation_started(act)]]),
        groups=groups,
        stop=stop,
        events_of={
            str(node.name): (ctx.event_names[node], finish)
            for node in nodes
            if isinstance(finish := finishes[node], str)
        },
        declared=_declared(root, ctx.traits.variables),
    )


def _declared(root: scm.RootNode, variables_allowed: bool) -> dict[str, list[dict[str, Any]]]:
    try:
        return declarations(root, variables_allowed)
    except ValueError as problem:
        raise MappingError(str(problem), element=root.name) from None


def _plan(ctx: Context, nodes: list[scm.GraphElement]) -> tuple[list[Event], dict[Any, Finish]]:
    """Events of every node in topological order, and each node's finish (`triggers.Finish`)."""
    finishes: dict[Any, Finish] = {}
    events: list[Event] = []
    for node in nodes:
        kind = node.eClass.name
        planner = PLANNERS.get(kind)
        if planner is None:
            raise MappingError(f"{kind} has no OpenSCENARIO mapping", element=str(node.name))
        before = [finishes.get(p) for p in graph.predecessors(node)]
        node_events, finish = planner(
            ctx, node, activation(before, graph.finishes_with_first(node), ctx.event_names[node])
        )
        events.extend(_repeated(node, node_events))
        finishes[node] = finish
    return events, finishes


def _repeated(node: scm.GraphElement, events: list[Event]) -> list[Event]:
    """The node's event with its maxRuns as the maximumExecutionCount.

    Only a node written as one event can repeat: a node written as several (a wait and what
    it waits for) would repeat them out of step.
    """
    runs = getattr(node, "maxRuns", 1)
    if runs == 1:
        return events
    if len(events) != 1:
        raise MappingError(
            f"{node.eClass.name} runs {runs} times, but it is written as "
            f"{len(events)} events: only a node written as one event can repeat",
            element=str(node.name),
        )
    return [replace(events[0], runs=runs)]


def _groups(ctx: Context, actors: list[scm.Actor], events: list[Event]) -> list[dict[str, Any]]:
    """One ManeuverGroup per actor, each event in a Maneuver of its own."""
    groups = []
    for actor in actors:
        entity_name = ctx.entity(actor)
        maneuvers = [
            {
                "name": ctx.names.claim(f"{event.name}__maneuver"),
                "event": replace(event, groups=_unique(ctx.names, event.groups)),
            }
            for event in events
            if event.actor == entity_name
        ]
        if not maneuvers and written_in_place(actor):
            continue  # players name a trailer written in place after its tower (`Truck+`)
        groups.append(
            {
                "name": ctx.names.claim(f"{entity_name}_Group"),
                "actor": entity_name,
                "maneuvers": maneuvers,
            }
        )
    return groups


def _unique(names: NameTable, groups: list[Group]) -> list[Group]:
    """The groups with every condition name made unique in the document; a condition named
    after its inlined node keeps the name the node took."""
    return [
        [c if c.own else replace(c, name=names.claim(c.name)) for c in group] for group in groups
    ]


def _header(root: scm.RootNode, date: str) -> dict[str, str]:
    description = root.description or f"SceML scenario {root.scenarioName or ''}".strip()
    return {"date": date, "description": description, "author": root.author or "SceML"}
