"""Init to the root: start positions, initial speeds, controllers and the environment; any other
Init action becomes an opaque node right after the root (it runs at the start, as it did)."""

from __future__ import annotations

from copy import deepcopy

from lxml import etree

import scemlmodel as scm

from . import traced
from .actions import Motion, Request, map_action
from .context import Build
from .controllers import controls_speed, init_controller
from .opaque import opaque_node
from .placing import place
from .positions import number

#: fractionalCloudCover (1.2+) -> cloud state; eight oktas is overcast or, with dim sun, rainy.
OKTAS = {
    "zeroOktas": "free",
    "oneOktas": "free",
    "twoOktas": "free",
    "threeOktas": "cloudy",
    "fourOktas": "cloudy",
    "fiveOktas": "cloudy",
    "sixOktas": "overcast",
    "sevenOktas": "overcast",
    "eightOktas": "overcast",
    "nineOktas": "overcast",
}
#: SceML writes rainy skies with this sun (lux or the older intensity) or less.
RAINY_SUN = 10000.0
CLOUD_STATES = {"free", "cloudy", "overcast", "rainy"}


def read_init(build: Build) -> list[scm.GraphElement]:
    """Apply the Init actions; returns the opaque nodes made for the ones SceML cannot hold."""
    actions = build.source.root.find("Storyboard/Init/Actions")
    kept: list[scm.GraphElement] = []
    for item in [] if actions is None else actions:
        if not isinstance(item.tag, str):
            continue
        if item.tag == "Private":
            actor = build.actor(item.get("entityRef"), item)
            for private in item.iterchildren("PrivateAction"):
                if not _private(build, actor, private):
                    kept.append(_keep(build, private, actor))
        elif item.tag == "GlobalAction" and item.find("EnvironmentAction") is not None:
            _environment(build, item.find("EnvironmentAction/Environment"))
        else:
            kept.append(_global(build, item))
    return kept


def _global(build: Build, element: etree._Element) -> scm.GraphElement:
    """An Init global action as its node (a traffic signal state, a parameter set) performed at
    the start, or an opaque node."""
    wrapper = etree.Element("Action", name=f"init_{element.sourceline}")
    wrapper.append(deepcopy(element))
    request = Request(wrapper, build.default_actor(), f"Init_{_global_word(element)}")
    made = map_action(build, request, Motion())
    if isinstance(made, str):
        return _keep(build, element, build.default_actor())
    build.flow(build.root, made)
    return made


def _global_word(element: etree._Element) -> str:
    """`TrafficSignalStateAction` for a GlobalAction holding one: the innermost element's tag."""
    inner = element
    while len(inner) and isinstance(inner[0].tag, str):
        inner = inner[0]
    return str(inner.tag)


def _keep(build: Build, element: etree._Element, actor: scm.Actor) -> scm.GraphElement:
    """An Init action as an opaque node performed at the start (wrapped as an Action)."""
    wrapper = etree.Element("Action", name=f"init_{element.sourceline}")
    wrapper.append(deepcopy(element))
    why = "an Init action SceML has no field for; performed at the start"
    node = opaque_node(build, wrapper, actor, f"Init_{actor.name}", why, build.where(element))
    build.flow(build.root, node)
    return node


def _private(build: Build, actor: scm.Actor, private: etree._Element) -> bool:
    """Apply a teleport, speed or controller action to the actor; False when it is something
    else."""
    if init_controller(build, actor, private):
        return True
    teleport = private.find("TeleportAction")
    if teleport is not None:
        start = place(build, teleport, initial=True)
        if start is None:
            return False
        actor.startPosition = start
        build.report.add("mapped", f"{actor.name}: start position", build.where(teleport))
        return True
    follow = private.find("RoutingAction/FollowTrajectoryAction")
    if follow is not None and actor.startPosition is None:
        return _starts_on_trajectory(build, actor, private, follow)
    if (
        private.find("LateralAction/LaneOffsetAction") is not None
        or private.find("AppearanceAction/LightStateAction") is not None
        or private.find("TrailerAction") is not None  # release 1.5's couplings
    ):
        return _from_the_start(build, actor, private)
    speed = private.find("LongitudinalAction/SpeedAction")
    if speed is not None and speed.find("SpeedActionTarget/RelativeTargetSpeed") is not None:
        return _relative_speed(build, actor, private, speed)
    target = None if speed is None else speed.find("SpeedActionTarget/AbsoluteTargetSpeed")
    if speed is None or target is None:
        return False
    dynamics = speed.find("SpeedActionDynamics")
    if (
        dynamics is not None
        and dynamics.get("dynamicsShape") != "step"
        and number(dynamics, "value", 0.0) != 0  # zero time or distance: a step after all
    ):
        return _gradual(build, actor, private, speed)
    if controls_speed(actor):
        return _after_the_controller(build, actor, private, speed)
    actor.initialSpeed = traced.value(number(target, "value"))
    build.report.add("mapped", f"{actor.name}: initial speed", build.where(speed))
    return True


def _relative_speed(
    build: Build, actor: scm.Actor, private: etree._Element, speed: etree._Element
) -> bool:
    """A step Init speed relative to another actor's Init speed (ALKS: the lead vehicle at the
    ego's speed): the initial speed it comes to, from that actor's, once it is known. A
    continuous one (it keeps tracking the other's speed), a gradual one or one before the
    other's speed is set is also a MatchSpeed right after the root."""
    target = speed.find("SpeedActionTarget/RelativeTargetSpeed")
    dynamics = speed.find("SpeedActionDynamics")
    other = build.actors.get(str(target.get("entityRef")).split("::")[-1])
    step = dynamics is None or (
        dynamics.get("dynamicsShape") == "step" or number(dynamics, "value", 0.0) == 0
    )
    known = other is not None and isinstance(other.initialSpeed, scm.Value)
    base = _speed_of(other) if known and other is not None else 0.0
    value = number(target, "value")
    factor = target.get("speedTargetValueType") == "factor"
    if known and step:
        # The speed it comes to, also when the action stays opaque (continuous): later
        # actions given in time (a lane change's duration) get their length from it
        # (`lane_change_crest`: 2 s at 19.5 m/s, not the default 30 m).
        build.init_speeds[str(actor.name)] = base * value if factor else base + value
    if other is None:
        return False
    continuous = target.get("continuous") == "true"
    if continuous or not step or not known:
        if continuous and known and step:
            # Players set it at the start as a step, then keep it: the initial speed, and a
            # MatchSpeed right after the root that keeps it.
            actor.initialSpeed = traced.value(base * value if factor else base + value)
        return _from_the_start(build, actor, private)
    actor.initialSpeed = traced.value(base * value if factor else base + value)
    build.report.add(
        "mapped",
        f"{actor.name}: initial speed {'×' if factor else '+'} {value:g} of {other.name}'s "
        f"({float(actor.initialSpeed.value):g} m/s)",
        build.where(speed),
    )
    return True


def _gradual(
    build: Build, actor: scm.Actor, private: etree._Element, speed: etree._Element
) -> bool:
    """A gradual Init speed change: a speed maneuver right after the root, as players run it
    (the actor starts at the speed it had, and reaches the target at the given rate)."""
    shape = speed.find("SpeedActionDynamics").get("dynamicsShape")
    return _speed_from_the_start(build, actor, private, speed, f"the Init speed change ({shape})")


def _after_the_controller(
    build: Build, actor: scm.Actor, private: etree._Element, speed: etree._Element
) -> bool:
    """An Init speed set after a controller took the actor's longitudinal domain: a speed
    maneuver right after the root, so that the export writes it after the activation again.

    Players' controllers take over at the speed the actor has when they are activated (esmini's
    interactive, ACC, ALKS and sloppy drivers read it then); as the initial speed it would be
    set before the activation, and the interactive driver of `cut-in_interactive` drove off at
    30 m/s where the original stands still."""
    return _speed_from_the_start(
        build, actor, private, speed, "the Init speed, set after its controller took over,"
    )


def _speed_from_the_start(
    build: Build, actor: scm.Actor, private: etree._Element, speed: etree._Element, what: str
) -> bool:
    name = str(actor.name)
    before = build.init_speeds.get(name, _speed_of(actor))
    motion = Motion(speed={name: before})
    made = _as_story_action(build, actor, private, f"Init_{name}_speed", motion)
    if isinstance(made, str):
        return False
    build.flow(build.root, made)
    build.init_speeds[name] = motion.speed[name]
    build.report.add(
        "guessed",
        f"{name}: {what} is {made.name} from the start, from {before:g} m/s "
        "(it is not the initial speed)",
        build.where(speed),
    )
    return True


def _starts_on_trajectory(
    build: Build, actor: scm.Actor, private: etree._Element, follow: etree._Element
) -> bool:
    """An Init trajectory of an actor that has no TeleportAction: players put the actor at the
    trajectory's first vertex, so that is its start, and the trajectory is a FollowTrajectory
    from the start (a file would otherwise lose the actor's start: SCEML-E002). A NURBS curve
    starts at its first control point (players clamp its knots)."""
    shape = follow.find(".//Trajectory/Shape")
    first = None
    if shape is not None:
        first = shape.find("Polyline/Vertex")
        first = shape.find("Nurbs/ControlPoint") if first is None else first
    start = None if first is None else place(build, first, initial=True)
    if start is None:
        return False
    actor.startPosition = start
    build.report.add(
        "mapped",
        f"{actor.name}: start position at the first point of its Init trajectory",
        build.where(first),
    )
    name = str(actor.name)
    motion = Motion(speed={name: build.init_speeds.get(name, _speed_of(actor))})
    made = _as_story_action(build, actor, private, f"Init_{name}_trajectory", motion)
    if isinstance(made, str):
        _keep(build, private, actor)  # the start is known; the trajectory stays as it was read
        return True
    if isinstance(made, scm.FollowTrajectory) and len(made.waypoints) > 1:
        made.waypoints.remove(made.waypoints[0])  # the start itself
        made.fromFirstWaypoint = False  # it begins where the actor starts: that point
    build.flow(build.root, made)
    return True


def _from_the_start(build: Build, actor: scm.Actor, private: etree._Element) -> bool:
    """An Init action that takes time (a lane offset, a light's transition): its node right
    after the root, as players run it from the start."""
    made = _as_story_action(
        build,
        actor,
        private,
        f"Init_{actor.name}",
        Motion(),
        f"Init_{actor.name}_{private.sourceline}",
    )
    if isinstance(made, str):
        return False
    build.flow(build.root, made)
    return True


def _as_story_action(
    build: Build,
    actor: scm.Actor,
    private: etree._Element,
    hint: str,
    motion: Motion,
    wrapper_name: str | None = None,
) -> scm.ActionNode | str:
    """An Init PrivateAction mapped as the storyboard action it would be (wrapped in an Action
    named `wrapper_name`, else `hint`): its node, or why it has none."""
    wrapper = etree.Element("Action", name=wrapper_name or hint)
    wrapper.append(deepcopy(private))
    return map_action(build, Request(wrapper, actor, hint), motion)


def _speed_of(actor: scm.Actor) -> float:
    held = actor.initialSpeed
    return float(held.value) if isinstance(held, scm.Value) else 0.0


def _environment(build: Build, element: etree._Element | None) -> None:
    if element is None:
        return
    environment = scm.Environment()
    time = element.find("TimeOfDay")
    if time is not None and "T" in str(time.get("dateTime", "")):
        environment.timeOfDay = str(time.get("dateTime")).split("T", 1)[1][:8]
    weather = element.find("Weather")
    if weather is not None:
        environment.cloudState = scm.CloudState.getEEnumLiteral(_cloud(weather))
        fog = weather.find("Fog")
        if fog is not None and fog.get("visualRange") is not None:
            environment.fogVisualRange = traced.value(number(fog, "visualRange"))
        rain = weather.find("Precipitation")
        if rain is not None:
            kind = rain.get("precipitationType", "dry")
            environment.precipitation = scm.PrecipitationType.getEEnumLiteral(
                kind if kind in ("dry", "rain", "snow") else "dry"
            )
            key = (
                "precipitationIntensity" if "precipitationIntensity" in rain.attrib else "intensity"
            )
            if rain.get(key) is not None:
                environment.precipitationIntensity = traced.value(number(rain, key))
    build.root.environment = environment
    build.report.add("mapped", "environment -> root", build.where(element))


def _cloud(weather: etree._Element) -> str:
    sun = weather.find("Sun")
    light = None if sun is None else sun.get("illuminance", sun.get("intensity"))
    state = weather.get("cloudState")
    if state is None:
        state = OKTAS.get(str(weather.get("fractionalCloudCover")), "free")
        if state == "overcast" and light is not None and float(light) <= RAINY_SUN:
            state = "rainy"
    return state if state in CLOUD_STATES else "overcast"
