"""The review report: one self-contained HTML page with the diagram, diagnostics, actors and parameters.

Each diagnostic links to the diagram elements that show the element it is about (or the nearest
drawn container: a parameter of a node highlights the node, an actor the root box, a node inside
a module definition every expanded use of it). Clicking a diagnostic adds the `sceml-highlight`
class to those SVG groups. No network resource is used: CSS, JavaScript and SVG are inline.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from lxml import etree
from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..files.safexml import hardened_parser
from ..model import catalog, params
from ..model.documents import Document
from ..model.graph import actors, root_node
from ..render import MAX_DIAGRAM_NODES, labels, to_bytes
from ..render.flow import Modules, flow_diagram
from ..templating import template
from .figure import Figure

_SVG_NAMESPACE = "http://www.w3.org/2000/svg"
TEMPLATE = "report.html.j2"


@dataclass(frozen=True)
class DiagnosticRow:
    """One diagnostic as the report lists it, with the SVG ids it highlights."""

    diagnostic: Diagnostic
    targets: tuple[str, ...]

    @property
    def severity(self) -> str:
        return str(self.diagnostic.severity)

    @property
    def where(self) -> str:
        """`file:line` of the diagnostic, as far as known."""
        diagnostic = self.diagnostic
        where = Path(diagnostic.file).name if diagnostic.file else ""
        return where + (f":{diagnostic.line}" if diagnostic.line else "")


@dataclass(frozen=True)
class ParameterRow:
    """One parameter of one node: what the model holds, or the default it falls back to."""

    name: str
    shown: str
    unit: str
    status: str


@dataclass(frozen=True)
class NodeRow:
    """A node of the parameter table."""

    name: str
    kind: str
    category: str
    actors: str
    targets: tuple[str, ...]
    parameters: tuple[ParameterRow, ...]


def build_report(
    document: Document,
    diagnostics: Sequence[Diagnostic] | None,
    *,
    modules: Modules = "expanded",
    figures: Sequence[Figure] = (),
) -> str:
    """The report as HTML text; `diagnostics` None means validation was not run.

    `figures` are drawn after the scenario's diagram, in the order given.
    """
    root = document.root
    diagram = flow_diagram(root, modules=modules)
    rows = [
        DiagnosticRow(d, tuple(_targets(d, document, diagram.ids)))
        for d in sorted(diagnostics or (), key=lambda d: (-d.severity, d.line or 0, d.code))
    ]
    # Graphviz cannot lay out a diagram of tens of thousands of boxes in reasonable time or
    # memory; the report then says so and keeps its tables.
    boxes = sum(len(ids) for ids in diagram.ids.values())
    too_large = boxes > MAX_DIAGRAM_NODES
    svg = "" if too_large else _mark(to_bytes(diagram.graph, "svg"), rows)
    scenario = root if isinstance(root, scm.Scenario) else None
    return template(TEMPLATE).render(
        title=_title(document),
        file=document.path.name,
        root=root_node(scenario) if scenario is not None else None,
        svg=svg,
        omitted=f"{boxes:,} boxes, more than the {MAX_DIAGRAM_NODES:,} drawn"
        if too_large
        else None,
        figures=figures,
        validated=diagnostics is not None,
        rows=rows,
        counts={s: sum(r.diagnostic.severity == s for r in rows) for s in reversed(Severity)},
        actors=[_actor_row(actor) for actor in (actors(scenario) if scenario else [])],
        nodes=list(_node_rows(root, diagram.ids)),
    )


def _title(document: Document) -> str:
    root = document.root
    if isinstance(root, scm.Scenario):
        return f"Scenario {labels.scenario_title(root)}"
    return f"Module library {root.name or document.path.name}"


def _element_of(diagnostic: Diagnostic, document: Document) -> EObject | None:
    if diagnostic.element is not None:
        return diagnostic.element
    if not diagnostic.fragment:
        return None
    resource = document.resource
    if diagnostic.file and Path(diagnostic.file).resolve() != document.path.resolve():
        wanted = Path(diagnostic.file).resolve()
        resource = next(
            (
                r
                for r in document.resource_set.resources.values()
                if Path(r.uri.normalize()).resolve() == wanted
            ),
            None,
        )
    if resource is None:
        return None
    try:
        return resource.resolve(diagnostic.fragment)
    except Exception:  # pyecore raises assorted errors for fragments that do not resolve
        return None


def _targets(
    diagnostic: Diagnostic, document: Document, ids: dict[EObject, list[str]]
) -> Iterator[str]:
    """The SVG ids of the nearest drawn element that holds the diagnostic's element."""
    current = _element_of(diagnostic, document)
    while current is not None:
        if current in ids:
            yield from ids[current]
            return
        if isinstance(current, scm.Actor):
            current = root_node(current.eContainer().eContainer())
            continue
        current = current.eContainer()


def _mark(svg_bytes: bytes, rows: list[DiagnosticRow]) -> str:
    """The SVG element as text, with elements that carry diagnostics marked by severity."""
    svg = etree.fromstring(svg_bytes, parser=hardened_parser())
    worst: dict[str, Severity] = {}
    for row in rows:
        for target in row.targets:
            worst[target] = max(worst.get(target, Severity.INFO), row.diagnostic.severity)
    for group in svg.iter(f"{{{_SVG_NAMESPACE}}}g"):
        severity = worst.get(group.get("id", ""))
        if severity is not None:
            group.set("class", f"{group.get('class', '')} sceml-has-{severity}")
    text: str = etree.tostring(svg, encoding="unicode")
    return text


def _actor_row(actor: scm.Actor) -> dict[str, str]:
    scope = labels.Scope()
    return {
        "name": str(actor.name),
        "kind": actor.eClass.name,
        "ego": "yes" if actor.isEgo else "",
        "model": str(actor.model or ""),
        "start": labels.describe_position(actor.startPosition, scope),
        "speed": labels.describe_value(actor.initialSpeed, "m/s", scope)
        if actor.initialSpeed is not None
        else "default 0 m/s",
        "size": " × ".join(
            params.describe(actor.eGet(d)) if actor.eGet(d) is not None else f"{v:g}"
            for d, v in catalog.actor_dimensions(actor).items()
        )
        + " m",
    }


def _node_rows(root: EObject, ids: dict[EObject, list[str]]) -> Iterator[NodeRow]:
    """Every action node and module use the diagram shows, in model order."""
    for obj in [root, *root.eAllContents()]:
        if not isinstance(obj, scm.ActionNode | scm.ModuleUse):
            continue
        scope = labels.Scope()
        if isinstance(obj, scm.ModuleUse):
            yield _use_row(obj, ids)
            continue
        yield NodeRow(
            str(obj.name),
            obj.eClass.name,
            catalog.category(obj) or "",
            labels.actor_line(obj, scope),
            tuple(ids.get(obj, ())),
            tuple(_parameter_rows(obj, scope)),
        )


def _use_row(use: scm.ModuleUse, ids: dict[EObject, list[str]]) -> NodeRow:
    """A module use: its bindings as actors, its overrides and the defaults it leaves alone."""
    scope = labels.Scope()
    bindings = ", ".join(
        f"{b.role} = {labels.participant_text(b.actor, scope)}" for b in use.bindings
    )
    definition = labels.loaded_definition(use)
    declared = {str(p.name): p for p in (definition.parameters if definition else ())}
    rows = []
    for override in use.overrides:
        parameter = declared.get(str(override.parameter))
        unit = str(parameter.unit or "") if parameter is not None else ""
        shown = labels.describe_value(override.value, unit, scope)
        rows.append(ParameterRow(str(override.parameter), shown, unit, "override"))
    overridden = {str(o.parameter) for o in use.overrides}
    for name, parameter in declared.items():
        if name not in overridden:
            unit = str(parameter.unit or "")
            default = parameter.default
            shown = params.describe(default, unit) if default is not None else "—"
            rows.append(ParameterRow(name, shown, unit, "default" if default else "missing"))
    kind = f"module {definition.name}" if definition is not None else "module (not found)"
    return NodeRow(str(use.name), kind, "module", bindings, tuple(ids.get(use, ())), tuple(rows))


def _parameter_rows(node: scm.ActionNode, scope: labels.Scope) -> Iterator[ParameterRow]:
    set_items = dict(labels.parameter_items(node, scope))
    specs = {spec.name: spec for spec in catalog.parameters(node)}
    for name, shown in set_items.items():
        spec = specs.get(name)
        yield ParameterRow(name, shown, labels.unit_text(spec.unit) if spec else "", "set")
    for name, spec in specs.items():
        if name in set_items:
            continue
        if spec.required:
            yield ParameterRow(name, "—", labels.unit_text(spec.unit), "missing")
        elif spec.per_actor_default:
            yield ParameterRow(name, "actor's size", labels.unit_text(spec.unit), "default")
        elif spec.default is None:
            # An optional parameter whose absence has its own meaning (a Follow's limits: the
            # actor's own; MatchSpeed's rate: a step): nothing to show as a number.
            yield ParameterRow(name, "unset", labels.unit_text(spec.unit), "default")
        else:
            unit = labels.unit_text(spec.unit)
            yield ParameterRow(name, f"{spec.default:g} {unit}".strip(), unit, "default")
