// What every node component needs besides its own data: the style, the direction, the toggle.

import { createContext, useContext } from "react";
import type { Direction } from "../lib/layout";
import type { Style } from "../types";

export interface DiagramContextValue {
  style: Style | undefined;
  direction: Direction;
  readOnly: boolean;
  toggleExpanded: (id: string) => void;
  /** The node a keyboard connection starts from, while one is being made. */
  connectFrom: { id: string; name: string } | null;
  /** Start (from a source) or end (at a target) a keyboard connection at a node. */
  keyConnect: (id: string, end: "source" | "target") => void;
}

export const DiagramContext = createContext<DiagramContextValue>({
  style: undefined,
  direction: "DOWN",
  readOnly: true,
  toggleExpanded: () => undefined,
  connectFrom: null,
  keyConnect: () => undefined,
});

export const useDiagram = () => useContext(DiagramContext);
