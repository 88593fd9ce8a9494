import { describe, expect, it } from "vitest";
import { positionDraft, positionOfDraft } from "../positions";
import type { Position } from "../../types";

// A start on a route as the server sends it (sceml.editor.values.position_to_json).
const onRoute: Position = {
  type: "route",
  routeName: "KeepRight",
  closed: false,
  waypoints: [
    { routeStrategy: "shortest", position: { type: "lane", roadId: "1", laneId: -2, s: { type: "value", value: 20 }, offset: null, h: null } },
    { routeStrategy: "fastest", position: { type: "lane", roadId: "1", laneId: -2, s: { type: "value", value: 900 }, offset: null, h: null } },
  ],
  laneId: -2,
  pathS: { type: "value", value: 30 },
  laneOffset: { type: "value", value: 0.5 },
  t: null,
};

describe("route positions", () => {
  it("keep their route while the place on it is edited", () => {
    const draft = positionDraft(onRoute);
    expect(draft.inputs).toEqual({ pathS: "30", laneId: "-2", laneOffset: "0.5", t: "" });
    expect(positionOfDraft(draft)).toEqual(onRoute);
    const moved = positionOfDraft({ ...draft, inputs: { ...draft.inputs, pathS: "45" } });
    expect(moved).toEqual({ ...onRoute, pathS: { type: "value", value: 45 } });
  });

  it("read an empty lane as road coordinates (no lane), not lane 0", () => {
    const draft = positionDraft(onRoute);
    const onRoad = positionOfDraft({ ...draft, inputs: { ...draft.inputs, laneId: "", t: "-1.75" } });
    expect(onRoad).toMatchObject({ laneId: null, t: { type: "value", value: -1.75 } });
  });

  it("are incomplete when made from scratch: the waypoints come from a file", () => {
    expect(positionOfDraft({ type: "route", inputs: { pathS: "10" } })).toBeUndefined();
  });
});
