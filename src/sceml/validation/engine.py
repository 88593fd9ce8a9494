"""One validation pass: every object against every rule of its metaclass, module internals included."""

from __future__ import annotations

from collections.abc import Hashable, Iterable, Iterator

from pyecore.ecore import EClass, EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..model.collector import collector_paused
from ..model.documents import Document
from ..model.locating import model_path, uri_fragment
from ..model.traversal import all_contents
from ..modules.bindings import binding_key
from .context import Context
from .edits import Aspect
from .limits import Limits
from .registry import REGISTRY, Check, Finding, Registry, Rule

INTERNAL_ERROR = "SCEML-X000"
#: A file saved with an older metamodel release, migrated as it was read (sceml.migrations).
OLDER_RELEASE = "SCEML-V001"


def iter_diagnostics(
    model: EObject,
    *,
    document: Document | None = None,
    limits: Limits | None = None,
    osc_version: str | None = None,
    osc_profile: str | None = None,
    registry: Registry = REGISTRY,
) -> Iterator[Diagnostic]:
    """Every diagnostic of a Scenario or Library, in one pass; never raises on a bad model.

    Module definitions a scenario uses (in library files) are checked too, once each, and reported
    in their own file. A rule that fails unexpectedly becomes a SCEML-X000 diagnostic.
    """
    context = Context(model, document, limits or Limits(), osc_version, osc_profile)
    seen: set[Key] = set()
    try:
        yield from unique(each_object(objects(model, context), context, document, registry), seen)
        yield from unique(through_modules(context, document, registry), seen)
    finally:
        context.release()


def each_object(
    found_objects: Iterable[EObject],
    context: Context,
    document: Document | None,
    registry: Registry = REGISTRY,
) -> Iterator[Diagnostic]:
    """The diagnostics of each object's own rules, in order, repeats included (`unique` drops
    them)."""
    # Each metaclass's rules with their checks, looked up once per class, not once per object.
    by_class: dict[EClass, tuple[tuple[Rule, Check], ...]] = {}
    for obj in found_objects:
        eclass = obj.eClass
        checks = by_class.get(eclass)
        if checks is None:
            checks = by_class[eclass] = tuple(
                (rule, rule.check) for rule in registry.rules_for(eclass)
            )
        for rule, check in checks:
            # `run_rule` inlined: this loop makes about 16 rule runs per node, most of which
            # find nothing, and the call was a tenth of a large scenario's validation.
            try:
                found = list(check(obj, context))
            except Exception as error:  # a broken model must not stop the run
                yield crashed(rule, error, obj, document)
                continue
            if found:
                yield from located(rule, found, document)


def through_modules(
    context: Context,
    document: Document | None,
    registry: Registry = REGISTRY,
    *,
    share: bool = True,
) -> Iterator[Diagnostic]:
    """The `through_modules` rules on the nodes the scenario's module uses expand to.

    Values a module use gives its internals exist only once expanded; they are checked there and
    reported at the use, where an engineer can change them. Nothing for a model without uses.

    Uses of a definition with the same binding (the same actors, equal values: `binding_key`)
    expand to copies that differ only in their names and places in the graph, so a rule that
    reads neither (`shares_clean_runs`) and found nothing on one use's copy of a node finds
    nothing on another's: it runs once per distinct binding. Where it found something it runs
    on every use, whose findings name that use's copies. `share=False` runs every rule on every
    use (what the tests compare against).
    """
    flat = context.flat()
    if flat is None:
        return
    by_class: dict[EClass, tuple[tuple[Rule, bool], ...]] = {}
    bindings = _Bindings()
    # For each definition's node and binding, the rule runs on its copy (numbered in the order
    # they are made: the same for every use of that binding) that found nothing, as bits.
    clean: dict[tuple[EObject, int], int] = {}
    # Those on which every rule that ran was shared and found nothing: another use of the same
    # binding need not walk its copy at all.
    clean_nodes: set[tuple[EObject, int]] = set()
    for node in flat.nodes:
        origin = flat.origins.get(node)
        if origin is None or not origin.uses:
            continue  # a node of the scenario's own graph: checked where it is
        at = origin.in_scenario
        binding = bindings.number(origin.uses) if share else None
        if binding is None:
            for obj in (node, *all_contents(node)):
                for rule, _ in _through_rules(obj.eClass, registry, by_class):
                    yield from run_rule(rule, obj, context, document, at=at)
            continue
        copy_of = (origin.element, binding)
        if copy_of in clean_nodes:
            continue
        known = clean.get(copy_of, 0)
        found_clean = 0
        all_clean = True
        run = 0
        for obj in (node, *all_contents(node)):
            for rule, shared in _through_rules(obj.eClass, registry, by_class):
                bit = 1 << run
                run += 1
                if not shared:
                    all_clean = False
                    yield from run_rule(rule, obj, context, document, at=at)
                elif known & bit:
                    found_clean |= bit
                elif found := run_rule(rule, obj, context, document, at=at):
                    all_clean = False
                    yield from found
                else:
                    found_clean |= bit
        clean[copy_of] = known | found_clean
        if all_clean:
            clean_nodes.add(copy_of)


def _through_rules(
    eclass: EClass, registry: Registry, by_class: dict[EClass, tuple[tuple[Rule, bool], ...]]
) -> tuple[tuple[Rule, bool], ...]:
    """The `through_modules` rules of a metaclass, each with whether it shares clean runs."""
    rules = by_class.get(eclass)
    if rules is None:
        rules = by_class[eclass] = tuple(
            (rule, shares_clean_runs(rule))
            for rule in registry.rules_for(eclass)
            if rule.through_modules
        )
    return rules


#: What a rule must not read for its clean run on one use's copies to hold for another use of
#: the same binding: the graph around the node (the expanded flows) and names.
_PER_USE = Aspect.STRUCTURE | Aspect.NAMES


def shares_clean_runs(rule: Rule) -> bool:
    """Whether a rule's finding nothing on a copy holds for every use of the same binding: it
    declares what it reads, and that is neither the graph's shape nor names."""
    return rule.reads is not None and not rule.reads.aspects & _PER_USE


class _Bindings:
    """Each chain of uses numbered by its binding (`binding_key`): uses with the same key get the
    same number; only the distinct keys are kept, not one per use."""

    def __init__(self) -> None:
        self._by_uses: dict[tuple[scm.ModuleUse, ...], int | None] = {}
        self._by_key: dict[Hashable, int] = {}

    def number(self, uses: tuple[scm.ModuleUse, ...]) -> int | None:
        """The binding's number; None for a use the key cannot read (checked on its own)."""
        if uses not in self._by_uses:
            try:
                key = binding_key(uses)
            except Exception:  # e.g. a broken model pyecore refuses to read
                self._by_uses[uses] = None
            else:
                self._by_uses[uses] = self._by_key.setdefault(key, len(self._by_key))
        return self._by_uses[uses]


def validate(model: EObject, *, jobs: int = 1, **options: object) -> list[Diagnostic]:
    """The list of every diagnostic (see `iter_diagnostics`).

    With `jobs` > 1, a large scenario is checked in two processes where the system allows it
    (`sceml.validation.split`), with the same diagnostics in the same order.
    """
    with collector_paused():
        if jobs > 1:
            from .split import validate_split, worth_splitting

            if worth_splitting(model):
                return validate_split(model, **options)  # type: ignore[arg-type]
        return list(iter_diagnostics(model, **options))  # type: ignore[arg-type]


def is_valid(model: EObject, **options: object) -> bool:
    """Whether the model has no ERROR diagnostic (warnings and infos are allowed)."""
    diagnostics = iter_diagnostics(model, **options)  # type: ignore[arg-type]
    return not any(d.severity is Severity.ERROR for d in diagnostics)


def objects(model: EObject, context: Context) -> Iterator[EObject]:
    """The model, its contents, and the contents of every module definition reached from it."""
    visited: set[EObject] = set(model.modules) if isinstance(model, scm.Library) else set()
    pending: list[EObject] = [model]
    while pending:
        top = pending.pop(0)
        for obj in (top, *all_contents(top)):
            yield obj
            if isinstance(obj, scm.ModuleUse):
                definition = context.definition_of(obj)
                if definition is not None and definition not in visited:
                    visited.add(definition)
                    pending.append(definition)


#: What makes two diagnostics the same: code, message, fragment and file.
Key = tuple[str, str, str | None, str | None]


def unique(diagnostics: Iterable[Diagnostic], seen: set[Key]) -> Iterator[Diagnostic]:
    """The diagnostics not yet in `seen` (which records them): a finding is reported once."""
    for diagnostic in diagnostics:
        key = (diagnostic.code, diagnostic.message, diagnostic.fragment, diagnostic.file)
        if key not in seen:
            seen.add(key)
            yield diagnostic


def run_rule(
    rule: Rule,
    obj: EObject,
    context: Context,
    document: Document | None,
    at: EObject | None = None,
) -> list[Diagnostic]:
    """One rule on one object, located at `at` if given; a crash becomes SCEML-X000."""
    try:
        # Materialised, so that a failure midway is caught as a whole.
        found = list(rule.check(obj, context))
    except Exception as error:  # a broken model must not stop the run; report and go on
        return [crashed(rule, error, at or obj, document)]
    # Most runs find nothing: no list of diagnostics to build then.
    return located(rule, found, document, at) if found else []


def crashed(
    rule: Rule, error: Exception, element: EObject, document: Document | None
) -> Diagnostic:
    """The SCEML-X000 diagnostic of a rule that failed on `element`."""
    message = f"internal error in {rule.code} ({rule.name}): {type(error).__name__}: {error}"
    return locate(INTERNAL_ERROR, Severity.ERROR, message, element, document)


def located(
    rule: Rule,
    found: list[Finding],
    document: Document | None,
    at: EObject | None = None,
) -> list[Diagnostic]:
    """The diagnostics of a rule's findings, each located at its element (or at `at`)."""
    return [
        locate(rule.code, rule.severity, message, at or element, document)
        for element, message in found
    ]


def locate(
    code: str, severity: Severity, message: str, element: EObject, document: Document | None
) -> Diagnostic:
    """A diagnostic about `element`, with its fragment, readable path, file and line."""
    fragment = path = file = line = None
    try:
        fragment = uri_fragment(element)
        path = model_path(element)
        if document is not None:
            file, line = document.where(element)
    except Exception:  # locating is best effort; the finding itself must get through
        pass
    return Diagnostic(severity, code, message, fragment, path or None, file, line, element)
