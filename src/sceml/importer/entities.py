"""Entities to actors: the kind from the vehicle or pedestrian category, the ego, the box."""

from __future__ import annotations

import re

from lxml import etree

import scemlmodel as scm

from ..model import catalog
from . import traced
from .catalog_entries import keep_catalog_entry
from .context import Build
from .controllers import object_controller
from .performance import keep_performance, read_performance
from .positions import number
from .unplaced import is_referenced, is_sumo_template

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
        if is_sumo_template(item) and not is_referenced(build, str(item.get("name"))):
            _sumo_template(build, item)
            continue
        _add(build, item, str(item.get("name")))
    _link_trailers(build)
    if not build.actors:
        raise build.source.error("the file declares no vehicle or pedestrian entity", entities)
    _choose_ego(build)


def _sumo_template(build: Build, item: etree._Element) -> None:
    """esmini never places a SUMO controller's template entity (SUMO adds its vehicles): no
    actor, so no actor without a start; SceML has no co-simulated traffic to keep it in."""
    build.report.add(
        "not represented",
        f"entity {item.get('name')!r}: the template of the vehicles its SUMO controller adds "
        "from the SUMO configuration; esmini never places it itself, and SceML has no "
        "co-simulated traffic (the export runs without SUMO's vehicles)",
        build.where(item),
    )


def _add(build: Build, item: etree._Element, name: str) -> scm.Actor | None:
    """The actor of a ScenarioObject (or of a trailer written in place), with its own trailer."""
    actor = _actor(build, item, name)
    if actor is None:
        return None
    build.root.actors.append(actor)
    build.actors[name] = actor
    body = next((c for c in item if isinstance(c.tag, str) and c.tag == "Vehicle"), None)
    if body is not None:
        _coupling(build, actor, body)
    return actor


def _coupling(build: Build, actor: scm.Actor, body: etree._Element) -> None:
    """A vehicle's TrailerHitch and TrailerCoupler offsets and the Trailer it tows (1.3).

    A trailer written in place (a ScenarioObject inside Trailer, or a catalog entry copied
    there) becomes an actor of its own named as esmini names it, its tower's name and a `+`
    (`Truck+`, and its own trailer `Truck++`); it has no start: it starts at the hitch. A
    TrailerRef is linked once every entity is read; an empty one (a catalog's default) tows
    nothing."""
    for tag, feature in (("TrailerHitch", "hitchX"), ("TrailerCoupler", "couplerX")):
        element = body.find(tag)
        if element is not None and element.get("dx") is not None:
            actor.eSet(feature, traced.value(number(element, "dx")))
    trailer = body.find("Trailer")
    if trailer is None:
        return
    reference = trailer.find("TrailerRef")
    if reference is not None:
        named = str(reference.get("entityRef") or "")
        if named:
            _needs_trailers(build, trailer)
            build.trailer_refs.append((actor, named, trailer))
        return
    inline = trailer.find("Trailer")
    if inline is not None:
        _needs_trailers(build, trailer)
        towed = _add(build, inline, f"{actor.name}+")
        if towed is not None:
            actor.trailer = towed
            build.report.add(
                "mapped",
                f"entity {actor.name!r} tows {towed.name!r} (a trailer written in place)",
                build.where(inline),
            )


def _needs_trailers(build: Build, trailer: etree._Element) -> None:
    """Trailers are OpenSCENARIO 1.3: a file of an earlier version that has them (esmini reads
    them in any) can only be exported back as 1.3."""
    if build.report.version < "1.3":
        build.report.needs_version = "1.3"
        build.report.add(
            "guessed",
            f"a trailer in an OpenSCENARIO {build.report.version} file (trailers are 1.3): its "
            "export needs 1.3",
            build.where(trailer),
        )


def _link_trailers(build: Build) -> None:
    for actor, named, element in build.trailer_refs:
        towed = build.actors.get(named)
        if towed is None or towed is actor:
            build.report.add(
                "not represented",
                f"entity {actor.name!r}: its trailer {named!r} is no other vehicle of the file",
                build.where(element),
            )
            continue
        actor.trailer = towed
        build.report.add("mapped", f"entity {actor.name!r} tows {named!r}", build.where(element))


def _actor(build: Build, item: etree._Element, name: str) -> scm.Actor | None:
    body = next((c for c in item if isinstance(c.tag, str) and c.tag != "ObjectController"), None)
    if body is not None and body.tag == "Vehicle":
        category = str(body.get("vehicleCategory"))
        kind, guessed = VEHICLE_KINDS.get(category, ("Car", True))
        if category in ("trailer", "semitrailer"):
            build.trailer_entities.add(name)
        if guessed:
            build.report.add(
                "guessed",
                f"entity {name!r}: vehicleCategory {category} as {kind}",
                build.where(body),
            )
        model = body.get("name")
        actor = _make(kind, name, None if model == category else model)
        own = read_performance(body)
        if body.find("Performance") is not None:
            build.performance[name] = (
                float(own.max_acceleration or 0.0),
                float(own.max_deceleration or 0.0),
            )
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
    if body.tag == "Vehicle":
        keep_performance(build, actor, body)
        keep_catalog_entry(build, actor, body)
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
        vehicles = [
            a
            for a in actors
            if not isinstance(a, scm.Pedestrian) and str(a.name) not in build.trailer_entities
        ]
        chosen, why = (vehicles or actors)[0], "the first vehicle (no ego property or ego name)"
    chosen.isEgo = True
    build.ego = chosen
    build.report.add("guessed", f"ego: {chosen.name!r}, {why}")
