import { describe, expect, it } from "vitest";
import { handlesOf } from "../build";

/** A handle's centre: where editor.css centres the drawn handle, on the box's border. */
const centre = (handle: { x: number; y: number; width?: number; height?: number }) => [
  handle.x + (handle.width ?? 0) / 2,
  handle.y + (handle.height ?? 0) / 2,
];

describe("handles before React Flow measures them", () => {
  it("sit on the middle of the top and bottom border, top down", () => {
    const [into, out] = handlesOf(120, 40, "DOWN");
    expect([into?.type, into?.position, out?.type, out?.position]).toEqual(["target", "top", "source", "bottom"]);
    expect(into && centre(into)).toEqual([60, 0]);
    expect(out && centre(out)).toEqual([60, 40]);
  });

  it("sit on the middle of the left and right border, left to right", () => {
    const [into, out] = handlesOf(120, 40, "RIGHT");
    expect([into?.position, out?.position]).toEqual(["left", "right"]);
    expect(into && centre(into)).toEqual([0, 20]);
    expect(out && centre(out)).toEqual([120, 20]);
  });
});
