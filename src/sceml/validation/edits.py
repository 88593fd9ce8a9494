"""What an edit changed: the objects it touched, and the aspects of the model it changed.

The editor records every edit as small changes (`Change`: a feature of an owner went from one
value to another; sceml.editor.changes). `Impact` turns a list of them into what incremental
validation (sceml.validation.incremental) needs to know: which objects were touched, which
objects hold one or lie next to one, which actors were touched, and which `Aspect`s changed.
"""

from __future__ import annotations

from collections.abc import Iterable
from enum import Flag, auto
from typing import NamedTuple

from pyecore.ecore import EObject, EProxy, EReference

import scemlmodel as scm

from ..model.traversal import all_contents, root_of, single_references

__all__ = ["EVERYTHING", "Aspect", "Change", "Impact", "aspects_of", "placed_alone", "refers_to"]


class Change(NamedTuple):
    """One small change: `feature` of `owner` went from `old` to `new`.

    For a many-valued feature, an insertion has `old` None and the item as `new`, a removal the
    other way round. Undoing or redoing a change changes the same things, so the same record
    serves all three.
    """

    owner: EObject
    feature: str
    old: object = None
    new: object = None


class Aspect(Flag):
    """What an edit can change across the model; a rule reading one re-runs wherever it applies."""

    NONE = 0
    #: Which nodes and flows a graph holds, in which order and of which kinds; where flows lead.
    STRUCTURE = auto()
    #: The names of nodes, module uses, actors, roles and modules.
    NAMES = auto()
    #: Which actor or role each node and each role binding refers to.
    ROLES = auto()
    #: The declared actors and roles: which, of which kind, allowed kinds, the ego flag.
    CAST = auto()
    #: Module uses (definition, bindings, overrides) and everything module definitions hold.
    MODULES = auto()
    #: Which node is the scenario's root node, and its level and map.
    SETTINGS = auto()
    #: Positions (start positions, destinations, waypoints) and the values in them.
    POSITIONS = auto()
    #: Parameter values other than positions: speeds, rates, durations, sizes, environment.
    PARAMETERS = auto()
    #: Plain attributes no graph-wide rule reads: direction, comparison rule, opaque XML, date.
    ATTRIBUTES = auto()


EVERYTHING = (
    Aspect.STRUCTURE
    | Aspect.NAMES
    | Aspect.ROLES
    | Aspect.CAST
    | Aspect.MODULES
    | Aspect.SETTINGS
    | Aspect.POSITIONS
    | Aspect.PARAMETERS
    | Aspect.ATTRIBUTES
)


#: Features by name whose changes matter beyond their owner. A feature not named here is judged
#: by its type (`_by_type`): a parameter value, a position, a plain attribute, or else everything.
_FEATURES: dict[str, Aspect] = {
    # A node comes or goes with all it holds.
    "nodes": Aspect.STRUCTURE | Aspect.NAMES | Aspect.ROLES | Aspect.MODULES,
    "flows": Aspect.STRUCTURE,
    "source": Aspect.STRUCTURE,
    "target": Aspect.STRUCTURE,
    "incoming": Aspect.STRUCTURE,
    "outgoing": Aspect.STRUCTURE,
    "name": Aspect.NAMES,
    "referenceActor": Aspect.ROLES,
    "targetActor": Aspect.ROLES,
    "actor": Aspect.ROLES | Aspect.MODULES,
    "actors": Aspect.CAST,
    "isEgo": Aspect.CAST,
    # Which actor tows which: who needs a start of its own (SCEML-E002), towing loops (A009).
    "trailer": Aspect.CAST,
    "roles": Aspect.CAST | Aspect.MODULES,
    "allowedKinds": Aspect.CAST | Aspect.MODULES,
    "kind": Aspect.CAST | Aspect.MODULES,
    "level": Aspect.SETTINGS,
    "map": Aspect.SETTINGS,
    # The folder actors' catalog entries are looked up in (SCEML-A011).
    "vehicleCatalog": Aspect.SETTINGS,
    "definition": Aspect.STRUCTURE | Aspect.MODULES,
    "bindings": Aspect.MODULES,
    "overrides": Aspect.MODULES,
    "role": Aspect.MODULES,
    "parameter": Aspect.MODULES,
    "parameters": Aspect.MODULES,
    "default": Aspect.MODULES,
    "modules": EVERYTHING,
    # Which maneuvers may run together (SCEML-C001 reads it with the graph's shape).
    "interrupts": Aspect.STRUCTURE,
}


def _is_notation(change: Change) -> bool:
    """Diagram positions: no rule reads them (validation ignores the layout, docs/editor.md)."""
    return change.feature == "diagramPosition" or isinstance(change.owner, scm.DiagramPosition)


def _by_type(owner: EObject, name: str) -> Aspect:
    feature = owner.eClass.findEStructuralFeature(name)
    if feature is None:
        return EVERYTHING
    if not isinstance(feature, EReference):
        return Aspect.ATTRIBUTES
    kind = feature.eType
    if feature.containment and isinstance(kind, type) and issubclass(kind, scm.Position):
        return Aspect.POSITIONS
    if feature.containment and isinstance(kind, type) and issubclass(kind, scm.ParameterValue):
        return Aspect.PARAMETERS
    if feature.containment and kind is scm.Environment:
        return Aspect.PARAMETERS | Aspect.ATTRIBUTES
    return EVERYTHING


def _where(owner: EObject) -> Aspect:
    """What a change means by where its owner lies: in a position, a value, a module."""
    found = Aspect.NONE
    current: EObject | None = owner
    while current is not None:
        if isinstance(current, scm.Position):
            found |= Aspect.POSITIONS
        elif isinstance(current, scm.ParameterValue):
            found |= Aspect.PARAMETERS
        elif isinstance(current, scm.ModuleUse | scm.ModuleDefinition | scm.Library):
            found |= Aspect.MODULES
        current = current.eContainer()
    return found


def _refers_out(obj: EObject) -> bool:
    """Whether anything in `obj` refers to another object (a parameter reference, an actor):
    expanding module uses checks every such reference."""
    return any(
        next(single_references(held), None) is not None for held in (obj, *all_contents(obj))
    )


def aspects_of(change: Change) -> Aspect:
    """Which aspects of the model one change changes (none for a diagram position)."""
    if _is_notation(change):
        return Aspect.NONE
    owner, name = change.owner, change.feature
    found = _FEATURES.get(name)
    if found is None:
        found = _by_type(owner, name)
    found |= _where(owner)
    feature = owner.eClass.findEStructuralFeature(name)
    held = isinstance(feature, EReference) and feature.containment
    for value in (change.old, change.new):
        if not isinstance(value, EObject):
            continue
        if name == "nodes" and isinstance(value, scm.RootNode):
            found |= Aspect.SETTINGS | Aspect.CAST  # which root node, so which level, map, cast
        if held and _refers_out(value):
            found |= Aspect.ROLES | Aspect.MODULES
    return found


#: Nodes that can stand alone: not a module use (expanded), root or end (the scenario's level,
#: map and cast), nor a port (a module's).
_ALONE_KINDS = (scm.ActionNode, scm.JoiningPolicy)


def placed_alone(change: Change) -> scm.GraphElement | None:
    """The node a change put into a scenario, when it stands there alone: an action node or a
    join, in the scenario now, with no flow at it, referring only to what the scenario holds.

    Such a node (a node dropped from the palette) changes no other node's findings: no path
    leads through it, and expanding the module uses reads only its name. So the change makes
    the rules on the node and on its scenario run again, not every rule reading the graph's
    shape (`Impact.graphs`). The state is judged now, not from `old` and `new`: undoing the
    insertion gives the same record, with the node gone.
    """
    node, scenario = change.new, change.owner
    if change.feature != "nodes" or change.old is not None:
        return None
    if not isinstance(scenario, scm.Scenario) or not isinstance(node, _ALONE_KINDS):
        return None
    if node.eContainer() is not scenario or len(node.incoming) or len(node.outgoing):
        return None
    for held in (node, *all_contents(node)):
        for _, target in single_references(held):
            # A proxy, or an object of another file, would make the expansion fail on it.
            if type(target) is EProxy or root_of(target) is not scenario:
                return None
    return node


def _moves(owner: EObject, name: str) -> bool:
    """Whether the values of this feature are themselves changed by the change: contained
    objects move, a flow's ends gain or lose it in `incoming` and `outgoing`."""
    feature = owner.eClass.findEStructuralFeature(name)
    if not isinstance(feature, EReference):
        return feature is None
    return bool(feature.containment or feature.many or feature.eOpposite is not None)


class Impact:
    """What a list of changes touched, worked out once per run."""

    def __init__(self, changes: Iterable[Change], *, alone: bool = True) -> None:
        """With `alone` False, a node placed alone counts as any other insertion: the caller
        cannot show that the expansion of module uses stays the same around it."""
        self.aspects = Aspect.NONE
        self.touched: set[EObject] = set()
        # Nodes placed alone (`placed_alone`), and the graphs whose every rule runs again.
        self.alone: dict[EObject, scm.Scenario] = {}
        self.graphs: set[EObject] = set()
        #: Whether every change (diagram positions aside) placed a node alone.
        self.only_alone = True
        for change in changes:
            if _is_notation(change):
                continue
            node = placed_alone(change) if alone else None
            if node is not None:
                self.alone[node] = change.owner
                self.graphs.add(change.owner)
            else:
                self.only_alone = False
                self.aspects |= aspects_of(change)
            self.touched.add(change.owner)
            if _moves(change.owner, change.feature):
                self.touched.update(v for v in (change.old, change.new) if isinstance(v, EObject))
        # SELF: touched, or holding a touched object, or a flow or node next to a touched one.
        self.around: set[EObject] = set()
        # ABOVE: held by a touched object.
        self.inside: set[EObject] = set()
        # ACTORS: the ids of actors and roles touched or holding a touched object.
        self.participants: set[int] = set()
        for obj in self.touched:
            self._spread(obj)

    def _spread(self, obj: EObject) -> None:
        current: EObject | None = obj
        while current is not None:
            self.around.add(current)
            if isinstance(current, scm.Participant):
                self.participants.add(id(current))
            current = current.eContainer()
        if isinstance(obj, scm.Flow):
            self.around.update(end for end in (obj.source, obj.target) if end is not None)
        if isinstance(obj, scm.GraphElement):
            self.around.update(obj.incoming)
            self.around.update(obj.outgoing)
        if not isinstance(obj, scm.Graph | scm.Library):
            # A graph holds everything; what lies above a node (the graph) no ABOVE rule reads.
            self.inside.update(all_contents(obj))

    def moved(self, element: EObject) -> bool:
        """Whether `element` or anything above it was touched: its fragment, path or line may
        differ (an index in a list, a name)."""
        current: EObject | None = element
        while current is not None:
            if current in self.touched:
                return True
            current = current.eContainer()
        return False


def refers_to(obj: EObject, participants: set[int]) -> bool:
    """Whether `obj`, its node, binding or use refers to one of these participants (by id)."""
    current: EObject | None = obj
    while current is not None and not isinstance(current, scm.Graph | scm.Library):
        if isinstance(current, scm.ActionNode):
            held = [current.referenceActor, current.targetActor]
        elif isinstance(current, scm.RoleBinding):
            held = [current.actor]
        elif isinstance(current, scm.ModuleUse):
            held = [binding.actor for binding in current.bindings]
        elif isinstance(current, scm.Participant):
            held = [current]
        else:
            current = current.eContainer()
            continue
        return any(id(p) in participants for p in held if p is not None)
    return False
