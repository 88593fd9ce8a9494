"""What each maneuver kind does to its actor, and when it has finished (SPEC §3).

One class per kind, registered by metaclass name. `start` is called when the node is activated;
`done` after every step (and at once) until it returns True. A maneuver *claims* the parts of
its actor it controls (`speed`, `path`); a later maneuver claiming the same part supersedes it.
What each kind does and when it finishes is `xosc.meaning`, which the export also follows:
speed changes when the target speed is reached, routed and trajectory maneuvers on arrival within
their tolerance, DriveDistance when the distance is driven from the node's start (after
distance / speed seconds), Follow when the gap is first reached (it keeps following afterwards),
Approach when it is held, Overtake when the lane change back is done.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from pyecore.ecore import EObject

import scemlmodel as scm

from ..export.entities import performance_of
from ..maps import RoadMap
from ..model import speed_shapes
from ..model.params import concrete
from ..model.towing import Coupling
from ..xosc import meaning
from . import lanes, trailers
from .actors import Actor, GapKeeping, GapSpec, Hold, Ramp, ShapedRamp, Shift, SpeedMatching
from .paths import LaneSpot, Path, joined, straight
from .world import World

#: A lane change where the map names no lane beside the actor moves it this far.
DEFAULT_LANE_WIDTH = 3.5  # m
#: A path to a destination off the lanes goes on this far past it, straight.
_BEYOND = 1.0


class Behaviour:
    """A running maneuver; subclasses implement `start` and `done`. `claims` are the parts of
    the actor it controls (`xosc.meaning.controls`)."""

    def __init__(self, node: EObject, world: World) -> None:
        self.node = node
        self.name = str(node.name)
        self.actor: Actor = world.actor(node.referenceActor, self.name)
        self.claims = meaning.controls(node.eClass.name)
        #: When the node started (the instant its trigger held), which is a step before the
        #: maneuver acts when it waits for the next step; set by the engine before `start`.
        self.started_at: float | None = None

    def start(self, world: World) -> None:
        """Take control of the actor."""

    def done(self, world: World) -> bool:
        """Whether the goal is reached."""
        return True

    def release(self, world: World) -> None:
        """Give control back when the maneuver is superseded (the actor keeps its speed)."""


_KINDS: dict[str, type[Behaviour]] = {}


def kind(*names: str) -> Callable[[type[Behaviour]], type[Behaviour]]:
    def register(cls: type[Behaviour]) -> type[Behaviour]:
        for name in names:
            _KINDS[name] = cls
        return cls

    return register


def behaviour_for(node: EObject, world: World) -> Behaviour | None:
    """The behaviour of a maneuver node; None for a kind the preview does not know."""
    cls = _KINDS.get(node.eClass.name)
    return cls(node, world) if cls is not None else None


# --- longitudinal ---------------------------------------------------------------------------


def step_speed(actor: Actor, speed: float) -> None:
    """A step change of speed: it holds from this instant (the export's step SpeedAction)."""
    actor.speed = speed
    actor.control = Ramp(speed)


@kind("Accelerate", "Decelerate", "Stop")
class SpeedChange(Behaviour):
    """Change the speed to `targetSpeed` (Stop: to 0) in its shape: linearly at `rate`, at
    once (step), or along a cubic or sinusoidal curve whose peak rate is `rate`."""

    def start(self, world: World) -> None:
        stop = isinstance(self.node, scm.Stop)
        self.target = 0.0 if stop else concrete(self.node, "targetSpeed")
        shape, rate = self.node.shape.name, concrete(self.node, "rate")
        if shape == "step":
            step_speed(self.actor, self.target)
        elif shape == "linear":
            self.actor.control = Ramp(self.target, rate)
        else:
            start = self.actor.speed
            seconds = speed_shapes.duration(shape, start, self.target, rate)
            self.actor.control = ShapedRamp(shape, start, self.target, seconds)

    def done(self, world: World) -> bool:
        return abs(self.actor.speed - self.target) < meaning.SPEED_TOLERANCE


@kind("KeepVelocity")
class KeepVelocity(Behaviour):
    """Hold the speed the actor has for `duration` seconds (it ends a running Follow)."""

    def start(self, world: World) -> None:
        self.actor.control = Hold()
        self.until = world.t + concrete(self.node, "duration")

    def done(self, world: World) -> bool:
        return world.t >= self.until - 1e-9


@kind("DriveDistance")
class DriveDistance(Behaviour):
    """Step to `speed` and drive `distance` metres from the node's start: distance / speed s."""

    def start(self, world: World) -> None:
        speed = concrete(self.node, "speed")
        step_speed(self.actor, speed)
        duration = meaning.drive_distance_duration(concrete(self.node, "distance"), speed)
        self.until = world.t + duration

    def done(self, world: World) -> bool:
        return world.t >= self.until - 1e-9


@kind("Follow", "Approach")
class GapManeuver(Behaviour):
    """Close up to the gap behind (or ahead of) the target; Follow keeps the gap afterwards,
    Approach holds its speed once the gap is held (`xosc.meaning`)."""

    def start(self, world: World) -> None:
        node = self.node
        self.lead = world.actor(node.targetActor, self.name)
        timed = node.timeGap is not None
        self.spec = GapSpec(
            concrete(node, "timeGap" if timed else "distance"),
            time_gap=timed,
            freespace=bool(node.freespace),
            leading=node.displacement.name == "leading",
        )
        self.follow = isinstance(node, scm.Follow)
        hold = None if self.follow else meaning.APPROACH_HOLD
        limits = _gap_limits(node, self.actor)
        self.actor.control = GapKeeping(self.lead.name, self.spec, limits, hold)

    def done(self, world: World) -> bool:
        # The export's finish marker: the gap's size, or the headway for a time gap.
        gap = abs(self.spec.measured(self.actor, self.lead))
        if self.spec.time_gap:
            gap = math.inf if self.actor.speed <= 0 else gap / self.actor.speed
            if self.follow:
                return gap < self.spec.value + meaning.follow_time_slack(self.spec.value)
            return abs(gap - self.spec.value) < meaning.APPROACH_REACHED_TIME
        if self.follow:
            return meaning.follow_reached(gap, self.spec.value)
        return meaning.approach_reached(gap, self.spec.value)


def _gap_limits(node: EObject, actor: Actor) -> meaning.GapLimits:
    """The limits the export writes to the LongitudinalDistanceAction (the node's, else the
    actor's within the gap-keeping limits), held to the actor's performance as players hold
    DynamicConstraints to the Vehicle's."""
    own = actor.own_limits
    stated = (own.max_speed, own.max_acceleration, own.max_deceleration)
    performance = tuple(
        mine if mine is not None else d
        for mine, d in zip(stated, performance_of(actor.kind), strict=True)
    )
    fallback = meaning.gap_limits(*performance)

    def limit(feature: str, default: float, ceiling: float = math.inf) -> float:
        return default if node.eGet(feature) is None else min(concrete(node, feature), ceiling)

    return meaning.GapLimits(
        limit("maxAcceleration", fallback.acceleration, performance[1]),
        limit("maxDeceleration", fallback.deceleration, performance[2]),
        limit("maxSpeed", fallback.max_speed, performance[0]),
        limit("maxAccelerationRate", math.inf),
        limit("maxDecelerationRate", math.inf),
    )


# --- lateral --------------------------------------------------------------------------------


#: How many lanes a search for a lane by id or by another actor's lane walks at most.
_LANE_SEARCH = 12


def _walk(
    road_map: RoadMap, spot: LaneSpot, side: str, count: int
) -> tuple[LaneSpot, float] | None:
    """`count` lanes to the `side` of `spot` and how far left of it their centre lies."""
    total = 0.0
    for _ in range(count):
        beside = lanes.neighbour(road_map, spot, side)
        if beside is None:
            return None
        spot, total = beside[0], total + beside[1]
    return spot, total


def _to_lane(road_map: RoadMap, spot: LaneSpot, lane: int) -> tuple[LaneSpot, float] | None:
    """The lane of id `lane` on the road of `spot`, found beside it on either side."""
    if spot.lane == lane:
        return spot, 0.0
    for side in ("left", "right"):
        here, total = spot, 0.0
        for _ in range(_LANE_SEARCH):
            beside = lanes.neighbour(road_map, here, side)
            if beside is None:
                break
            here, total = beside[0], total + beside[1]
            if here.lane == lane:
                return here, total
    return None


class LaneShift:
    """One lane change of an actor: the lateral profile, then the path on the new lane.

    `count` lanes to `side` of the actor's lane, or of `toward`'s lane (another actor's), or
    into the absolute lane `lane`; `offset` m left of that lane's centre at the end (as an
    OpenSCENARIO LaneChangeAction's targetLaneOffset), or, with None, as far off the centre as
    the actor was before."""

    def __init__(
        self,
        world: World,
        actor: Actor,
        side: str,
        distance: float,
        what: str,
        *,
        count: int = 1,
        toward: Actor | None = None,
        lane: int | None = None,
        offset: float | None = None,
    ) -> None:
        self.actor = actor
        spot = actor.path.spot(actor.d)
        found = None
        if world.road_map is not None and spot is not None:
            found = self._find(world.road_map, spot, side, count, toward, lane)
        self.target = found[0] if found is not None else None
        if found is not None:
            amount = found[1]
        else:
            amount = self._without_map(side, count, toward)
            wanted = f"lane {lane}" if lane is not None else f"{count} lane(s) on the {side}"
            world.note(f"{what}: no {wanted} on the map; moved {amount:g} m sideways")
        self.across = amount
        # From where the actor is in its lane to `offset` in the new one.
        within = 0.0 if offset is None else offset - actor.lateral
        actor.shift = Shift(actor.d, distance, amount + within)

    @staticmethod
    def _find(
        road_map: RoadMap,
        spot: LaneSpot,
        side: str,
        count: int,
        toward: Actor | None,
        lane: int | None,
    ) -> tuple[LaneSpot, float] | None:
        if lane is not None:
            return _to_lane(road_map, spot, lane)
        if toward is None:
            return _walk(road_map, spot, side, count)
        theirs = toward.path.spot(toward.d)
        if theirs is None or theirs.road != spot.road:
            return None
        start = _to_lane(road_map, spot, theirs.lane)
        if start is None:
            return None
        then = _walk(road_map, start[0], side, count)
        return None if then is None else (then[0], start[1] + then[1])

    def _without_map(self, side: str, count: int, toward: Actor | None) -> float:
        """Lane widths of DEFAULT_LANE_WIDTH, from the other actor's centre where there is one."""
        step = DEFAULT_LANE_WIDTH * count * (1 if side == "left" else -1)
        if toward is None:
            return step
        dx, dy = toward.x - self.actor.x, toward.y - self.actor.y
        heading = self.actor.heading
        return -dx * math.sin(heading) + dy * math.cos(heading) + step

    def finished(self, world: World) -> bool:
        shift = self.actor.shift
        if shift is None or shift.progress(self.actor.d) < 1.0:
            return shift is None
        self.actor.settle_shift()
        spot = self.actor.path.spot(self.actor.d)
        if self.target is not None and spot is not None and world.road_map is not None:
            moved = LaneSpot(self.target.road, self.target.lane, spot.s, spot.forward)
            # The lanes crossed become the new path; what is left is the offset within it.
            lateral = self.actor.lateral - self.across
            self.actor.follow(lanes.lane_path(world.road_map, moved), lateral)
        return True


@kind("LaneChange")
class LaneChange(Behaviour):
    """Move into the lane beside, along half a cosine over `distance` m, or over what the
    actor drives in `duration` s at the speed it starts with (release 1.5)."""

    def start(self, world: World) -> None:
        node = self.node
        length = concrete(node, "distance")
        if node.duration is not None:
            # The path's shape is kept in metres (the actor's shift follows its travel), so a
            # speed change during the lane change stretches it: a preview, not a player.
            length = abs(self.actor.speed) * concrete(node, "duration")
        side = str(node.direction.name if node.direction is not None else "left")
        toward = None
        if node.targetActor is not None and node.targetLane is None:
            toward = world.actor(node.targetActor, self.name)
        if node.shape.name != "sinusoidal":
            world.note(f"{self.name}: a {node.shape.name} lane change is previewed as sinusoidal")
        self.shift = LaneShift(
            world,
            self.actor,
            side,
            length,
            self.name,
            count=int(node.lanes),
            toward=toward,
            lane=node.targetLane,
            offset=concrete(node, "targetOffset"),
        )

    def done(self, world: World) -> bool:
        return self.shift.finished(world)

    def release(self, world: World) -> None:
        self.actor.settle_shift()


class Arrival(Behaviour):
    """A maneuver that finishes when its actor comes within `tolerance` of a point."""

    goal: tuple[float, float]
    tolerance: float

    def done(self, world: World) -> bool:
        return self.actor.distance_to(*self.goal) <= self.tolerance + 1e-9

    def go_straight(
        self, world: World, points: list[tuple[float, float]], from_here: bool = True
    ) -> None:
        """Head straight through `points` from where the actor is (or, not `from_here`, from
        the first point, where the actor is put); past the last, on along the lane there (as
        players go on after a trajectory), or straight on off the lanes."""
        here = [(self.actor.x, self.actor.y)] if from_here or len(points) < 2 else []
        route = [*here, *points]
        (ax, ay), (bx, by) = route[-2], route[-1]
        heading = math.atan2(by - ay, bx - ax)
        onward = lanes.onward(world.road_map, bx, by, heading) if world.road_map else None
        if onward is None:
            length = math.hypot(bx - ax, by - ay) or 1.0
            route.append((bx + (bx - ax) / length * _BEYOND, by + (by - ay) / length * _BEYOND))
            self.actor.follow(straight(route))
        else:
            self.actor.follow(joined(straight(route), onward))


@kind("TurnLeft", "TurnRight")
class Turn(Arrival):
    """Through the next junction by a connection that turns the named way, to `destination`."""

    def start(self, world: World) -> None:
        self.goal = world.point(self.node.destination, f"{self.name}'s destination")
        self.tolerance = concrete(self.node, "tolerance")
        turn = "left" if isinstance(self.node, scm.TurnLeft) else "right"
        spot = self.actor.path.spot(self.actor.d)
        path: Path | None = None
        if world.road_map is not None and spot is not None:
            path = lanes.turn_path(world.road_map, spot, turn, self.goal)
        if path is None:
            world.note(
                f"{self.name}: no {turn} turn from the actor's lane; it drives straight there"
            )
            self.go_straight(world, [self.goal])
        else:
            self.actor.follow(path, self.actor.lateral)


@kind("Cross")
class Cross(Arrival):
    """Straight across to `destination` at the current speed."""

    def start(self, world: World) -> None:
        self.goal = world.point(self.node.destination, f"{self.name}'s destination")
        self.tolerance = concrete(self.node, "tolerance")
        self.go_straight(world, [self.goal])


@kind("FollowTrajectory")
class FollowTrajectory(Arrival):
    """Along the polyline through the waypoints; finished at the last one."""

    def start(self, world: World) -> None:
        points = [
            world.point(p, f"{self.name}'s waypoint {i + 1}")
            for i, p in enumerate(self.node.waypoints)
        ]
        if not points:
            points = [(self.actor.x, self.actor.y)]
        self.goal = points[-1]
        self.tolerance = concrete(self.node, "tolerance")
        # An imported trajectory begins at its first waypoint: the actor is put there.
        self.go_straight(world, points, from_here=not self.node.fromFirstWaypoint)


@kind("Overtake")
class Overtake(Behaviour):
    """Out to the `side` lane at `speed`, past the target until `gap` m ahead, then back."""

    def start(self, world: World) -> None:
        self.lead = world.actor(self.node.targetActor, self.name)
        self.side = str(self.node.side.name if self.node.side is not None else "left")
        self.gap = concrete(self.node, "gap")
        self.distance = concrete(self.node, "laneChangeDistance")
        step_speed(self.actor, concrete(self.node, "speed"))
        self.phase = "out"
        self.shift = LaneShift(world, self.actor, self.side, self.distance, self.name)

    def done(self, world: World) -> bool:
        if self.phase == "out" and self.shift.finished(world):
            self.phase = "pass"
        if self.phase == "pass" and self._ahead():
            back = "right" if self.side == "left" else "left"
            self.shift = LaneShift(world, self.actor, back, self.distance, self.name)
            self.phase = "back"
        return self.phase == "back" and self.shift.finished(world)

    def release(self, world: World) -> None:
        self.actor.settle_shift()

    def _ahead(self) -> bool:
        """Near the point `gap` m ahead of the target (`xosc.meaning`), as the export says."""
        lead = self.lead
        x = lead.x + self.gap * math.cos(lead.heading)
        y = lead.y + self.gap * math.sin(lead.heading)
        return self.actor.distance_to(x, y) <= meaning.overtake_back_tolerance(self.gap) + 1e-9


@kind("LaneOffset")
class LaneOffset(Behaviour):
    """Move sideways within the lane to the offset (from the lane's centre, or from the target
    actor), along half a cosine over the distance driven in `xosc.meaning.lane_offset_duration`."""

    def start(self, world: World) -> None:
        node, actor = self.node, self.actor
        offset = concrete(node, "offset")
        if node.targetActor is not None:
            other = world.actor(node.targetActor, self.name)
            dx, dy = other.x - actor.x, other.y - actor.y
            across = -dx * math.sin(actor.heading) + dy * math.cos(actor.heading)
            amount = across + offset
        else:
            spot = actor.path.spot(actor.d)
            # The offset is along the road's t (esmini), the actor's lateral along its travel.
            forward = spot is None or spot.forward
            amount = (offset if forward else -offset) - actor.lateral
        if node.shape.name not in ("sinusoidal", "step"):
            world.note(f"{self.name}: a {node.shape.name} lane offset is previewed as sinusoidal")
        duration = meaning.lane_offset_duration(
            amount, concrete(node, "maxLateralAcc"), node.shape.name
        )
        actor.shift = Shift(actor.d, max(actor.speed, 0.0) * duration, amount)

    def done(self, world: World) -> bool:
        shift = self.actor.shift
        if shift is not None and shift.progress(self.actor.d) < 1.0:
            return False
        self.actor.settle_shift()
        return True

    def release(self, world: World) -> None:
        self.actor.settle_shift()


@kind("LightState")
class LightState(Behaviour):
    """Switch a light: nothing moves (the preview draws no lights); finished once the
    transition is over, never while flashing (`xosc.meaning.light_state_duration`)."""

    def start(self, world: World) -> None:
        world.note(f"{self.name}: the preview draws no lights; only its timing is kept")
        duration = meaning.light_state_duration(
            concrete(self.node, "transitionTime"), self.node.mode.name
        )
        # The transition runs from the node's start, as esmini's from its action's start.
        began = world.t if self.started_at is None else self.started_at
        self.until = None if duration is None else began + duration

    def done(self, world: World) -> bool:
        return self.until is not None and world.t >= self.until - 1e-9


@kind("MatchSpeed")
class MatchSpeed(Behaviour):
    """Bring the speed to the target actor's times the factor or plus the delta, following it
    (`actors.SpeedMatching`); finished when first reached. A continuous one keeps following
    afterwards (as Follow keeps its gap) until another maneuver of the actor's speed takes
    over; any other holds the speed it reached."""

    def start(self, world: World) -> None:
        node = self.node
        self.other = world.actor(node.targetActor, self.name)
        factor = node.relation.name == "factor"
        self.factor = concrete(node, "speedFactor") if factor else 1.0
        self.delta = 0.0 if factor else concrete(node, "speedDelta")
        rate = math.inf if node.rate is None else concrete(node, "rate")
        self.actor.control = SpeedMatching(self.other.name, self.factor, self.delta, rate)

    def done(self, world: World) -> bool:
        wanted = self.other.speed * self.factor + self.delta
        if abs(self.actor.speed - wanted) >= meaning.SPEED_TOLERANCE:
            return False
        if not self.node.continuous:
            self.actor.control = Hold()
        return True


@kind("ConnectTrailer")
class ConnectTrailer(Behaviour):
    """Couple the target actor to the actor's hitch (release 1.5): from the next drag on it is
    towed (`trailers.connect`); finished at once, as players complete the action."""

    def start(self, world: World) -> None:
        trailer = world.actor(self.node.targetActor, self.name)
        link = Coupling(
            self.actor.name,
            trailer.name,
            concrete(self.node.referenceActor, "hitchX"),
            concrete(self.node.targetActor, "couplerX"),
        )
        trailers.connect(world.actors, world.couplings, link, rolls_on=world.road_map is not None)
        world.towed_by[trailer.name] = self.actor.name


@kind("DisconnectTrailer")
class DisconnectTrailer(Behaviour):
    """Uncouple what the actor tows (release 1.5): the trailer rolls on straight at its speed
    on a map with roads and stops without one (`trailers.disconnect`); finished at once."""

    def start(self, world: World) -> None:
        rolls_on = world.road_map is not None
        if trailers.disconnect(world.actors, world.couplings, self.actor.name, rolls_on) is None:
            world.note(f"{self.name}: {self.actor.name} tows nothing; nothing to uncouple")
