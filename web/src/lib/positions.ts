// The inputs of a position (none, world, lane) and the Position they stand for.

import type { ParamValue, Position } from "../types";
import { formatParam, parseParam } from "./values";

export type PositionType = "none" | "world" | "lane";

/** The inputs of each position type: protocol key and the word in the input's label. */
export const POSITION_INPUTS: Record<Exclude<PositionType, "none">, { key: string; label: string; required: boolean }[]> = {
  world: [
    { key: "x", label: "x", required: true },
    { key: "y", label: "y", required: true },
    { key: "z", label: "z", required: false },
    { key: "h", label: "heading", required: false },
  ],
  lane: [
    { key: "roadId", label: "road", required: true },
    { key: "laneId", label: "lane", required: true },
    { key: "s", label: "s", required: true },
    { key: "offset", label: "offset", required: false },
  ],
};

export interface PositionDraft {
  type: PositionType;
  inputs: Record<string, string>;
}

export function positionDraft(value: Position | null): PositionDraft {
  if (value === null) return { type: "none", inputs: {} };
  if (value.type === "world") {
    return {
      type: "world",
      inputs: { x: formatParam(value.x), y: formatParam(value.y), z: formatParam(value.z), h: formatParam(value.h) },
    };
  }
  return {
    type: "lane",
    inputs: {
      roadId: value.roadId,
      laneId: String(value.laneId),
      s: formatParam(value.s),
      offset: formatParam(value.offset),
    },
  };
}

/** The Position of a draft: null for none, undefined while incomplete or malformed. */
export function positionOfDraft(draft: PositionDraft): Position | null | undefined {
  const param = (key: string) => parseParam(draft.inputs[key] ?? "");
  if (draft.type === "none") return null;
  if (draft.type === "world") {
    const [x, y, z, h] = [param("x"), param("y"), param("z"), param("h")];
    if (!x || !y || z === undefined || h === undefined) return undefined;
    return { type: "world", x, y, z, h };
  }
  const roadId = (draft.inputs.roadId ?? "").trim();
  const laneText = (draft.inputs.laneId ?? "").trim();
  const laneId = Number(laneText);
  const [s, offset]: (ParamValue | null | undefined)[] = [param("s"), param("offset")];
  if (!roadId || laneText === "" || !Number.isInteger(laneId) || !s || offset === undefined) return undefined;
  return { type: "lane", roadId, laneId, s, offset };
}
