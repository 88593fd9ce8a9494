// Automatic layout with ELK (layered): for nodes without a saved position, and for "Arrange".

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

// ELK is 1.6 MB of the page's 1.9 MB script: it is loaded when a layout first needs it, not
// before the first paint of a file whose nodes all have their places. It runs in a web worker:
// its second or more at 500 nodes does not stop the page from drawing (lib/quickLayout.ts) or
// answering the user meanwhile. Without workers (the unit tests under Node) it runs in place.
type Engine = { layout: (graph: ElkNode) => Promise<ElkNode> };
let engine: Promise<Engine> | null = null;
function elk(): Promise<Engine> {
  engine ??=
    typeof Worker === "undefined"
      ? import("elkjs/lib/elk.bundled.js").then(({ default: ELK }) => new ELK())
      : Promise.all([import("elkjs/lib/elk-api.js"), import("elkjs/lib/elk-worker.min.js?worker")]).then(
          ([{ default: ELK }, { default: ElkWorker }]) => new ELK({ workerFactory: () => new ElkWorker() }),
        );
  return engine;
}
const FRAME_PAD = 16;

function options(direction: Direction): Record<string, string> {
  return {
    "elk.algorithm": "layered",
    "elk.direction": direction,
    "elk.layered.spacing.nodeNodeBetweenLayers": "50",
    "elk.spacing.nodeNode": "30",
    "elk.layered.nodePlacement.strategy": "BRANDES_KOEPF",
    "elk.padding": "[top=0,left=0,bottom=0,right=0]",
    "elk.layered.considerModelOrder.strategy": "NODES_AND_EDGES",
  };
}

interface Level {
  positions: Map<string, XY>;
  sizes: Map<string, Size>;
  width: number;
  height: number;
}

/**
 * Lay out the nodes directly inside `parent` (null: the top level). Expanded frames are laid out
 * first, inside out, so that each is one box of known size at its own level.
 */
async function layoutLevel(
  shown: Shown,
  parent: string | null,
  direction: Direction,
  measures: Measures,
  keepSaved = false,
): Promise<Level> {
  const nodes = new Map(shown.nodes.map((node) => [node.id, node]));
  const members = shown.nodes.filter((node) => (parent === null ? node.parent === null || !nodes.has(node.parent) : node.parent === parent));
  const memberIds = new Set(members.map((node) => node.id));
  const positions = new Map<string, XY>();
  const sizes = new Map<string, Size>();
  const frameOffsets = new Map<string, XY>();
  const children: ElkNode[] = [];
  for (const node of members) {
    if (shown.frames.has(node.id)) {
      const inner = await layoutLevel(shown, node.id, direction, measures);
      const header = measures.header(node);
      const width = Math.max(inner.width + 2 * FRAME_PAD, header.width + 2 * FRAME_PAD);
      const height = inner.height + header.height + 2 * FRAME_PAD;
      inner.positions.forEach((position, id) => positions.set(id, position));
      inner.sizes.forEach((size, id) => sizes.set(id, size));
      frameOffsets.set(node.id, { x: (width - inner.width) / 2, y: header.height + FRAME_PAD });
      sizes.set(node.id, { width, height });
    } else {
      sizes.set(node.id, measures.size(node));
    }
    // A tall frame shares its layer with small nodes: keep them at the layer's start, not its middle.
    const alignment = direction === "DOWN" ? "TOP" : "LEFT";
    children.push({ id: node.id, ...(sizes.get(node.id) as Size), layoutOptions: { "elk.alignment": alignment } });
  }
  // An edge is drawn between the members that hold its ends.
  const memberOf = (id: string): string | null => {
    let current = nodes.get(id);
    while (current && !memberIds.has(current.id)) current = current.parent === null ? undefined : nodes.get(current.parent);
    return current?.id ?? null;
  };
  const edges: ElkExtendedEdge[] = [];
  const seen = new Set<string>();
  for (const edge of shown.edges) {
    const [source, target] = [memberOf(edge.source), memberOf(edge.target)];
    if (source === null || target === null || source === target || seen.has(`${source}>${target}`)) continue;
    seen.add(`${source}>${target}`);
    edges.push({ id: edge.id, sources: [source], targets: [target] });
  }
  // Every node already has its place (saved in the model): ELK would only be overruled. This
  // is the common case after the first edit, and ELK is most of a large graph's redraw.
  const placed = keepSaved && members.every((node) => node.position !== null);
  const graph: ElkNode = { id: parent ?? "__root__", layoutOptions: options(direction), children, edges };
  const result = placed ? { children: [], width: 0, height: 0 } : await (await elk()).layout(graph);
  for (const child of result.children ?? []) {
    positions.set(child.id, { x: Math.round(child.x ?? 0), y: Math.round(child.y ?? 0) });
  }
  // Children of a frame are placed relative to the frame, below its header.
  for (const [frame, offset] of frameOffsets) {
    for (const node of shown.nodes) {
      if (node.parent !== frame) continue;
      const position = positions.get(node.id);
      if (position) positions.set(node.id, { x: Math.round(position.x + offset.x), y: Math.round(position.y + offset.y) });
    }
  }
  return { positions, sizes, width: result.width ?? 0, height: result.height ?? 0 };
}

/** How much wider a box may grow (a longer number) and keep its place: less than ELK's spacing
 * between nodes, so it cannot reach its neighbour. */
const WIDTH_SLACK = 24;

/** What the layout depends on besides sizes: the direction, what is drawn where, the edges. */
export function structureKey(shown: Shown, direction: Direction): string {
  const nodes = shown.nodes.map((node) => {
    const where = node.parent === null && node.position ? `${node.position.x},${node.position.y}` : "";
    return `${node.id}<${node.parent ?? ""}@${where}${shown.frames.has(node.id) ? "F" : ""}`;
  });
  const edges = shown.edges.map((edge) => `${edge.source}>${edge.target}`);
  return `${direction}|${nodes.join(";")}|${edges.join(";")}`;
}

/** `layout` (made for the same structure) with every box measured again, or null when a box
 * changed its height or grew too much to keep its place: then ELK must lay out again. */
export function remeasured(layout: Layout, shown: Shown, measures: Measures): Layout | null {
  const sizes = new Map(layout.sizes);
  for (const node of shown.nodes) {
    if (shown.frames.has(node.id)) continue;
    const before = layout.sizes.get(node.id);
    const now = measures.size(node);
    if (!before || before.height !== now.height || now.width > before.width + WIDTH_SLACK) return null;
    sizes.set(node.id, now);
  }
  return { positions: layout.positions, sizes };
}

/** Lay out what is shown; saved positions of top-level nodes win unless `ignoreSaved`. */
export async function layoutGraph(
  shown: Shown,
  direction: Direction,
  measures: Measures,
  ignoreSaved = false,
): Promise<Layout> {
  const level = await layoutLevel(shown, null, direction, measures, !ignoreSaved);
  if (!ignoreSaved) {
    for (const node of shown.nodes) {
      if (node.parent === null && node.position) level.positions.set(node.id, node.position);
    }
  }
  return { positions: level.positions, sizes: level.sizes };
}
