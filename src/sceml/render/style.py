"""The SceML notation's look: colours, shapes and symbols per node category, and the legend.

Decisions where the paper's legend (Table "Node Notation Legend") gives only pictures:

- maneuvers are square-cornered boxes filled by category (longitudinal yellow, lateral red,
  composite green); conditions are rounded boxes filled blue, so shape tells them apart even for
  readers who cannot tell the colours apart;
- join-all-finished is a small circle with the double arrow of the behavior-tree parallel-all
  node, join-one-finished a small diamond with the question mark of parallel-one;
- the end node is a double circle (filled dark) labelled "End"; a join-one end adds "?";
- a module use is a double-framed white box when collapsed, a dashed frame (cluster) with small
  "in"/"out" port pentagons when expanded.
"""

from __future__ import annotations

from dataclasses import dataclass
from html import escape
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import graphviz

FONT = "DejaVu Sans"

#: Symbols shared by the flow view's join nodes and the behavior-tree view's composite nodes.
SEQUENCE_SYMBOL = "→"
PARALLEL_ALL_SYMBOL = "⇉"
PARALLEL_ONE_SYMBOL = "?"


@dataclass(frozen=True)
class Look:
    """Graphviz attributes of one kind of drawn element, plus its legend text."""

    css_class: str
    legend: str
    attributes: tuple[tuple[str, str], ...]

    def attrs(self) -> dict[str, str]:
        """The attributes as a dict for graphviz, with the CSS class tests and the report use."""
        return {**dict(self.attributes), "class": f"sceml-node {self.css_class}"}


def _box(fill: str, border: str, *, rounded: bool = False) -> tuple[tuple[str, str], ...]:
    style = "rounded,filled" if rounded else "filled"
    return (("shape", "box"), ("style", style), ("fillcolor", fill), ("color", border))


#: One look per action-node category (catalog.category names).
CATEGORY_LOOKS = {
    "longitudinal": Look("sceml-longitudinal", "Longitudinal maneuver", _box("#ffe066", "#b08800")),
    "lateral": Look("sceml-lateral", "Lateral maneuver", _box("#f28b82", "#b3261e")),
    "composite": Look("sceml-composite", "Composite maneuver", _box("#81c995", "#2e7d32")),
    # Grey-violet: no other category is violet, and it stays apart from the opaque grey.
    "controller": Look("sceml-controller", "Controller change", _box("#8e7cc3", "#4b3b8a")),
    # Teal: a change of the actor's lights, apart from every maneuver colour and the condition blue.
    "appearance": Look("sceml-appearance", "Appearance (lights)", _box("#80cbc4", "#00695c")),
    # Brown: a trailer coupled or uncoupled, apart from every maneuver colour and the opaque grey.
    "coupling": Look("sceml-coupling", "Trailer coupling", _box("#bcaaa4", "#5d4037")),
    "condition": Look("sceml-condition", "Condition", _box("#8ab4f8", "#1a56b0", rounded=True)),
    # Performed by no actor (a parameter, a variable, a traffic signal): orange, apart from the
    # controller's violet and the longitudinal yellow.
    "global": Look("sceml-global", "Global (no actor)", _box("#ffb74d", "#e65100")),
}

#: Fill colour per category, for tests and for the report's tables.
CATEGORY_FILLS = {name: dict(look.attributes)["fillcolor"] for name, look in CATEGORY_LOOKS.items()}

ROOT = Look(
    "sceml-root", "Root: name, level, map, actors", _box("#eceff1", "#455a64", rounded=True)
)
JOIN_ALL = Look(
    "sceml-join-all",
    "Join: all finished",
    (
        ("shape", "circle"),
        ("style", "filled,bold"),
        ("fillcolor", "white"),
        ("width", "0.45"),
        ("fixedsize", "true"),
        ("fontsize", "16"),
        ("label", PARALLEL_ALL_SYMBOL),
    ),
)
JOIN_ONE = Look(
    "sceml-join-one",
    "Join: one finished",
    (
        ("shape", "diamond"),
        ("style", "filled,bold"),
        ("fillcolor", "white"),
        ("width", "0.5"),
        ("height", "0.5"),
        ("fixedsize", "true"),
        ("fontsize", "16"),
        ("label", PARALLEL_ONE_SYMBOL),
    ),
)
END = Look(
    "sceml-end",
    "End node",
    (
        ("shape", "doublecircle"),
        ("style", "filled"),
        ("fillcolor", "#263238"),
        ("fontcolor", "white"),
        ("width", "0.55"),
        ("fixedsize", "true"),
        ("fontsize", "10"),
    ),
)
MODULE = Look(
    "sceml-module-use",
    "Module use (collapsed)",
    (("shape", "box"), ("style", "filled,bold"), ("fillcolor", "white"), ("peripheries", "2")),
)
BROKEN_MODULE = Look(
    "sceml-module-use sceml-broken",
    "Module that cannot be expanded",
    (("shape", "box"), ("style", "filled,dashed"), ("fillcolor", "#fce8e6"), ("color", "#b3261e")),
)
IN_PORT = Look(
    "sceml-in-port",
    "Module in-port",
    (
        ("shape", "invhouse"),
        ("style", "filled"),
        ("fillcolor", "white"),
        ("fontsize", "9"),
        ("width", "0.45"),
        ("height", "0.3"),
        ("label", "in"),
    ),
)
OUT_PORT = Look(
    "sceml-out-port",
    "Module out-port",
    (
        ("shape", "house"),
        ("style", "filled"),
        ("fillcolor", "white"),
        ("fontsize", "9"),
        ("width", "0.45"),
        ("height", "0.3"),
        ("label", "out"),
    ),
)
UNKNOWN = Look("sceml-unknown", "Unknown element", _box("white", "black"))
#: An OpaqueAction (kept verbatim by `sceml import`): grey and dashed, so it reads as "not
#: understood by SceML" next to the coloured kinds; its category in the metamodel is `opaque`.
OPAQUE = Look(
    "sceml-opaque",
    "Kept from import (opaque)",
    (("shape", "box"), ("style", "filled,dashed"), ("fillcolor", "#e0e0e0"), ("color", "#616161")),
)


def _bt_composite(symbol: str) -> tuple[tuple[str, str], ...]:
    return (
        ("shape", "box"),
        ("width", "0.45"),
        ("height", "0.4"),
        ("fixedsize", "true"),
        ("fontsize", "16"),
        ("label", symbol),
    )


#: The behavior-tree view's own nodes: sequences, parallels and the wait leaf of a cut join.
BT_SEQUENCE = Look(
    "sceml-bt-sequence", "Sequence: children in turn, left to right", _bt_composite(SEQUENCE_SYMBOL)
)
BT_PARALLEL_ALL = Look(
    "sceml-bt-parallel-all",
    "Parallel: done when all children are",
    _bt_composite(PARALLEL_ALL_SYMBOL),
)
BT_PARALLEL_ONE = Look(
    "sceml-bt-parallel-one",
    "Parallel: done when one child is",
    _bt_composite(PARALLEL_ONE_SYMBOL),
)
BT_WAIT = Look(
    "sceml-bt-wait",
    "Wait until all or one of the named nodes have finished",
    (("shape", "box"), ("style", "dashed,rounded"), ("label", "wait")),
)

#: The frame of an expanded module use.
CLUSTER_ATTRIBUTES = {
    "style": "rounded,dashed",
    "color": "#5f6368",
    "penwidth": "1.5",
    "margin": "12",
    "class": "sceml-module",
}

GRAPH_ATTRIBUTES = {
    "rankdir": "TB",
    "nodesep": "0.35",
    "ranksep": "0.4",
    "fontname": FONT,
    "newrank": "true",
}
NODE_ATTRIBUTES = {"fontname": FONT, "fontsize": "11", "margin": "0.12,0.05"}
EDGE_ATTRIBUTES = {"arrowsize": "0.7", "color": "#37474f"}


def html_label(title: str, lines: list[str], *, subtitle: str | None = None) -> str:
    """A Graphviz HTML-like label: a bold title, an optional italic line, then left-aligned lines."""
    parts = [f"<B>{escape(title)}</B>"]
    if subtitle:
        parts.append(f'<BR/><FONT POINT-SIZE="10"><I>{escape(subtitle)}</I></FONT>')
    if lines:
        body = '<BR ALIGN="LEFT"/>'.join(escape(line) for line in lines)
        parts.append(f'<BR/><FONT POINT-SIZE="9">{body}<BR ALIGN="LEFT"/></FONT>')
    return "<" + "".join(parts) + ">"


#: (id, look, sample label): the sample shows a typical kind, the caption says what it stands for.
LEGEND_ENTRIES = (
    ("legend-root", ROOT, "UIS1"),
    ("legend-longitudinal", CATEGORY_LOOKS["longitudinal"], "Accelerate"),
    ("legend-lateral", CATEGORY_LOOKS["lateral"], "TurnRight"),
    ("legend-composite", CATEGORY_LOOKS["composite"], "Overtake"),
    ("legend-controller", CATEGORY_LOOKS["controller"], "ActivateController"),
    ("legend-condition", CATEGORY_LOOKS["condition"], "InVehicleRadius"),
    ("legend-global", CATEGORY_LOOKS["global"], "SetParameter"),
    ("legend-join-all", JOIN_ALL, ""),
    ("legend-join-one", JOIN_ONE, ""),
    ("legend-end", END, "End"),
    ("legend-module", MODULE, "CrossingManeuver"),
    ("legend-in-port", IN_PORT, ""),
    ("legend-out-port", OUT_PORT, ""),
)


#: The behavior-tree view's legend: its composites, its leaves (drawn as in the flow view), wait.
BT_LEGEND_ENTRIES = (
    ("legend-bt-sequence", BT_SEQUENCE, ""),
    ("legend-bt-parallel-all", BT_PARALLEL_ALL, ""),
    ("legend-bt-parallel-one", BT_PARALLEL_ONE, ""),
    ("legend-longitudinal", CATEGORY_LOOKS["longitudinal"], "Accelerate"),
    ("legend-lateral", CATEGORY_LOOKS["lateral"], "TurnRight"),
    ("legend-composite", CATEGORY_LOOKS["composite"], "Overtake"),
    ("legend-controller", CATEGORY_LOOKS["controller"], "ActivateController"),
    ("legend-condition", CATEGORY_LOOKS["condition"], "InVehicleRadius"),
    ("legend-module", MODULE, "CrossingManeuver"),
    ("legend-bt-wait", BT_WAIT, ""),
)


def add_legend(
    graph: graphviz.Digraph, entries: tuple[tuple[str, Look, str], ...] = LEGEND_ENTRIES
) -> None:
    """Add a legend to a diagram: a framed column of sample nodes with captions.

    `entries` default to the flow view's notation; the behavior-tree view passes its own.
    """
    with graph.subgraph(name="cluster_legend") as legend:
        legend.attr(label="Legend", style="rounded", color="#9aa0a6", fontsize="12")
        legend.attr(**{"class": "sceml-legend"})
        previous = None
        for name, look, text in entries:
            attributes = look.attrs()
            attributes["class"] = "sceml-legend-sample"
            attributes.setdefault("label", text)
            with legend.subgraph() as row:
                row.attr(rank="same")
                row.node(name, **attributes)
                row.node(
                    f"{name}-caption",
                    label=look.legend + "\\l",
                    shape="plaintext",
                    width="2.2",
                    fontsize="10",
                    **{"class": "sceml-legend-caption"},
                )
                row.edge(name, f"{name}-caption", style="invis")
            if previous is not None:
                legend.edge(previous, name, style="invis")
            previous = name


def legend_graph() -> graphviz.Digraph:
    """A diagram that holds only the legend (docs/diagrams/legend.png)."""
    import graphviz  # only where a legend is drawn: the preview page reads the colours alone

    graph = graphviz.Digraph("legend", graph_attr={**GRAPH_ATTRIBUTES, "ranksep": "0.15"})
    graph.node_attr.update(NODE_ATTRIBUTES)
    add_legend(graph)
    return graph


#: The editor's name for each look (docs/editor-protocol.md), the same Look objects as above.
EDITOR_LOOKS = {
    **CATEGORY_LOOKS,
    "root": ROOT,
    "end": END,
    "endOne": END,
    "joinAll": JOIN_ALL,
    "joinOne": JOIN_ONE,
    "module": MODULE,
    "brokenModule": BROKEN_MODULE,
    "inPort": IN_PORT,
    "outPort": OUT_PORT,
    "opaque": OPAQUE,
}


def look_data(look: Look) -> dict[str, object]:
    """One look as plain data: fill, border, text colour, shape and its style words."""
    attributes = dict(look.attributes)
    words = set(attributes.get("style", "").split(","))
    return {
        "fill": attributes.get("fillcolor", "white"),
        "border": attributes.get("color", "black"),
        "text": attributes.get("fontcolor", "black"),
        "shape": attributes.get("shape", "box"),
        "rounded": "rounded" in words,
        "dashed": "dashed" in words,
        "bold": "bold" in words,
        "double": attributes.get("peripheries") == "2" or attributes.get("shape") == "doublecircle",
        "label": attributes.get("label"),
    }


def style_data() -> dict[str, object]:
    """The notation as data for the editor's browser page: looks, symbols and font."""
    return {
        "looks": {name: look_data(look) for name, look in EDITOR_LOOKS.items()},
        "symbols": {"joinAll": PARALLEL_ALL_SYMBOL, "joinOne": PARALLEL_ONE_SYMBOL},
        "font": FONT,
        "edge": {"color": EDGE_ATTRIBUTES["color"]},
    }


# --- The map view (`sceml render --view map`): a top view of the start situation. -----------------

#: Lane fills by OpenDRIVE lane type; any other type gets MAP_OTHER_LANE_FILL.
MAP_LANE_FILLS = {"driving": "#5f6368", "sidewalk": "#dadce0"}
MAP_OTHER_LANE_FILL = "#a8adb3"
MAP_LANE_EDGE = "#3c4043"
MAP_LANE_MARKING = "#ffffff"
MAP_BACKGROUND = "#f8f9fa"
#: The ego is blue, as the paper's Fig. 1a draws it; the other actors take these in turn.
MAP_EGO_COLOUR = "#1a73e8"
MAP_ACTOR_COLOURS = ("#e8710a", "#188038", "#a142f4", "#d93025", "#129eaf", "#e52592", "#8d6e63")
#: Radii and positions no actor owns (a condition without a reference actor).
MAP_NEUTRAL_COLOUR = "#202124"
