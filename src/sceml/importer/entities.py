"""Entities to actors: the kind from the vehicle or pedestrian category, the ego, the box."""

from __future__ import annotations

import re

from lxml import etree

import scemlmodel as scm

from ..model import catalog
from . import traced
from .context import Build
from .controllers import object_controller
from .positions import number

#: OpenSCENARIO vehicleCategory -> SceML actor kind (and whether that is a guess).
VEHICLE_KINDS = {
    "car": ("Car", False),
    "van": ("Van", False),
    "truck": ("Truck", False),
    "bus": ("Bus", False),
    "motorbike": ("Motorcycle", False),
    "bicycle": ("Bicycle", False),
    "trailer": ("Truck", True),
    "semitrailer": ("Truck", True),
    "tram": ("Bus", True),
    "train": ("Bus", True),
}
#: Names people give the vehicle under test.
EGO_NAME = re.compile(r"^(ego|hero)(\b|_|$)|(\b|_)(ego|hero)$", re.IGNORECASE)


def read_entities(build: Build) -> None:
    """One actor per ScenarioObject that is a Vehicle or Pedestrian; then choose the ego."""
    entities = build.source.root.find("Entities")
    for item in [] if entities is None else entities:
        if not isinstance(item.tag, str):
            continue
        if item.tag != "ScenarioObject":
            build.report.add(
                "not represented", f"<{item.tag} name={item.get('name')!r}>", build.where(item)
            )
            continue
        actor = _actor(build, item)
        if actor is not None:
            build.root.actors.append(actor)
            build.actors[str(item.get("name"))] = actor
    if not build.actors:
        raise build.source.error("the file declares no vehicle or pedestrian entity", entities)
    _choose_ego(build)


def _actor(build: Build, item: etree._Element) -> scm.Actor | None:
    name = str(item.get("name"))
    body = next((c for c in item if isinstance(c.tag, str) and c.tag != "ObjectController"), None)
    if body is not None and body.tag == "Vehicle":
        category = str(body.get("vehicleCategory"))
        kind, guessed = VEHICLE_KINDS.get(category, ("Car", True))
        if guessed:
            build.report.add(
                "guessed",
                f"entity {name!r}: vehicleCategory {category} as {kind}",
                build.where(body),
            )
        model = body.get("name")
        actor = _make(kind, name, None if model == category else model)
        limits = body.find("Performance")
        if limits is not None:
            rates = (number(limits, "maxAcceleration", 0.0), number(limits, "maxDeceleration", 0.0))
            build.performance[name] = (float(rates[0]), float(rates[1]))
    elif body is not None and body.tag == "Pedestrian":
        category = str(body.get("pedestrianCategory"))
        if category != "pedestrian":
            build.report.add(
                "guessed",
                f"entity {name!r}: pedestrianCategory {category} as Pedestrian",
                build.where(body),
            )
        model = body.get("model") or body.get("name")
        actor = _make("Pedestrian", name, None if model == "pedestrian" else model)
    elif body is not None and body.tag == "MiscObject":
        actor = _misc_object(build, name, body)
    else:
        what = body.tag if body is not None else "nothing"
        build.report.add(
            "not represented",
            f"entity {name!r} is a {what}, not a vehicle or pedestrian (no SceML actor kind)",
            build.where(item),
        )
        return None
    _dimensions(actor, body)
    if _is_marked_ego(body):
        actor.isEgo = True
    build.report.add("mapped", f"entity {name!r} -> {actor.eClass.name}", build.where(item))
    object_controller(build, actor, item)
    return actor


def _misc_object(build: Build, name: str, body: etree._Element) -> scm.Actor:
    """A MiscObject (obstacle, pole, barrier...) as a Car of its own size.

    SceML has no kind for objects that are not road users; a Car with the object's bounding
    box is the actor a player places and draws most like it (it does not move unless told to).
    The original category stays in the report.
    """
    category = str(body.get("miscObjectCategory"))
    build.report.add(
        "guessed",
        f"entity {name!r}: MiscObject of category {category} as a Car of its size (SceML has "
        "no MiscObject kind)",
        build.where(body),
    )
    model = body.get("name")
    return _make("Car", name, None if model == category else model)


def _make(kind: str, name: str, model: str | None) -> scm.Actor:
    actor: scm.Actor = getattr(scm, kind)(name=name)
    actor.model = model
    return actor


def _dimensions(actor: scm.Actor, body: etree._Element) -> None:
    """The bounding box, where it differs from the kind's default (else left to the default)."""
    box = body.find("BoundingBox/Dimensions")
    if box is None:
        return
    defaults = catalog.actor_dimensions(actor)
    for feature in ("length", "width", "height"):
        text = box.get(feature)
        if text is None:
            continue
        value = number(box, feature)
        if value > 0 and abs(value - defaults.get(feature, -1.0)) > 1e-9:
            actor.eSet(feature, traced.value(value))
    _box_center(actor, body)


def _box_center(actor: scm.Actor, body: etree._Element) -> None:
    """Where the box's centre lies ahead of the reference point (BoundingBox/Center x), kept
    where it is not 0: the original's positions mean that point, and a re-export that put it
    at the centre would move every start, stop and radius by as much (ALKS: the Ego 1.25 m on)."""
    center = body.find("BoundingBox/Center")
    if center is None or center.get("x") is None:
        return
    value = number(center, "x")
    if value != 0:
        actor.boxCenterX = traced.value(value)


def _is_marked_ego(body: etree._Element) -> bool:
    return any(
        p.get("name") == "type" and p.get("value") == "ego_vehicle"
        for p in body.iterfind("Properties/Property")
    )


def _choose_ego(build: Build) -> None:
    actors = list(build.actors.values())
    marked = [a for a in actors if a.isEgo]
    if marked:
        for extra in marked[1:]:
            extra.isEgo = False
        build.ego = marked[0]
        return
    named = [a for a in actors if EGO_NAME.search(str(a.name))]
    if named:
        chosen, why = named[0], "by its name"
    else:
        vehicles = [a for a in actors if not isinstance(a, scm.Pedestrian)]
        chosen, why = (vehicles or actors)[0], "the first vehicle (no ego property or ego name)"
    chosen.isEgo = True
    build.ego = chosen
    build.report.add("guessed", f"ego: {chosen.name!r}, {why}")
