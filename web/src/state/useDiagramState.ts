// React Flow's nodes and edges for the current view: laid out by ELK where no position is saved,
// re-laid out when the view, the expanded uses or the direction change. Selection survives.

import { applyEdgeChanges, applyNodeChanges, type EdgeChange, type NodeChange } from "@xyflow/react";
import { useCallback, useEffect, useRef, useState } from "react";
import { flowEdges, flowNodes, measures } from "../canvas/build";
import type { DiagramEdge, DiagramNode } from "../canvas/types";
import { shownGraph } from "../lib/graph";
import { layoutGraph, type Direction } from "../lib/layout";
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
}

export function useDiagramState(
  view: View | null,
  expanded: Set<string>,
  direction: Direction,
): DiagramState {
  const [nodes, setNodes] = useState<DiagramNode[]>([]);
  const [edges, setEdges] = useState<DiagramEdge[]>([]);
  const [laidOut, setLaidOut] = useState<View | null>(null);
  const selection = useRef<{ nodes: Set<string>; edges: Set<string> }>({ nodes: new Set(), edges: new Set() });
  const pending = useRef<Set<string> | null>(null);
  const selectNext = useCallback((ids: string[]) => {
    pending.current = new Set(ids);
  }, []);

  useEffect(() => {
    selection.current = {
      nodes: new Set(nodes.filter((node) => node.selected).map((node) => node.id)),
      edges: new Set(edges.filter((edge) => edge.selected).map((edge) => edge.id)),
    };
  }, [nodes, edges]);

  useEffect(() => {
    if (!view) return;
    let cancelled = false;
    const shown = shownGraph(view.nodes, view.edges, expanded);
    void layoutGraph(shown, direction, measures).then((layout) => {
      if (cancelled) return;
      const chosen = pending.current;
      pending.current = null;
      const selectedNodes = chosen ?? selection.current.nodes;
      const selectedEdges = chosen ? new Set<string>() : selection.current.edges;
      setNodes(flowNodes(shown, layout, view.nodes, selectedNodes, view.readOnly));
      setEdges(flowEdges(shown, selectedEdges, view.readOnly));
      setLaidOut(view);
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

  return { nodes, edges, setNodes, setEdges, onNodesChange, onEdgesChange, laidOut, arrange, selectNext };
}
