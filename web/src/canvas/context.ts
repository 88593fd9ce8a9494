// What every node component needs besides its own data: the style, the direction, the toggle.

import { createContext, useContext } from "react";
import type { Direction } from "../lib/layout";
import type { Style } from "../types";

export interface DiagramContextValue {
  style: Style | undefined;
  direction: Direction;
  readOnly: boolean;
  toggleExpanded: (id: string) => void;
}

export const DiagramContext = createContext<DiagramContextValue>({
  style: undefined,
  direction: "DOWN",
  readOnly: true,
  toggleExpanded: () => undefined,
});

export const useDiagram = () => useContext(DiagramContext);
