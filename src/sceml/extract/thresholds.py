"""The numbers that decide how a recording is cut into maneuvers and conditions (all settable)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Thresholds:
    """Settable thresholds of the extraction (SI units); docs/extract.md explains each.

    The defaults suit urban recordings sampled at 10 Hz or faster with position noise of a
    decimetre: smoothing windows long enough to average that noise out, and changes small
    enough to be real maneuvers rather than noise.
    """

    #: Savitzky-Golay window for positions (s); a longer one smooths more and blurs corners.
    smoothing_window: float = 1.0
    #: Below this speed (m/s) an actor is standing; its heading is then not judged.
    standing_speed: float = 0.3
    #: A speed change smaller than this (m/s) is no maneuver (noise, or a drift).
    min_speed_change: float = 0.5
    #: An acceleration (m/s²) above this marks a speed change in progress.
    accel_threshold: float = 0.4
    #: A heading change (rad) larger than this is a turn (or, for people and bikes, a crossing).
    turn_angle: float = 0.52
    #: A heading rate (rad/s) above this marks a turn or lane change in progress.
    yaw_rate: float = 0.08
    #: A sideways move of at least this (m) with the heading back as before is a lane change.
    lane_change_offset: float = 2.0
    #: Tolerance (m) written on TurnLeft, TurnRight and Cross, and radius of the arrival check.
    arrival_tolerance: float = 2.0
    #: Distance (m) past the end of a turn where its destination is put.
    turn_settle: float = 3.0
    #: A start is explained by another actor being this close (m) at most (InVehicleRadius).
    vehicle_radius: float = 22.0
    #: Radius (m) of an inferred InLocationRadius about another actor's position.
    location_radius: float = 3.0
    #: Only a place this close (m) to the waiting actor can explain its start (InLocationRadius).
    location_reach: float = 50.0
    #: A shorter wait (s) between two maneuvers of an actor needs no node between them.
    min_wait: float = 0.3
    #: How far (s) an inferred condition may fire from the start it explains, on the recording.
    sync_tolerance: float = 0.3
    #: A set-off from standing that a crossing follows with a bend at least this sharp (rad) is
    #: fitted to the raw positions in the plane, the bend pinning the ramp's end (`setoff`).
    sharp_bend: float = 0.5
    #: A speed change under way when a noisy recording starts is taken at this rate (m/s²)
    #: where the noise leaves its length open: the distance driven pins only the speed change
    #: times its length (`longitudinal._start_change`). 2 m/s² is a brisk, comfortable rate.
    start_rate: float = 2.0
    #: ... and counts when it explains this many times the noise's variance beyond a steady
    #: speed (a likelihood-ratio test for one parameter more: noise alone passes 9 about 1 in
    #: 400 times; lower finds smaller changes and makes up more).
    start_significance: float = 9.0
