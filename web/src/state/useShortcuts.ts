// The keyboard shortcuts of the protocol; none fires while the user types in a field or a dialog.

import { useEffect, useRef } from "react";

export interface Shortcuts {
  undo: () => void;
  redo: () => void;
  remove: () => void;
  copy: () => void;
  paste: () => void;
  cut: () => void;
  selectAll: () => void;
  save: () => void;
  clearSelection: () => void;
  fit: () => void;
  /** C: start a connection at the selected node, or end it there. */
  connect: () => void;
  /** /: search the palette. */
  search: () => void;
}

function typing(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  return target.isContentEditable || ["INPUT", "TEXTAREA", "SELECT"].includes(target.tagName) || target.closest("[role=dialog]") !== null;
}

/** The shortcut a key press means, if any. */
export function shortcutOf(event: Pick<KeyboardEvent, "key" | "ctrlKey" | "metaKey" | "shiftKey" | "altKey">): keyof Shortcuts | null {
  const mod = event.ctrlKey || event.metaKey;
  const key = event.key.toLowerCase();
  if (event.altKey) return null;
  if (mod) {
    if (key === "z") return event.shiftKey ? "redo" : "undo";
    const map: Record<string, keyof Shortcuts> = { y: "redo", c: "copy", v: "paste", x: "cut", a: "selectAll", s: "save" };
    return map[key] ?? null;
  }
  if (event.key === "Delete" || event.key === "Backspace") return "remove";
  if (event.key === "Escape") return "clearSelection";
  if (key === "f" && !event.shiftKey) return "fit";
  if (key === "c" && !event.shiftKey) return "connect";
  if (event.key === "/") return "search";
  return null;
}

export function useShortcuts(handlers: Shortcuts): void {
  const current = useRef(handlers);
  useEffect(() => {
    current.current = handlers;
  });
  useEffect(() => {
    const onKey = (event: KeyboardEvent) => {
      const name = shortcutOf(event);
      if (name === null) return;
      // Save works everywhere; the others leave text fields and dialogs alone.
      if (name !== "save" && typing(event.target)) return;
      event.preventDefault();
      current.current[name]();
    };
    window.addEventListener("keydown", onKey);
    return () => window.removeEventListener("keydown", onKey);
  }, []);
}
