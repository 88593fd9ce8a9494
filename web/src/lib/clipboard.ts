// Successive pastes of one copy land side by side instead of on top of each other.

import type { XY } from "../types";

export const PASTE_STEP = 40;

/** The offset of the `count`-th paste (1, 2, ...) since the last copy. */
export function pasteOffset(count: number): XY {
  const step = PASTE_STEP * Math.max(1, count);
  return { x: step, y: step };
}
