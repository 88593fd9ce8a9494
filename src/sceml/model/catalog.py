"""What the metamodel says about each kind: categories, parameters, units and language defaults.

The generated classes carry no EAnnotations, so these facts come from the `.ecore`, which stays
the single source of truth: `sceml dev generate` writes what the catalog reads of it beside the
generated classes (`sceml.model.ecore_facts`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from pyecore.ecore import EClass, EObject

import scemlmodel as scm

NODE_ANNOTATION = "http://sceml.org/node"
PARAMETER_ANNOTATION = "http://sceml.org/parameter"
ACTOR_ANNOTATION = "http://sceml.org/actor"

#: A parameter whose default depends on the actor kind (its bounding box).
ACTOR_DEFAULT = "actor"

#: Signs a parameter annotation may state: above zero, zero and above, or either sign where the
#: sign has a meaning of its own (a speed below zero is driving backwards, release 1.4).
POSITIVE = "positive"
NON_NEGATIVE = "nonNegative"
SIGNED = "signed"

CATEGORIES = (
    "longitudinal",
    "lateral",
    "composite",
    "controller",
    "appearance",
    "coupling",
    "condition",
    "global",
)

#: Features that only say how a node is drawn (the editor's layout); never a parameter or a meaning.
NOTATION_FEATURES = frozenset({"diagramPosition"})


@dataclass(frozen=True)
class ParameterSpec:
    """One numeric parameter of a kind: its feature name, SI unit and language default.

    `sign` is `positive` (above zero), `nonNegative` (zero or above), `signed` (any number, the
    sign meaning a direction: a negative speed reverses) or None (any number);
    `limit` names the actor limit that bounds it (a key of the limits file, e.g. `max_speed`).
    `optional` (annotation `optional="true"`): unset has a meaning of its own, so no level
    requires it (a road position's h: unset follows the lane).
    """

    name: str
    unit: str
    default: float | None
    per_actor_default: bool = False
    sign: str | None = None
    limit: str | None = None
    optional: bool = False

    @property
    def required(self) -> bool:
        """A parameter without a language default must be given at the logical and concrete levels."""
        return self.default is None and not self.per_actor_default and not self.optional


@dataclass(frozen=True)
class _Feature:
    """What the catalog reads of one structural feature in the .ecore."""

    name: str
    type_name: str  # the EClass a reference holds; "" for an attribute
    annotations: dict[str, dict[str, str]]


@dataclass(frozen=True)
class _Class:
    """What the catalog reads of one EClass in the .ecore."""

    name: str
    abstract: bool
    supertypes: tuple[str, ...]
    annotations: dict[str, dict[str, str]]
    features: tuple[_Feature, ...]


@cache
def _ecore_classes() -> dict[str, _Class]:
    """The EClasses of the shipped .ecore, by name, in file order, with their annotations.

    Read from the module `sceml dev generate` writes beside the generated classes
    (`sceml.model.ecore_facts`; CI checks it against the .ecore): parsing the .ecore itself cost
    every command's start 5-10 ms, and building pyecore's dynamic metamodel from it about 20.
    """
    from scemlmodel._catalog_facts import CLASSES

    return {
        name: _Class(name, abstract, supertypes, annotations, tuple(_Feature(*f) for f in features))
        for name, (abstract, supertypes, annotations, features) in CLASSES.items()
    }


@cache
def _all_supertypes(name: str) -> tuple[str, ...]:
    """Every ancestor of a class, in the order pyecore's eAllSuperTypes gives them."""
    found: dict[str, None] = {}

    # Direct supertypes first, then each one's own, depth first, each once.
    def walk(current: str) -> None:
        direct = _ecore_classes()[current].supertypes
        for parent in direct:
            found.setdefault(parent, None)
        for parent in direct:
            walk(parent)

    walk(name)
    return tuple(found)


def _all_features(name: str) -> list[_Feature]:
    """A class's features, then its supertypes', depth first, each once (pyecore's order)."""
    seen: dict[str, _Feature] = {}

    def walk(current: str) -> None:
        eclass = _ecore_classes()[current]
        for feature in eclass.features:
            seen.setdefault(f"{current}.{feature.name}", feature)
        for parent in eclass.supertypes:
            walk(parent)

    walk(name)
    return list(seen.values())


def _annotation(eclass: _Class, source: str) -> dict[str, str]:
    return dict(eclass.annotations.get(source, {}))


def _inherited_annotation(class_name: str, source: str) -> dict[str, str]:
    """Annotation details merged along the superclass chain; the most specific class wins."""
    classes = _ecore_classes()
    merged: dict[str, str] = {}
    for ancestor in reversed([class_name, *_all_supertypes(class_name)]):
        merged.update(_annotation(classes[ancestor], source))
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
    """`longitudinal`, `lateral`, `composite`, `controller`, `appearance`, `coupling`,
    `condition` or `global` for action nodes (`opaque` for an OpaqueAction), else None."""
    return _node_details(class_name(kind)).get("category")


def complexity(kind: EObject | EClass | type | str) -> int | None:
    """The read-only complexity level the paper shows in a node's properties."""
    value = _node_details(class_name(kind)).get("complexity")
    return int(value) if value is not None else None


def needs_target(kind: EObject | EClass | type | str) -> bool:
    """Whether the node kind needs a target actor besides its reference actor."""
    return _node_details(class_name(kind)).get("needsTarget") == "true"


def performed_by_actor(kind: EObject | EClass | type | str) -> bool:
    """Whether a node of the kind has a reference actor; a global kind (annotation
    `actor="none"`: a parameter, variable or traffic signal node) is performed by no actor."""
    return _node_details(class_name(kind)).get("actor") != "none"


def allows_target(kind: EObject | EClass | type | str) -> bool:
    """Whether the node kind uses a target actor when it has one (needed, or optional as a
    LaneChange's relative to another actor's lane)."""
    details = _node_details(class_name(kind))
    return needs_target(kind) or details.get("optionalTarget") == "true"


@cache
def _node_details(name: str) -> dict[str, str]:
    return _inherited_annotation(name, NODE_ANNOTATION)


def parameters(kind: EObject | EClass | type | str) -> tuple[ParameterSpec, ...]:
    """The numeric parameters of a kind, inherited ones first, in metamodel order."""
    return _parameters(class_name(kind))


@cache
def _parameters(name: str) -> tuple[ParameterSpec, ...]:
    specs = []
    for feature in _all_features(name):
        if feature.type_name != "ParameterValue":
            continue
        details = feature.annotations.get(PARAMETER_ANNOTATION, {})
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
                details.get("optional") == "true",
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
    """`positive`, `nonNegative`, `signed` or None: what the metamodel says of a parameter's sign.

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
        if any("limit" in f.annotations.get(PARAMETER_ANNOTATION, {}) for f in eclass.features)
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
        if name == base or base in _all_supertypes(name):
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
    return name == kind_name or kind_name in _all_supertypes(name)
