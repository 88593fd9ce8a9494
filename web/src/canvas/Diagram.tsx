// The canvas: React Flow with the notation's nodes, connect by dragging, drop from the palette.

import { Background, Controls, MiniMap, ReactFlow, type Connection } from "@xyflow/react";
import { useCallback, useEffect, useMemo, useRef, type DragEvent } from "react";
import { useReactFlow } from "@xyflow/react";
import type { Direction } from "../lib/layout";
import { resolveLook } from "../lib/looks";
import { PALETTE_MIME } from "../panels/Palette";
import type { DiagramState } from "../state/useDiagramState";
import type { PaletteItem, View, XY } from "../types";
import { DiagramContext } from "./context";
import { nodeTypes } from "./nodeTypes";
import type { DiagramNode } from "./types";

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

  const onDrop = (event: DragEvent) => {
    const data = event.dataTransfer.getData(PALETTE_MIME);
    if (!data || readOnly) return;
    event.preventDefault();
    onDropItem(JSON.parse(data) as PaletteItem, flow.screenToFlowPosition({ x: event.clientX, y: event.clientY }));
  };

  const minimapColour = (node: DiagramNode) => {
    if (node.type === "frame") return "transparent";
    return resolveLook(view?.style, node.data.node.look).fill;
  };

  return (
    <DiagramContext.Provider value={context}>
      <div className="diagram" role="application" aria-label="Diagram" onDragOver={(event) => event.preventDefault()} onDrop={onDrop}>
        <ReactFlow<DiagramNode>
          nodes={state.nodes}
          edges={state.edges}
          nodeTypes={nodeTypes}
          onNodesChange={state.onNodesChange}
          onEdgesChange={state.onEdgesChange}
          onConnect={(connection: Connection) => onConnect(connection.source, connection.target)}
          onNodeDragStop={(_event, _node, dragged) => {
            const positions: Record<string, XY> = {};
            for (const node of dragged) {
              if (!node.parentId) positions[node.id] = { x: Math.round(node.position.x), y: Math.round(node.position.y) };
            }
            if (Object.keys(positions).length > 0) onMoved(positions);
          }}
          nodesDraggable={!readOnly}
          nodesConnectable={!readOnly}
          edgesReconnectable={false}
          deleteKeyCode={null}
          selectionKeyCode="Shift"
          multiSelectionKeyCode={["Shift", "Meta", "Control"]}
          selectionOnDrag={false}
          panOnDrag
          minZoom={0.02}
          onlyRenderVisibleElements
          maxZoom={2.5}
          connectionRadius={30}
          proOptions={{ hideAttribution: true }}
          defaultEdgeOptions={{ type: "default" }}
        >
          <Background gap={20} color="#e0e4e8" />
          <MiniMap<DiagramNode> pannable zoomable style={{ width: 170, height: 120 }} nodeColor={minimapColour} nodeStrokeColor="#37474f" nodeStrokeWidth={2} />
          <Controls showInteractive={false} showFitView={false} />
        </ReactFlow>
        <div className="connect-hint" aria-live="polite">
          {connectFrom ? `Connecting from ${connectFrom.name}: select the target and press C (or Enter on its in-handle); Escape cancels.` : ""}
        </div>
      </div>
    </DiagramContext.Provider>
  );
}
