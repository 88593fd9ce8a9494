import { describe, expect, it } from "vitest";
import { freeSpot } from "../placement";

const box = (x: number, y: number, width = 120, height = 40) => ({ x, y, width, height });

describe("free spot for a new node", () => {
  it("keeps the wanted place when nothing is there", () => {
    expect(freeSpot(box(0, 0), [box(400, 400)])).toEqual({ x: 0, y: 0 });
  });

  it("moves below a node it would cover", () => {
    expect(freeSpot(box(0, 0), [box(-20, -10, 200, 100)])).toEqual({ x: 0, y: 114 });
  });

  it("moves past a stack of nodes, not into the next one", () => {
    const stack = [box(0, 0), box(0, 70), box(0, 140)];
    const spot = freeSpot(box(10, 10), stack);
    expect(spot.y).toBe(204);
  });
});
