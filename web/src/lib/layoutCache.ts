// The layouts ELK made, kept in localStorage per file: reloading or reopening a file whose nodes
// have no saved places draws it at once, instead of waiting for ELK again (at 500 nodes most of
// a first paint). A layout is used only for the very structure it was made for (structureKey),
// and its boxes are measured again before it is (remeasured).

import type { XY } from "../types";
import type { Layout } from "./layout";
import type { Size } from "./sizes";

const PREFIX = "sceml-layout:";
const INDEX = "sceml-layouts";
/** How many files' layouts are kept (each is tens of kilobytes at 500 nodes). */
const KEEP = 4;

interface Stored {
  key: string;
  positions: [string, XY][];
  sizes: [string, Size][];
}

function kept(): string[] {
  try {
    const index: unknown = JSON.parse(localStorage.getItem(INDEX) ?? "[]");
    return Array.isArray(index) ? index.filter((item): item is string => typeof item === "string") : [];
  } catch {
    return [];
  }
}

/** The layout stored for `document` if it was made for the structure `key`. */
export function storedLayout(document: string, key: string): Layout | null {
  try {
    const stored = JSON.parse(localStorage.getItem(PREFIX + document) ?? "null") as Stored | null;
    if (!stored || stored.key !== key) return null;
    return { positions: new Map(stored.positions), sizes: new Map(stored.sizes) };
  } catch {
    return null;
  }
}

/** Keep `layout` for `document`; the oldest files' layouts make room. */
export function storeLayout(document: string, key: string, layout: Layout): void {
  const stored: Stored = { key, positions: [...layout.positions], sizes: [...layout.sizes] };
  const index = [document, ...kept().filter((item) => item !== document)];
  try {
    for (const old of index.slice(KEEP)) localStorage.removeItem(PREFIX + old);
    localStorage.setItem(PREFIX + document, JSON.stringify(stored));
    localStorage.setItem(INDEX, JSON.stringify(index.slice(0, KEEP)));
  } catch {
    // Storage full or disabled: the next open lays the file out again, nothing else is lost.
  }
}
