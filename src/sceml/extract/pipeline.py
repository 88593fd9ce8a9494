"""From a recording to a concrete SceML scenario: smooth, segment, explain, build, replay."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np

import scemlmodel as scm

from ..errors import ArgumentError
from ..maps import RoadMap
from ..model.build import ScenarioBuilder
from ..validation.limits import Limits
from .actors import ActorSpec, actor_kind, start_position
from .assemble import Inferred, add_actor_graph
from .events import Event
from .lateral import path_events
from .longitudinal import (
    RateLimits,
    crossings_after_set_offs,
    drive_distances,
    end_by_crossings,
    speed_events,
    start_shift,
    within_limits,
)
from .motion import Motion, sample_step, smooth
from .recording import Recording, Track
from .replay import ReplayFit, replay
from .setoff import fit_set_offs
from .thresholds import Thresholds


@dataclass(frozen=True)
class ExtractedActor:
    """An actor as extracted: its kind, whether it is the ego, and its maneuvers in order."""

    name: str
    kind: str
    ego: bool
    initial_speed: float
    maneuvers: tuple[Event, ...]


@dataclass(frozen=True)
class Extraction:
    """The scenario extracted from a recording, with what was inferred and how well it replays."""

    scenario: scm.Scenario
    recording: Recording
    actors: tuple[ExtractedActor, ...]
    inferred: tuple[Inferred, ...]
    replay: ReplayFit | None
    thresholds: Thresholds
    notes: tuple[str, ...] = field(default=())


def extract(
    recording: Recording,
    road_map: RoadMap | None = None,
    *,
    map_reference: str | None = None,
    name: str = "Extracted",
    thresholds: Thresholds | None = None,
    actors: Sequence[ActorSpec] = (),
    ego: str | None = None,
    check_replay: bool = True,
    limits: Limits | None = None,
) -> Extraction:
    """Extract a concrete scenario from a recording driven on `road_map`.

    `map_reference` is the map as the scenario names it (a path relative to where the
    scenario will be saved); `actors` set kinds and sizes the recording lacks; `ego` names
    the ego (else the recording's, else the first actor). Rates are kept within `limits`
    (the plausibility limits validation applies). With `check_replay`, the scenario is run in
    the preview and compared with the recording.
    """
    thresholds = thresholds or Thresholds()
    limits = limits or Limits()
    given = {spec.name: spec for spec in actors}
    ego = _check_names(recording, given, ego)
    step = min(sample_step(t) for t in recording.tracks)
    motions = {t.name: smooth(t, thresholds, step) for t in recording.tracks}
    builder = ScenarioBuilder(
        name,
        map=map_reference,
        level="concrete",
        max_duration=math.ceil(recording.end - recording.start + 0.5),
        description=f"Extracted from {recording.source} ({recording.format}) by sceml extract.",
    )
    builder.environment()
    found: list[ExtractedActor] = []
    notes: list[str] = []
    models: dict[str, scm.Actor] = {}
    for track in recording.tracks:
        actor, model, said = _actor(
            builder,
            track,
            motions[track.name],
            given.get(track.name),
            ego,
            thresholds,
            limits,
            road_map,
        )
        found.append(actor)
        models[track.name] = model
        notes += said
    inferred: list[Inferred] = []
    speed_changes = {a.name: [e for e in a.maneuvers if e.longitudinal] for a in found}
    for actor in found:
        inferred += add_actor_graph(
            builder,
            models[actor.name],
            list(actor.maneuvers),
            motions,
            models,
            ego,
            thresholds,
            speed_changes,
        )
    if not builder.end.incoming:
        builder.flow(builder.root, builder.end)  # nobody did anything: the scenario is the start
    scenario = builder.scenario
    fit = replay(scenario, recording, road_map) if check_replay else None
    return Extraction(
        scenario, recording, tuple(found), tuple(inferred), fit, thresholds, tuple(notes)
    )


def _check_names(recording: Recording, given: dict[str, ActorSpec], ego: str | None) -> str:
    """The ego's name, after checking that every actor named by the caller is recorded."""
    names = [t.name for t in recording.tracks]
    unknown = sorted(set(given) - set(names))
    if ego is not None and ego not in names:
        unknown.append(ego)
    if unknown:
        raise ArgumentError(
            f"no actor {', '.join(unknown)} in the recording; it has {', '.join(names)}"
        )
    return ego or next((t.name for t in recording.tracks if t.ego), names[0])


def _actor(
    builder: ScenarioBuilder,
    track: Track,
    motion: Motion,
    spec: ActorSpec | None,
    ego: str,
    thresholds: Thresholds,
    limits: Limits,
    road_map: RoadMap | None,
) -> tuple[ExtractedActor, scm.Actor, list[str]]:
    """One actor: its kind, maneuvers, start and speed, added to the scenario; and notes."""
    kind = actor_kind(track, motion, spec, ego=track.name == ego)
    rates = RateLimits(
        limits.limit(kind, "max_acceleration"),
        limits.limit(kind, "max_deceleration"),
        thresholds.standing_speed,
    )
    speeds = speed_events(motion, thresholds, rates)
    notes = within_limits(
        speeds, kind, rates.acceleration, rates.deceleration, thresholds.standing_speed
    )
    events = sorted(speeds + path_events(motion, kind, thresholds, road_map), key=lambda e: e.start)
    drive_distances(events, motion)
    if motion.noisy:
        crossings_after_set_offs(events, thresholds.standing_speed, thresholds.smoothing_window)
    fit_set_offs(events, motion, thresholds, rates.acceleration)
    end_by_crossings(events)
    speed = _initial_speed(motion, events, thresholds.standing_speed)
    length = spec.length if spec and spec.length else track.length
    width = spec.width if spec and spec.width else track.width
    size = {k: v for k, v in (("length", length), ("width", width)) if v is not None}
    model = builder.actor(
        kind,
        track.name,
        ego=track.name == ego,
        start=start_position(motion, kind, road_map, start_shift(motion, events, speed)),
        speed=round(speed, 2),
        **cast(dict[str, Any], size),
    )
    return ExtractedActor(track.name, kind, track.name == ego, speed, tuple(events)), model, notes


def _initial_speed(motion: Motion, events: list[Event], standing: float) -> float:
    """The speed at the start: before a speed change that starts at once, 0 for an actor that
    stands (the smoothed speed of a standing actor is noise), else the median of its first
    second."""
    t0 = float(motion.times[0])
    for event in events:
        if event.longitudinal and event.start <= t0 + 1e-9 and event.from_speed is not None:
            return event.from_speed if event.from_speed > standing else 0.0
    if not motion.moving[0]:
        return 0.0
    # A steady speed up to the first speed change (or the end): the slope of the distance
    # driven, which noise moves far less than the first second's smoothed speed.
    changes = [e.start for e in events if e.longitudinal]
    last = motion.index(changes[0]) if changes else len(motion.times) - 1
    if last < 4:
        last = len(motion.times) - 1
    span = motion.times[: last + 1] - t0
    speed = float(np.polyfit(span, motion.along[: last + 1], 1)[0])
    return speed if speed > standing else 0.0
