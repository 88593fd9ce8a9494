"""What the metamodel says about each kind: categories, parameters, units and language defaults.

The generated classes carry no EAnnotations, so these facts are read from the shipped `.ecore`,
which stays the single source of truth.
"""

from __future__ import annotations

import importlib.resources
from dataclasses import dataclass
from functools import cache

from pyecore.ecore import EClass, EObject, EReference
from pyecore.resources import URI, ResourceSet

import scemlmodel as scm

NODE_ANNOTATION = "http://sceml.org/node"
PARAMETER_ANNOTATION = "http://sceml.org/parameter"
ACTOR_ANNOTATION = "http://sceml.org/actor"

#: A parameter whose default depends on the actor kind (its bounding box).
ACTOR_DEFAULT = "actor"

#: Signs a parameter annotation may require: above zero, or zero and above.
POSITIVE = "positive"
NON_NEGATIVE = "nonNegative"

CATEGORIES = ("longitudinal", "lateral", "composite", "condition")

#: Features that only say how a node is drawn (the editor's layout); never a parameter or a meaning.
NOTATION_FEATURES = frozenset({"diagramPosition"})


@dataclass(frozen=True)
class ParameterSpec:
    """One numeric parameter of a kind: its feature name, SI unit and language default.

    `sign` is `positive` (above zero), `nonNegative` (zero or above) or None (any number);
    `limit` names the actor limit that bounds it (a key of the limits file, e.g. `max_speed`).
    """

    name: str
    unit: str
    default: float | None
    per_actor_default: bool = False
    sign: str | None = None
    limit: str | None = None

    @property
    def required(self) -> bool:
        """A parameter without a language default must be given at the logical and concrete levels."""
        return self.default is None and not self.per_actor_default


@cache
def _ecore_classes() -> dict[str, EClass]:
    """The EClasses of the shipped .ecore, by name, with their annotations."""
    resource_set = ResourceSet()
    ecore_file = importlib.resources.files("sceml.metamodel") / "scemlmodel.ecore"
    with importlib.resources.as_file(ecore_file) as path:
        resource = resource_set.get_resource(URI(str(path)))
    package = resource.contents[0]
    return {c.name: c for c in package.eClassifiers if isinstance(c, EClass)}


def _annotation(eclass: EClass, source: str) -> dict[str, str]:
    for annotation in eclass.eAnnotations:
        if annotation.source == source:
            return dict(annotation.details.items())
    return {}


def _inherited_annotation(class_name: str, source: str) -> dict[str, str]:
    """Annotation details merged along the superclass chain; the most specific class wins."""
    eclass = _ecore_classes()[class_name]
    merged: dict[str, str] = {}
    for ancestor in reversed([eclass, *eclass.eAllSuperTypes()]):
        merged.update(_annotation(ancestor, source))
    return merged


def class_name(kind: EObject | EClass | type | str) -> str:
    """The metaclass name of an object, an EClass, a generated class or a name."""
    if isinstance(kind, str):
        return kind
    if isinstance(kind, EClass):
        return str(kind.name)
    if isinstance(kind, type):
        return kind.__name__
    return str(kind.eClass.name)


# Every question is cached by metaclass name, never by the object asked about: a cache keyed by
# model objects would keep every scenario ever exported or drawn alive.


def category(kind: EObject | EClass | type | str) -> str | None:
    """`longitudinal`, `lateral`, `composite` or `condition` for action nodes, else None."""
    return _node_details(class_name(kind)).get("category")


def complexity(kind: EObject | EClass | type | str) -> int | None:
    """The read-only complexity level the paper shows in a node's properties."""
    value = _node_details(class_name(kind)).get("complexity")
    return int(value) if value is not None else None


def needs_target(kind: EObject | EClass | type | str) -> bool:
    """Whether the node kind needs a target actor besides its reference actor."""
    return _node_details(class_name(kind)).get("needsTarget") == "true"


@cache
def _node_details(name: str) -> dict[str, str]:
    return _inherited_annotation(name, NODE_ANNOTATION)


def parameters(kind: EObject | EClass | type | str) -> tuple[ParameterSpec, ...]:
    """The numeric parameters of a kind, inherited ones first, in metamodel order."""
    return _parameters(class_name(kind))


@cache
def _parameters(name: str) -> tuple[ParameterSpec, ...]:
    eclass = _ecore_classes()[name]
    specs = []
    for feature in eclass.eAllStructuralFeatures():
        if not isinstance(feature, EReference) or feature.eType.name != "ParameterValue":
            continue
        details = next(
            (
                dict(a.details.items())
                for a in feature.eAnnotations
                if a.source == PARAMETER_ANNOTATION
            ),
            {},
        )
        raw_default = details.get("default")
        per_actor = raw_default == ACTOR_DEFAULT
        default = None if raw_default is None or per_actor else float(raw_default)
        specs.append(
            ParameterSpec(
                feature.name,
                details.get("unit", ""),
                default,
                per_actor,
                details.get("sign"),
                details.get("limit"),
            )
        )
    return tuple(specs)


def parameter(kind: EObject | EClass | type | str, name: str) -> ParameterSpec:
    """One parameter spec by name; KeyError if the kind has no such parameter."""
    for spec in parameters(kind):
        if spec.name == name:
            return spec
    raise KeyError(f"{class_name(kind)} has no parameter {name!r}")


def sign(kind: EObject | EClass | type | str, name: str) -> str | None:
    """`positive`, `nonNegative` or None: what the metamodel requires of a parameter's numbers.

    None as well for a feature that is no annotated parameter (an override's value, say).
    """
    try:
        return parameter(kind, name).sign
    except KeyError:
        return None


def limited(kind: EObject | EClass | type | str, limit: str) -> tuple[str, ...]:
    """The parameters of a kind that an actor limit (e.g. `max_speed`) bounds."""
    return tuple(spec.name for spec in parameters(kind) if spec.limit == limit)


def limited_kinds() -> tuple[str, ...]:
    """Every metaclass that declares a parameter bounded by an actor limit, in metamodel order."""
    return tuple(
        name
        for name, eclass in _ecore_classes().items()
        if any(_declares_limit(feature) for feature in eclass.eStructuralFeatures)
    )


def _declares_limit(feature: object) -> bool:
    return any(
        a.source == PARAMETER_ANNOTATION and "limit" in dict(a.details.items())
        for a in getattr(feature, "eAnnotations", ())
    )


def actor_dimensions(kind: EObject | EClass | type | str) -> dict[str, float]:
    """Default bounding box (length, width, height in m) of an actor kind."""
    return dict(_actor_dimensions(class_name(kind)))


@cache
def _actor_dimensions(name: str) -> tuple[tuple[str, float], ...]:
    details = _inherited_annotation(name, ACTOR_ANNOTATION)
    return tuple((key, float(value)) for key, value in details.items())


def concrete_subclasses(base: str) -> tuple[type, ...]:
    """Generated classes of every non-abstract kind below `base` (itself included)."""
    classes = _ecore_classes()
    result = []
    for name, eclass in classes.items():
        if eclass.abstract:
            continue
        if name == base or base in {s.name for s in eclass.eAllSuperTypes()}:
            result.append(getattr(scm, name))
    return tuple(result)


def action_node_kinds() -> tuple[type, ...]:
    """Every maneuver and condition kind."""
    return concrete_subclasses("ActionNode")


def actor_kinds() -> tuple[type, ...]:
    """Every concrete actor kind."""
    return concrete_subclasses("Actor")


def is_kind_of(obj_or_class: EObject | str, kind_name: str) -> bool:
    """Whether a metaclass (by object or name) is `kind_name` or one of its subclasses."""
    return _is_kind_of(class_name(obj_or_class), kind_name)


@cache
def _is_kind_of(name: str, kind_name: str) -> bool:
    # Cached by name: pyecore recomputes eAllSuperTypes on every call, and validation asks this
    # for every node of every sample in a batch.
    eclass = _ecore_classes()[name]
    return eclass.name == kind_name or kind_name in {s.name for s in eclass.eAllSuperTypes()}
