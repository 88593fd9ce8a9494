// The canvas: React Flow with the notation's nodes, connect by dragging, drop from the palette.

import { Background, Controls, MiniMap, ReactFlow, type Connection } from "@xyflow/react";
import { useCallback, useEffect, useMemo, useRef, type DragEvent } from "react";
import { useReactFlow } from "@xyflow/react";
import type { Direction } from "../lib/layout";
import { resolveLook } from "../lib/looks";
import { PALETTE_MIME } from "../panels/Palette";
import type { DiagramState } from "../state/useDiagramState";
import type { PaletteItem, View, XY } from "../types";
import { useStable } from "../state/useStable";
import { DiagramContext } from "./context";
import { nodeTypes } from "./nodeTypes";
import type { DiagramNode } from "./types";

const MULTI_SELECTION_KEYS = ["Shift", "Meta", "Control"];
const PRO_OPTIONS = { hideAttribution: true };
const DEFAULT_EDGE_OPTIONS = { type: "default" };
const MINIMAP_STYLE = { width: 170, height: 120 };

interface Props {
  view: View | null;
  state: DiagramState;
  direction: Direction;
  toggleExpanded: (id: string) => void;
  connectFrom: { id: string; name: string } | null;
  keyConnect: (id: string, end: "source" | "target") => void;
  onConnect: (source: string, target: string) => void;
  onMoved: (positions: Record<string, XY>) => void;
  onDropItem: (item: PaletteItem, at: XY) => void;
}

export function Diagram({ view, state, direction, toggleExpanded, connectFrom, keyConnect, onConnect, onMoved, onDropItem }: Props) {
  const flow = useReactFlow();
  const readOnly = view?.readOnly ?? true;
  // Every view brings a new (equal) style object; a new context value would redraw every node.
  const styleText = JSON.stringify(view?.style ?? null);
  const style = useMemo(() => (JSON.parse(styleText) as View["style"] | null) ?? undefined, [styleText]);
  // The toggle changes with every view (it reads the view's nodes); the nodes get a stable one.
  const latestToggle = useRef(toggleExpanded);
  useEffect(() => {
    latestToggle.current = toggleExpanded;
  }, [toggleExpanded]);
  const toggle = useCallback((id: string) => latestToggle.current(id), []);
  const context = useMemo(
    () => ({ style, direction, readOnly, toggleExpanded: toggle, connectFrom, keyConnect }),
    [style, direction, readOnly, toggle, connectFrom, keyConnect],
  );

  // Every prop React Flow gets must keep its identity across renders: its StoreUpdater writes
  // each changed prop into the store, one update per prop, and every update runs the selector
  // of every node, edge and minimap node (at 500 nodes that was most of an edit's time).
  const connect = useStable((connection: Connection) => onConnect(connection.source, connection.target));
  const dragStop = useStable((_event: unknown, _node: DiagramNode, dragged: DiagramNode[]) => {
    const positions: Record<string, XY> = {};
    for (const node of dragged) {
      if (!node.parentId) positions[node.id] = { x: Math.round(node.position.x), y: Math.round(node.position.y) };
    }
    if (Object.keys(positions).length > 0) onMoved(positions);
  });

  const onDrop = (event: DragEvent) => {
    const data = event.dataTransfer.getData(PALETTE_MIME);
    if (!data || readOnly) return;
    event.preventDefault();
    onDropItem(JSON.parse(data) as PaletteItem, flow.screenToFlowPosition({ x: event.clientX, y: event.clientY }));
  };

  const minimapColour = useCallback(
    (node: DiagramNode) => (node.type === "frame" ? "transparent" : resolveLook(style, node.data.node.look).fill),
    [style],
  );

  return (
    <DiagramContext.Provider value={context}>
      <div className="diagram" role="application" aria-label="Diagram" onDragOver={(event) => event.preventDefault()} onDrop={onDrop}>
        <ReactFlow<DiagramNode>
          nodes={state.nodes}
          edges={state.edges}
          nodeTypes={nodeTypes}
          onNodesChange={state.onNodesChange}
          onEdgesChange={state.onEdgesChange}
          onConnect={connect}
          onNodeDragStop={dragStop}
          nodesDraggable={!readOnly}
          nodesConnectable={!readOnly}
          edgesReconnectable={false}
          deleteKeyCode={null}
          selectionKeyCode="Shift"
          multiSelectionKeyCode={MULTI_SELECTION_KEYS}
          selectionOnDrag={false}
          panOnDrag
          minZoom={0.02}
          onlyRenderVisibleElements
          maxZoom={2.5}
          connectionRadius={30}
          proOptions={PRO_OPTIONS}
          defaultEdgeOptions={DEFAULT_EDGE_OPTIONS}
        >
          <Background gap={20} color="#e0e4e8" />
          <MiniMap<DiagramNode> pannable zoomable style={MINIMAP_STYLE} nodeColor={minimapColour} nodeStrokeColor={style?.edge.color} nodeStrokeWidth={2} />
          <Controls showInteractive={false} showFitView={false} />
        </ReactFlow>
        <div className="connect-hint" aria-live="polite">
          {connectFrom ? `Connecting from ${connectFrom.name}: select the target and press C (or Enter on its in-handle); Escape cancels.` : ""}
        </div>
      </div>
    </DiagramContext.Provider>
  );
}
