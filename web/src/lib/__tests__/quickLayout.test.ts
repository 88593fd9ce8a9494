import { describe, expect, it } from "vitest";
import { shownGraph } from "../graph";
import { quickLayout } from "../quickLayout";
import type { ViewEdge, ViewNode } from "../../types";

const size = { width: 100, height: 40 };
const measures = { size: () => size, header: () => size };

function node(id: string, position: { x: number; y: number } | null = null): ViewNode {
  return { id, parent: null, position } as unknown as ViewNode;
}
const edge = (source: string, target: string): ViewEdge => ({ id: `${source}>${target}`, source, target });

describe("quick layout", () => {
  // a -> b -> c, a -> d, and c -> a closing a loop.
  const nodes = [node("a"), node("b"), node("c"), node("d")];
  const edges = [edge("a", "b"), edge("b", "c"), edge("a", "d"), edge("c", "a")];

  it("puts every node one layer below its predecessors, leaving out the flow that closes a loop", () => {
    const { positions } = quickLayout(shownGraph(nodes, edges, new Set()), "DOWN", measures);
    const y = (id: string) => positions.get(id)?.y;
    // 40 px boxes, 50 px between layers.
    expect([y("a"), y("b"), y("c"), y("d")]).toEqual([0, 90, 180, 90]);
  });

  it("keeps boxes of one layer apart and a single successor under its predecessor", () => {
    const { positions } = quickLayout(shownGraph(nodes, edges, new Set()), "DOWN", measures);
    const b = positions.get("b");
    const d = positions.get("d");
    expect(b && d && Math.abs(b.x - d.x)).toBeGreaterThanOrEqual(130);
    expect(positions.get("c")?.x).toBe(b?.x);
  });

  it("lays layers out left to right for the direction RIGHT, and keeps saved places", () => {
    const placed = [node("a"), node("b", { x: 500, y: 7 })];
    const { positions } = quickLayout(shownGraph(placed, [edge("a", "b")], new Set()), "RIGHT", measures);
    expect(positions.get("a")).toEqual({ x: 0, y: 0 });
    expect(positions.get("b")).toEqual({ x: 500, y: 7 });
  });
});
