// The in (target) and out (source) handle of a node, on the sides the layout direction gives.
// Both are keyboard controls too: Enter on an out-handle starts a connection, Enter on another
// node's in-handle ends it (as do C on a selected node and C on the target). They are drawn at
// any zoom: React Flow measures a node's handles in the page when it draws the node, and a node
// drawn without them (tried zoomed out, where they are a few pixels) lost its edges.

import { Handle, Position, useNodeId } from "@xyflow/react";
import type { KeyboardEvent } from "react";
import { useDiagram } from "./context";

export function Handles({ connectable, name }: { connectable: boolean; name?: string }) {
  const { direction, connectFrom, keyConnect } = useDiagram();
  const id = useNodeId();
  const across = direction === "RIGHT";
  const keyboard = connectable && id !== null && name !== undefined;
  const onKey = (end: "source" | "target") => (event: KeyboardEvent) => {
    if (!keyboard || (event.key !== "Enter" && event.key !== " ")) return;
    event.preventDefault();
    event.stopPropagation();
    keyConnect(id, end);
  };
  const into = connectFrom !== null && connectFrom.id !== id ? `Connect ${connectFrom.name} to ${name}` : `Connect into ${name}`;
  return (
    <>
      <Handle
        type="target"
        position={across ? Position.Left : Position.Top}
        isConnectable={connectable}
        tabIndex={keyboard ? 0 : -1}
        role={keyboard ? "button" : undefined}
        aria-label={keyboard ? into : undefined}
        onKeyDown={onKey("target")}
      />
      <Handle
        type="source"
        position={across ? Position.Right : Position.Bottom}
        isConnectable={connectable}
        tabIndex={keyboard ? 0 : -1}
        role={keyboard ? "button" : undefined}
        aria-label={keyboard ? `Connect from ${name}` : undefined}
        onKeyDown={onKey("source")}
      />
    </>
  );
}
