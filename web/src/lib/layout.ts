// Automatic layout with ELK (layered): for nodes without a saved position, and for "Arrange".

import ELK from "elkjs/lib/elk.bundled.js";
import type { ElkExtendedEdge, ElkNode } from "elkjs/lib/elk-api";
import type { ViewNode, XY } from "../types";
import type { Shown } from "./graph";
import type { Size } from "./sizes";

export type Direction = "RIGHT" | "DOWN";

export interface Layout {
  /** Top-level nodes: absolute; nodes inside a frame: relative to the frame. */
  positions: Map<string, XY>;
  /** Every node's drawn size; frames are sized around what they hold. */
  sizes: Map<string, Size>;
}

export interface Measures {
  size: (node: ViewNode) => Size;
  /** Height of an expanded frame's header, and the width its text needs. */
  header: (node: ViewNode) => Size;
}

const elk = new ELK();

function options(direction: Direction): Record<string, string> {
  return {
    "elk.algorithm": "layered",
    "elk.direction": direction,
    "elk.layered.spacing.nodeNodeBetweenLayers": "50",
    "elk.spacing.nodeNode": "30",
    "elk.layered.nodePlacement.strategy": "BRANDES_KOEPF",
    "elk.layered.crossingMinimization.forceNodeModelOrder": "false",
    "elk.layered.considerModelOrder.strategy": "NODES_AND_EDGES",
  };
}

function elkTree(shown: Shown, direction: Direction, measures: Measures): ElkNode {
  const nodes = new Map(shown.nodes.map((node) => [node.id, node]));
  const toElk = (node: ViewNode): ElkNode => {
    if (!shown.frames.has(node.id)) return { id: node.id, ...measures.size(node) };
    const header = measures.header(node);
    return {
      id: node.id,
      layoutOptions: {
        ...options(direction),
        "elk.padding": `[top=${header.height + 12},left=20,bottom=20,right=20]`,
        "elk.nodeSize.constraints": "MINIMUM_SIZE",
        "elk.nodeSize.minimum": `(${header.width + 40}, ${header.height + 40})`,
      },
      children: shown.nodes.filter((child) => child.parent === node.id).map(toElk),
    };
  };
  const edges: ElkExtendedEdge[] = shown.edges
    .filter((edge) => nodes.has(edge.source) && nodes.has(edge.target))
    .map((edge) => ({ id: edge.id, sources: [edge.source], targets: [edge.target] }));
  return {
    id: "__root__",
    layoutOptions: { ...options(direction), "elk.hierarchyHandling": "INCLUDE_CHILDREN" },
    children: shown.nodes.filter((node) => node.parent === null || !nodes.has(node.parent)).map(toElk),
    edges,
  };
}

/** Lay out what is shown; saved positions of top-level nodes win unless `ignoreSaved`. */
export async function layoutGraph(
  shown: Shown,
  direction: Direction,
  measures: Measures,
  ignoreSaved = false,
): Promise<Layout> {
  const result = await elk.layout(elkTree(shown, direction, measures));
  const positions = new Map<string, XY>();
  const sizes = new Map<string, Size>();
  const saved = new Map(shown.nodes.map((node) => [node.id, node]));
  const collect = (elkNode: ElkNode, topLevel: boolean) => {
    for (const child of elkNode.children ?? []) {
      const node = saved.get(child.id);
      const own = topLevel && !ignoreSaved ? node?.position : null;
      positions.set(child.id, own ?? { x: Math.round(child.x ?? 0), y: Math.round(child.y ?? 0) });
      sizes.set(child.id, { width: child.width ?? 0, height: child.height ?? 0 });
      collect(child, false);
    }
  };
  collect(result, true);
  return { positions, sizes };
}
