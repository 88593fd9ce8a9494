// The React Flow node and edge types of the diagram.

import type { Edge, Node } from "@xyflow/react";
import type { ViewNode } from "../types";

export type NodeData = {
  node: ViewNode;
  width: number;
  height: number;
  expanded: boolean;
  canExpand: boolean;
};

export type DiagramNode = Node<NodeData>;
export type DiagramEdge = Edge;
