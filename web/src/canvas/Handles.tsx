// The in (target) and out (source) handle of a node, on the sides the layout direction gives.

import { Handle, Position } from "@xyflow/react";
import { useDiagram } from "./context";

export function Handles({ connectable }: { connectable: boolean }) {
  const { direction } = useDiagram();
  const across = direction === "RIGHT";
  return (
    <>
      <Handle type="target" position={across ? Position.Left : Position.Top} isConnectable={connectable} />
      <Handle type="source" position={across ? Position.Right : Position.Bottom} isConnectable={connectable} />
    </>
  );
}
