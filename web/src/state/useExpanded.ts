// Which module uses are drawn expanded: a view choice kept in localStorage per file. Ids are not
// stable across sessions, so uses are remembered by their names.

import { useCallback, useMemo, useState } from "react";
import type { View, ViewNode } from "../types";

function key(view: View): string {
  return `sceml-expanded:${view.document.path}${view.document.module ? `#${view.document.module}` : ""}`;
}

function namePath(node: ViewNode, byId: Map<string, ViewNode>): string {
  const names = [node.name];
  let parent = node.parent === null ? undefined : byId.get(node.parent);
  while (parent) {
    names.unshift(parent.name);
    parent = parent.parent === null ? undefined : byId.get(parent.parent);
  }
  return names.join("/");
}

function load(storageKey: string): string[] {
  try {
    const stored: unknown = JSON.parse(localStorage.getItem(storageKey) ?? "[]");
    return Array.isArray(stored) ? stored.filter((item): item is string => typeof item === "string") : [];
  } catch {
    return [];
  }
}

export function useExpanded(view: View | null): [Set<string>, (id: string) => void] {
  const [revision, setRevision] = useState(0);
  const storageKey = view ? key(view) : null;
  const nodes = view?.nodes;

  const expanded = useMemo(() => {
    void revision;
    if (!storageKey || !nodes) return new Set<string>();
    const names = new Set(load(storageKey));
    const byId = new Map(nodes.map((node) => [node.id, node]));
    return new Set(nodes.filter((node) => names.has(namePath(node, byId))).map((node) => node.id));
  }, [storageKey, nodes, revision]);

  const toggle = useCallback(
    (id: string) => {
      if (!storageKey || !nodes) return;
      const byId = new Map(nodes.map((node) => [node.id, node]));
      const node = byId.get(id);
      if (!node) return;
      const path = namePath(node, byId);
      const names = new Set(load(storageKey));
      if (names.has(path)) names.delete(path);
      else names.add(path);
      localStorage.setItem(storageKey, JSON.stringify([...names]));
      setRevision((value) => value + 1);
    },
    [storageKey, nodes],
  );

  return [expanded, toggle];
}
