
from .scemlmodel import getEClassifier, eClassifiers
from .scemlmodel import name, nsURI, nsPrefix, eClass
from .scemlmodel import AbstractionLevel, JoinPolicy, LaneChangeDirection, ComparisonRule, SpeedShape, TrajectoryFollowingMode, LongitudinalDisplacement, CloudState, PrecipitationType, ActorKind, NamedElement, Graph, Scenario, Library, Flow, GraphElement, DiagramPosition, RootNode, EndNode, ModuleElement, ActionNode, Maneuver, LongitudinalManeuver, LateralManeuver, CompositeManeuver, Condition, ConditionEdge, Accelerate, Decelerate, Stop, KeepVelocity, DriveDistance, DistanceKeeping, Follow, Approach, LaneChange, RoutedManeuver, TurnLeft, TurnRight, Cross, FollowTrajectory, Overtake, InLocationRadius, InVehicleRadius, TimeElapsed, SpeedCondition, TimeToCollision, Property, Controller, ControllerActivation, ControllerManeuver, ActivateController, AssignController, ControllerOverrideKind, ControllerOverride, OverrideController, OpaqueAction, DeclarationType, ModifyRule, Declaration, GlobalAction, ParameterCondition, VariableCondition, SetParameter, SetVariable, TrafficSignalState, TrafficSignalCondition, LaneOffset, JoiningPolicy, JoinAllFinished, JoinOneFinished, ModuleDefinition, InPort, OutPort, ModuleUse, RoleBinding, ParameterOverride, ModuleParameter, Participant, ActorRole, AllowedKind, Actor, Pedestrian, TwoWheeler, Bicycle, Motorcycle, FourWheeler, Car, Van, Truck, Bus, Position, WorldPosition, LanePosition, RoadPosition, RelativeLanePosition, RelativeRoadPosition, RelativeObjectPosition, RelativeWorldPosition, RoutePosition, RouteWaypoint, RouteStrategy, Environment, ParameterValue, Value, Range, Distribution, UniformDistribution, NormalDistribution, DiscreteDistribution, WeightedValue, ParameterRef, RelativeDistanceType, CoordinateSystem, TraveledDistance, TimeHeadway, LaneChangeShape, AppearanceManeuver, VehicleLightType, LightMode, LightState, StandStill, AccelerationDirection, AccelerationCondition, SpeedRelation, MatchSpeed, CouplingManeuver, ConnectTrailer, DisconnectTrailer


from . import scemlmodel

__all__ = ['AbstractionLevel', 'JoinPolicy', 'LaneChangeDirection', 'ComparisonRule', 'SpeedShape', 'TrajectoryFollowingMode', 'LongitudinalDisplacement', 'CloudState', 'PrecipitationType', 'ActorKind', 'NamedElement', 'Graph', 'Scenario', 'Library', 'Flow', 'GraphElement', 'DiagramPosition', 'RootNode', 'EndNode', 'ModuleElement', 'ActionNode', 'Maneuver', 'LongitudinalManeuver', 'LateralManeuver', 'CompositeManeuver', 'Condition', 'ConditionEdge', 'Accelerate', 'Decelerate', 'Stop', 'KeepVelocity', 'DriveDistance', 'DistanceKeeping', 'Follow', 'Approach', 'LaneChange', 'RoutedManeuver', 'TurnLeft', 'TurnRight', 'Cross', 'FollowTrajectory', 'Overtake', 'InLocationRadius', 'InVehicleRadius', 'TimeElapsed', 'SpeedCondition', 'TimeToCollision', 'Property', 'Controller', 'ControllerActivation', 'ControllerManeuver', 'ActivateController', 'AssignController', 'ControllerOverrideKind', 'ControllerOverride', 'OverrideController', 'OpaqueAction', 'DeclarationType', 'ModifyRule', 'Declaration', 'GlobalAction', 'ParameterCondition', 'VariableCondition', 'SetParameter', 'SetVariable',
           'TrafficSignalState', 'TrafficSignalCondition', 'LaneOffset', 'JoiningPolicy', 'JoinAllFinished', 'JoinOneFinished', 'ModuleDefinition', 'InPort', 'OutPort', 'ModuleUse', 'RoleBinding', 'ParameterOverride', 'ModuleParameter', 'Participant', 'ActorRole', 'AllowedKind', 'Actor', 'Pedestrian', 'TwoWheeler', 'Bicycle', 'Motorcycle', 'FourWheeler', 'Car', 'Van', 'Truck', 'Bus', 'Position', 'WorldPosition', 'LanePosition', 'RoadPosition', 'RelativeLanePosition', 'RelativeRoadPosition', 'RelativeObjectPosition', 'RelativeWorldPosition', 'RoutePosition', 'RouteWaypoint', 'RouteStrategy', 'Environment', 'ParameterValue', 'Value', 'Range', 'Distribution', 'UniformDistribution', 'NormalDistribution', 'DiscreteDistribution', 'WeightedValue', 'ParameterRef', 'RelativeDistanceType', 'CoordinateSystem', 'TraveledDistance', 'TimeHeadway', 'LaneChangeShape', 'AppearanceManeuver', 'VehicleLightType', 'LightMode', 'LightState', 'StandStill', 'AccelerationDirection', 'AccelerationCondition', 'SpeedRelation', 'MatchSpeed', 'CouplingManeuver', 'ConnectTrailer', 'DisconnectTrailer']

eSubpackages = []
eSuperPackage = None
scemlmodel.eSubpackages = eSubpackages
scemlmodel.eSuperPackage = eSuperPackage

Graph.nodes.eType = GraphElement
Graph.flows.eType = Flow
Library.modules.eType = ModuleDefinition
GraphElement.diagramPosition.eType = DiagramPosition
RootNode.maxDuration.eType = ParameterValue
RootNode.environment.eType = Environment
RootNode.actors.eType = Actor
RootNode.declarations.eType = Declaration
ActionNode.referenceActor.eType = Participant
ActionNode.targetActor.eType = Participant
Accelerate.targetSpeed.eType = ParameterValue
Accelerate.rate.eType = ParameterValue
Decelerate.targetSpeed.eType = ParameterValue
Decelerate.rate.eType = ParameterValue
Stop.rate.eType = ParameterValue
KeepVelocity.duration.eType = ParameterValue
DriveDistance.distance.eType = ParameterValue
DriveDistance.speed.eType = ParameterValue
DistanceKeeping.maxAcceleration.eType = ParameterValue
DistanceKeeping.maxDeceleration.eType = ParameterValue
DistanceKeeping.maxSpeed.eType = ParameterValue
DistanceKeeping.maxAccelerationRate.eType = ParameterValue
DistanceKeeping.maxDecelerationRate.eType = ParameterValue
DistanceKeeping.timeGap.eType = ParameterValue
Follow.distance.eType = ParameterValue
Approach.distance.eType = ParameterValue
LaneChange.distance.eType = ParameterValue
LaneChange.duration.eType = ParameterValue
LaneChange.targetOffset.eType = ParameterValue
RoutedManeuver.destination.eType = Position
RoutedManeuver.tolerance.eType = ParameterValue
FollowTrajectory.waypoints.eType = Position
FollowTrajectory.tolerance.eType = ParameterValue
Overtake.speed.eType = ParameterValue
Overtake.gap.eType = ParameterValue
Overtake.laneChangeDistance.eType = ParameterValue
InLocationRadius.position.eType = Position
InLocationRadius.radius.eType = ParameterValue
InVehicleRadius.radius.eType = ParameterValue
TimeElapsed.duration.eType = ParameterValue
SpeedCondition.speed.eType = ParameterValue
TimeToCollision.time.eType = ParameterValue
Controller.properties.eType = Property
AssignController.controller.eType = Controller
AssignController.activation.eType = ControllerActivation
OverrideController.overrides.eType = ControllerOverride
LaneOffset.offset.eType = ParameterValue
LaneOffset.maxLateralAcc.eType = ParameterValue
ModuleDefinition.roles.eType = ActorRole
ModuleDefinition.parameters.eType = ModuleParameter
ModuleUse.definition.eType = ModuleDefinition
ModuleUse.bindings.eType = RoleBinding
ModuleUse.overrides.eType = ParameterOverride
RoleBinding.actor.eType = Participant
ParameterOverride.value.eType = ParameterValue
ModuleParameter.default.eType = ParameterValue
ActorRole.allowedKinds.eType = AllowedKind
Actor.startPosition.eType = Position
Actor.initialSpeed.eType = ParameterValue
Actor.length.eType = ParameterValue
Actor.width.eType = ParameterValue
Actor.height.eType = ParameterValue
Actor.boxCenterX.eType = ParameterValue
Actor.trailer.eType = Actor
Actor.hitchX.eType = ParameterValue
Actor.couplerX.eType = ParameterValue
Actor.maxSpeed.eType = ParameterValue
Actor.maxAcceleration.eType = ParameterValue
Actor.maxDeceleration.eType = ParameterValue
Actor.controller.eType = Controller
Actor.controllerActivation.eType = ControllerActivation
WorldPosition.x.eType = ParameterValue
WorldPosition.y.eType = ParameterValue
WorldPosition.z.eType = ParameterValue
WorldPosition.h.eType = ParameterValue
LanePosition.s.eType = ParameterValue
LanePosition.offset.eType = ParameterValue
LanePosition.h.eType = ParameterValue
RoadPosition.s.eType = ParameterValue
RoadPosition.t.eType = ParameterValue
RoadPosition.h.eType = ParameterValue
RelativeLanePosition.entity.eType = Participant
RelativeLanePosition.ds.eType = ParameterValue
RelativeLanePosition.offset.eType = ParameterValue
RelativeRoadPosition.entity.eType = Participant
RelativeRoadPosition.ds.eType = ParameterValue
RelativeRoadPosition.dt.eType = ParameterValue
RelativeObjectPosition.entity.eType = Participant
RelativeObjectPosition.dx.eType = ParameterValue
RelativeObjectPosition.dy.eType = ParameterValue
RelativeObjectPosition.dz.eType = ParameterValue
RelativeObjectPosition.h.eType = ParameterValue
RelativeWorldPosition.entity.eType = Participant
RelativeWorldPosition.dx.eType = ParameterValue
RelativeWorldPosition.dy.eType = ParameterValue
RelativeWorldPosition.dz.eType = ParameterValue
RoutePosition.waypoints.eType = RouteWaypoint
RoutePosition.pathS.eType = ParameterValue
RoutePosition.laneOffset.eType = ParameterValue
RoutePosition.t.eType = ParameterValue
RouteWaypoint.position.eType = Position
Environment.precipitationIntensity.eType = ParameterValue
Environment.fogVisualRange.eType = ParameterValue
DiscreteDistribution.options.eType = WeightedValue
ParameterRef.parameter.eType = ModuleParameter
TraveledDistance.distance.eType = ParameterValue
TimeHeadway.time.eType = ParameterValue
LightState.transitionTime.eType = ParameterValue
LightState.luminousIntensity.eType = ParameterValue
LightState.flashingOnDuration.eType = ParameterValue
LightState.flashingOffDuration.eType = ParameterValue
StandStill.duration.eType = ParameterValue
AccelerationCondition.acceleration.eType = ParameterValue
MatchSpeed.speedDelta.eType = ParameterValue
MatchSpeed.speedFactor.eType = ParameterValue
MatchSpeed.rate.eType = ParameterValue
Flow.source.eType = GraphElement
Flow.target.eType = GraphElement
GraphElement.incoming.eType = Flow
GraphElement.incoming.eOpposite = Flow.target
GraphElement.outgoing.eType = Flow
GraphElement.outgoing.eOpposite = Flow.source

otherClassifiers = [AbstractionLevel, JoinPolicy, LaneChangeDirection, ComparisonRule, SpeedShape, TrajectoryFollowingMode, LongitudinalDisplacement, CloudState, PrecipitationType, ActorKind, ConditionEdge,
                    ControllerOverrideKind, DeclarationType, ModifyRule, RouteStrategy, RelativeDistanceType, CoordinateSystem, LaneChangeShape, VehicleLightType, LightMode, AccelerationDirection, SpeedRelation]

for classif in otherClassifiers:
    eClassifiers[classif.name] = classif
    classif.ePackage = eClass

for classif in eClassifiers.values():
    eClass.eClassifiers.append(classif.eClass)

for subpack in eSubpackages:
    eClass.eSubpackages.append(subpack.eClass)
