// The in (target) and out (source) handle of a node, on the sides the layout direction gives.
// Both are keyboard controls too: Enter on an out-handle starts a connection, Enter on another
// node's in-handle ends it (as do C on a selected node and C on the target). Zoomed out below
// FAR_ZOOM they are not drawn (a handle is a few pixels there, and 1,000 of them at 500 nodes
// cost a first paint a quarter of React's work): edges end where `handlesOf` says, and
// C connects the selected nodes.

import { Handle, Position, useNodeId } from "@xyflow/react";
import type { KeyboardEvent } from "react";
import { useDiagram } from "./context";
import { useFar } from "./zoom";

export function Handles({ connectable, name }: { connectable: boolean; name?: string }) {
  const { direction, connectFrom, keyConnect } = useDiagram();
  const id = useNodeId();
  const far = useFar();
  const across = direction === "RIGHT";
  const keyboard = connectable && id !== null && name !== undefined;
  const onKey = (end: "source" | "target") => (event: KeyboardEvent) => {
    if (!keyboard || (event.key !== "Enter" && event.key !== " ")) return;
    event.preventDefault();
    event.stopPropagation();
    keyConnect(id, end);
  };
  if (far) return null;
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
