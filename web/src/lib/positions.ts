// The inputs of a position (none, world, lane, road, relative to an actor, or on a route) and the
// Position they stand for; the protocol's types are those of docs/editor-protocol.md.

import type { Position } from "../types";
import { editText, parseParam } from "./values";

export type PositionType = "none" | Position["type"];

/** What an input holds: a name (road id, the actor a relative position is measured from), a
 * whole number (a lane, a lane difference), or a parameter value (a coordinate). */
export type InputKind = "name" | "integer" | "parameter";

export interface PositionInput {
  key: string;
  label: string;
  required: boolean;
  kind: InputKind;
  /** What an empty optional whole number stands for (0 unless given: a route's lane is null). */
  empty?: number | null;
}

const name = (key: string, label: string): PositionInput => ({ key, label, required: true, kind: "name" });
const integer = (key: string, label: string, required = true, empty: number | null = 0): PositionInput => ({
  key,
  label,
  required,
  kind: "integer",
  empty,
});
const param = (key: string, label: string, required = false): PositionInput => ({ key, label, required, kind: "parameter" });

/** The inputs of each position type: protocol key and the word in the input's label. */
export const POSITION_INPUTS: Record<Exclude<PositionType, "none">, PositionInput[]> = {
  world: [param("x", "x", true), param("y", "y", true), param("z", "z"), param("h", "heading")],
  lane: [name("roadId", "road"), integer("laneId", "lane"), param("s", "s", true), param("offset", "offset"), param("h", "heading")],
  road: [name("roadId", "road"), param("s", "s", true), param("t", "t"), param("h", "heading")],
  relativeLane: [name("entity", "from"), integer("dLane", "lanes", false), param("ds", "ds"), param("offset", "offset")],
  relativeRoad: [name("entity", "from"), param("ds", "ds"), param("dt", "dt")],
  relativeObject: [name("entity", "from"), param("dx", "dx"), param("dy", "dy"), param("dz", "dz"), param("h", "heading")],
  relativeWorld: [name("entity", "from"), param("dx", "dx"), param("dy", "dy"), param("dz", "dz")],
  // The place on the route; the route itself (its waypoints) is kept as read, not edited here.
  route: [param("pathS", "pathS"), integer("laneId", "lane", false, null), param("laneOffset", "lane offset"), param("t", "t")],
};

/** The words the type select shows. */
export const POSITION_LABELS: Record<PositionType, string> = {
  none: "none",
  world: "world",
  lane: "lane",
  road: "road",
  relativeLane: "relative lane",
  relativeRoad: "relative road",
  relativeObject: "relative to actor",
  relativeWorld: "relative world",
  route: "on a route",
};

export interface PositionDraft {
  type: PositionType;
  inputs: Record<string, string>;
  /** What the inputs do not edit and the Position carries on: a route's name, closed, waypoints. */
  kept?: Record<string, unknown>;
}

export function positionDraft(value: Position | null): PositionDraft {
  if (value === null) return { type: "none", inputs: {} };
  const fields = value as unknown as Record<string, unknown>;
  const inputs: Record<string, string> = {};
  for (const input of POSITION_INPUTS[value.type]) {
    const held = fields[input.key];
    if (input.kind === "parameter") inputs[input.key] = editText((held ?? null) as Parameters<typeof editText>[0]);
    else inputs[input.key] = held === null || held === undefined ? "" : String(held);
  }
  if (value.type === "route") {
    const kept = { routeName: value.routeName, closed: value.closed, waypoints: value.waypoints };
    return { type: value.type, inputs, kept };
  }
  return { type: value.type, inputs };
}

/** The Position of a draft: null for none, undefined while incomplete or malformed. */
export function positionOfDraft(draft: PositionDraft): Position | null | undefined {
  if (draft.type === "none") return null;
  // A route needs its waypoints, which only a route read from a file has.
  if (draft.type === "route" && !Array.isArray(draft.kept?.waypoints)) return undefined;
  const built: Record<string, unknown> = { type: draft.type, ...(draft.type === "route" ? draft.kept : {}) };
  for (const input of POSITION_INPUTS[draft.type]) {
    const text = (draft.inputs[input.key] ?? "").trim();
    if (input.kind === "name") {
      if (!text) return undefined;
      built[input.key] = text;
    } else if (input.kind === "integer") {
      if (text === "") {
        if (input.required) return undefined;
        built[input.key] = input.empty === undefined ? 0 : input.empty;
        continue;
      }
      const whole = Number(text);
      if (!Number.isInteger(whole)) return undefined;
      built[input.key] = whole;
    } else {
      const value = parseParam(draft.inputs[input.key] ?? "");
      if (value === undefined || (input.required && !value)) return undefined;
      built[input.key] = value;
    }
  }
  return built as unknown as Position;
}
