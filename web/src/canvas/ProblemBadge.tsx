// The count of a node's problems, coloured by the worst severity.

import type { ViewNode } from "../types";

export function ProblemBadge({ node }: { node: ViewNode }) {
  if (node.problems <= 0) return null;
  const label = `${node.problems} problems`; // the protocol names it so, whatever the count
  return (
    <span className={`problem-badge severity-${node.severity ?? "info"}`} role="img" aria-label={label} title={label}>
      {node.problems}
    </span>
  );
}
