"""Which node kinds each OpenSCENARIO version and profile can express, and why not when not."""

from __future__ import annotations

from .profiles import CARLA_VERSION, PROFILES, default_version
from .schema import SUPPORTED_VERSIONS as VERSIONS

__all__ = [
    "CARLA_VERSION",
    "MAPPED_KINDS",
    "REPEATABLE_KINDS",
    "PROFILES",
    "default_version",
    "repeatable",
    "unsupported_reason",
    "unsupported_setting",
]

#: The node kinds the exporter maps (each has a planner in `sceml.export.actions`, which refuses
#: to register one for a kind not listed here; a test checks that every kind listed has one).
MAPPED_KINDS = frozenset(
    {
        "Accelerate",
        "AccelerationCondition",
        "ActivateController",
        "Approach",
        "AssignController",
        "ConnectTrailer",
        "Cross",
        "Decelerate",
        "DisconnectTrailer",
        "DriveDistance",
        "Follow",
        "FollowTrajectory",
        "InLocationRadius",
        "InPort",
        "InVehicleRadius",
        "JoinAllFinished",
        "JoinOneFinished",
        "KeepVelocity",
        "LaneChange",
        "LaneOffset",
        "LightState",
        "MatchSpeed",
        "OpaqueAction",
        "OutPort",
        "OverrideController",
        "Overtake",
        "ParameterCondition",
        "SetParameter",
        "SetVariable",
        "SpeedCondition",
        "StandStill",
        "Stop",
        "TimeElapsed",
        "TimeHeadway",
        "TimeToCollision",
        "TrafficSignalCondition",
        "TrafficSignalState",
        "TraveledDistance",
        "TurnLeft",
        "TurnRight",
        "VariableCondition",
    }
)

#: The kinds the exporter writes as one event, so that they can run more than once (`maxRuns`:
#: maximumExecutionCount is an event's; a node written as an event and its finish marker cannot
#: repeat them together). `sceml.export.actions.planner(one_event=True)` must agree.
REPEATABLE_KINDS = frozenset(
    {
        "Accelerate",
        "ActivateController",
        "AssignController",
        "ConnectTrailer",
        "Decelerate",
        "DisconnectTrailer",
        "LaneChange",
        "LaneOffset",
        "LightState",
        "OpaqueAction",
        "OverrideController",
        "SetParameter",
        "SetVariable",
        "Stop",
        "TrafficSignalState",
    }
)

#: Node kinds that never become events: the root starts the act, the end feeds the StopTrigger,
#: module uses are flattened away before mapping.
STRUCTURAL = ("RootNode", "EndNode", "ModuleUse")

#: Kinds scenario_runner cannot run faithfully, with the reason (see docs/openscenario-mapping.md).
CARLA_UNSUPPORTED = {
    "TimeElapsed": "scenario_runner starts a condition delay when the act starts, not when the "
    "node is activated, so a duration after activation cannot be expressed",
    "KeepVelocity": "its duration is a condition delay, which scenario_runner starts when the act "
    "starts, not when the node is activated",
}


_VARIABLES = "variables came with 1.2 (earlier versions have parameters only)"
#: Kinds a version before the given one cannot say, with the reason where one helps: 1.0 allows
#: an OverrideControllerValueAction only beside an assignment, with every input given.
SINCE: dict[str, tuple[str, str | None]] = {
    "OverrideController": ("1.1", None),
    "VariableCondition": ("1.2", _VARIABLES),
    "SetVariable": ("1.2", _VARIABLES),
    # The action came with 1.2, but 1.2's schema wants a UserDefinedLight beside every
    # VehicleLight (its LightType is a sequence; 1.3 made it a choice), so an XSD-valid 1.2
    # file cannot switch a vehicle light.
    "LightState": ("1.3", "1.2's schema asks for a user-defined light beside each vehicle light"),
    "ConnectTrailer": ("1.3", "TrailerAction came with 1.3"),
    "DisconnectTrailer": ("1.3", "TrailerAction came with 1.3"),
}


def repeatable(kind_name: str) -> bool:
    """Whether a node of this kind can run more than once when exported (`maxRuns`)."""
    return kind_name in REPEATABLE_KINDS


def unsupported_reason(kind_name: str, version: str, profile: str = "generic") -> str | None:
    """Why `kind_name` cannot be exported to `version` under `profile`; None when it can."""
    if profile not in PROFILES:
        return f"unknown export profile {profile!r}; use one of {', '.join(PROFILES)}"
    if version not in VERSIONS:
        return f"OpenSCENARIO {version} is not supported; use one of {', '.join(VERSIONS)}"
    if profile == "carla" and version != CARLA_VERSION:
        return f"the carla profile writes OpenSCENARIO {CARLA_VERSION} only (scenario_runner reads no other)"
    if kind_name in STRUCTURAL:
        return None
    if kind_name not in MAPPED_KINDS:
        return f"{kind_name} has no OpenSCENARIO mapping"
    since, why = SINCE.get(kind_name, (None, None))
    if since is not None and _minor(version) < _minor(since):
        return f"{kind_name} needs OpenSCENARIO {since} or later" + (f": {why}" if why else "")
    if profile == "carla" and kind_name in CARLA_UNSUPPORTED:
        return f"{kind_name} is not supported by the carla profile: {CARLA_UNSUPPORTED[kind_name]}"
    return None


#: Node settings OpenSCENARIO 1.0 has no attribute for: (feature, the value 1.0 always means).
#: 1.1 added relativeDistanceType and coordinateSystem to the measuring conditions.
_SINCE_1_1 = (("relativeDistanceType", "euclidean"), ("coordinateSystem", "entity"))
#: The exceptions: 1.0's RelativeDistanceCondition (InVehicleRadius) already measures
#: longitudinal and lateral distances; only its coordinateSystem is new in 1.1.
_IN_1_0 = (("InVehicleRadius", "relativeDistanceType"),)


#: ComparisonRule literals OpenSCENARIO 1.0's Rule does not have.
_RULES_SINCE_1_1 = ("greaterOrEqual", "lessOrEqual")


def _kind_name(node: object) -> str:
    eclass = getattr(node, "eClass", None)
    return str(getattr(eclass, "name", ""))


def _minor(version: str) -> int:
    return int(version.split(".")[1])


def unsupported_setting(node: object, version: str) -> str | None:
    """Why a node's or actor's settings (not its kind) cannot be said in `version`; None when
    they can."""
    reason = (
        _trailer_setting(node, _minor(version))
        or _controller_setting(node, _minor(version))
        or _direction_setting(node, version)
        or _distance_setting(node, _minor(version))
    )
    if reason is not None or version != "1.0":
        return reason
    rule = getattr(getattr(node, "rule", None), "name", None)
    if rule in _RULES_SINCE_1_1:
        # Not written as the strict neighbour: a value that settles on the threshold (a
        # speed stopped at 0 for `lessOrEqual 0`) would never fulfil it.
        return f"the rule {rule} needs OpenSCENARIO 1.1 or later (1.0 compares strictly)"
    for feature, plain in _SINCE_1_1:
        if (_kind_name(node), feature) in _IN_1_0:
            continue
        held = getattr(node, feature, None)
        if held is not None and held.name != plain:
            return (
                f"{feature} {held.name} needs OpenSCENARIO 1.1 or later (1.0 measures {plain} only)"
            )
    return None


def unsupported_profile_setting(node: object, profile: str) -> str | None:
    """Why a node's settings cannot be said to a profile's player; None when they can."""
    timed = _kind_name(node) == "LaneChange" and getattr(node, "duration", None) is not None
    if profile == "carla" and timed:
        return "a lane change given in time (CARLA's parser reads a distance only)"
    return None


def supported_kinds(version: str, profile: str = "generic") -> tuple[str, ...]:
    """The action, join and port kinds that map for a version and profile."""
    return tuple(k for k in sorted(MAPPED_KINDS) if unsupported_reason(k, version, profile) is None)


def _trailer_setting(node: object, minor: int) -> str | None:
    """A towing actor (release 1.4's Actor.trailer): TrailerHitch, TrailerCoupler and Trailer
    are OpenSCENARIO 1.3 elements."""
    if minor < 3 and getattr(node, "trailer", None) is not None:
        return "a trailer (TrailerHitch, TrailerCoupler, Trailer) needs OpenSCENARIO 1.3 or later"
    return None


def _direction_setting(node: object, version: str) -> str | None:
    """An AccelerationCondition's direction: OpenSCENARIO 1.2 added it (before, the magnitude)."""
    direction = (
        getattr(node, "direction", None) if _kind_name(node) == "AccelerationCondition" else None
    )
    if direction is not None and direction.name != "total" and _minor(version) < 2:
        return f"an acceleration's direction ({direction.name}) needs OpenSCENARIO 1.2 or later"
    return None


#: DynamicConstraints' jerks, which OpenSCENARIO 1.2 added.
_JERKS = ("maxAccelerationRate", "maxDecelerationRate")


def _distance_setting(node: object, minor: int) -> str | None:
    """What of a Follow's or Approach's gap a version cannot say: 1.0 has no displacement
    (it keeps the actor behind a positive distance), 1.1 no jerk limits."""
    if _kind_name(node) not in ("Follow", "Approach"):
        return None
    side = getattr(node, "displacement", None)
    if minor < 1 and side is not None and side.name != "trailing":
        return (
            f"a gap kept on the {side.name} side needs OpenSCENARIO 1.1 or later "
            "(1.0 has no displacement)"
        )
    for jerk in _JERKS:
        if minor < 2 and getattr(node, jerk, None) is not None:
            return f"{jerk} needs OpenSCENARIO 1.2 or later (DynamicConstraints has no jerk before)"
    return None


_ACTIVATE_SINCE_1_1 = ("lateral", "longitudinal")
#: Controller domains OpenSCENARIO 1.2 added.
_DOMAINS_SINCE_1_2 = ("lighting", "animation")


def _controller_setting(node: object, minor: int) -> str | None:
    """What of a controller a version cannot say: lighting and animation domains and
    controllerType (1.2), an assignment that also activates (1.1). `node` is an
    ActivateController, an AssignController or an actor (its controller and Init activation)."""
    controller = getattr(node, "controller", None)
    switches = (
        node,
        getattr(node, "activation", None),
        getattr(node, "controllerActivation", None),
    )
    if minor < 2:
        if controller is not None and controller.controllerType:
            return "a controller's controllerType needs OpenSCENARIO 1.2 or later"
        for holder in switches:
            for domain in _DOMAINS_SINCE_1_2:
                if getattr(holder, domain, None) is not None:
                    return f"switching the {domain} domain needs OpenSCENARIO 1.2 or later"
    activation = getattr(node, "activation", None)
    if minor < 1 and any(getattr(activation, d, None) is not None for d in _ACTIVATE_SINCE_1_1):
        return "an assignment that also activates needs OpenSCENARIO 1.1 or later"
    return None
