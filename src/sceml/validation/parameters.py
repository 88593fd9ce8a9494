"""Parameter rules (paper rule 2): values fit the abstraction level, are well-formed and make sense."""

from __future__ import annotations

import math
from collections.abc import Iterator
from functools import cache

from pyecore.ecore import EClass, EObject, EStructuralFeature

import scemlmodel as scm

from ..diagnostics import Severity
from ..model import catalog
from ..model.graph import root_node
from ..model.params import describe
from ..model.traversal import single_value
from .context import Context, is_kind
from .reads import LEVEL, MODULES, SELF, VALUE, Aspect, Reads
from .registry import Finding, constraint

ERROR = Severity.ERROR

#: Positions a node kind needs at the logical and concrete levels: (kind, feature, minimum count).
REQUIRED_POSITIONS = (
    ("RoutedManeuver", "destination", 1),
    ("InLocationRadius", "position", 1),
    ("FollowTrajectory", "waypoints", 2),
)


def parameter_path(obj: EObject, feature: str | None = None) -> str:
    """Where a parameter sits, as `actor.node.parameter` (e.g. `ego.TurnRight_1.destination.x`)."""
    parts = [feature] if feature else []
    current: EObject | None = obj
    while current is not None:
        if isinstance(current, scm.ActionNode):
            actor = current.referenceActor
            parts += [str(current.name), str(getattr(actor, "name", None) or "?")]
            break
        if isinstance(current, scm.ParameterOverride):
            parts[-1:] = [str(current.parameter)]
        elif isinstance(current, scm.NamedElement) and current.name:
            parts.append(str(current.name))
            break
        else:
            containment = current.eContainmentFeature()
            if containment is None:
                break
            step = str(containment.name)
            if containment.many:
                step += f"[{current.eContainer().eGet(containment).index(current)}]"
            parts.append(step)
        current = current.eContainer()
    return ".".join(reversed(parts))


def numbers(value: EObject) -> list[float]:
    """Every number a parameter value states: a value, range ends, distribution parameters."""
    if type(value) is scm.Value:
        # Most values are single: read without the descriptor (SCEML-P007 asks 22,000 times
        # at 10k nodes); `single_value` reads both kinds of object as `value.value` does.
        number = single_value(value, "value")
        return [] if number is None else [float(number)]
    if isinstance(value, scm.Value):
        candidates = [value.value]
    elif isinstance(value, scm.Range | scm.UniformDistribution):
        candidates = [value.min, value.max]
    elif isinstance(value, scm.NormalDistribution):
        candidates = [value.mean, value.lowerBound, value.upperBound]
    elif isinstance(value, scm.DiscreteDistribution):
        candidates = [option.value for option in value.options]
    else:
        candidates = []
    return [float(number) for number in candidates if number is not None]


def _unit(value: EObject) -> str:
    owner, feature = value.eContainer(), value.eContainmentFeature()
    try:
        return catalog.parameter(owner.eClass.name, feature.name).unit
    except (KeyError, AttributeError):
        return ""


#: The values a concrete scenario may not hold (SCEML-P001); the editor offers the others.
SPREAD_KINDS = ("Range", "Distribution")
#: The values only a module definition may hold (SCEML-P008).
MODULE_ONLY_KINDS = ("ParameterRef",)


def refused_value_kinds(level: str | None, in_module: bool) -> tuple[str, ...]:
    """The value kinds the parameter rules refuse at `level` (SCEML-P001: no spread in a concrete
    scenario) or outside a module definition (SCEML-P008), which has no level of its own; the
    editor offers the others."""
    if in_module:
        return ()
    return MODULE_ONLY_KINDS + (SPREAD_KINDS if level == "concrete" else ())


@constraint(
    "SCEML-P001",
    ERROR,
    SPREAD_KINDS,
    "a concrete scenario holds single values: no range or distribution",
    paper_rule="2",
    through_modules=True,
    reads=Reads(VALUE, LEVEL),
)
def no_spread_when_concrete(value: EObject, context: Context) -> Iterator[Finding]:
    if context.level_of(value) == "concrete":
        yield (
            value,
            f"{parameter_path(value)} is {describe(value, _unit(value))}; a concrete scenario "
            "needs a single value",
        )


@cache
def _required_positions(eclass: EClass) -> tuple[tuple[str, bool, int], ...]:
    """REQUIRED_POSITIONS that apply to a metaclass, with whether each feature is many-valued:
    worked out once per class, not once per node."""
    return tuple(
        (feature, bool(eclass.findEStructuralFeature(feature).many), minimum)
        for kind, feature, minimum in REQUIRED_POSITIONS
        if is_kind(eclass.name, kind)
    )


@cache
def _required_parameters(eclass: EClass) -> tuple[str, ...]:
    """The parameters of a metaclass without a language default, once per class."""
    return tuple(spec.name for spec in catalog.parameters(eclass.name) if spec.required)


def _missing_parameters(owner: EObject) -> Iterator[str]:
    for name in _required_parameters(owner.eClass):
        if single_value(owner, name) is None:
            yield name
    for feature, many, minimum in _required_positions(owner.eClass):
        held = owner.eGet(feature)
        count = len(held) if many else int(held is not None)
        if count < minimum:
            yield feature if minimum == 1 else f"{feature} (at least {minimum})"
    if isinstance(owner, scm.LanePosition | scm.RoadPosition) and not owner.roadId:
        yield "roadId"


@constraint(
    "SCEML-P002",
    ERROR,
    ("ActionNode", "Position"),
    "a logical or concrete scenario gives every value needed for execution "
    "(parameters without a language default, destinations, positions, waypoints)",
    paper_rule="2",
    through_modules=True,
    reads=Reads(VALUE, LEVEL),
    export=True,
)
def required_values_present(owner: EObject, context: Context) -> Iterator[Finding]:
    level = context.level_of(owner)
    if level not in ("logical", "concrete"):
        return
    for name in _missing_parameters(owner):
        yield owner, f"{parameter_path(owner, name)} is missing; a {level} scenario needs it"


@constraint(
    "SCEML-P003",
    ERROR,
    "Range",
    "a range has min <= max",
    paper_rule="2",
    reads=Reads(VALUE),
)
def range_bounds_ordered(value: scm.Range, context: Context) -> Iterator[Finding]:
    if value.min is not None and value.max is not None and value.min > value.max:
        yield value, f"{parameter_path(value)}: range min {value.min:g} is above max {value.max:g}"


@constraint(
    "SCEML-P004",
    ERROR,
    "Range",
    "a range's step, if given, is above zero",
    paper_rule="2",
    reads=Reads(VALUE),
)
def range_step_positive(value: scm.Range, context: Context) -> Iterator[Finding]:
    if value.step is not None and not value.step > 0:
        yield value, f"{parameter_path(value)}: range step {value.step:g} must be above zero"


@constraint(
    "SCEML-P005",
    ERROR,
    ("UniformDistribution", "NormalDistribution"),
    "a uniform distribution has min <= max; a normal one has standard deviation >= 0 and "
    "lower bound <= upper bound",
    paper_rule="2",
    reads=Reads(VALUE),
)
def continuous_distribution_well_formed(value: EObject, context: Context) -> Iterator[Finding]:
    where = parameter_path(value)
    if isinstance(value, scm.UniformDistribution):
        if value.min is not None and value.max is not None and value.min > value.max:
            yield value, f"{where}: uniform min {value.min:g} is above max {value.max:g}"
        return
    sd = value.standardDeviation
    if sd is not None and sd < 0:
        yield value, f"{where}: standard deviation {sd:g} is negative"
    low, high = value.lowerBound, value.upperBound
    if low is not None and high is not None and low > high:
        yield value, f"{where}: lower bound {low:g} is above upper bound {high:g}"


@constraint(
    "SCEML-P006",
    ERROR,
    "DiscreteDistribution",
    "a discrete distribution has at least one option, no negative weight, and not all weights zero",
    paper_rule="2",
    reads=Reads(VALUE),
)
def discrete_distribution_well_formed(
    value: scm.DiscreteDistribution, context: Context
) -> Iterator[Finding]:
    where = parameter_path(value)
    options = list(value.options)
    if not options:
        yield value, f"{where}: a discrete distribution needs at least one option"
        return
    weights = [option.weight for option in options]
    if any(weight is not None and weight < 0 for weight in weights):
        yield value, f"{where}: weights must not be negative"
    elif all(weight is not None and weight == 0 for weight in weights):
        yield value, f"{where}: all weights are zero"


@cache
def _sign(eclass: EClass, feature: EStructuralFeature) -> str | None:
    """`catalog.sign` of a metaclass's feature, once per pair: keyed by the metamodel's own
    objects, never by model objects."""
    return catalog.sign(eclass.name, feature.name)


@constraint(
    "SCEML-P007",
    ERROR,
    "ParameterValue",
    "values are finite and physically meaningful: radius, tolerance, duration, distance, rate, "
    "time, gap and dimensions above zero; driving speeds and lane s at least zero (initial, "
    "target and compared speeds may be negative: driving backwards)",
    paper_rule="2",
    through_modules=True,
    reads=Reads(VALUE),
)
def values_physically_meaningful(value: EObject, context: Context) -> Iterator[Finding]:
    stated = numbers(value)
    if not all(map(math.isfinite, stated)):
        yield value, f"{parameter_path(value)} is {describe(value)}: not a finite number"
        return
    if not stated:
        return  # no number to judge by its sign
    feature = value.eContainmentFeature()
    sign = _sign(value.eContainer().eClass, feature) if feature is not None else None
    # Every number is finite here, so the smallest decides both signs.
    if sign == catalog.POSITIVE and min(stated) <= 0:
        yield (
            value,
            f"{parameter_path(value)} is {describe(value, _unit(value))}; it must be above 0",
        )
    elif sign == catalog.NON_NEGATIVE and min(stated) < 0:
        yield value, f"{parameter_path(value)} is {describe(value, _unit(value))}; it must be >= 0"


@constraint(
    "SCEML-P008",
    ERROR,
    MODULE_ONLY_KINDS,
    "a parameter reference sits inside a module definition and names one of its parameters",
    # its module's parameters
    reads=Reads(VALUE, MODULES),
)
def parameter_ref_in_its_module(ref: scm.ParameterRef, context: Context) -> Iterator[Finding]:
    module = ref.eContainer()
    while module is not None and not isinstance(module, scm.ModuleDefinition):
        module = module.eContainer()
    if module is None:
        yield ref, f"{parameter_path(ref)} refers to a module parameter outside any module"
    elif ref.parameter is None or ref.parameter not in set(module.parameters):
        yield ref, f"{parameter_path(ref)} refers to no parameter of module {module.name!r}"


#: The global kinds that name a parameter or variable: the feature naming it, and a variable?
_NAMING = {
    "ParameterCondition": ("parameter", False),
    "SetParameter": ("parameter", False),
    "VariableCondition": ("variable", True),
    "SetVariable": ("variable", True),
}


@constraint(
    "SCEML-P009",
    ERROR,
    tuple(_NAMING),
    "a parameter or variable node names one the root declares (RootNode.declarations); an "
    "empty name, as CARLA's criteria write, is left alone",
    # the root's declarations: their names and whether each is a variable
    reads=Reads(SELF, Aspect.STRUCTURE | Aspect.ATTRIBUTES),
)
def global_value_declared(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    feature, variable = _NAMING[node.eClass.name]
    name = str(single_value(node, feature) or "")
    root = root_node(node.eContainer()) if isinstance(node.eContainer(), scm.Scenario) else None
    if not name or root is None:
        return
    if not any(d.name == name and bool(d.variable) == variable for d in root.declarations):
        what = "variable" if variable else "parameter"
        yield node, f"{node.name!r} names the {what} {name!r}, which the root does not declare"


@constraint(
    "SCEML-P010",
    ERROR,
    "LaneChange",
    "a lane change is given by a distance or by a duration (release 1.5), not by both",
    paper_rule="2",
    through_modules=True,
    # the node's own distance and duration
    reads=Reads(SELF),
)
def lane_change_one_dimension(node: scm.LaneChange, context: Context) -> Iterator[Finding]:
    if node.distance is not None and node.duration is not None:
        yield (
            node,
            f"{node.name!r} gives both a distance and a duration; players take a lane change "
            "over one of them: unset the other",
        )
