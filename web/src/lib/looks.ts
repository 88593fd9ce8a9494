// How a node's `look` is drawn: colours and shape come from the view's `style` (the same data as
// `sceml render`); the browser only knows which component draws which look.

import type { LookStyle, Style } from "../types";

export type NodeComponent = "action" | "root" | "join" | "end" | "module" | "port";

const COMPONENTS: Record<string, NodeComponent> = {
  root: "root",
  joinAll: "join",
  joinOne: "join",
  end: "end",
  endOne: "end",
  module: "module",
  brokenModule: "module",
  inPort: "port",
  outPort: "port",
};

/** The component that draws a look; every other look (the action categories) is a box. */
export function componentOf(look: string): NodeComponent {
  return COMPONENTS[look] ?? "action";
}

export interface ResolvedLook {
  fill: string;
  border: string;
  text: string;
  rounded: boolean;
  dashed: boolean;
}

/** The colours and outline of a look, read from the style; neutral when the style lacks it. */
export function resolveLook(style: Style | undefined, look: string): ResolvedLook {
  const entry: LookStyle = style?.looks?.[look] ?? {};
  const shape = String(entry.shape ?? "");
  const styleText = String(entry.style ?? "");
  return {
    fill: entry.fill ?? "#ffffff",
    border: entry.border ?? "#37474f",
    text: typeof entry.text === "string" ? entry.text : typeof entry.fontcolor === "string" ? entry.fontcolor : "#111111",
    rounded: /round/i.test(shape) || /round/i.test(styleText) || entry.rounded === true,
    dashed: /dash/i.test(shape) || /dash/i.test(styleText) || entry.dashed === true,
  };
}

/** A symbol of the notation (join-all ⇉, join-one ?), from the style. */
export function symbolOf(style: Style | undefined, name: string, fallback: string): string {
  return style?.symbols?.[name] ?? fallback;
}
