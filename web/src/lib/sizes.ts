// The size each node is drawn at, so that ELK lays out the same boxes the page draws.

import type { ViewNode } from "../types";
import { componentOf } from "./looks";

export interface Size {
  width: number;
  height: number;
}

export const FONT_FAMILY = '"DejaVu Sans", "Verdana", sans-serif';
export const TITLE_PX = 13;
export const LINE_PX = 11;
export const LINE_HEIGHT = 1.3;
const PAD_X = 12;
const PAD_Y = 6;

type Measure = (text: string, px: number, bold: boolean) => number;

let context: CanvasRenderingContext2D | null | undefined;

/** Text width in pixels: the canvas's measure in a browser, an estimate elsewhere (tests). */
export const measureText: Measure = (text, px, bold) => {
  if (context === undefined) {
    context = typeof document === "undefined" ? null : document.createElement("canvas").getContext("2d");
  }
  if (!context) return text.length * px * (bold ? 0.66 : 0.6);
  context.font = `${bold ? "bold " : ""}${px}px ${FONT_FAMILY}`;
  return context.measureText(text).width;
};

function textBlock(title: string, lines: string[], measure: Measure, extraLines = 0): Size {
  const widths = [measure(title, TITLE_PX, true), ...lines.map((line) => measure(line, LINE_PX, false))];
  const width = Math.ceil(Math.max(...widths) * 1.06 + 2 * PAD_X + 6);
  const height = Math.ceil(
    TITLE_PX * LINE_HEIGHT + (lines.length + extraLines) * LINE_PX * LINE_HEIGHT + 2 * PAD_Y,
  );
  return { width: Math.max(width, 90), height: Math.max(height, 36) };
}

/** The drawn size of a node (a collapsed module use; an expanded one is sized by its frame). */
export function nodeSize(node: ViewNode, measure: Measure = measureText): Size {
  switch (componentOf(node.look)) {
    case "join":
      return { width: 40, height: 40 };
    case "end":
      return { width: 48, height: 48 };
    case "port":
      return { width: 48, height: 30 };
    case "module": {
      const size = textBlock(node.title, ["module", ...nameAndLines(node)], measure);
      return { width: size.width + 10, height: size.height + 30 }; // double frame, Expand button
    }
    case "root":
      return textBlock(node.title, node.lines, measure);
    default:
      return textBlock(node.title, nameAndLines(node), measure);
  }
}

/** The lines under a box's title: its name (when it is not the title), then the server's lines. */
export function nameAndLines(node: ViewNode): string[] {
  return node.name && node.name !== node.title ? [node.name, ...node.lines] : node.lines;
}

/** The header of an expanded module frame: the use's title and lines. */
export function frameHeaderHeight(node: ViewNode): number {
  return Math.ceil(TITLE_PX * 1.2 * LINE_HEIGHT + node.lines.length * LINE_PX * LINE_HEIGHT + 16);
}
