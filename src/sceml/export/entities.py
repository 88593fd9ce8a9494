"""Entities and Init: inline Vehicle/Pedestrian objects, their controllers, start positions,
initial speeds and controller activations."""

from __future__ import annotations

from typing import Any

import scemlmodel as scm

from ..model.kind_performance import PERFORMANCE_FEATURES, VEHICLE_CATEGORIES

# The kinds' tables moved below the export (release 1.5: validation compares catalog entries
# with them); named here too for the modules that read them as the export's.
from ..model.kind_performance import own_performance as own_performance
from ..model.kind_performance import performance_of as performance_of
from ..model.towing import is_towed
from .catalog_refs import reference_for
from .context import Context
from .controllers import init_activation, object_controller
from .values import number

PEDESTRIAN_MASS = "80.0"


def entity(ctx: Context, actor: scm.Actor) -> dict[str, Any]:
    """The ScenarioObject of an actor: an inline Vehicle or Pedestrian."""
    name = ctx.entity(actor)
    kind = actor.eClass.name
    length, width, height = (ctx.values.raw(actor, f) for f in ("length", "width", "height"))
    bbox = {
        # The reference point is where SceML positions are: the box's centre unless the actor
        # says its centre lies ahead of it (boxCenterX, from an imported Center x).
        "x": ctx.values.text(actor, "boxCenterX"),
        "z": number(round(height / 2, 6)),
        "length": ctx.values.text(actor, "length"),
        "width": ctx.values.text(actor, "width"),
        "height": ctx.values.text(actor, "height"),
    }
    properties = [("type", "ego_vehicle")] if actor.isEgo else []
    if kind == "Pedestrian":
        model = actor.model or "pedestrian"
        return {
            "name": name,
            "object": "pedestrian",
            "controller": object_controller(ctx, actor),
            "model": model,
            "model_name": model,
            "mass": PEDESTRIAN_MASS,
            "bbox": bbox,
            "properties": properties,
            "reference": None,  # a pedestrian catalog is not kept (release 1.5: vehicles)
        }
    category = VEHICLE_CATEGORIES[kind]
    wheel = (
        0.7
        if category in ("bicycle", "motorbike")
        else 0.8
        if category in ("truck", "bus")
        else 0.6
    )
    track = 0.0 if category in ("bicycle", "motorbike") else round(width * 0.85, 6)
    written = {
        "name": name,
        "object": "vehicle",
        "controller": object_controller(ctx, actor),
        # CARLA takes the blueprint from the Vehicle name; others read it as a label.
        "model_name": actor.model or category,
        "category": category,
        "bbox": bbox,
        "performance": performance(ctx, actor),
        "front_axle": _axle(0.5, wheel, track, round(length * 0.6, 6)),
        "rear_axle": _axle(0.0, wheel, track, 0.0),
        **_coupling(ctx, actor),
        "properties": properties,
    }
    written["reference"] = reference_for(ctx, actor, written)
    return written


def _coupling(ctx: Context, actor: scm.Actor) -> dict[str, Any]:
    """TrailerHitch, TrailerCoupler and Trailer (1.3; SCEML-E008 refuses earlier versions).

    A towed actor without a start of its own is written in place, inside its tower's Trailer,
    as the files that have such trailers write them (players place it at the hitch and name it
    after its tower, `Truck+`); one with a start is its own ScenarioObject, named by TrailerRef."""
    towed = actor.trailer
    trailer = None
    if towed is not None:
        inline = entity(ctx, towed) if written_in_place(towed) else None
        trailer = {"inline": inline, "ref": ctx.entity(towed)}
    return {
        "hitch": _offset(ctx, actor, "hitchX"),
        "coupler": _offset(ctx, actor, "couplerX"),
        "trailer": trailer,
    }


def _offset(ctx: Context, actor: scm.Actor, feature: str) -> str | None:
    """A hitch or coupler offset where the actor sets one (else no element at all). Before 1.3
    there is none to write: with nothing towed (SCEML-E008 refuses a trailer there) a hitch
    means nothing, as esmini's catalog cars, which all have one, show."""
    if actor.eGet(feature) is None or ctx.traits.rev_minor < 3:
        return None
    return ctx.values.text(actor, feature)


def towed_first(actors: list[scm.Actor]) -> list[scm.Actor]:
    """The actors in order, but each towed one before its tower: esmini resolves a TrailerRef
    as it reads the entities ("Failed to find object" when the trailer comes later)."""
    ordered: list[scm.Actor] = []

    def put(actor: scm.Actor, chain: tuple[scm.Actor, ...]) -> None:
        if actor in ordered or actor in chain:
            return  # placed already, or a towing loop (SCEML-A009 refuses the export)
        towed = actor.trailer
        if towed is not None and towed in actors:
            put(towed, (*chain, actor))
        ordered.append(actor)

    for actor in actors:
        put(actor, ())
    return ordered


def written_in_place(actor: scm.Actor) -> bool:
    """Whether an actor is written inside its tower's Trailer, not as a ScenarioObject of its
    own: it is towed and has no start (it starts at the hitch), so it has no Init either."""
    return actor.startPosition is None and is_towed(actor)


def performance(ctx: Context, actor: scm.Actor) -> dict[str, str]:
    """The actor's limits as OpenSCENARIO attributes (maxSpeed, maxAcceleration, maxDeceleration):
    the Vehicle's Performance, each the actor's own where it states one (as a `$parameter`
    where the hook names it), its kind's otherwise."""
    defaults = performance_of(actor.eClass.name)
    return {
        feature: ctx.values.text(actor, feature) if actor.eGet(feature) is not None else number(d)
        for feature, d in zip(PERFORMANCE_FEATURES, defaults, strict=True)
    }


def _axle(steering: float, wheel: float, track: float, position_x: float) -> dict[str, str]:
    return {
        "maxSteering": number(steering),
        "wheelDiameter": number(wheel),
        "trackWidth": number(track),
        "positionX": number(position_x),
        "positionZ": number(wheel / 2),
    }


def init_actions(ctx: Context, actor: scm.Actor) -> dict[str, Any]:
    """The Private init block of an actor: teleport to the start, its initial speed, then the
    domains of its controller switched at the start."""
    return {
        "entity": ctx.entity(actor),
        "position": ctx.position(actor.startPosition),
        "speed": ctx.values.text(actor, "initialSpeed"),
        "activation": init_activation(ctx, actor),
    }
