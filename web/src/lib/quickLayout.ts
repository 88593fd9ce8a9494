// A first picture of a large graph in a few milliseconds, while ELK (a second or more at 500
// nodes) makes the real layout in a web worker: layers by the longest path from the graph's
// starts, each layer ordered once by where its predecessors stand. Top level only; a graph with
// an expanded use waits for ELK, which lays frames out inside out.

import type { XY } from "../types";
import type { Shown } from "./graph";
import type { Direction, Layout, Measures } from "./layout";
import type { Size } from "./sizes";

/** The same gaps ELK is given (lib/layout.ts), so the first picture is as dense as the final. */
const BETWEEN_LAYERS = 50;
const BETWEEN_NODES = 30;

/** Each node's layer: the longest path to it from a node without predecessors. Flows that
 * close a loop (found by a depth-first walk in model order) are left out. */
function layersOf(ids: string[], successors: Map<string, string[]>): Map<string, number> {
  const state = new Map<string, "open" | "done">();
  const forward = new Map<string, string[]>(ids.map((id) => [id, []]));
  for (const start of ids) {
    if (state.has(start)) continue;
    // An explicit stack: a chain of hundreds of nodes must not exhaust the call stack.
    const stack: { id: string; next: number }[] = [{ id: start, next: 0 }];
    state.set(start, "open");
    while (stack.length > 0) {
      const top = stack[stack.length - 1] as { id: string; next: number };
      const out = successors.get(top.id) ?? [];
      if (top.next >= out.length) {
        state.set(top.id, "done");
        stack.pop();
        continue;
      }
      const target = out[top.next++] as string;
      const seen = state.get(target);
      if (seen === "open") continue; // a loop back: not a layering constraint
      forward.get(top.id)?.push(target);
      if (seen === undefined) {
        state.set(target, "open");
        stack.push({ id: target, next: 0 });
      }
    }
  }
  // Longest path over what is left (a DAG), in topological order.
  const incoming = new Map<string, number>(ids.map((id) => [id, 0]));
  for (const targets of forward.values()) for (const target of targets) incoming.set(target, (incoming.get(target) ?? 0) + 1);
  const layer = new Map<string, number>(ids.map((id) => [id, 0]));
  const ready = ids.filter((id) => incoming.get(id) === 0);
  for (let index = 0; index < ready.length; index++) {
    const id = ready[index] as string;
    for (const target of forward.get(id) ?? []) {
      layer.set(target, Math.max(layer.get(target) ?? 0, (layer.get(id) ?? 0) + 1));
      const left = (incoming.get(target) ?? 0) - 1;
      incoming.set(target, left);
      if (left === 0) ready.push(target);
    }
  }
  return layer;
}

/** A layered layout of the top-level nodes; saved positions win, as in `layoutGraph`. */
export function quickLayout(shown: Shown, direction: Direction, measures: Measures): Layout {
  const nodes = shown.nodes.filter((node) => node.parent === null);
  const ids = nodes.map((node) => node.id);
  const known = new Set(ids);
  const successors = new Map<string, string[]>();
  const predecessors = new Map<string, string[]>();
  for (const edge of shown.edges) {
    if (!known.has(edge.source) || !known.has(edge.target) || edge.source === edge.target) continue;
    successors.set(edge.source, [...(successors.get(edge.source) ?? []), edge.target]);
    predecessors.set(edge.target, [...(predecessors.get(edge.target) ?? []), edge.source]);
  }
  const layerOf = layersOf(ids, successors);
  const layers: string[][] = [];
  for (const id of ids) {
    const index = layerOf.get(id) ?? 0;
    (layers[index] ??= []).push(id);
  }
  const sizes = new Map<string, Size>(nodes.map((node) => [node.id, measures.size(node)]));
  const down = direction === "DOWN";
  // Along a layer: widths going down, heights going right; across: the other way round.
  const along = (id: string) => (down ? sizes.get(id)?.width : sizes.get(id)?.height) ?? 0;
  const across = (id: string) => (down ? sizes.get(id)?.height : sizes.get(id)?.width) ?? 0;
  const positions = new Map<string, XY>();
  const centre = new Map<string, number>();
  let offset = 0;
  for (const layer of layers) {
    if (!layer) continue;
    // Under the middle of its predecessors where there is room (one sweep), so that a chain
    // runs straight; nodes without any come first, in model order.
    const wanted = (id: string): number | null => {
      const before = (predecessors.get(id) ?? []).map((other) => centre.get(other)).filter((value) => value !== undefined);
      return before.length > 0 ? before.reduce((sum, value) => sum + value, 0) / before.length : null;
    };
    const order = layer
      .map((id, index) => ({ id, index, key: wanted(id) }))
      .sort((a, b) => (a.key ?? -Infinity) - (b.key ?? -Infinity) || a.index - b.index);
    let cursor = 0;
    let depth = 0;
    for (const { id, key } of order) {
      const start = key === null ? cursor : Math.max(cursor, Math.round(key - along(id) / 2));
      positions.set(id, down ? { x: start, y: offset } : { x: offset, y: start });
      centre.set(id, start + along(id) / 2);
      cursor = start + along(id) + BETWEEN_NODES;
      depth = Math.max(depth, across(id));
    }
    offset += depth + BETWEEN_LAYERS;
  }
  for (const node of nodes) if (node.position) positions.set(node.id, node.position);
  return { positions, sizes };
}
