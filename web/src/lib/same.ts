// Whether two protocol values (plain JSON) say the same thing.

export function sameJson(a: unknown, b: unknown): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}
