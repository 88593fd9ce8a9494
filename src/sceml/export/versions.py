"""What differs between OpenSCENARIO 1.0, 1.1, 1.2 and 1.3, as flags the view model reads."""

from __future__ import annotations

from dataclasses import dataclass

from ..xosc.schema import SUPPORTED_VERSIONS

#: The OpenSCENARIO versions the exporter writes.
VERSIONS = SUPPORTED_VERSIONS


@dataclass(frozen=True)
class Traits:
    """Per-version choices; templates only ever see these flags, never a version number test."""

    version: str
    rev_minor: int
    #: Event priority that stops other events of the same maneuver (only ever one event there).
    priority: str
    #: ParameterSetAction (up to 1.1) or VariableSetAction (1.2 on) for marker events.
    variables: bool
    #: ReachPositionCondition (deprecated from 1.2) or DistanceCondition.
    reach_position: bool
    #: 1.0 requires `alongRoute` on DistanceCondition and TimeToCollisionCondition.
    along_route: bool
    #: 1.0 names it cartesianDistance; 1.1 deprecates that for euclidianDistance.
    euclidian: str
    #: 1.0 wants the Trajectory inline; 1.1 wraps it in TrajectoryRef.
    trajectory_ref: bool
    #: 1.2 replaces cloudState with fractionalCloudCover and Sun intensity with illuminance.
    cloud_cover: bool
    #: 1.1 replaces Precipitation intensity with precipitationIntensity.
    precipitation_intensity: bool
    #: 1.0 requires the Pedestrian `model` attribute.
    pedestrian_model_required: bool
    #: 1.1 introduced `${...}` expressions in attribute values.
    expressions: bool = False
    #: 1.1 wraps ActivateControllerAction in ControllerAction and makes its parts optional
    #: (1.0 needs an OverrideControllerValueAction of all six inputs beside an assignment).
    controller_action: bool = False
    #: 1.2 added Controller's controllerType.
    controller_type: bool = False
    #: The SimulationTimeCondition (value, rule) that holds from t = 0 on: "the simulation
    #: has begun". `greaterOrEqual` came with 1.1; in 1.0 a time above -1 says the same.
    started: tuple[str, str] = ("0.0", "greaterOrEqual")


def traits(version: str) -> Traits:
    """The traits of a supported version; ValueError for any other."""
    if version not in VERSIONS:
        raise ValueError(
            f"OpenSCENARIO {version!r} is not supported; use one of {', '.join(VERSIONS)}"
        )
    minor = int(version.split(".")[1])
    return Traits(
        version=version,
        rev_minor=minor,
        priority="override" if minor >= 2 else "overwrite",
        variables=minor >= 2,
        reach_position=minor <= 1,
        along_route=minor == 0,
        euclidian="cartesianDistance" if minor == 0 else "euclidianDistance",
        trajectory_ref=minor >= 1,
        cloud_cover=minor >= 2,
        precipitation_intensity=minor >= 1,
        pedestrian_model_required=minor == 0,
        expressions=minor >= 1,
        controller_action=minor >= 1,
        controller_type=minor >= 2,
        started=("0.0", "greaterOrEqual") if minor >= 1 else ("-1.0", "greaterThan"),
    )
