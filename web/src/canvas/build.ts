// From the shown graph and its layout to React Flow's nodes and edges.

import { MarkerType, Position, type NodeHandle } from "@xyflow/react";
import type { Shown } from "../lib/graph";
import { childrenOf } from "../lib/graph";
import type { Direction, Layout, Measures } from "../lib/layout";
import { componentOf } from "../lib/looks";
import { frameHeaderHeight, LINE_PX, measureText, nodeSize, TITLE_PX, type Size } from "../lib/sizes";
import type { ViewNode } from "../types";
import { nodeType } from "./nodeTypes";
import type { DiagramEdge, DiagramNode } from "./types";

// Sizes by node object: a patch keeps the objects of unchanged nodes, so an edit measures the
// text of the nodes it changed, not of every node.
const sized = new WeakMap<ViewNode, Size>();

export const measures: Measures = {
  size: (node: ViewNode) => {
    let size = sized.get(node);
    if (!size) {
      size = nodeSize(node);
      sized.set(node, size);
    }
    return size;
  },
  header: (node: ViewNode) => {
    const title = node.name ? `${node.name}: ${node.title}` : node.title;
    const widths = [measureText(title, TITLE_PX + 2, true) + 90, ...node.lines.map((l) => measureText(l, LINE_PX, false))];
    return { width: Math.ceil(Math.max(...widths)), height: frameHeaderHeight(node) };
  },
};

/** A drawn handle's size (editor.css: 14 px and a 2 px border), centred on the box's border. */
const HANDLE_PX = 18;

/** Where a node's in and out handles are before React Flow has measured them in the page.
 * Without them React Flow draws every node once, visible or not, only to measure its handles:
 * at 500 nodes that drew 528 boxes with their text before the first fit and took them away
 * again, most of a first paint. Once a node is drawn its measured handles replace these. */
export function handlesOf(width: number, height: number, direction: Direction): NodeHandle[] {
  const half = HANDLE_PX / 2;
  const box = { width: HANDLE_PX, height: HANDLE_PX };
  if (direction === "RIGHT") {
    return [
      { type: "target", position: Position.Left, x: -half, y: height / 2 - half, ...box },
      { type: "source", position: Position.Right, x: width - half, y: height / 2 - half, ...box },
    ];
  }
  return [
    { type: "target", position: Position.Top, x: width / 2 - half, y: -half, ...box },
    { type: "source", position: Position.Bottom, x: width / 2 - half, y: height - half, ...box },
  ];
}

/** React Flow nodes, parents first; `selected` keeps the user's selection across views. */
export function flowNodes(
  shown: Shown,
  layout: Layout,
  allNodes: ViewNode[],
  selected: Set<string>,
  readOnly: boolean,
  direction: Direction,
): DiagramNode[] {
  const children = childrenOf(allNodes);
  return shown.nodes.map((node) => {
    const size = layout.sizes.get(node.id) ?? measures.size(node);
    const expanded = shown.frames.has(node.id);
    const canExpand = componentOf(node.look) === "module" && (children.get(node.id)?.length ?? 0) > 0;
    const inner = node.parent !== null && shown.frames.has(node.parent);
    const locked = readOnly || node.readOnly || inner;
    const domAttributes = (node.severity ? { "data-severity": node.severity } : {}) as DiagramNode["domAttributes"];
    return {
      id: node.id,
      type: nodeType(node.look, expanded),
      position: layout.positions.get(node.id) ?? node.position ?? { x: 0, y: 0 },
      data: { node, width: size.width, height: size.height, expanded, canExpand },
      width: size.width,
      height: size.height,
      // Known, not measured: "Fit view" fits the nodes React Flow knows the size of, and with
      // only the visible nodes drawn (onlyRenderVisibleElements) it would measure no others.
      measured: { width: size.width, height: size.height },
      handles: handlesOf(size.width, size.height, direction),
      ...(inner ? { parentId: node.parent ?? undefined, extent: "parent" as const } : {}),
      draggable: !locked,
      connectable: !locked,
      deletable: !locked,
      selectable: true,
      selected: selected.has(node.id),
      ariaLabel: node.name,
      domAttributes,
      zIndex: expanded ? -1 : undefined,
      className: [node.severity ? `has-problems severity-${node.severity}` : "", node.mark ? `diff-${node.mark}` : ""].filter(Boolean).join(" ") || undefined,
    };
  });
}

/** The flows as React Flow edges, drawn in `colour` (the server's style, as `sceml render` draws flows). */
export function flowEdges(shown: Shown, selected: Set<string>, readOnly: boolean, colour: string): DiagramEdge[] {
  const parentOf = new Map(shown.nodes.map((node) => [node.id, node.parent]));
  return shown.edges.map((edge) => {
    const inner = parentOf.get(edge.source) != null && parentOf.get(edge.target) != null;
    return {
      id: edge.id,
      source: edge.source,
      target: edge.target,
      markerEnd: { type: MarkerType.ArrowClosed, color: colour, width: 18, height: 18 },
      style: { stroke: colour, strokeWidth: 1.4 },
      selectable: !inner && !readOnly,
      deletable: !inner && !readOnly,
      selected: selected.has(edge.id),
      zIndex: 1,
    };
  });
}

/** Ids of the boxes drawn for a node the server has yet to add (see `pendingNode`). */
export const PENDING_PREFIX = "pending:";

/** A box for a node being added, drawn at once where it was dropped while the server adds it
 * and validates the model: its answer replaces the box with the real node (or, refused, takes
 * it away). Greyed, and nothing can be done with it. */
export function pendingNode(
  id: string,
  kind: string,
  title: string,
  look: string,
  position: { x: number; y: number },
  direction: Direction,
): DiagramNode {
  const node: ViewNode = { id, kind, look, name: "", title, lines: [], position, parent: null, readOnly: true, severity: null, problems: 0, fields: [] };
  const size = measures.size(node);
  return {
    id,
    type: nodeType(look, false),
    position,
    data: { node, width: size.width, height: size.height, expanded: false, canExpand: false },
    width: size.width,
    height: size.height,
    measured: { width: size.width, height: size.height },
    handles: handlesOf(size.width, size.height, direction),
    draggable: false,
    connectable: false,
    deletable: false,
    selectable: false,
    ariaLabel: `${title} (adding)`,
    className: "pending",
  };
}
