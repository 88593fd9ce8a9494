"""Path changes: turns through junctions, lane changes, and crossings by people and bikes.

They are found where the heading (of the smoothed motion) turns faster than a threshold. What
the change was is told by how much the heading turned in the end and how far the actor moved
sideways: a lasting turn is TurnLeft or TurnRight (for people and bikes off a junction: Cross);
a sideways move with the heading back as before is a LaneChange.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..maps import RoadMap
from .events import Event
from .motion import Array, Motion
from .thresholds import Thresholds

#: Actor kinds whose lasting change of heading off a junction is a crossing.
CROSSERS = ("Pedestrian", "Bicycle")
#: A crossing needs only this change of heading (rad): a bike veers across the road.
_CROSS_ANGLE = 0.15
#: Below this speed (m/s) the heading is not judged (a chord of 0.8 m over a 1 s window).
_HEADING_SPEED = 0.8
#: Nor where the recording's noise moves it by more than this (rad, one standard deviation):
#: a third of a crossing's change, so that noise alone seldom makes one.
_HEADING_ERROR = _CROSS_ANGLE / 3


def path_events(
    motion: Motion, kind: str, thresholds: Thresholds, road_map: RoadMap | None
) -> list[Event]:
    """The actor's path changes in time order."""
    step = motion.step
    moving = motion.moving
    # Slower than this the heading of a noisy track is mostly noise: it is not judged there.
    judged = moving & (motion.speed > max(thresholds.standing_speed, _HEADING_SPEED))
    judged &= motion.heading_error <= _HEADING_ERROR
    turning = (np.abs(motion.turn_rate) > thresholds.yaw_rate) & judged
    settle = max(1, int(round(thresholds.smoothing_window / step / 2)))
    events: list[Event] = []
    for a, b in _runs(turning, gap=max(1, int(0.5 / step))):
        first, last = max(a - settle, 0), min(b + settle, len(motion.times) - 1)
        cut_off = b >= len(motion.times) - settle
        if cut_off and abs(_turned(motion, first, b, 2 * settle)) <= _CROSS_ANGLE:
            # The smoothing's last window extrapolates a cubic, whose heading wanders: a
            # walker going straight on to the end "bent" there by 0.09 rad, and its crossing
            # was ended at that bend, a metre short. A bend the recording ends in counts only
            # once the heading has turned by a crossing's angle.
            continue
        if (
            events
            and events[-1].kind == "Cross"
            and (cut_off or _along_lane(motion, last, road_map))
        ):
            # After a crossing the actor goes on along the lane it reached (docs/simulate.md):
            # this bend is where the crossing ended, not a maneuver. A bend the recording ends
            # in cannot be judged, but a crossing goes straight, so it ended there too. Later
            # such bends are the lane's own, which following it makes anyway.
            if events[-1].destination is None:
                _end_crossing(events[-1], motion, first, last)
            continue
        if cut_off:
            continue  # still turning when the recording ends (or the smoothing's edge)
        turned = _turned(motion, first, last, 2 * settle)
        if events and events[-1].kind == "LaneChange" and motion.times[first] < events[-1].end:
            continue  # the way back of a lane change already found (its heading swings twice)
        event = _classify(motion, kind, first, last, turned, thresholds, road_map)
        if event is not None:
            events.append(event)
    if kind == "Pedestrian" and not any(e.kind == "Cross" for e in events) and moving.any():
        events.append(_walk(motion, int(np.argmax(moving)), len(motion.times) - 1, thresholds))
    events = _one_crossing_at_a_time(events)
    _finish_destinations(motion, events, thresholds)
    return sorted(events, key=lambda e: e.start)


def _classify(
    motion: Motion,
    kind: str,
    first: int,
    last: int,
    turned: float,
    thresholds: Thresholds,
    road_map: RoadMap | None,
) -> Event | None:
    times = motion.times
    if (
        kind in CROSSERS
        and abs(turned) > _CROSS_ANGLE
        and not _in_junction(motion, first, last, road_map)
    ):
        middle = _midway(motion, first, last)
        tolerance: dict[str, object] = {"tolerance": thresholds.arrival_tolerance}
        return Event("Cross", motion.name, middle, middle, tolerance, turned=turned)
    if abs(turned) > thresholds.turn_angle:
        if road_map is not None and not _in_junction(motion, first, last, road_map, any_lane=True):
            return None  # a bend of the road, which following the lane already does
        side = "TurnLeft" if turned > 0 else "TurnRight"
        return Event(
            side,
            motion.name,
            float(times[first]),
            float(times[last]),
            {"tolerance": thresholds.arrival_tolerance},
            flexible=True,
        )
    return _lane_change(motion, first, last, thresholds)


def _turned(motion: Motion, first: int, last: int, span: int) -> float:
    """How far the heading turned from before `first` to after `last`: the medians over `span`
    samples either side, which noise moves less than single samples. Samples where the actor
    moves with a heading the noise leaves unsure (setting off slowly) are left out: those where
    it moves surely count, else those where it stands (its heading held); with neither on a
    side, nothing is known to have turned (0)."""
    sure = motion.moving & (motion.heading_error <= _HEADING_ERROR)
    usable = sure | ~motion.moving

    def median(lo: int, hi: int) -> float | None:
        values = motion.heading[lo:hi]
        for mask in (sure[lo:hi], usable[lo:hi]):
            if mask.any():
                return float(np.median(values[mask]))
        return None

    after = median(last, last + span + 1)
    before = median(max(first - span, 0), first + 1)
    if before is None:
        # An actor that set off with the recording has no sure heading before the change:
        # its first second is a slow set-off, whose chord the noise swings. Its heading is
        # then the one it first surely had, over the span after `first` (a bike that set off
        # at once and veered 0.21 rad across the road a second later had "turned" 0 and
        # crossed nowhere, 2.9 m off in the replay). Part of the change may fall in that span,
        # which only makes the turn smaller: it adds no change that was not there.
        before = median(first, min(first + span, last) + 1)
    return 0.0 if after is None or before is None else after - before


def _lane_change(motion: Motion, first: int, last: int, thresholds: Thresholds) -> Event | None:
    """A sideways move (against the heading before it) of at least the threshold, fitted as the
    half cosine over a distance that lane changes follow.

    Only the turning stretch and a smoothing window either side are looked at, so the start of
    a crossing or turn just after it does not count as sideways motion.
    """
    reach = max(1, int(round(thresholds.smoothing_window / motion.step)))
    # Sideways is judged against the heading before the change; but within the smoothing's
    # first half window that heading already shows the change (its chord reaches into it),
    # so there the heading after it is taken: a lane change ends heading as it began.
    # So is a heading the noise leaves unsure (an actor setting off, whose chord is short).
    if first >= reach // 2 and motion.heading_error[first] <= _HEADING_ERROR:
        h0 = float(motion.heading[first])
    else:
        h0 = float(np.median(motion.heading[last : last + reach + 1]))
    lo, hi = max(first - reach, 0), min(last + reach, len(motion.times) - 1)
    dx, dy = motion.x[lo : hi + 1] - motion.x[lo], motion.y[lo : hi + 1] - motion.y[lo]
    sideways = -dx * math.sin(h0) + dy * math.cos(h0)
    arc = motion.arc[lo : hi + 1]
    s1, length, shift = _fit_half_cosine(
        arc, sideways, float(motion.arc[first]), float(motion.arc[last])
    )
    if abs(shift) < thresholds.lane_change_offset or length < 3 * abs(shift):
        return None  # too little, or too abrupt for a lane change: noise
    t1 = float(np.interp(s1, motion.arc, motion.times))
    t2 = float(np.interp(s1 + length, motion.arc, motion.times))
    return Event(
        "LaneChange",
        motion.name,
        t1,
        t2,
        {"direction": "left" if shift > 0 else "right", "distance": round(length, 1)},
        finish=t2,
    )


def _fit_half_cosine(
    arc: Array, offset: Array, s_first: float, s_last: float
) -> tuple[float, float, float]:
    """(start, length, shift d) along the path of the half cosine c + d (1 - cos(pi w)) / 2
    that fits the sideways offset best; each candidate is a linear least-squares problem in
    (c, d)."""
    pad = max((s_last - s_first) / 2, 2.0)
    starts = np.arange(s_first - pad, s_first + pad, 0.25)
    lengths = np.arange(max(s_last - s_first - 2 * pad, 2.0), s_last - s_first + 2 * pad, 0.25)
    s1, length = (g.ravel() for g in np.meshgrid(starts, lengths, indexing="ij"))
    w = np.clip((arc[None, :] - s1[:, None]) / length[:, None], 0.0, 1.0)
    shape = (1 - np.cos(np.pi * w)) / 2
    n = arc.size
    sum_shape, sum_square = shape.sum(axis=1), (shape**2).sum(axis=1)
    sum_y, sum_shape_y = offset.sum(), shape @ offset
    determinant = n * sum_square - sum_shape**2
    d = (n * sum_shape_y - sum_shape * sum_y) / np.where(determinant == 0, 1, determinant)
    c = (sum_y - d * sum_shape) / n
    errors = ((c[:, None] + d[:, None] * shape - offset[None, :]) ** 2).sum(axis=1)
    best = int(np.argmin(errors))
    return float(s1[best]), float(length[best]), float(d[best])


#: A heading within this much (rad) of a lane's direction goes along the lane.
_ALONG_LANE = 0.15


def _along_lane(motion: Motion, last: int, road_map: RoadMap | None) -> bool:
    """Whether the actor goes along (or against) the lane under it after sample `last`."""
    if road_map is None:
        return False
    k = min(last, len(motion.times) - 1)
    heading = float(np.median(motion.heading[k:])) if k < len(motion.times) - 1 else None
    heading = float(motion.heading[-1]) if heading is None else heading
    for lane in road_map.world_to_lane(float(motion.x[k]), float(motion.y[k]), tolerance=1.0):
        traffic = road_map.traffic_heading(lane.road_id, lane.lane_id, lane.s)
        off = abs((heading - traffic + math.pi / 2) % math.pi - math.pi / 2)
        if off < _ALONG_LANE:
            return True
    return False


def _end_crossing(crossing: Event, motion: Motion, first: int, last: int) -> None:
    """Put a crossing's destination where the actor turned onto its lane.

    A crossing goes straight to its destination, where the actor turns onto the lane at once.
    The corner is where the straight line got to at the moment of the bend: the smoothing
    rounds the corner, so it is extrapolated from before the bend by the distance driven.
    """
    corner_time = _midway(motion, first, last)
    heading = float(motion.heading[first])
    run = motion.at(motion.arc, corner_time) - float(motion.arc[first])
    x = float(motion.x[first]) + run * math.cos(heading)
    y = float(motion.y[first]) + run * math.sin(heading)
    crossing.destination = (x, y, heading)


def _one_crossing_at_a_time(events: list[Event]) -> list[Event]:
    """Of crossings that follow each other with no other path change between, keep the one
    that bent most: a crossing goes straight to its destination, so the other bends are noise."""
    kept: list[Event] = []
    for event in sorted(events, key=lambda e: e.start):
        if event.kind == "Cross" and kept and kept[-1].kind == "Cross":
            if abs(event.turned) > abs(kept[-1].turned):
                kept[-1] = event
            continue
        kept.append(event)
    return kept


def _walk(motion: Motion, first: int, last: int, thresholds: Thresholds) -> Event:
    """A pedestrian that walks off without turning: a crossing from its first step."""
    start = float(motion.times[first])
    return Event(
        "Cross",
        motion.name,
        start,
        start,
        {"tolerance": thresholds.arrival_tolerance},
        flexible=True,
    )


def _midway(motion: Motion, first: int, last: int) -> float:
    """When the heading was halfway between its values before and after a quick change: the
    moment a sharp turn happened, which the smoothing spreads over its window."""
    before, after = motion.heading[first], motion.heading[last]
    middle = (before + after) / 2
    span = motion.heading[first : last + 1]
    crossed = np.nonzero((span - middle) * np.sign(after - before) >= 0)[0]
    k = first + int(crossed[0]) if len(crossed) else (first + last) // 2
    return float(motion.times[k])


def _in_junction(
    motion: Motion, first: int, last: int, road_map: RoadMap | None, *, any_lane: bool = False
) -> bool:
    """Whether the middle of a change lies in a junction: on junction roads only, or (with
    `any_lane`) on at least one, as a turn does where the junction's roads overlap the arms."""
    if road_map is None:
        return False
    k = (first + last) // 2
    found = road_map.world_to_lane(float(motion.x[k]), float(motion.y[k]), tolerance=1.0)
    inside = [road_map.road(c.road_id).junction != "-1" for c in found]
    return bool(found) and (any(inside) if any_lane else all(inside))


def _finish_destinations(motion: Motion, events: list[Event], thresholds: Thresholds) -> None:
    """Give turns and crossings a destination and the time they will finish in a replay.

    A turn ends a little past where its heading settled; a crossing where it stops going
    straight: at the next change of path, where it stops, or where the recording ends.
    """
    events.sort(key=lambda e: e.start)
    tolerance = thresholds.arrival_tolerance
    for i, event in enumerate(events):
        if event.kind not in ("TurnLeft", "TurnRight", "Cross"):
            continue
        if event.destination is None:  # not yet ended by a turn onto a lane
            if event.kind == "Cross":
                later = [e.start for e in events[i + 1 :]]
                end = _last_moving(motion, event.start, later[0] if later else None, thresholds)
            else:
                end_arc = motion.at(motion.arc, event.end) + thresholds.turn_settle
                end = float(np.interp(end_arc, motion.arc, motion.times))
            x, y = motion.position(end)
            event.destination = (x, y, motion.at(motion.heading, end))
        x, y, _ = event.destination
        event.end = max(event.end, event.start)
        event.finish = _arrival(motion, event.start, x, y, tolerance)


def _last_moving(
    motion: Motion, start: float, until: float | None, thresholds: Thresholds
) -> float:
    k0 = motion.index(start)
    k1 = motion.index(until) if until is not None else len(motion.times) - 1
    moving = np.nonzero(motion.moving[k0 : k1 + 1])[0]
    return float(motion.times[k0 + int(moving[-1])]) if len(moving) else float(motion.times[k1])


def _arrival(motion: Motion, start: float, x: float, y: float, tolerance: float) -> float:
    """The first time from `start` the actor is within `tolerance` of (x, y)."""
    k0 = motion.index(start)
    near = np.nonzero(np.hypot(motion.x[k0:] - x, motion.y[k0:] - y) <= tolerance)[0]
    return float(motion.times[k0 + int(near[0])]) if len(near) else float(motion.times[-1])


def _runs(mask: NDArray[np.bool_], gap: int) -> list[tuple[int, int]]:
    """Index spans [a, b] where mask holds, joining runs apart by at most `gap` samples."""
    spans: list[tuple[int, int]] = []
    k, n = 0, len(mask)
    while k < n:
        if not mask[k]:
            k += 1
            continue
        a = k
        while k < n and mask[k]:
            k += 1
        if spans and a - spans[-1][1] <= gap:
            spans[-1] = (spans[-1][0], k - 1)
        else:
            spans.append((a, k - 1))
    return spans
