"""UML-style class diagrams of the metamodel, drawn from the .ecore with Graphviz."""

from __future__ import annotations

import html
import importlib.resources
from dataclasses import dataclass
from functools import cache

import graphviz
from pyecore.ecore import EAttribute, EClass, EReference
from pyecore.resources import URI, ResourceSet

from ..model import catalog

#: The metamodel split into views a person can read; a class may appear in several.
VIEWS: dict[str, tuple[str, ...]] = {
    "graph": (
        "NamedElement",
        "Graph",
        "Scenario",
        "Library",
        "Flow",
        "GraphElement",
        "RootNode",
        "EndNode",
        "DiagramPosition",
        "ModuleElement",
        "ActionNode",
        "JoiningPolicy",
        "JoinAllFinished",
        "JoinOneFinished",
        "ModuleDefinition",
        "ModuleUse",
        "InPort",
        "OutPort",
        "RoleBinding",
        "ParameterOverride",
        "ModuleParameter",
        "Participant",
        "ActorRole",
        "AllowedKind",
        "Actor",
        "Environment",
    ),
    "actions": (
        "ActionNode",
        "Maneuver",
        "LongitudinalManeuver",
        "LateralManeuver",
        "CompositeManeuver",
        "Condition",
        "Accelerate",
        "Decelerate",
        "Stop",
        "KeepVelocity",
        "DriveDistance",
        "DistanceKeeping",
        "Follow",
        "Approach",
        "MatchSpeed",
        "LaneChange",
        "LaneOffset",
        "RoutedManeuver",
        "TurnLeft",
        "TurnRight",
        "Cross",
        "FollowTrajectory",
        "Overtake",
        "InLocationRadius",
        "InVehicleRadius",
        "TimeElapsed",
        "SpeedCondition",
        "TimeToCollision",
        "TraveledDistance",
        "TimeHeadway",
        "StandStill",
        "AccelerationCondition",
        "AppearanceManeuver",
        "LightState",
        "CouplingManeuver",
        "ConnectTrailer",
        "DisconnectTrailer",
        "ControllerManeuver",
        "ActivateController",
        "AssignController",
        "OverrideController",
        "ControllerOverride",
        "OpaqueAction",
        "Participant",
        "Position",
    ),
    "actors": (
        "Participant",
        "Actor",
        "Pedestrian",
        "TwoWheeler",
        "Bicycle",
        "Motorcycle",
        "FourWheeler",
        "Car",
        "Van",
        "Truck",
        "Bus",
        "ActorRole",
        "AllowedKind",
        "Position",
        "WorldPosition",
        "LanePosition",
        "RoadPosition",
        "RelativeLanePosition",
        "RelativeRoadPosition",
        "RelativeObjectPosition",
        "RelativeWorldPosition",
        "RoutePosition",
        "RouteWaypoint",
        "Controller",
        "Property",
        "ControllerActivation",
        "Environment",
    ),
    "global": (
        "RootNode",
        "Declaration",
        "ActionNode",
        "Condition",
        "GlobalAction",
        "ParameterCondition",
        "VariableCondition",
        "SetParameter",
        "SetVariable",
        "TrafficSignalState",
        "TrafficSignalCondition",
    ),
    "values": (
        "ParameterValue",
        "Value",
        "Range",
        "Distribution",
        "UniformDistribution",
        "NormalDistribution",
        "DiscreteDistribution",
        "WeightedValue",
        "ParameterRef",
        "ModuleParameter",
    ),
}

#: Fill colours follow the SceML notation so the diagrams read like the scenarios.
CATEGORY_FILL = {
    "longitudinal": "#ffe680",
    "lateral": "#ff9e9e",
    "composite": "#9ee6a0",
    "controller": "#8e7cc3",
    "appearance": "#80cbc4",
    "coupling": "#bcaaa4",
    "condition": "#9ec9ff",
    "global": "#ffb74d",
}
ABSTRACT_FILL = "#e6e6e6"
CONCRETE_FILL = "#ffd9b3"


@dataclass(frozen=True)
class Edge:
    """One relation drawn between two classes."""

    tail: str
    head: str
    label: str
    style: dict[str, str]


@cache
def _metamodel_classes() -> dict[str, EClass]:
    """The EClasses of the shipped .ecore as pyecore builds them: types, bounds and defaults."""
    ecore_file = importlib.resources.files("sceml.metamodel") / "scemlmodel.ecore"
    with importlib.resources.as_file(ecore_file) as path:
        resource = ResourceSet().get_resource(URI(str(path)))
    package = resource.contents[0]
    return {c.name: c for c in package.eClassifiers if isinstance(c, EClass)}


def _type_name(feature: EAttribute | EReference) -> str:
    name = str(feature.eType.name)
    bounds = "[*]" if feature.many else ("[0..1]" if feature.lowerBound == 0 else "[1]")
    return f"{name} {bounds}"


def _class_label(eclass: EClass, show: set[str]) -> str:
    title = html.escape(eclass.name)
    title = f"<I>{title}</I>" if eclass.abstract else f"<B>{title}</B>"
    rows = [f'<TR><TD ALIGN="CENTER">{title}</TD></TR>']
    lines = []
    for feature in eclass.eStructuralFeatures:
        drawn_as_edge = isinstance(feature, EReference) and feature.eType.name in show
        if drawn_as_edge and feature.eType.name != "ParameterValue":
            continue
        unit = _unit(eclass, feature.name)
        default = (
            f" = {feature.defaultValueLiteral}"
            if getattr(feature, "defaultValueLiteral", None)
            else ""
        )
        lines.append(html.escape(f"{feature.name}: {_type_name(feature)}{unit}{default}"))
    if lines:
        rows.append(f'<TR><TD ALIGN="LEFT" BALIGN="LEFT">{"<BR/>".join(lines)}</TD></TR>')
    return f'<<TABLE BORDER="0" CELLBORDER="1" CELLSPACING="0" CELLPADDING="3">{"".join(rows)}</TABLE>>'


def _unit(eclass: EClass, name: str) -> str:
    if eclass.abstract and eclass.name in ("ParameterValue", "Position"):
        return ""
    try:
        spec = catalog.parameter(eclass.name, name)
    except KeyError:
        return ""
    return f" ({spec.unit})" if spec.unit else ""


def _fill(eclass: EClass) -> str:
    category = catalog.category(eclass.name)
    if category in CATEGORY_FILL and eclass.eSuperTypes and not eclass.name.endswith("Maneuver"):
        return CATEGORY_FILL[category]
    return ABSTRACT_FILL if eclass.abstract else CONCRETE_FILL


def _edges(eclass: EClass, show: set[str]) -> list[Edge]:
    edges = []
    for parent in eclass.eSuperTypes:
        if parent.name in show:
            edges.append(Edge(eclass.name, parent.name, "", {"arrowhead": "empty"}))
    for reference in eclass.eReferences:
        target = reference.eType.name
        if target not in show or target == "ParameterValue" or reference.transient:
            continue
        bounds = "*" if reference.many else "0..1"
        style = {"arrowtail": "diamond", "dir": "both"} if reference.containment else {}
        edges.append(Edge(eclass.name, target, f"{reference.name} {bounds}", style))
    return edges


def class_diagram(view: str) -> graphviz.Digraph:
    """The Graphviz graph of one view of the metamodel."""
    classes = _metamodel_classes()
    show = set(VIEWS[view])
    # Wide hierarchies (many sibling kinds) read better with subclasses stacked to the left.
    direction = "RL" if view == "actions" else "BT"
    graph = graphviz.Digraph(view, graph_attr={"rankdir": direction, "fontname": "Helvetica"})
    graph.attr("node", shape="plain", fontname="Helvetica", fontsize="10")
    graph.attr("edge", fontname="Helvetica", fontsize="9")
    for name in VIEWS[view]:
        eclass = classes[name]
        graph.node(name, _class_label(eclass, show), style="filled", fillcolor=_fill(eclass))
    for name in VIEWS[view]:
        for edge in _edges(classes[name], show):
            graph.edge(edge.tail, edge.head, label=edge.label, **edge.style)
    return graph
