// Which nodes and edges the canvas shows, given which module uses the user has expanded.

import type { ViewEdge, ViewNode } from "../types";
import { componentOf } from "./looks";

export interface Shown {
  /** Visible nodes, every parent before its children. */
  nodes: ViewNode[];
  /** Visible edges, their ends moved to what is drawn (a collapsed use, an expanded use's port). */
  edges: ViewEdge[];
  /** Ids of the expanded module uses that are drawn as frames. */
  frames: Set<string>;
}

/** The children of every node that has some (module uses with inner nodes). */
export function childrenOf(nodes: ViewNode[]): Map<string, ViewNode[]> {
  const children = new Map<string, ViewNode[]>();
  for (const node of nodes) {
    if (node.parent === null) continue;
    const list = children.get(node.parent) ?? [];
    list.push(node);
    children.set(node.parent, list);
  }
  return children;
}

/** The nodes, edges and frames to draw when the uses in `expanded` are open. */
export function shownGraph(nodes: ViewNode[], edges: ViewEdge[], expanded: Set<string>): Shown {
  const byId = new Map(nodes.map((node) => [node.id, node]));
  const children = childrenOf(nodes);
  const frames = new Set<string>();
  const shown: ViewNode[] = [];
  const visit = (node: ViewNode) => {
    shown.push(node);
    const inner = children.get(node.id);
    if (!inner || !expanded.has(node.id) || componentOf(node.look) !== "module") return;
    frames.add(node.id);
    inner.forEach(visit);
  };
  nodes.filter((node) => node.parent === null || !byId.has(node.parent)).forEach(visit);
  const visible = new Set(shown.map((node) => node.id));

  // An edge end inside a collapsed use is drawn at that use. An edge into an expanded use ends
  // at its frame's border (the in-port sits just inside, under the header: an edge drawn to the
  // port would cross the header's text); an edge out of it starts at its out-port, at the
  // frame's far end.
  const drawnAt = (id: string): string | null => {
    let current = byId.get(id);
    while (current && !visible.has(current.id)) {
      current = current.parent === null ? undefined : byId.get(current.parent);
    }
    return current ? current.id : null;
  };
  const outPort = (use: string) => (children.get(use) ?? []).find((child) => child.look === "outPort")?.id ?? use;
  const result: ViewEdge[] = [];
  const seen = new Set<string>();
  for (const edge of edges) {
    let source = drawnAt(edge.source);
    const target = drawnAt(edge.target);
    if (source === null || target === null) continue;
    if (frames.has(source)) source = outPort(source);
    const key = `${source}->${target}`;
    if (source === target || seen.has(key)) continue;
    seen.add(key);
    result.push({ id: edge.id, source, target });
  }
  return { nodes: shown, edges: result, frames };
}

/** The nodes the user edits directly: top level, not inside a module use. */
export function topLevel(nodes: ViewNode[]): ViewNode[] {
  return nodes.filter((node) => node.parent === null);
}
