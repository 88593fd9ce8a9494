"""The picture of a change: the new diagram with added, changed and removed nodes and flows marked.

Every mark has a colour *and* a sign that does not need colour: added boxes have a bold border
and a `+ added` label, changed ones a dashed border and `~ changed`, removed ones are drawn as
grey dashed ghosts reading `- removed`; added arrows are bold and labelled `+`, removed ones
dashed and labelled `-`. A legend in the diagram says so.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass

import graphviz
from pyecore.ecore import EObject

import scemlmodel as scm

from ..render import MAX_DIAGRAM_NODES, to_bytes
from ..render.flow import dom_id, flow_diagram
from ..templating import template
from .changes import Change, Diff
from .reports import HEADINGS, DiffReport, summary
from .words import MARKS, describe

TEMPLATE = "diff.html.j2"


@dataclass(frozen=True)
class Mark:
    """How one kind of change is drawn: colour, border style, sign, legend text."""

    colour: str
    style: str
    sign: str
    legend: str


ADDED = Mark("#1e8e3e", "bold", "+ added", "Added: green, bold border")
CHANGED = Mark("#e37400", "dashed,bold", "~ changed", "Changed or renamed: orange, dashed border")
REMOVED = Mark("#d93025", "dashed", "- removed", "Removed: red border, grey dashed ghost")
MARKS_BY_ACTION = {"added": ADDED, "changed": CHANGED, "renamed": CHANGED, "removed": REMOVED}

_NODE_PARTS = ("root", "nodes", "modules")


def _node_attributes(mark: Mark) -> dict[str, str]:
    return {
        "color": mark.colour,
        "penwidth": "3",
        "style": mark.style,
        "xlabel": mark.sign,
        "fontcolor": "#202124",
        "class": f"sceml-diff-{mark.sign.split()[1]}",
    }


def _edge_attributes(mark: Mark) -> dict[str, str]:
    sign = mark.sign.split()[0]
    return {
        "color": mark.colour,
        "penwidth": "2.5",
        "style": mark.style,
        "label": sign,
        "fontcolor": mark.colour,
        "class": f"sceml-diff-{mark.sign.split()[1]}",
    }


def marked_graph(diff: Diff, *, legend: bool = True) -> graphviz.Digraph:
    """The new version's flow diagram with the changes marked, removed things as ghosts."""
    scenario = diff.new.root
    marks: dict[EObject, dict[str, str]] = {}
    for name, action in node_actions(diff.changes).items():
        element = diff.new.nodes.get(name)
        if element is not None:
            marks[element.obj] = _node_attributes(MARKS_BY_ACTION[action])
    flows = _flow_objects(diff)
    for change in diff.changes:
        if change.part == "flows" and change.action == "added" and flows[change.path]:
            marks[flows[change.path].pop(0)] = _edge_attributes(ADDED)
    drawn = flow_diagram(scenario, marks=marks)
    graph = drawn.graph
    graph.attr(forcelabels="true")
    ghosts = _ghosts(diff, graph)
    _removed_flows(diff, graph, ghosts, drawn.ids)
    if legend:
        _legend(graph)
    return graph


def node_actions(changes: list[Change]) -> dict[str, str]:
    """Each node's strongest change: added, else changed (or renamed); removed ones apart."""
    found: dict[str, str] = {}
    for change in changes:
        if change.part not in _NODE_PARTS or change.action not in ("added", "changed", "renamed"):
            continue
        if found.get(change.element) != "added":
            found[change.element] = "added" if change.action == "added" else "changed"
    return found


def _flow_objects(diff: Diff) -> dict[str, list[scm.Flow]]:
    names = {element.obj: name for name, element in diff.new.nodes.items()}
    found: dict[str, list[scm.Flow]] = defaultdict(list)
    for flow in diff.new.root.flows:
        if flow.source in names and flow.target in names:
            found[f"{names[flow.source]} -> {names[flow.target]}"].append(flow)
    return found


def _ghosts(diff: Diff, graph: graphviz.Digraph) -> dict[str, str]:
    """A grey dashed box for each removed node; old name -> its id in the diagram."""
    ids: dict[str, str] = {}
    for change in diff.changes:
        if change.part in _NODE_PARTS and change.action == "removed":
            ghost = f"removed/{change.element}"
            graph.node(
                ghost,
                label=f"{change.element}\\n({change.kind})",
                shape="box",
                style="dashed,filled",
                fillcolor="#f1f3f4",
                fontcolor="#5f6368",
                **{
                    k: v
                    for k, v in _node_attributes(REMOVED).items()
                    if k not in ("style", "fontcolor")
                },
            )
            ids[change.element] = ghost
    return ids


def _removed_flows(
    diff: Diff, graph: graphviz.Digraph, ghosts: dict[str, str], ids: dict[EObject, list[str]]
) -> None:
    for change in diff.changes:
        if change.part != "flows" or change.action != "removed":
            continue
        ends = [_drawn(name, diff, ghosts, ids) for name in change.path.split(" -> ")]
        if ends[0] is not None and ends[1] is not None:
            graph.edge(ends[0], ends[1], **_edge_attributes(REMOVED))


def _drawn(
    name: str, diff: Diff, ghosts: dict[str, str], ids: dict[EObject, list[str]]
) -> str | None:
    """The diagram id of a flow's end, named as the flow change names it (new names)."""
    if name in ghosts:
        return ghosts[name]
    element = diff.new.nodes.get(name)
    if element is None:
        return None
    drawn = ids.get(element.obj)
    return drawn[0] if drawn else dom_id(element.obj)


def _legend(graph: graphviz.Digraph) -> None:
    with graph.subgraph(name="cluster_diff_legend") as legend:
        # One row: chained down, each sample would take a rank as tall as the diagram's.
        legend.attr(label="Changes", style="rounded", color="#9aa0a6", fontsize="12", rank="same")
        previous = None
        for index, mark in enumerate((ADDED, CHANGED, REMOVED)):
            name = f"diff-legend-{index}"
            attributes = _node_attributes(mark)
            attributes["label"] = mark.legend
            attributes["shape"] = "box"
            attributes["fontsize"] = "10"
            if mark is REMOVED:
                attributes["style"] = "dashed,filled"
                attributes["fillcolor"] = "#f1f3f4"
            legend.node(name, **attributes)
            if previous is not None:
                legend.edge(previous, name, style="invis")
            previous = name


def diff_picture(diff: Diff, fmt: str) -> bytes:
    """The marked diagram as SVG, PNG or PDF."""
    return to_bytes(marked_graph(diff), fmt)


def diff_page(diff: Diff, report: DiffReport) -> str:
    """One self-contained HTML page: the marked diagram, a legend, and every change beside it."""
    boxes = len(diff.new.nodes) + len(diff.changes)
    svg = ""
    if boxes <= MAX_DIAGRAM_NODES:
        svg = to_bytes(marked_graph(diff, legend=False), "svg").decode("utf-8")
        svg = svg[svg.index("<svg") :]
    groups = []
    for part, heading in HEADINGS.items():
        rows = [(MARKS[c.action], c.action, describe(c)) for c in report.changes if c.part == part]
        if rows:
            groups.append((heading, rows))
    return template(TEMPLATE).render(
        old=report.old,
        new=report.new,
        summary=summary(report),
        svg=svg,
        omitted=None if svg else f"{boxes:,} boxes, more than the {MAX_DIAGRAM_NODES:,} drawn",
        legend=[(m.colour, m.style, m.sign, m.legend) for m in (ADDED, CHANGED, REMOVED)],
        groups=groups,
        blocked=[describe(c) for c in report.blocked],
    )
