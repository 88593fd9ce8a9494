// Which component draws which node.

import { componentOf } from "../lib/looks";
import { ActionNode, EndNode, FrameNode, JoinNode, ModuleNode, PortNode, RootNode } from "./nodes";

export const nodeTypes = {
  action: ActionNode,
  root: RootNode,
  join: JoinNode,
  end: EndNode,
  port: PortNode,
  module: ModuleNode,
  frame: FrameNode,
};

/** The React Flow type that draws a node. */
export function nodeType(look: string, expanded: boolean): keyof typeof nodeTypes {
  const component = componentOf(look);
  if (component === "module" && expanded) return "frame";
  return component;
}
