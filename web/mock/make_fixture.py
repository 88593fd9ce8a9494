"""Write view.json: a hand-made view (UIS2-like) for developing the page without the server."""

import json
from pathlib import Path

STYLE = {
    "looks": {
        "longitudinal": {"fill": "#ffe066", "border": "#b08800", "shape": "box"},
        "lateral": {"fill": "#f28b82", "border": "#b3261e", "shape": "box"},
        "composite": {"fill": "#81c995", "border": "#2e7d32", "shape": "box"},
        "condition": {"fill": "#8ab4f8", "border": "#1a56b0", "shape": "rounded"},
        "root": {"fill": "#eceff1", "border": "#455a64", "shape": "rounded"},
        "end": {"fill": "#263238", "border": "#263238", "shape": "doublecircle"},
        "endOne": {"fill": "#263238", "border": "#263238", "shape": "doublecircle"},
        "joinAll": {"fill": "#ffffff", "border": "#37474f", "shape": "circle"},
        "joinOne": {"fill": "#ffffff", "border": "#37474f", "shape": "diamond"},
        "module": {"fill": "#ffffff", "border": "#000000", "shape": "doublebox"},
        "brokenModule": {"fill": "#fce8e6", "border": "#b3261e", "shape": "dashed"},
        "inPort": {"fill": "#ffffff", "border": "#000000", "shape": "invhouse"},
        "outPort": {"fill": "#ffffff", "border": "#000000", "shape": "house"},
    },
    "symbols": {"joinAll": "⇉", "joinOne": "?"},
    "font": "DejaVu Sans",
    "edge": {"color": "#37474f"},
}


def param(name, label, unit, value, *, kmh=False, default=None, required=False):
    return {
        "name": name,
        "label": label,
        "type": "parameter",
        "unit": unit,
        "kmh": kmh,
        "default": default,
        "required": required,
        "value": value,
    }


def actor_fields(name):
    return [
        {
            "name": "referenceActor",
            "label": "Reference actor",
            "type": "actor",
            "value": name,
            "required": True,
        },
    ]


def node(id_, kind, look, name, lines, fields=(), parent=None, **extra):
    base = [{"name": "name", "label": "Name", "type": "text", "value": name}]
    return {
        "id": id_,
        "kind": kind,
        "look": look,
        "name": name,
        "title": extra.pop("title", kind),
        "lines": lines,
        "position": None,
        "parent": parent,
        "readOnly": parent is not None,
        "severity": None,
        "problems": 0,
        "fields": base + list(fields),
        **extra,
    }


V = lambda v: {"type": "value", "value": v}  # noqa: E731


def world(x, y, h=None):
    return {
        "type": "world",
        "x": V(x),
        "y": V(y),
        "z": None,  # noqa: E731
        "h": None if h is None else V(h),
    }


nodes = [
    node(
        "n1",
        "RootNode",
        "root",
        "Root",
        [
            "level: concrete",
            "map: ../maps/intersection.xodr",
            "max duration: 60 s",
            "actors:",
            "  ego: Car, ego",
            "  car: Car",
            "  pedestrian: Pedestrian",
        ],
        title="UIS2",
        fields=[
            {"name": "scenarioName", "label": "Scenario name", "type": "text", "value": "UIS2"},
            {
                "name": "level",
                "label": "Level",
                "type": "enum",
                "options": ["functional", "logical", "concrete"],
                "value": "concrete",
            },
            {"name": "map", "label": "Map", "type": "text", "value": "../maps/intersection.xodr"},
            param("maxDuration", "Max duration", "s", V(60.0), default=None),
        ],
    ),
    node(
        "n2",
        "Accelerate",
        "longitudinal",
        "Accelerate_1",
        ["ego", "targetSpeed = 8 m/s (28.8 km/h)", "rate: 2 m/s²"],
        actor_fields("ego")
        + [
            param("targetSpeed", "Target speed", "m/s", V(8.0), kmh=True, required=True),
            param("rate", "Rate", "m/s²", None, default=2.0),
        ],
    ),
    node(
        "n3",
        "TurnLeft",
        "lateral",
        "TurnLeft_1",
        ["ego", "destination: (-34, 1.75) m, h 3.14159 rad", "tolerance: 3 m"],
        actor_fields("ego")
        + [
            {
                "name": "destination",
                "label": "Destination",
                "type": "position",
                "required": True,
                "value": world(-34, 1.75, 3.14159),
            }
        ],
    ),
    node(
        "n4",
        "InLocationRadius",
        "condition",
        "InLocationRadius_1",
        ["ego", "position: (-34, 1.75) m", "radius: 3 m"],
        actor_fields("ego"),
    ),
    node(
        "n5",
        "InLocationRadius",
        "condition",
        "InLocationRadius_2",
        ["ego", "position: (-0.812, -0.812) m", "radius: 3 m"],
        actor_fields("ego"),
    ),
    node(
        "n6",
        "DriveDistance",
        "longitudinal",
        "DriveDistance_1",
        ["car", "distance: 60 m", "speed: 10 m/s"],
        actor_fields("car"),
        severity="error",
        problems=1,
    ),
    node(
        "n7",
        "ModuleUse",
        "module",
        "CrossingManeuver_1",
        ["crosser = pedestrian", "trigger = car", "triggerRadius: 15 m"],
        title="CrossingManeuver",
        module={
            "definition": "CrossingManeuver",
            "library": "library/sceml-library.xmi",
            "resolved": True,
            "bindings": [
                {
                    "role": "crosser",
                    "allowedKinds": ["Pedestrian", "Bicycle"],
                    "actor": "pedestrian",
                },
                {"role": "trigger", "allowedKinds": ["Car"], "actor": "car"},
            ],
            "parameters": [
                {"name": "triggerRadius", "unit": "m", "default": V(10.0), "override": V(15.0)},
                {"name": "crossingSpeed", "unit": "m/s", "default": V(1.5), "override": None},
            ],
        },
    ),
    node("n7/in", "InPort", "inPort", "in", [], parent="n7"),
    node(
        "n7/1",
        "InVehicleRadius",
        "condition",
        "InVehicleRadius_1",
        ["pedestrian (crosser), target car (trigger)", "radius: 15 m ($triggerRadius)"],
        parent="n7",
    ),
    node(
        "n7/2",
        "Accelerate",
        "longitudinal",
        "Accelerate_1",
        ["pedestrian (crosser)", "targetSpeed: 1.5 m/s ($crossingSpeed)"],
        parent="n7",
    ),
    node(
        "n7/3",
        "Cross",
        "lateral",
        "Cross_1",
        ["pedestrian (crosser)", "destination: (-10, 4.5) m"],
        parent="n7",
    ),
    node("n7/out", "OutPort", "outPort", "out", [], parent="n7"),
    node(
        "n8",
        "EndNode",
        "end",
        "End",
        [],
        title="End",
        fields=[
            {
                "name": "policy",
                "label": "Policy",
                "type": "enum",
                "options": ["joinAll", "joinOne"],
                "value": "joinAll",
            }
        ],
    ),
    node("n9", "JoinAllFinished", "joinAll", "JoinAllFinished_1", [], title="JoinAllFinished"),
]
edges = [
    ("n1", "n2"),
    ("n2", "n3"),
    ("n3", "n4"),
    ("n4", "n8"),
    ("n1", "n5"),
    ("n5", "n6"),
    ("n6", "n9"),
    ("n9", "n8"),
    ("n1", "n7"),
    ("n7", "n8"),
    ("n7/in", "n7/1"),
    ("n7/1", "n7/2"),
    ("n7/2", "n7/3"),
    ("n7/3", "n7/out"),
]


def actor(id_, name, kind, ego):
    return {
        "id": id_,
        "name": name,
        "kind": kind,
        "isEgo": ego,
        "fields": [
            {"name": "name", "label": "Name", "type": "text", "value": name},
            {
                "name": "kind",
                "label": "Kind",
                "type": "enum",
                "options": ["Pedestrian", "Bicycle", "Motorcycle", "Car", "Van", "Truck", "Bus"],
                "value": kind,
            },
            {"name": "isEgo", "label": "Ego", "type": "bool", "value": ego},
            {"name": "model", "label": "Model", "type": "text", "value": None},
            {
                "name": "startPosition",
                "label": "Start position",
                "type": "position",
                "value": {
                    "type": "lane",
                    "roadId": "1",
                    "laneId": -1,
                    "s": V(10.0),
                    "offset": None,
                },
            },
            param("initialSpeed", "Initial speed", "m/s", None, kmh=True, default=0.0),
            param("length", "Length", "m", None, default=4.5),
        ],
    }


PALETTE = [
    {
        "group": "longitudinal",
        "label": "Longitudinal maneuvers",
        "look": "longitudinal",
        "items": [
            {"kind": k, "label": k, "module": None, "library": None}
            for k in ["Accelerate", "Decelerate", "DriveDistance", "KeepVelocity"]
        ],
    },
    {
        "group": "lateral",
        "label": "Lateral maneuvers",
        "look": "lateral",
        "items": [
            {"kind": k, "label": k, "module": None, "library": None}
            for k in ["TurnLeft", "TurnRight", "LaneChange", "Cross"]
        ],
    },
    {
        "group": "composite",
        "label": "Composite maneuvers",
        "look": "composite",
        "items": [{"kind": "Overtake", "label": "Overtake", "module": None, "library": None}],
    },
    {
        "group": "condition",
        "label": "Conditions",
        "look": "condition",
        "items": [
            {"kind": k, "label": k, "module": None, "library": None}
            for k in ["InLocationRadius", "InVehicleRadius", "TimeElapsed"]
        ],
    },
    {
        "group": "join",
        "label": "Joins",
        "look": "joinAll",
        "items": [
            {"kind": k, "label": k, "module": None, "library": None}
            for k in ["JoinAllFinished", "JoinOneFinished"]
        ],
    },
    {
        "group": "library/sceml-library.xmi",
        "label": "sceml-library.xmi",
        "look": "module",
        "items": [
            {
                "kind": "ModuleUse",
                "label": "CrossingManeuver",
                "module": "CrossingManeuver",
                "library": "library/sceml-library.xmi",
            }
        ],
    },
]

view = {
    "version": 1,
    "document": {"kind": "scenario", "path": "/abs/uis2.xmi", "name": "uis2.xmi"},
    "readOnly": False,
    "dirty": False,
    "undo": None,
    "redo": None,
    "level": "concrete",
    "valueTypes": ["value"],
    "nodes": nodes,
    "edges": [{"id": f"f{i}", "source": s, "target": t} for i, (s, t) in enumerate(edges)],
    "actors": [
        actor("a1", "ego", "Car", True),
        actor("a2", "car", "Car", False),
        actor("a3", "pedestrian", "Pedestrian", False),
    ],
    "diagnostics": [
        {
            "severity": "error",
            "code": "SCEML-S010",
            "node": "n6",
            "actor": None,
            "message": "DriveDistance_1 needs a target speed",
            "path": "Root/DriveDistance_1",
            "line": 30,
        },
        {
            "severity": "warning",
            "code": "SCEML-S031",
            "node": None,
            "actor": "a3",
            "message": "pedestrian has no start position",
            "path": "pedestrian",
            "line": None,
        },
    ],
    "summary": {"errors": 1, "warnings": 1, "infos": 0},
    "palette": PALETTE,
    "style": STYLE,
    "choices": {
        "actorKinds": ["Pedestrian", "Bicycle", "Motorcycle", "Car", "Van", "Truck", "Bus"],
        "levels": ["functional", "logical", "concrete"],
        "cloudStates": ["free", "cloudy"],
        "precipitationTypes": ["dry", "rain"],
        "oscVersions": ["1.0", "1.1", "1.2", "1.3"],
    },
}
Path(__file__).with_name("view.json").write_text(json.dumps(view, indent=1, ensure_ascii=False))
