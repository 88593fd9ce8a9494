import { describe, expect, it } from "vitest";
import { applyAnswer } from "../patch";
import type { Answer, View } from "../../types";
import fixture from "../../../mock/view.json";

function must<T>(value: T | null | undefined): T {
  if (value === null || value === undefined) throw new Error("expected a value");
  return value;
}

const view = { ...(fixture as unknown as View), revision: 7 };

function small(from: View): Omit<View, "nodes" | "edges" | "actors" | "diagnostics" | "palette" | "style" | "choices" | "valueTypes" | "comparison"> {
  const { nodes: _n, edges: _e, actors: _a, diagnostics: _d, palette: _p, style: _s, choices: _c, valueTypes: _v, comparison: _x, ...rest } = from;
  void [_n, _e, _a, _d, _p, _s, _c, _v, _x];
  return rest;
}

describe("patches", () => {
  it("replaces a changed node and keeps every other node's object", () => {
    const [first, second, ...others] = view.nodes;
    const renamed = { ...must(second), name: "Renamed" };
    const answer: Answer = { ...small(view), revision: 8, undo: "Rename", patch: { base: 7, nodes: { changed: [renamed], removed: [] } } };
    const next = must(applyAnswer(view, answer));
    expect(next.revision).toBe(8);
    expect(next.undo).toBe("Rename");
    expect(next.nodes[1]).toBe(renamed);
    expect(next.nodes[0]).toBe(first);
    next.nodes.slice(2).forEach((node, index) => expect(node).toBe(others[index]));
    expect(next.edges).toBe(view.edges);
    expect(next.palette).toBe(view.palette);
    expect(next.diagnostics).toBe(view.diagnostics);
  });

  it("drops removed entries, appends added ones, and follows an order when given", () => {
    const gone = must(view.nodes[1]).id;
    const added = { ...must(view.nodes[1]), id: "new" };
    const next = must(applyAnswer(view, { ...small(view), revision: 8, patch: { base: 7, nodes: { changed: [added], removed: [gone] } } }));
    expect(next.nodes.map((node) => node.id)).toEqual([...view.nodes.map((node) => node.id).filter((id) => id !== gone), "new"]);
    const order = [...view.nodes.map((node) => node.id)].reverse();
    const reversed = must(applyAnswer(view, { ...small(view), revision: 8, patch: { base: 7, nodes: { changed: [], removed: [], order } } }));
    expect(reversed.nodes.map((node) => node.id)).toEqual(order);
    expect(reversed.nodes[0]).toBe(view.nodes[view.nodes.length - 1]);
  });

  it("answers null for a patch to a revision the page does not hold", () => {
    expect(applyAnswer(view, { ...small(view), revision: 9, patch: { base: 8 } })).toBeNull();
    expect(applyAnswer(null, { ...small(view), revision: 9, patch: { base: 8 } })).toBeNull();
  });

  it("takes a whole view as it is, and forgets a comparison the patch ends", () => {
    expect(applyAnswer(null, view)).toBe(view);
    const comparing = { ...view, comparison: { against: "f.xmi", saved: true, changes: [], removed: [] } };
    const next = must(applyAnswer(comparing, { ...small(comparing), revision: 8, patch: { base: 7, comparison: null } }));
    expect("comparison" in next).toBe(false);
    expect(next.nodes).toBe(view.nodes);
  });
});
