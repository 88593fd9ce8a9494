import { describe, expect, it } from "vitest";
import { shownGraph } from "../graph";
import { layoutGraph } from "../layout";
import { nodeSize } from "../sizes";
import type { View } from "../../types";
import fixture from "../../../mock/view.json";

const view = fixture as unknown as View;
const measures = { size: nodeSize, header: () => ({ width: 200, height: 60 }) };

describe("shown graph", () => {
  it("hides a collapsed use's inner nodes and their flows", () => {
    const shown = shownGraph(view.nodes, view.edges, new Set());
    expect(shown.nodes.some((node) => node.parent !== null)).toBe(false);
    expect(shown.edges.map((edge) => [edge.source, edge.target])).toContainEqual(["n1", "n7"]);
    expect(shown.edges.every((edge) => !edge.source.includes("/") && !edge.target.includes("/"))).toBe(true);
  });

  it("draws an expanded use's flows at its ports", () => {
    const shown = shownGraph(view.nodes, view.edges, new Set(["n7"]));
    expect(shown.frames).toEqual(new Set(["n7"]));
    const pairs = shown.edges.map((edge) => [edge.source, edge.target]);
    // Into the frame's border, not its in-port under the header (the edge would cross its text).
    expect(pairs).toContainEqual(["n1", "n7"]);
    expect(pairs).not.toContainEqual(["n1", "n7/in"]);
    expect(pairs).toContainEqual(["n7/out", "n8"]);
    expect(pairs).toContainEqual(["n7/1", "n7/2"]);
  });
});

describe("layout", () => {
  it("places every shown node, inner nodes inside their frame", async () => {
    const shown = shownGraph(view.nodes, view.edges, new Set(["n7"]));
    const layout = await layoutGraph(shown, "DOWN", measures);
    for (const node of shown.nodes) expect(layout.positions.has(node.id)).toBe(true);
    const frame = layout.sizes.get("n7");
    const inner = layout.positions.get("n7/2");
    expect(frame && inner).toBeTruthy();
    if (frame && inner) {
      expect(inner.y).toBeGreaterThanOrEqual(60);
      expect(inner.x + (layout.sizes.get("n7/2")?.width ?? 0)).toBeLessThanOrEqual(frame.width);
    }
  });

  it("keeps saved positions unless arranging", async () => {
    const nodes = view.nodes.map((node) => (node.id === "n2" ? { ...node, position: { x: 999, y: 7 } } : node));
    const shown = shownGraph(nodes, view.edges, new Set());
    expect((await layoutGraph(shown, "RIGHT", measures)).positions.get("n2")).toEqual({ x: 999, y: 7 });
    expect((await layoutGraph(shown, "RIGHT", measures, true)).positions.get("n2")).not.toEqual({ x: 999, y: 7 });
  });
});
