// React Flow's nodes and edges for the current view: laid out by ELK where no position is saved,
// re-laid out when the view, the expanded uses or the direction change. Selection survives.

import { applyEdgeChanges, applyNodeChanges, type EdgeChange, type NodeChange } from "@xyflow/react";
import { useCallback, useEffect, useRef, useState } from "react";
import { flowEdges, flowNodes, measures } from "../canvas/build";
import type { DiagramEdge, DiagramNode } from "../canvas/types";
import { shownGraph } from "../lib/graph";
import { layoutGraph, remeasured, structureKey, type Direction, type Layout } from "../lib/layout";
import { storedLayout, storeLayout } from "../lib/layoutCache";
import { quickLayout } from "../lib/quickLayout";
import type { View, XY } from "../types";

export interface DiagramState {
  nodes: DiagramNode[];
  edges: DiagramEdge[];
  setNodes: React.Dispatch<React.SetStateAction<DiagramNode[]>>;
  setEdges: React.Dispatch<React.SetStateAction<DiagramEdge[]>>;
  onNodesChange: (changes: NodeChange<DiagramNode>[]) => void;
  onEdgesChange: (changes: EdgeChange<DiagramEdge>[]) => void;
  /** The view the current nodes were laid out from (a new document's first one fits the view). */
  laidOut: View | null;
  /** Where ELK puts every top-level node, ignoring saved positions (Arrange). */
  arrange: (direction: Direction) => Promise<Record<string, XY>>;
  /** Select these nodes once the next view is laid out (what an op created). */
  selectNext: (ids: string[]) => void;
  /** Whether what is drawn is the quick first layout, ELK's still to come. */
  quick: boolean;
  /** Draw a box for a node the server is adding (canvas/build.ts `pendingNode`) at once. */
  showPending: (node: DiagramNode) => void;
  /** Take that box away (the server refused; an answer that adds the node replaces it). */
  dropPending: (id: string) => void;
}

/** From how many top-level nodes without a place the quick layout is drawn before ELK's:
 * below it ELK takes a fraction of a second, and a picture that rearranges itself is worse. */
const QUICK_FROM = 100;

/** Resolves when the page has nothing else to do (drawn, measured, fitted), at most 1 s on. */
function idle(): Promise<void> {
  return new Promise((resolve) => {
    if (typeof requestIdleCallback === "function") requestIdleCallback(() => resolve(), { timeout: 1000 });
    else setTimeout(resolve, 0);
  });
}

/** `next`, with each item that equals the one drawn before replaced by that very object. */
function reuse<T extends { id: string }>(next: T[], before: Map<string, T>, same: (a: T, b: T) => boolean): T[] {
  return next.map((item) => {
    const old = before.get(item.id);
    return old && same(old, item) ? old : item;
  });
}

function sameItems<T>(a: T[], b: T[]): boolean {
  return a.length === b.length && a.every((item, index) => item === b[index]);
}

function sameNode(old: DiagramNode, next: DiagramNode): boolean {
  return (
    old.type === next.type &&
    old.position.x === next.position.x &&
    old.position.y === next.position.y &&
    old.width === next.width &&
    old.height === next.height &&
    old.parentId === next.parentId &&
    Boolean(old.selected) === Boolean(next.selected) &&
    old.draggable === next.draggable &&
    old.className === next.className &&
    old.zIndex === next.zIndex &&
    old.handles?.[0]?.position === next.handles?.[0]?.position &&
    old.data.expanded === next.data.expanded &&
    old.data.canExpand === next.data.canExpand &&
    // Patches keep an unchanged node's object: the comparison of its content is the rare case.
    (old.data.node === next.data.node || JSON.stringify(old.data.node) === JSON.stringify(next.data.node))
  );
}

function sameEdge(old: DiagramEdge, next: DiagramEdge): boolean {
  return (
    old.source === next.source &&
    old.target === next.target &&
    Boolean(old.selected) === Boolean(next.selected) &&
    old.selectable === next.selectable
  );
}

export function useDiagramState(
  view: View | null,
  expanded: Set<string>,
  direction: Direction,
): DiagramState {
  const [nodes, setNodes] = useState<DiagramNode[]>([]);
  const [edges, setEdges] = useState<DiagramEdge[]>([]);
  const [laidOut, setLaidOut] = useState<View | null>(null);
  const [quick, setQuick] = useState(false);
  const selection = useRef<{ nodes: Set<string>; edges: Set<string> }>({ nodes: new Set(), edges: new Set() });
  const pending = useRef<Set<string> | null>(null);
  // The last layout and what it was made from: an edit that changes no structure (a parameter,
  // a name) reuses it instead of running ELK over the whole graph again.
  const lastLayout = useRef<{ key: string; layout: Layout } | null>(null);
  const drawn = useRef<{ nodes: Map<string, DiagramNode>; edges: Map<string, DiagramEdge> }>({ nodes: new Map(), edges: new Map() });
  const selectNext = useCallback((ids: string[]) => {
    pending.current = new Set(ids);
  }, []);

  useEffect(() => {
    drawn.current = { nodes: new Map(nodes.map((node) => [node.id, node])), edges: new Map(edges.map((edge) => [edge.id, edge])) };
    selection.current = {
      nodes: new Set(nodes.filter((node) => node.selected).map((node) => node.id)),
      edges: new Set(edges.filter((edge) => edge.selected).map((edge) => edge.id)),
    };
  }, [nodes, edges]);

  useEffect(() => {
    if (!view) return;
    let cancelled = false;
    const shown = shownGraph(view.nodes, view.edges, expanded);
    const key = structureKey(shown, direction);
    const last = lastLayout.current;
    const file = `${view.document.path}#${view.document.module ?? ""}`;
    // The layout drawn last, or one this browser made for this file before (a reload).
    const earlier = last?.key === key ? last.layout : storedLayout(file, key);
    const known = earlier ? remeasured(earlier, shown, measures) : null;
    if (earlier && known && last?.key !== key) lastLayout.current = { key, layout: earlier };
    // Read-only, an expanded use cannot make room by an Arrange step: lay it all out anew.
    const fresh = view.readOnly && shown.frames.size > 0;
    const started = performance.now();
    const draw = (layout: Layout, quick: boolean) => {
      const chosen = pending.current;
      pending.current = null;
      const selectedNodes = chosen ?? selection.current.nodes;
      const selectedEdges = chosen ? new Set<string>() : selection.current.edges;
      // Unchanged nodes and edges keep their objects, so React Flow redraws only what changed.
      const nextNodes = reuse(flowNodes(shown, layout, view.nodes, selectedNodes, view.readOnly, direction), drawn.current.nodes, sameNode);
      const nextEdges = reuse(flowEdges(shown, selectedEdges, view.readOnly, view.style.edge.color), drawn.current.edges, sameEdge);
      // The same list keeps its array: React Flow runs every node's and edge's selector on
      // each update of its store, so an update that changes nothing is worth skipping.
      setNodes((current) => (sameItems(current, nextNodes) ? current : nextNodes));
      setEdges((current) => (sameItems(current, nextEdges) ? current : nextEdges));
      // A new object for every layout: expanding a use lays out the same view again, and the
      // page fits the view after that layout (a same-object update would not be seen).
      setLaidOut({ ...view });
      setQuick(quick);
    };
    // A large graph ELK must place is drawn at once in a quick layered layout, then again
    // where ELK puts it (it runs in a worker meanwhile): a picture in milliseconds, not seconds.
    const unplaced = known ? 0 : shown.nodes.filter((node) => node.parent === null && node.position === null).length;
    const drawnQuick = unplaced >= QUICK_FROM && shown.frames.size === 0;
    if (drawnQuick) {
      draw(quickLayout(shown, direction, measures), true);
      performance.measure("sceml-layout-quick", { start: started });
    }
    // ELK starts once that picture is drawn: on two busy cores its worker would slow it down.
    const laying = known
      ? Promise.resolve(known)
      : (drawnQuick ? idle() : Promise.resolve()).then(() => (cancelled ? null : layoutGraph(shown, direction, measures, fresh)));
    void laying.then((layout) => {
      if (layout === null) return;
      // benchmarks/editor_browser.py reads these: how long each layout took, ELK or not.
      performance.measure(known ? "sceml-layout-reused" : "sceml-layout", { start: started });
      if (cancelled) return;
      // Kept with the sizes ELK saw, so that growth is measured from them, not step by step.
      if (!known) {
        lastLayout.current = { key, layout };
        // Kept for a reload only when ELK placed something (a top-level node without a saved
        // place, or the inside of a frame): saved places need no keeping.
        if (shown.nodes.some((node) => (node.parent === null ? node.position === null : shown.frames.has(node.parent)))) storeLayout(file, key, layout);
      }
      draw(layout, false);
    });
    return () => {
      cancelled = true;
    };
  }, [view, expanded, direction]);

  const onNodesChange = useCallback(
    (changes: NodeChange<DiagramNode>[]) =>
      // Removal goes through the server (op delete).
      setNodes((current) => applyNodeChanges(changes.filter((c) => c.type !== "remove"), current)),
    [],
  );
  const onEdgesChange = useCallback(
    (changes: EdgeChange<DiagramEdge>[]) =>
      setEdges((current) => applyEdgeChanges(changes.filter((c) => c.type !== "remove"), current)),
    [],
  );

  const arrange = useCallback(
    async (to: Direction) => {
      if (!view) return {};
      const layout = await layoutGraph(shownGraph(view.nodes, view.edges, expanded), to, measures, true);
      const positions: Record<string, XY> = {};
      for (const node of view.nodes) {
        const position = node.parent === null ? layout.positions.get(node.id) : undefined;
        if (position) positions[node.id] = position;
      }
      return positions;
    },
    [view, expanded],
  );

  const showPending = useCallback((node: DiagramNode) => setNodes((current) => [...current, node]), []);
  const dropPending = useCallback(
    (id: string) => setNodes((current) => (current.some((node) => node.id === id) ? current.filter((node) => node.id !== id) : current)),
    [],
  );

  return { nodes, edges, setNodes, setEdges, onNodesChange, onEdgesChange, laidOut, arrange, selectNext, quick, showPending, dropPending };
}
