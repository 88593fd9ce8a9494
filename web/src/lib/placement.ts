// Where a node added by click or Enter goes: the middle of the view, moved down past any node it
// would cover, so a new box never hides an existing one.

export interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

const GAP = 24;

function overlaps(a: Box, b: Box): boolean {
  return a.x < b.x + b.width + GAP && b.x < a.x + a.width + GAP && a.y < b.y + b.height + GAP && b.y < a.y + a.height + GAP;
}

/** The first place at or below `wanted` where a box of its size overlaps none of `taken`. */
export function freeSpot(wanted: Box, taken: readonly Box[]): { x: number; y: number } {
  const box = { ...wanted };
  // Each step moves just below the lowest box in the way; bounded so a crowded canvas still ends.
  for (let step = 0; step < taken.length + 1; step++) {
    const inTheWay = taken.filter((other) => overlaps(box, other));
    if (inTheWay.length === 0) break;
    box.y = Math.max(...inTheWay.map((other) => other.y + other.height)) + GAP;
  }
  return { x: box.x, y: box.y };
}
