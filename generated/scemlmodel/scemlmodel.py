"""Definition of meta model 'scemlmodel'."""
from functools import partial
import pyecore.ecore as Ecore
from pyecore.ecore import *
from ._static_features import attribute as _attribute, reference as _reference


name = 'scemlmodel'
nsURI = 'https://sceml.org/metamodel/1.5'
nsPrefix = 'scemlmodel'

eClass = EPackage(name=name, nsURI=nsURI, nsPrefix=nsPrefix)

eClassifiers = {}
getEClassifier = partial(Ecore.getEClassifier, searchspace=eClassifiers)
AbstractionLevel = EEnum('AbstractionLevel', literals=['functional', 'logical', 'concrete'])

JoinPolicy = EEnum('JoinPolicy', literals=['joinAll', 'joinOne'])

LaneChangeDirection = EEnum('LaneChangeDirection', literals=['left', 'right'])

ComparisonRule = EEnum('ComparisonRule', literals=[
                       'greaterThan', 'lessThan', 'equalTo', 'greaterOrEqual', 'lessOrEqual'])

SpeedShape = EEnum('SpeedShape', literals=['linear', 'step', 'cubic', 'sinusoidal'])

TrajectoryFollowingMode = EEnum('TrajectoryFollowingMode', literals=['position', 'follow'])

LongitudinalDisplacement = EEnum('LongitudinalDisplacement', literals=[
                                 'trailing', 'leading', 'any'])

CloudState = EEnum('CloudState', literals=['free', 'cloudy', 'overcast', 'rainy'])

PrecipitationType = EEnum('PrecipitationType', literals=['dry', 'rain', 'snow'])

ActorKind = EEnum('ActorKind', literals=[
                  'Pedestrian', 'TwoWheeler', 'Bicycle', 'Motorcycle', 'FourWheeler', 'Car', 'Van', 'Truck', 'Bus'])

ConditionEdge = EEnum('ConditionEdge', literals=['none', 'rising', 'falling', 'risingOrFalling'])

ControllerOverrideKind = EEnum('ControllerOverrideKind', literals=[
                               'throttle', 'brake', 'clutch', 'parkingBrake', 'steeringWheel', 'gear'])

DeclarationType = EEnum('DeclarationType', literals=[
                        'double', 'integer', 'string', 'boolean', 'unsignedInt', 'unsignedShort', 'dateTime'])

ModifyRule = EEnum('ModifyRule', literals=['set', 'add', 'multiply'])

RouteStrategy = EEnum('RouteStrategy', literals=[
                      'shortest', 'fastest', 'leastIntersections', 'random'])

RelativeDistanceType = EEnum('RelativeDistanceType', literals=[
                             'euclidean', 'longitudinal', 'lateral'])

CoordinateSystem = EEnum('CoordinateSystem', literals=['entity', 'lane', 'road', 'trajectory'])

LaneChangeShape = EEnum('LaneChangeShape', literals=['sinusoidal', 'linear', 'cubic', 'step'])

VehicleLightType = EEnum('VehicleLightType', literals=['daytimeRunningLights', 'lowBeam', 'highBeam', 'fogLights', 'fogLightsFront', 'fogLightsRear',
                         'brakeLights', 'warningLights', 'indicatorLeft', 'indicatorRight', 'reversingLights', 'licensePlateIllumination', 'specialPurposeLights'])

LightMode = EEnum('LightMode', literals=['on', 'off', 'flashing'])

AccelerationDirection = EEnum('AccelerationDirection', literals=[
                              'total', 'longitudinal', 'lateral', 'vertical'])

SpeedRelation = EEnum('SpeedRelation', literals=['delta', 'factor'])


@abstract
class NamedElement(EObject, metaclass=MetaEClass):

    name = _attribute(eType=EString, unique=True, derived=False, changeable=True)

    def __init__(self, *, name=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if name is not None:
            self.name = name


@abstract
class Graph(EObject, metaclass=MetaEClass):
    """A directed acyclic graph of nodes joined by flows: a scenario, or the inside of a module definition."""
    nodes = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)
    flows = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, nodes=None, flows=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if nodes:
            self.nodes.extend(nodes)

        if flows:
            self.flows.extend(flows)


class Flow(EObject, metaclass=MetaEClass):
    """A directed edge: the target is activated when the source has finished."""
    source = _reference(ordered=True, unique=True, containment=False, derived=False)
    target = _reference(ordered=True, unique=True, containment=False, derived=False)

    def __init__(self, *, source=None, target=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if source is not None:
            self.source = source

        if target is not None:
            self.target = target


class DiagramPosition(EObject, metaclass=MetaEClass):
    """A node's place in the diagram, kept with the model so that reopening shows the picture the user arranged. Pure notation: it never changes what the scenario means."""
    x = _attribute(eType=EDouble, unique=True, derived=False, changeable=True, default_value=0.0)
    y = _attribute(eType=EDouble, unique=True, derived=False, changeable=True, default_value=0.0)

    def __init__(self, *, x=None, y=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if x is not None:
            self.x = x

        if y is not None:
            self.y = y


class Property(EObject, metaclass=MetaEClass):
    """One name and value pair of a controller, as OpenSCENARIO's Property: text the player reads (e.g. esmini's timeGap or mode)."""
    name = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    value = _attribute(eType=EString, unique=True, derived=False, changeable=True)

    def __init__(self, *, name=None, value=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if name is not None:
            self.name = name

        if value is not None:
            self.value = value


class Controller(EObject, metaclass=MetaEClass):
    """What drives an actor instead of the player's default (OpenSCENARIO's Controller): its name, which players use to pick an implementation (esmini: ACCController, InteractiveController, ...), an optional controllerType (1.2+: movement, lateral, longitudinal, lighting, animation, appearance, all) and its properties. SceML's own preview does not run it."""
    name = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    controllerType = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    file = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    properties = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, name=None, controllerType=None, properties=None, file=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if name is not None:
            self.name = name

        if controllerType is not None:
            self.controllerType = controllerType

        if file is not None:
            self.file = file

        if properties:
            self.properties.extend(properties)


class ControllerActivation(EObject, metaclass=MetaEClass):
    """Which domains of an actor's controller are switched on (true) or off (false); unset leaves a domain as the player has it. lighting and animation exist from OpenSCENARIO 1.2."""
    lateral = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)
    longitudinal = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)
    lighting = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)
    animation = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)

    def __init__(self, *, lateral=None, longitudinal=None, lighting=None, animation=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if lateral is not None:
            self.lateral = lateral

        if longitudinal is not None:
            self.longitudinal = longitudinal

        if lighting is not None:
            self.lighting = lighting

        if animation is not None:
            self.animation = animation


class ControllerOverride(EObject, metaclass=MetaEClass):
    """One overridden input: active or released, and its value (pedals 0..1, steering wheel in rad, a manual gear's number)."""
    kind = _attribute(eType=ControllerOverrideKind, unique=True, derived=False,
                      changeable=True, default_value=ControllerOverrideKind.throttle)
    active = _attribute(eType=EBoolean, unique=True, derived=False,
                        changeable=True, default_value=True)
    value = _attribute(eType=EDouble, unique=True, derived=False,
                       changeable=True, default_value=0.0)

    def __init__(self, *, kind=None, active=None, value=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if kind is not None:
            self.kind = kind

        if active is not None:
            self.active = active

        if value is not None:
            self.value = value


class Declaration(EObject, metaclass=MetaEClass):
    """A parameter or variable the scenario declares for its global nodes to read and change (ParameterCondition, SetParameter, VariableCondition, SetVariable): exported as a ParameterDeclaration or (1.2+) VariableDeclaration with this initial value."""
    name = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    type = _attribute(eType=DeclarationType, unique=True, derived=False,
                      changeable=True, default_value=DeclarationType.double)
    value = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    variable = _attribute(eType=EBoolean, unique=True, derived=False,
                          changeable=True, default_value=False)

    def __init__(self, *, name=None, type=None, value=None, variable=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if name is not None:
            self.name = name

        if type is not None:
            self.type = type

        if value is not None:
            self.value = value

        if variable is not None:
            self.variable = variable


class RoleBinding(EObject, metaclass=MetaEClass):

    role = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    actor = _reference(ordered=True, unique=True, containment=False, derived=False)

    def __init__(self, *, role=None, actor=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if role is not None:
            self.role = role

        if actor is not None:
            self.actor = actor


class ParameterOverride(EObject, metaclass=MetaEClass):

    parameter = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    value = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, parameter=None, value=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if parameter is not None:
            self.parameter = parameter

        if value is not None:
            self.value = value


class AllowedKind(EObject, metaclass=MetaEClass):
    """One actor kind a role accepts. An object rather than a many-valued enum attribute, because pyecore writes an empty many-valued attribute as text that no reader accepts."""
    kind = _attribute(eType=ActorKind, unique=True, derived=False, changeable=True)

    def __init__(self, *, kind=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if kind is not None:
            self.kind = kind


@abstract
class Position(EObject, metaclass=MetaEClass):

    def __init__(self):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()


class RouteWaypoint(EObject, metaclass=MetaEClass):
    """One waypoint of a RoutePosition's route: a position (not relative, not itself on a route) and how the route reaches it from the one before (OpenSCENARIO's Waypoint)."""
    routeStrategy = _attribute(eType=RouteStrategy, unique=True, derived=False,
                               changeable=True, default_value=RouteStrategy.shortest)
    position = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, position=None, routeStrategy=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if routeStrategy is not None:
            self.routeStrategy = routeStrategy

        if position is not None:
            self.position = position


class Environment(EObject, metaclass=MetaEClass):

    timeOfDay = _attribute(eType=EString, unique=True, derived=False,
                           changeable=True, default_value='12:00:00')
    cloudState = _attribute(eType=CloudState, unique=True, derived=False,
                            changeable=True, default_value=CloudState.free)
    precipitation = _attribute(eType=PrecipitationType, unique=True,
                               derived=False, changeable=True, default_value=PrecipitationType.dry)
    precipitationIntensity = _reference(ordered=True, unique=True, containment=True, derived=False)
    fogVisualRange = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, timeOfDay=None, cloudState=None, precipitation=None, precipitationIntensity=None, fogVisualRange=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if timeOfDay is not None:
            self.timeOfDay = timeOfDay

        if cloudState is not None:
            self.cloudState = cloudState

        if precipitation is not None:
            self.precipitation = precipitation

        if precipitationIntensity is not None:
            self.precipitationIntensity = precipitationIntensity

        if fogVisualRange is not None:
            self.fogVisualRange = fogVisualRange


@abstract
class ParameterValue(EObject, metaclass=MetaEClass):
    """What a numeric parameter holds. An absent value means unset: the language default applies, or nothing at the functional level."""

    def __init__(self):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()


class WeightedValue(EObject, metaclass=MetaEClass):

    value = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)
    weight = _attribute(eType=EDoubleObject, unique=True, derived=False, changeable=True)

    def __init__(self, *, value=None, weight=None):
        # if kwargs:
        #    raise AttributeError('unexpected arguments: {}'.format(kwargs))

        super().__init__()

        if value is not None:
            self.value = value

        if weight is not None:
            self.weight = weight


class Scenario(Graph):
    """The document root of a scenario file. Its nodes hold exactly one RootNode and one EndNode."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Library(NamedElement):
    """The document root of a module library file."""
    description = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    modules = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, description=None, modules=None, **kwargs):

        super().__init__(**kwargs)

        if description is not None:
            self.description = description

        if modules:
            self.modules.extend(modules)


@abstract
class GraphElement(NamedElement):

    incoming = _reference(ordered=True, unique=True, containment=False,
                          derived=False, upper=-1, transient=True)
    outgoing = _reference(ordered=True, unique=True, containment=False,
                          derived=False, upper=-1, transient=True)
    diagramPosition = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, incoming=None, outgoing=None, diagramPosition=None, **kwargs):

        super().__init__(**kwargs)

        if incoming:
            self.incoming.extend(incoming)

        if outgoing:
            self.outgoing.extend(outgoing)

        if diagramPosition is not None:
            self.diagramPosition = diagramPosition


class ModuleDefinition(Graph):
    """A reusable sub-scenario stored in a library: actor roles, parameters, and a graph from one InPort to one OutPort. Its name is its ID, so uses in other files refer to it by name."""
    name = _attribute(eType=EString, unique=True, derived=False, changeable=True, iD=True)
    description = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    roles = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)
    parameters = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, name=None, description=None, roles=None, parameters=None, **kwargs):

        super().__init__(**kwargs)

        if name is not None:
            self.name = name

        if description is not None:
            self.description = description

        if roles:
            self.roles.extend(roles)

        if parameters:
            self.parameters.extend(parameters)


class ModuleParameter(NamedElement):

    unit = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    description = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    default = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, unit=None, description=None, default=None, **kwargs):

        super().__init__(**kwargs)

        if unit is not None:
            self.unit = unit

        if description is not None:
            self.description = description

        if default is not None:
            self.default = default


@abstract
class Participant(NamedElement):
    """Who an action node refers to: an actor of a scenario, or an actor role of a module definition."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class WorldPosition(Position):

    x = _reference(ordered=True, unique=True, containment=True, derived=False)
    y = _reference(ordered=True, unique=True, containment=True, derived=False)
    z = _reference(ordered=True, unique=True, containment=True, derived=False)
    h = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, x=None, y=None, z=None, h=None, **kwargs):

        super().__init__(**kwargs)

        if x is not None:
            self.x = x

        if y is not None:
            self.y = y

        if z is not None:
            self.z = z

        if h is not None:
            self.h = h


class LanePosition(Position):

    roadId = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    laneId = _attribute(eType=EInt, unique=True, derived=False, changeable=True)
    s = _reference(ordered=True, unique=True, containment=True, derived=False)
    offset = _reference(ordered=True, unique=True, containment=True, derived=False)
    h = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, roadId=None, laneId=None, s=None, offset=None, h=None, **kwargs):

        super().__init__(**kwargs)

        if roadId is not None:
            self.roadId = roadId

        if laneId is not None:
            self.laneId = laneId

        if s is not None:
            self.s = s

        if offset is not None:
            self.offset = offset

        if h is not None:
            self.h = h


class RoadPosition(Position):
    """A point in road coordinates: s along the road's reference line, t across it (positive to the left), as OpenSCENARIO's RoadPosition. h, when given, is the heading relative to the road's direction at s."""
    roadId = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    s = _reference(ordered=True, unique=True, containment=True, derived=False)
    t = _reference(ordered=True, unique=True, containment=True, derived=False)
    h = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, roadId=None, s=None, t=None, h=None, **kwargs):

        super().__init__(**kwargs)

        if roadId is not None:
            self.roadId = roadId

        if s is not None:
            self.s = s

        if t is not None:
            self.t = t

        if h is not None:
            self.h = h


class RelativeLanePosition(Position):
    """dLane lanes across (positive to the left, lane 0 skipped) and ds along the road from the entity's lane, offset from that lane's centre, relative to where the entity is when the position is used (Init: its start; a destination: when the maneuver starts; a condition: each time it is evaluated), as OpenSCENARIO's RelativeLanePosition."""
    dLane = _attribute(eType=EInt, unique=True, derived=False, changeable=True, default_value=0)
    entity = _reference(ordered=True, unique=True, containment=False, derived=False)
    ds = _reference(ordered=True, unique=True, containment=True, derived=False)
    offset = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, entity=None, dLane=None, ds=None, offset=None, **kwargs):

        super().__init__(**kwargs)

        if dLane is not None:
            self.dLane = dLane

        if entity is not None:
            self.entity = entity

        if ds is not None:
            self.ds = ds

        if offset is not None:
            self.offset = offset


class RelativeRoadPosition(Position):
    """ds along and dt across the road (positive to the left) from the entity's road coordinate, relative to where the entity is when the position is used (Init: its start; a destination: when the maneuver starts; a condition: each time it is evaluated), as OpenSCENARIO's RelativeRoadPosition."""
    entity = _reference(ordered=True, unique=True, containment=False, derived=False)
    ds = _reference(ordered=True, unique=True, containment=True, derived=False)
    dt = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, entity=None, ds=None, dt=None, **kwargs):

        super().__init__(**kwargs)

        if entity is not None:
            self.entity = entity

        if ds is not None:
            self.ds = ds

        if dt is not None:
            self.dt = dt


class RelativeObjectPosition(Position):
    """dx ahead, dy to the left and dz above the entity, in its own frame; h, when given, the heading relative to the entity's; relative to where the entity is when the position is used (Init: its start; a destination: when the maneuver starts; a condition: each time it is evaluated), as OpenSCENARIO's RelativeObjectPosition."""
    entity = _reference(ordered=True, unique=True, containment=False, derived=False)
    dx = _reference(ordered=True, unique=True, containment=True, derived=False)
    dy = _reference(ordered=True, unique=True, containment=True, derived=False)
    dz = _reference(ordered=True, unique=True, containment=True, derived=False)
    h = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, entity=None, dx=None, dy=None, dz=None, h=None, **kwargs):

        super().__init__(**kwargs)

        if entity is not None:
            self.entity = entity

        if dx is not None:
            self.dx = dx

        if dy is not None:
            self.dy = dy

        if dz is not None:
            self.dz = dz

        if h is not None:
            self.h = h


class RelativeWorldPosition(Position):
    """dx, dy, dz in world axes from the entity, heading the entity's, relative to where the entity is when the position is used (Init: its start; a destination: when the maneuver starts; a condition: each time it is evaluated), as OpenSCENARIO's RelativeWorldPosition."""
    entity = _reference(ordered=True, unique=True, containment=False, derived=False)
    dx = _reference(ordered=True, unique=True, containment=True, derived=False)
    dy = _reference(ordered=True, unique=True, containment=True, derived=False)
    dz = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, entity=None, dx=None, dy=None, dz=None, **kwargs):

        super().__init__(**kwargs)

        if entity is not None:
            self.entity = entity

        if dx is not None:
            self.dx = dx

        if dy is not None:
            self.dy = dy

        if dz is not None:
            self.dz = dz


class RoutePosition(Position):
    """A place on a route, as OpenSCENARIO's RoutePosition: the route through its waypoints (two or more, each a position and the strategy that reaches it), then pathS along the route from its first waypoint, in the direction of traffic of that waypoint's lane; with laneId set, laneOffset from the centre of that lane (FromLaneCoordinates), else t from the road's reference line (FromRoadCoordinates)."""
    routeName = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    closed = _attribute(eType=EBoolean, unique=True, derived=False,
                        changeable=True, default_value=False)
    laneId = _attribute(eType=EIntegerObject, unique=True, derived=False, changeable=True)
    waypoints = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)
    pathS = _reference(ordered=True, unique=True, containment=True, derived=False)
    laneOffset = _reference(ordered=True, unique=True, containment=True, derived=False)
    t = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, routeName=None, closed=None, waypoints=None, pathS=None, laneId=None, laneOffset=None, t=None, **kwargs):

        super().__init__(**kwargs)

        if routeName is not None:
            self.routeName = routeName

        if closed is not None:
            self.closed = closed

        if laneId is not None:
            self.laneId = laneId

        if waypoints:
            self.waypoints.extend(waypoints)

        if pathS is not None:
            self.pathS = pathS

        if laneOffset is not None:
            self.laneOffset = laneOffset

        if t is not None:
            self.t = t


class Value(ParameterValue):

    value = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)

    def __init__(self, *, value=None, **kwargs):

        super().__init__(**kwargs)

        if value is not None:
            self.value = value


class Range(ParameterValue):

    min = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)
    max = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)
    step = _attribute(eType=EDoubleObject, unique=True, derived=False, changeable=True)

    def __init__(self, *, min=None, max=None, step=None, **kwargs):

        super().__init__(**kwargs)

        if min is not None:
            self.min = min

        if max is not None:
            self.max = max

        if step is not None:
            self.step = step


@abstract
class Distribution(ParameterValue):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class ParameterRef(ParameterValue):
    """Inside a module definition: take the value of one of the module's parameters (its override, or else its default)."""
    parameter = _reference(ordered=True, unique=True, containment=False, derived=False)

    def __init__(self, *, parameter=None, **kwargs):

        super().__init__(**kwargs)

        if parameter is not None:
            self.parameter = parameter


class RootNode(GraphElement):
    """Where the scenario starts: its name, map, environment, abstraction level, maximum duration and actors."""
    scenarioName = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    description = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    author = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    date = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    map = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    vehicleCatalog = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    level = _attribute(eType=AbstractionLevel, unique=True, derived=False,
                       changeable=True, default_value=AbstractionLevel.functional)
    maxDuration = _reference(ordered=True, unique=True, containment=True, derived=False)
    environment = _reference(ordered=True, unique=True, containment=True, derived=False)
    actors = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)
    declarations = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, scenarioName=None, description=None, author=None, date=None, map=None, vehicleCatalog=None, level=None, maxDuration=None, environment=None, actors=None, declarations=None, **kwargs):

        super().__init__(**kwargs)

        if scenarioName is not None:
            self.scenarioName = scenarioName

        if description is not None:
            self.description = description

        if author is not None:
            self.author = author

        if date is not None:
            self.date = date

        if map is not None:
            self.map = map

        if vehicleCatalog is not None:
            self.vehicleCatalog = vehicleCatalog

        if level is not None:
            self.level = level

        if maxDuration is not None:
            self.maxDuration = maxDuration

        if environment is not None:
            self.environment = environment

        if actors:
            self.actors.extend(actors)

        if declarations:
            self.declarations.extend(declarations)


class EndNode(GraphElement):
    """Where all paths end. It finishes when all (joinAll) or the first (joinOne) of its predecessors have finished, and then the scenario stops."""
    policy = _attribute(eType=JoinPolicy, unique=True, derived=False,
                        changeable=True, default_value=JoinPolicy.joinAll)

    def __init__(self, *, policy=None, **kwargs):

        super().__init__(**kwargs)

        if policy is not None:
            self.policy = policy


@abstract
class ModuleElement(GraphElement):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class InPort(GraphElement):
    """Where a module's internal flow starts when its use is activated."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class OutPort(GraphElement):
    """Where a module's internal flow ends; the module use finishes when its single predecessor has finished."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class ModuleUse(GraphElement):
    """One use of a module definition inside a scenario or another module. It refers to the definition, usually in a library file, binds each role to an actor of its context and may override parameters."""
    definition = _reference(ordered=True, unique=True, containment=False, derived=False)
    bindings = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)
    overrides = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, definition=None, bindings=None, overrides=None, **kwargs):

        super().__init__(**kwargs)

        if definition is not None:
            self.definition = definition

        if bindings:
            self.bindings.extend(bindings)

        if overrides:
            self.overrides.extend(overrides)


class ActorRole(Participant):

    allowedKinds = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, allowedKinds=None, **kwargs):

        super().__init__(**kwargs)

        if allowedKinds:
            self.allowedKinds.extend(allowedKinds)


@abstract
class Actor(Participant):

    isEgo = _attribute(eType=EBoolean, unique=True, derived=False,
                       changeable=True, default_value=False)
    model = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    catalogEntry = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    startPosition = _reference(ordered=True, unique=True, containment=True, derived=False)
    initialSpeed = _reference(ordered=True, unique=True, containment=True, derived=False)
    length = _reference(ordered=True, unique=True, containment=True, derived=False)
    width = _reference(ordered=True, unique=True, containment=True, derived=False)
    height = _reference(ordered=True, unique=True, containment=True, derived=False)
    boxCenterX = _reference(ordered=True, unique=True, containment=True, derived=False)
    trailer = _reference(ordered=True, unique=True, containment=False, derived=False)
    hitchX = _reference(ordered=True, unique=True, containment=True, derived=False)
    couplerX = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxSpeed = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxAcceleration = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxDeceleration = _reference(ordered=True, unique=True, containment=True, derived=False)
    controller = _reference(ordered=True, unique=True, containment=True, derived=False)
    controllerActivation = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, isEgo=None, model=None, catalogEntry=None, startPosition=None, initialSpeed=None, length=None, width=None, height=None, boxCenterX=None, trailer=None, hitchX=None, couplerX=None, maxSpeed=None, maxAcceleration=None, maxDeceleration=None, controller=None, controllerActivation=None, **kwargs):

        super().__init__(**kwargs)

        if isEgo is not None:
            self.isEgo = isEgo

        if model is not None:
            self.model = model

        if catalogEntry is not None:
            self.catalogEntry = catalogEntry

        if startPosition is not None:
            self.startPosition = startPosition

        if initialSpeed is not None:
            self.initialSpeed = initialSpeed

        if length is not None:
            self.length = length

        if width is not None:
            self.width = width

        if height is not None:
            self.height = height

        if boxCenterX is not None:
            self.boxCenterX = boxCenterX

        if trailer is not None:
            self.trailer = trailer

        if hitchX is not None:
            self.hitchX = hitchX

        if couplerX is not None:
            self.couplerX = couplerX

        if maxSpeed is not None:
            self.maxSpeed = maxSpeed

        if maxAcceleration is not None:
            self.maxAcceleration = maxAcceleration

        if maxDeceleration is not None:
            self.maxDeceleration = maxDeceleration

        if controller is not None:
            self.controller = controller

        if controllerActivation is not None:
            self.controllerActivation = controllerActivation


class UniformDistribution(Distribution):

    min = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)
    max = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)

    def __init__(self, *, min=None, max=None, **kwargs):

        super().__init__(**kwargs)

        if min is not None:
            self.min = min

        if max is not None:
            self.max = max


class NormalDistribution(Distribution):

    mean = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)
    standardDeviation = _attribute(eType=EDouble, unique=True, derived=False, changeable=True)
    lowerBound = _attribute(eType=EDoubleObject, unique=True, derived=False, changeable=True)
    upperBound = _attribute(eType=EDoubleObject, unique=True, derived=False, changeable=True)

    def __init__(self, *, mean=None, standardDeviation=None, lowerBound=None, upperBound=None, **kwargs):

        super().__init__(**kwargs)

        if mean is not None:
            self.mean = mean

        if standardDeviation is not None:
            self.standardDeviation = standardDeviation

        if lowerBound is not None:
            self.lowerBound = lowerBound

        if upperBound is not None:
            self.upperBound = upperBound


class DiscreteDistribution(Distribution):

    options = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, options=None, **kwargs):

        super().__init__(**kwargs)

        if options:
            self.options.extend(options)


@abstract
class ActionNode(ModuleElement):
    """A maneuver or condition. The reference actor performs the maneuver or must fulfil the condition; some kinds also need a target actor."""
    maxRuns = _attribute(eType=EInt, unique=True, derived=False, changeable=True, default_value=1)
    referenceActor = _reference(ordered=True, unique=True, containment=False, derived=False)
    targetActor = _reference(ordered=True, unique=True, containment=False, derived=False)

    def __init__(self, *, referenceActor=None, targetActor=None, maxRuns=None, **kwargs):

        super().__init__(**kwargs)

        if maxRuns is not None:
            self.maxRuns = maxRuns

        if referenceActor is not None:
            self.referenceActor = referenceActor

        if targetActor is not None:
            self.targetActor = targetActor


@abstract
class JoiningPolicy(ModuleElement):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Pedestrian(Actor):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


@abstract
class TwoWheeler(Actor):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


@abstract
class FourWheeler(Actor):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


@abstract
class Maneuver(ActionNode):

    interrupts = _attribute(eType=EBoolean, unique=True, derived=False,
                            changeable=True, default_value=False)

    def __init__(self, *, interrupts=None, **kwargs):

        super().__init__(**kwargs)

        if interrupts is not None:
            self.interrupts = interrupts


@abstract
class Condition(ActionNode):

    edge = _attribute(eType=ConditionEdge, unique=True, derived=False,
                      changeable=True, default_value=ConditionEdge.none)

    def __init__(self, *, edge=None, **kwargs):

        super().__init__(**kwargs)

        if edge is not None:
            self.edge = edge


class OpaqueAction(ActionNode):
    """An OpenSCENARIO action or condition that no SceML kind expresses, kept verbatim by sceml import so that nothing is lost: it is drawn, validated as a node and exported back as it was read. The reference actor is the entity it acts on or that triggers it (the ego for a global action)."""
    xml = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    sourceLine = _attribute(eType=EIntegerObject, unique=True, derived=False, changeable=True)
    sourceVersion = _attribute(eType=EString, unique=True, derived=False, changeable=True)

    def __init__(self, *, xml=None, sourceLine=None, sourceVersion=None, **kwargs):

        super().__init__(**kwargs)

        if xml is not None:
            self.xml = xml

        if sourceLine is not None:
            self.sourceLine = sourceLine

        if sourceVersion is not None:
            self.sourceVersion = sourceVersion


@abstract
class GlobalAction(ActionNode):
    """An action no actor performs: it changes the scenario state (a parameter, a variable, a traffic signal). It has no reference actor and finishes at once."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class JoinAllFinished(JoiningPolicy):
    """Finishes when all of its predecessors have finished."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class JoinOneFinished(JoiningPolicy):
    """Finishes when the first of its predecessors has finished; the other branches keep running."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Bicycle(TwoWheeler):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Motorcycle(TwoWheeler):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Car(FourWheeler):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Van(FourWheeler):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Truck(FourWheeler):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Bus(FourWheeler):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


@abstract
class LongitudinalManeuver(Maneuver):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


@abstract
class LateralManeuver(Maneuver):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


@abstract
class CompositeManeuver(Maneuver):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class InLocationRadius(Condition):

    position = _reference(ordered=True, unique=True, containment=True, derived=False)
    radius = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, position=None, radius=None, **kwargs):

        super().__init__(**kwargs)

        if position is not None:
            self.position = position

        if radius is not None:
            self.radius = radius


class InVehicleRadius(Condition):

    freespace = _attribute(eType=EBoolean, unique=True, derived=False,
                           changeable=True, default_value=False)
    relativeDistanceType = _attribute(eType=RelativeDistanceType, unique=True,
                                      derived=False, changeable=True, default_value=RelativeDistanceType.euclidean)
    coordinateSystem = _attribute(eType=CoordinateSystem, unique=True,
                                  derived=False, changeable=True, default_value=CoordinateSystem.entity)
    rule = _attribute(eType=ComparisonRule, unique=True, derived=False,
                      changeable=True, default_value=ComparisonRule.lessThan)
    radius = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, radius=None, freespace=None, relativeDistanceType=None, coordinateSystem=None, rule=None, **kwargs):

        super().__init__(**kwargs)

        if freespace is not None:
            self.freespace = freespace

        if relativeDistanceType is not None:
            self.relativeDistanceType = relativeDistanceType

        if coordinateSystem is not None:
            self.coordinateSystem = coordinateSystem

        if rule is not None:
            self.rule = rule

        if radius is not None:
            self.radius = radius


class TimeElapsed(Condition):

    duration = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, duration=None, **kwargs):

        super().__init__(**kwargs)

        if duration is not None:
            self.duration = duration


class SpeedCondition(Condition):

    rule = _attribute(eType=ComparisonRule, unique=True, derived=False,
                      changeable=True, default_value=ComparisonRule.greaterThan)
    speed = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, rule=None, speed=None, **kwargs):

        super().__init__(**kwargs)

        if rule is not None:
            self.rule = rule

        if speed is not None:
            self.speed = speed


class TimeToCollision(Condition):

    rule = _attribute(eType=ComparisonRule, unique=True, derived=False,
                      changeable=True, default_value=ComparisonRule.lessThan)
    freespace = _attribute(eType=EBoolean, unique=True, derived=False,
                           changeable=True, default_value=True)
    relativeDistanceType = _attribute(eType=RelativeDistanceType, unique=True,
                                      derived=False, changeable=True, default_value=RelativeDistanceType.euclidean)
    coordinateSystem = _attribute(eType=CoordinateSystem, unique=True,
                                  derived=False, changeable=True, default_value=CoordinateSystem.entity)
    time = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, rule=None, time=None, freespace=None, relativeDistanceType=None, coordinateSystem=None, **kwargs):

        super().__init__(**kwargs)

        if rule is not None:
            self.rule = rule

        if freespace is not None:
            self.freespace = freespace

        if relativeDistanceType is not None:
            self.relativeDistanceType = relativeDistanceType

        if coordinateSystem is not None:
            self.coordinateSystem = coordinateSystem

        if time is not None:
            self.time = time


@abstract
class ControllerManeuver(Maneuver):
    """A change of the reference actor's controller during the run. It completes at once, as players complete controller actions; what the controller then does is the player's."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class ParameterCondition(Condition):
    """Holds once the scenario's parameter compares by rule with value (OpenSCENARIO's ParameterCondition). A global condition: no actor fulfils it."""
    parameter = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    rule = _attribute(eType=ComparisonRule, unique=True, derived=False,
                      changeable=True, default_value=ComparisonRule.equalTo)
    value = _attribute(eType=EString, unique=True, derived=False, changeable=True)

    def __init__(self, *, parameter=None, rule=None, value=None, **kwargs):

        super().__init__(**kwargs)

        if parameter is not None:
            self.parameter = parameter

        if rule is not None:
            self.rule = rule

        if value is not None:
            self.value = value


class VariableCondition(Condition):
    """Holds once the scenario's variable compares by rule with value (OpenSCENARIO 1.2+'s VariableCondition). A global condition: no actor fulfils it."""
    variable = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    rule = _attribute(eType=ComparisonRule, unique=True, derived=False,
                      changeable=True, default_value=ComparisonRule.equalTo)
    value = _attribute(eType=EString, unique=True, derived=False, changeable=True)

    def __init__(self, *, variable=None, rule=None, value=None, **kwargs):

        super().__init__(**kwargs)

        if variable is not None:
            self.variable = variable

        if rule is not None:
            self.rule = rule

        if value is not None:
            self.value = value


class SetParameter(GlobalAction):
    """Sets the scenario's parameter to value, or adds value to it, or multiplies it by value (OpenSCENARIO's ParameterAction)."""
    parameter = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    value = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    modify = _attribute(eType=ModifyRule, unique=True, derived=False,
                        changeable=True, default_value=ModifyRule.set)

    def __init__(self, *, parameter=None, value=None, modify=None, **kwargs):

        super().__init__(**kwargs)

        if parameter is not None:
            self.parameter = parameter

        if value is not None:
            self.value = value

        if modify is not None:
            self.modify = modify


class SetVariable(GlobalAction):
    """Sets the scenario's variable to value, or adds value to it, or multiplies it by value (OpenSCENARIO 1.2+'s VariableAction)."""
    variable = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    value = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    modify = _attribute(eType=ModifyRule, unique=True, derived=False,
                        changeable=True, default_value=ModifyRule.set)

    def __init__(self, *, variable=None, value=None, modify=None, **kwargs):

        super().__init__(**kwargs)

        if variable is not None:
            self.variable = variable

        if value is not None:
            self.value = value

        if modify is not None:
            self.modify = modify


class TrafficSignalState(GlobalAction):
    """Switches a traffic signal of the map to a state (OpenSCENARIO's TrafficSignalStateAction)."""
    signalId = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    state = _attribute(eType=EString, unique=True, derived=False, changeable=True)

    def __init__(self, *, signalId=None, state=None, **kwargs):

        super().__init__(**kwargs)

        if signalId is not None:
            self.signalId = signalId

        if state is not None:
            self.state = state


class TrafficSignalCondition(Condition):
    """Holds once a traffic signal of the map shows the state (OpenSCENARIO's TrafficSignalCondition). A global condition: no actor fulfils it."""
    signalId = _attribute(eType=EString, unique=True, derived=False, changeable=True)
    state = _attribute(eType=EString, unique=True, derived=False, changeable=True)

    def __init__(self, *, signalId=None, state=None, **kwargs):

        super().__init__(**kwargs)

        if signalId is not None:
            self.signalId = signalId

        if state is not None:
            self.state = state


class TraveledDistance(Condition):
    """Holds once the reference actor's odometer reaches the distance: every metre it has moved since the simulation started, whichever way (OpenSCENARIO's TraveledDistanceCondition), not since the node's activation."""
    distance = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, distance=None, **kwargs):

        super().__init__(**kwargs)

        if distance is not None:
            self.distance = distance


class TimeHeadway(Condition):
    """Compares by rule the time headway to the target actor with time: the distance to the target over the reference actor's own speed (OpenSCENARIO's TimeHeadwayCondition); undefined, so never holding, while the target is behind or the actor stands."""
    rule = _attribute(eType=ComparisonRule, unique=True, derived=False,
                      changeable=True, default_value=ComparisonRule.lessThan)
    freespace = _attribute(eType=EBoolean, unique=True, derived=False,
                           changeable=True, default_value=True)
    relativeDistanceType = _attribute(eType=RelativeDistanceType, unique=True,
                                      derived=False, changeable=True, default_value=RelativeDistanceType.euclidean)
    coordinateSystem = _attribute(eType=CoordinateSystem, unique=True,
                                  derived=False, changeable=True, default_value=CoordinateSystem.entity)
    time = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, rule=None, time=None, freespace=None, relativeDistanceType=None, coordinateSystem=None, **kwargs):

        super().__init__(**kwargs)

        if rule is not None:
            self.rule = rule

        if freespace is not None:
            self.freespace = freespace

        if relativeDistanceType is not None:
            self.relativeDistanceType = relativeDistanceType

        if coordinateSystem is not None:
            self.coordinateSystem = coordinateSystem

        if time is not None:
            self.time = time


@abstract
class AppearanceManeuver(Maneuver):
    """A change of how the reference actor looks to others (its lights; release 1.4): it controls neither its speed nor its path, so it runs beside the actor's other maneuvers."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class StandStill(Condition):
    """Holds once the reference actor has stood still for longer than duration, counted from when it stopped, also before the node's activation (OpenSCENARIO's StandStillCondition, as esmini measures it)."""
    duration = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, duration=None, **kwargs):

        super().__init__(**kwargs)

        if duration is not None:
            self.duration = duration


class AccelerationCondition(Condition):
    """Compares by rule the reference actor's acceleration (negative: braking, for a component) with acceleration (OpenSCENARIO's AccelerationCondition)."""
    rule = _attribute(eType=ComparisonRule, unique=True, derived=False,
                      changeable=True, default_value=ComparisonRule.greaterThan)
    direction = _attribute(eType=AccelerationDirection, unique=True, derived=False,
                           changeable=True, default_value=AccelerationDirection.total)
    acceleration = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, rule=None, acceleration=None, direction=None, **kwargs):

        super().__init__(**kwargs)

        if rule is not None:
            self.rule = rule

        if direction is not None:
            self.direction = direction

        if acceleration is not None:
            self.acceleration = acceleration


@abstract
class CouplingManeuver(Maneuver):
    """A change of what the reference actor tows during the run (release 1.5). It completes at once, as players complete trailer actions; while coupled, the trailer is dragged behind its tower and drives on its own no more."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Accelerate(LongitudinalManeuver):

    shape = _attribute(eType=SpeedShape, unique=True, derived=False,
                       changeable=True, default_value=SpeedShape.linear)
    targetSpeed = _reference(ordered=True, unique=True, containment=True, derived=False)
    rate = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, targetSpeed=None, rate=None, shape=None, **kwargs):

        super().__init__(**kwargs)

        if shape is not None:
            self.shape = shape

        if targetSpeed is not None:
            self.targetSpeed = targetSpeed

        if rate is not None:
            self.rate = rate


class Decelerate(LongitudinalManeuver):

    shape = _attribute(eType=SpeedShape, unique=True, derived=False,
                       changeable=True, default_value=SpeedShape.linear)
    targetSpeed = _reference(ordered=True, unique=True, containment=True, derived=False)
    rate = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, targetSpeed=None, rate=None, shape=None, **kwargs):

        super().__init__(**kwargs)

        if shape is not None:
            self.shape = shape

        if targetSpeed is not None:
            self.targetSpeed = targetSpeed

        if rate is not None:
            self.rate = rate


class Stop(LongitudinalManeuver):

    shape = _attribute(eType=SpeedShape, unique=True, derived=False,
                       changeable=True, default_value=SpeedShape.linear)
    rate = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, rate=None, shape=None, **kwargs):

        super().__init__(**kwargs)

        if shape is not None:
            self.shape = shape

        if rate is not None:
            self.rate = rate


class KeepVelocity(LongitudinalManeuver):

    duration = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, duration=None, **kwargs):

        super().__init__(**kwargs)

        if duration is not None:
            self.duration = duration


class DriveDistance(LongitudinalManeuver):

    distance = _reference(ordered=True, unique=True, containment=True, derived=False)
    speed = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, distance=None, speed=None, **kwargs):

        super().__init__(**kwargs)

        if distance is not None:
            self.distance = distance

        if speed is not None:
            self.speed = speed


@abstract
class DistanceKeeping(LongitudinalManeuver):
    """What Follow and Approach share (release 1.5): how they measure the gap and the limits they drive within, as OpenSCENARIO's LongitudinalDistanceAction and its DynamicConstraints say them. An unset limit is the actor's own performance, taken down to the language's gap-keeping limits (3 m/s2 speeding up, 6 m/s2 slowing down), what the export wrote before release 1.5; a set one is held to the actor's performance, as players do."""
    freespace = _attribute(eType=EBoolean, unique=True, derived=False,
                           changeable=True, default_value=False)
    displacement = _attribute(eType=LongitudinalDisplacement, unique=True, derived=False,
                              changeable=True, default_value=LongitudinalDisplacement.trailing)
    maxAcceleration = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxDeceleration = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxSpeed = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxAccelerationRate = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxDecelerationRate = _reference(ordered=True, unique=True, containment=True, derived=False)
    timeGap = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, maxAcceleration=None, maxDeceleration=None, maxSpeed=None, maxAccelerationRate=None, maxDecelerationRate=None, timeGap=None, freespace=None, displacement=None, **kwargs):

        super().__init__(**kwargs)

        if freespace is not None:
            self.freespace = freespace

        if displacement is not None:
            self.displacement = displacement

        if maxAcceleration is not None:
            self.maxAcceleration = maxAcceleration

        if maxDeceleration is not None:
            self.maxDeceleration = maxDeceleration

        if maxSpeed is not None:
            self.maxSpeed = maxSpeed

        if maxAccelerationRate is not None:
            self.maxAccelerationRate = maxAccelerationRate

        if maxDecelerationRate is not None:
            self.maxDecelerationRate = maxDecelerationRate

        if timeGap is not None:
            self.timeGap = timeGap


class LaneChange(LateralManeuver):

    direction = _attribute(eType=LaneChangeDirection, unique=True, derived=False,
                           changeable=True, default_value=LaneChangeDirection.left)
    lanes = _attribute(eType=EInt, unique=True, derived=False, changeable=True, default_value=1)
    targetLane = _attribute(eType=EIntegerObject, unique=True, derived=False, changeable=True)
    shape = _attribute(eType=LaneChangeShape, unique=True, derived=False,
                       changeable=True, default_value=LaneChangeShape.sinusoidal)
    distance = _reference(ordered=True, unique=True, containment=True, derived=False)
    duration = _reference(ordered=True, unique=True, containment=True, derived=False)
    targetOffset = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, direction=None, distance=None, duration=None, lanes=None, targetLane=None, targetOffset=None, shape=None, **kwargs):

        super().__init__(**kwargs)

        if direction is not None:
            self.direction = direction

        if lanes is not None:
            self.lanes = lanes

        if targetLane is not None:
            self.targetLane = targetLane

        if shape is not None:
            self.shape = shape

        if distance is not None:
            self.distance = distance

        if duration is not None:
            self.duration = duration

        if targetOffset is not None:
            self.targetOffset = targetOffset


@abstract
class RoutedManeuver(LateralManeuver):
    """A lateral maneuver whose goal is a destination; it finishes when the actor is within the arrival tolerance of it."""
    destination = _reference(ordered=True, unique=True, containment=True, derived=False)
    tolerance = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, destination=None, tolerance=None, **kwargs):

        super().__init__(**kwargs)

        if destination is not None:
            self.destination = destination

        if tolerance is not None:
            self.tolerance = tolerance


class FollowTrajectory(CompositeManeuver):

    followingMode = _attribute(eType=TrajectoryFollowingMode, unique=True, derived=False,
                               changeable=True, default_value=TrajectoryFollowingMode.position)
    fromFirstWaypoint = _attribute(eType=EBoolean, unique=True,
                                   derived=False, changeable=True, default_value=False)
    waypoints = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)
    tolerance = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, waypoints=None, tolerance=None, followingMode=None, fromFirstWaypoint=None, **kwargs):

        super().__init__(**kwargs)

        if followingMode is not None:
            self.followingMode = followingMode

        if fromFirstWaypoint is not None:
            self.fromFirstWaypoint = fromFirstWaypoint

        if waypoints:
            self.waypoints.extend(waypoints)

        if tolerance is not None:
            self.tolerance = tolerance


class Overtake(CompositeManeuver):

    side = _attribute(eType=LaneChangeDirection, unique=True, derived=False,
                      changeable=True, default_value=LaneChangeDirection.left)
    speed = _reference(ordered=True, unique=True, containment=True, derived=False)
    gap = _reference(ordered=True, unique=True, containment=True, derived=False)
    laneChangeDistance = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, side=None, speed=None, gap=None, laneChangeDistance=None, **kwargs):

        super().__init__(**kwargs)

        if side is not None:
            self.side = side

        if speed is not None:
            self.speed = speed

        if gap is not None:
            self.gap = gap

        if laneChangeDistance is not None:
            self.laneChangeDistance = laneChangeDistance


class ActivateController(ControllerManeuver):
    """Switches the domains of the actor's controller on or off (OpenSCENARIO's ActivateControllerAction); unset leaves a domain as it is."""
    lateral = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)
    longitudinal = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)
    lighting = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)
    animation = _attribute(eType=EBooleanObject, unique=True, derived=False, changeable=True)

    def __init__(self, *, lateral=None, longitudinal=None, lighting=None, animation=None, **kwargs):

        super().__init__(**kwargs)

        if lateral is not None:
            self.lateral = lateral

        if longitudinal is not None:
            self.longitudinal = longitudinal

        if lighting is not None:
            self.lighting = lighting

        if animation is not None:
            self.animation = animation


class AssignController(ControllerManeuver):
    """Gives the actor another controller (OpenSCENARIO's AssignControllerAction); activation, when set, also switches its domains (1.1+)."""
    controller = _reference(ordered=True, unique=True, containment=True, derived=False)
    activation = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, controller=None, activation=None, **kwargs):

        super().__init__(**kwargs)

        if controller is not None:
            self.controller = controller

        if activation is not None:
            self.activation = activation


class OverrideController(ControllerManeuver):
    """Overrides driver inputs of the actor's controller (OpenSCENARIO's OverrideControllerValueAction): throttle, brake, clutch, parking brake, steering wheel or gear, each at most once."""
    overrides = _reference(ordered=True, unique=True, containment=True, derived=False, upper=-1)

    def __init__(self, *, overrides=None, **kwargs):

        super().__init__(**kwargs)

        if overrides:
            self.overrides.extend(overrides)


class LaneOffset(LateralManeuver):
    """Moves the reference actor sideways within its lane to offset m left of the lane's centre (or, with a target actor, offset m left of that actor's lateral position), its lateral acceleration peaking at maxLateralAcc along shape (OpenSCENARIO's LaneOffsetAction). Finished when the offset is reached, as esmini ends the action then (continuous or not)."""
    shape = _attribute(eType=LaneChangeShape, unique=True, derived=False,
                       changeable=True, default_value=LaneChangeShape.sinusoidal)
    continuous = _attribute(eType=EBoolean, unique=True, derived=False,
                            changeable=True, default_value=False)
    offset = _reference(ordered=True, unique=True, containment=True, derived=False)
    maxLateralAcc = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, offset=None, maxLateralAcc=None, shape=None, continuous=None, **kwargs):

        super().__init__(**kwargs)

        if shape is not None:
            self.shape = shape

        if continuous is not None:
            self.continuous = continuous

        if offset is not None:
            self.offset = offset

        if maxLateralAcc is not None:
            self.maxLateralAcc = maxLateralAcc


class LightState(AppearanceManeuver):
    """Switches one of the reference actor's lights on, off or to flashing over transitionTime (OpenSCENARIO 1.2's LightStateAction). Finished when the transition is over for on and off; a flashing light never finishes, as players keep its action running until another overrides it."""
    lightType = _attribute(eType=VehicleLightType, unique=True, derived=False,
                           changeable=True, default_value=VehicleLightType.lowBeam)
    mode = _attribute(eType=LightMode, unique=True, derived=False,
                      changeable=True, default_value=LightMode.on)
    transitionTime = _reference(ordered=True, unique=True, containment=True, derived=False)
    luminousIntensity = _reference(ordered=True, unique=True, containment=True, derived=False)
    flashingOnDuration = _reference(ordered=True, unique=True, containment=True, derived=False)
    flashingOffDuration = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, lightType=None, mode=None, transitionTime=None, luminousIntensity=None, flashingOnDuration=None, flashingOffDuration=None, **kwargs):

        super().__init__(**kwargs)

        if lightType is not None:
            self.lightType = lightType

        if mode is not None:
            self.mode = mode

        if transitionTime is not None:
            self.transitionTime = transitionTime

        if luminousIntensity is not None:
            self.luminousIntensity = luminousIntensity

        if flashingOnDuration is not None:
            self.flashingOnDuration = flashingOnDuration

        if flashingOffDuration is not None:
            self.flashingOffDuration = flashingOffDuration


class MatchSpeed(LongitudinalManeuver):
    """Brings the reference actor's speed to the target actor's speed plus speedDelta, or times speedFactor (relation), at rate (unset: at once, a step), as OpenSCENARIO's SpeedAction with a RelativeTargetSpeed. It follows the target's speed as it changes and is finished when the speed is first reached; a continuous one keeps the relation afterwards (as Follow keeps its gap) until another maneuver of the actor's speed takes over, as a later speed action overrides a continuous one in players (release 1.4)."""
    relation = _attribute(eType=SpeedRelation, unique=True, derived=False,
                          changeable=True, default_value=SpeedRelation.delta)
    continuous = _attribute(eType=EBoolean, unique=True, derived=False,
                            changeable=True, default_value=False)
    speedDelta = _reference(ordered=True, unique=True, containment=True, derived=False)
    speedFactor = _reference(ordered=True, unique=True, containment=True, derived=False)
    rate = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, relation=None, speedDelta=None, speedFactor=None, rate=None, continuous=None, **kwargs):

        super().__init__(**kwargs)

        if relation is not None:
            self.relation = relation

        if continuous is not None:
            self.continuous = continuous

        if speedDelta is not None:
            self.speedDelta = speedDelta

        if speedFactor is not None:
            self.speedFactor = speedFactor

        if rate is not None:
            self.rate = rate


class ConnectTrailer(CouplingManeuver):
    """Couples the target actor to the reference actor's hitch, wherever it stands (OpenSCENARIO 1.3's ConnectTrailerAction): from then on it is towed as Actor.trailer tows, until a DisconnectTrailer."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class DisconnectTrailer(CouplingManeuver):
    """Uncouples whatever the reference actor tows (OpenSCENARIO 1.3's DisconnectTrailerAction): the trailer keeps the speed it had and rolls on along its road, or stops where there is no road, as esmini 3.6 moves it; nothing when the actor tows nothing."""

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Follow(DistanceKeeping):

    distance = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, distance=None, **kwargs):

        super().__init__(**kwargs)

        if distance is not None:
            self.distance = distance


class Approach(DistanceKeeping):

    distance = _reference(ordered=True, unique=True, containment=True, derived=False)

    def __init__(self, *, distance=None, **kwargs):

        super().__init__(**kwargs)

        if distance is not None:
            self.distance = distance


class TurnLeft(RoutedManeuver):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class TurnRight(RoutedManeuver):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)


class Cross(RoutedManeuver):

    def __init__(self, **kwargs):

        super().__init__(**kwargs)
