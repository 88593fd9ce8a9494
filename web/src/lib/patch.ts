// Apply the server's patch to the view the page holds. Entries the patch does not name keep
// their very objects, so that everything drawn from them (React Flow's nodes, memoised
// components) sees them unchanged and is not redrawn.

import type { Answer, ListPatch, View, ViewPatch } from "../types";

function patchList<T extends { id: string }>(list: T[], patch: ListPatch<T> | undefined): T[] {
  if (!patch) return list;
  const changed = new Map(patch.changed.map((entry) => [entry.id, entry]));
  const removed = new Set(patch.removed);
  if (patch.order) {
    const old = new Map(list.map((entry) => [entry.id, entry]));
    return patch.order.map((id) => {
      const entry = changed.get(id) ?? old.get(id);
      if (!entry) throw new Error(`the patch names ${id}, which the page does not hold`);
      return entry;
    });
  }
  const kept = list.filter((entry) => !removed.has(entry.id)).map((entry) => changed.get(entry.id) ?? entry);
  const known = new Set(kept.map((entry) => entry.id));
  return [...kept, ...patch.changed.filter((entry) => !known.has(entry.id))];
}

/** The view after `answer`, or null when it is a patch to a revision the page does not hold
 * (it missed a change): then the page asks for the whole view. */
export function applyAnswer(current: View | null, answer: Answer): View | null {
  if (!("patch" in answer)) return answer;
  const { patch, ...small } = answer;
  if (current === null || current.revision !== patch.base) return null;
  return applyPatch(current, patch, small);
}

function applyPatch(current: View, patch: ViewPatch, small: Partial<View>): View {
  // What one answer said about this tab (created nodes) must not stick to the next.
  const { created: _created, ...rest } = current;
  void _created;
  const next: View = {
    ...rest,
    ...small,
    nodes: patchList(current.nodes, patch.nodes),
    edges: patchList(current.edges, patch.edges),
    actors: patch.actors ?? current.actors,
    diagnostics: patch.diagnostics ?? current.diagnostics,
    palette: patch.palette ?? current.palette,
    style: patch.style ?? current.style,
    choices: patch.choices ?? current.choices,
    valueTypes: patch.valueTypes ?? current.valueTypes,
  };
  if ("comparison" in patch) {
    if (patch.comparison) next.comparison = patch.comparison;
    else delete next.comparison;
  }
  return next;
}
