import { describe, expect, it } from "vitest";
import { draftOf, editText, numberListProblem, numberProblem, paramTextProblem, parseParam, switchKind, valueOfDraft } from "../values";
import type { ParamValue } from "../../types";
import notation from "./value-notation.json";

// The case table tests/editor/test_value_notation.py reads too: the server's notation, as the
// coordinate inputs write and read it.
const notationCases = notation.cases.map((item) => ({ value: item.value as ParamValue, edit: item.edit }));

const samples: ParamValue[] = [
  { type: "value", value: 8 },
  { type: "range", min: 5, max: 10, step: 1 },
  { type: "range", min: 5, max: 10, step: null },
  { type: "uniform", min: -1.5, max: 2 },
  { type: "normal", mean: 8, sd: 1, min: null, max: null },
  { type: "normal", mean: 8, sd: 1, min: 6, max: 10 },
  { type: "discrete", values: [5, 8], weights: [1, 2] },
  { type: "discrete", values: [5, 8], weights: null },
  { type: "ref", parameter: "speed" },
];

describe("number problems", () => {
  it("names text that is not a number and numbers beyond a double", () => {
    expect(numberProblem("fast")).toBe("“fast” is not a number");
    expect(numberProblem("1e400")).toBe("1e400 is too large: numbers go up to about 1.8e308");
    expect(numberProblem("-1e400")).toBe("-1e400 is too large: numbers go up to about 1.8e308");
    expect(numberListProblem("5, 8, slow")).toBe("“slow” is not a number");
  });

  it("explains coordinate text that is neither a number nor a distribution", () => {
    expect(paramTextProblem("1e400")).toBe("1e400 is too large: numbers go up to about 1.8e308");
    expect(paramTextProblem("far")).toBe("“far” is neither a number nor a value like [5, 10], U(5, 10), N(8, 1) or {5, 8}");
    expect(paramTextProblem("U(1, 2)")).toBeNull();
    expect(paramTextProblem("34")).toBeNull();
  });

  it("accepts numbers, a decimal comma and the empty text", () => {
    expect(numberProblem("8.5")).toBeNull();
    expect(numberProblem("8,5")).toBeNull();
    expect(numberProblem(" ")).toBeNull();
    expect(numberListProblem("5, 8")).toBeNull();
  });
});

describe("parameter drafts", () => {
  it.each(samples)("round-trips %j through the inputs", (value) => {
    expect(valueOfDraft(draftOf(value))).toEqual(value);
  });

  it("unset is null, an incomplete draft is undefined", () => {
    expect(valueOfDraft(draftOf(null))).toBeNull();
    expect(valueOfDraft({ type: "range", inputs: { min: "1", max: "" } })).toBeUndefined();
    expect(valueOfDraft({ type: "value", inputs: { value: "abc" } })).toBeUndefined();
  });

  it("keeps the number when the kind changes", () => {
    const range = switchKind(draftOf({ type: "value", value: 8 }), "range");
    expect(valueOfDraft(range)).toEqual({ type: "range", min: 8, max: 8, step: null });
    expect(valueOfDraft(switchKind(range, "value"))).toEqual({ type: "value", value: 8 });
  });

  it("accepts a decimal comma", () => {
    expect(valueOfDraft({ type: "value", inputs: { value: "1,5" } })).toEqual({ type: "value", value: 1.5 });
  });
});

describe("compact parameter text", () => {
  it.each(samples)("round-trips %j", (value) => {
    expect(parseParam(editText(value))).toEqual(value);
  });

  it.each(notationCases)("writes $edit as the case table says, and reads it back", ({ value, edit }) => {
    expect(editText(value)).toBe(edit);
    expect(parseParam(edit)).toEqual(value);
  });

  it("reads an open bound left empty as well as written ?", () => {
    expect(parseParam("N(8, 1) in [6, ]")).toEqual({ type: "normal", mean: 8, sd: 1, min: 6, max: null });
  });

  it("reads empty as null and nonsense as undefined", () => {
    expect(parseParam("  ")).toBeNull();
    expect(parseParam("N(1)")).toBeUndefined();
  });
});
