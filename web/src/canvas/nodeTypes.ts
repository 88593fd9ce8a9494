// Which component draws which node.

import { memo } from "react";
import { componentOf } from "../lib/looks";
import { ActionNode, EndNode, FrameNode, JoinNode, ModuleNode, PortNode, RootNode } from "./nodes";

// Memoised: a node whose props are the same objects (the page keeps unchanged nodes' objects
// across patches) is not drawn again when another node changes.
export const nodeTypes = {
  action: memo(ActionNode),
  root: memo(RootNode),
  join: memo(JoinNode),
  end: memo(EndNode),
  port: memo(PortNode),
  module: memo(ModuleNode),
  frame: memo(FrameNode),
};

/** The React Flow type that draws a node. */
export function nodeType(look: string, expanded: boolean): keyof typeof nodeTypes {
  const component = componentOf(look);
  if (component === "module" && expanded) return "frame";
  return component;
}
