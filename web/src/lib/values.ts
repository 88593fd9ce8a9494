// Turning what the user types into the protocol's ParamValue, and back. Only syntax: whether a
// value is allowed (units, ranges, the level) is the server's call, and so is the text a value
// is shown as (the view's `text` fields). The one text written here is an input's: a coordinate
// in SceML's value notation with every digit kept, so that editing it loses nothing.

import type { ParamType, ParamValue } from "../types";

/** The inputs a parameter kind has, in order, and which of them must be filled. */
export const PARAM_INPUTS: Record<ParamType, { name: string; required: boolean }[]> = {
  value: [{ name: "value", required: true }],
  range: [
    { name: "min", required: true },
    { name: "max", required: true },
    { name: "step", required: false },
  ],
  uniform: [
    { name: "min", required: true },
    { name: "max", required: true },
  ],
  normal: [
    { name: "mean", required: true },
    { name: "sd", required: true },
    { name: "min", required: false },
    { name: "max", required: false },
  ],
  discrete: [
    { name: "values", required: true },
    { name: "weights", required: false },
  ],
  ref: [{ name: "parameter", required: true }],
};

export const PARAM_TYPES = Object.keys(PARAM_INPUTS) as ParamType[];

export function isParamType(text: string): text is ParamType {
  return (PARAM_TYPES as string[]).includes(text);
}

export interface Draft {
  type: ParamType | "unset";
  inputs: Record<string, string>;
}

const num = (value: number | null | undefined): string =>
  value === null || value === undefined ? "" : String(value);

/** The text of each input for a value. */
export function draftOf(value: ParamValue | null): Draft {
  if (value === null) return { type: "unset", inputs: {} };
  switch (value.type) {
    case "value":
      return { type: "value", inputs: { value: num(value.value) } };
    case "range":
      return { type: "range", inputs: { min: num(value.min), max: num(value.max), step: num(value.step) } };
    case "uniform":
      return { type: "uniform", inputs: { min: num(value.min), max: num(value.max) } };
    case "normal":
      return {
        type: "normal",
        inputs: { mean: num(value.mean), sd: num(value.sd), min: num(value.min), max: num(value.max) },
      };
    case "discrete":
      return {
        type: "discrete",
        inputs: { values: value.values.join(", "), weights: value.weights ? value.weights.join(", ") : "" },
      };
    case "ref":
      return { type: "ref", inputs: { parameter: value.parameter } };
  }
}

/** A number typed by the user (a comma as decimal mark is accepted), or null. */
export function parseNumber(text: string | undefined): number | null {
  const trimmed = (text ?? "").trim().replace(/^(-?\d+),(\d+)$/, "$1.$2");
  if (trimmed === "") return null;
  const value = Number(trimmed);
  return Number.isFinite(value) ? value : null;
}

/** Why a typed number cannot be used ("fast" is not a number; 1e400 is too large), or null
 * when it can (an empty text is a missing number, not a wrong one). */
export function numberProblem(text: string | undefined): string | null {
  const trimmed = (text ?? "").trim().replace(/^(-?\d+),(\d+)$/, "$1.$2");
  if (trimmed === "") return null;
  const value = Number(trimmed);
  if (Number.isNaN(value)) return `“${trimmed}” is not a number`;
  if (!Number.isFinite(value)) return `${trimmed} is too large: numbers go up to about 1.8e308`;
  return null;
}

/** Why a coordinate's text (a number or a compact distribution, see editText) cannot be
 * used, or null. */
export function paramTextProblem(text: string | undefined): string | null {
  const trimmed = (text ?? "").trim();
  if (trimmed === "" || parseParam(trimmed) !== undefined) return null;
  // A number too large for a double is named as such; anything else gets the forms it may take.
  if (Math.abs(Number(trimmed)) === Infinity) return numberProblem(trimmed);
  return `“${trimmed}” is neither a number nor a value like [5, 10], U(5, 10), N(8, 1) or {5, 8}`;
}

/** Why a typed list of numbers cannot be used: the first item's problem, or null. */
export function numberListProblem(text: string | undefined): string | null {
  for (const item of (text ?? "").split(/[,;\s]+/)) {
    const problem = numberProblem(item);
    if (problem) return problem;
  }
  return null;
}

/** A comma- or space-separated list of numbers, or null when any item is not a number. */
export function parseNumberList(text: string | undefined): number[] | null {
  const items = (text ?? "").split(/[,;\s]+/).filter((item) => item !== "");
  if (items.length === 0) return null;
  const numbers = items.map((item) => parseNumber(item));
  return numbers.every((item): item is number => item !== null) ? numbers : null;
}

/** The value a draft stands for: null for "unset", undefined while it is incomplete or malformed. */
export function valueOfDraft(draft: Draft): ParamValue | null | undefined {
  const n = (name: string) => parseNumber(draft.inputs[name]);
  const filled = (name: string) => (draft.inputs[name] ?? "").trim() !== "";
  const optional = (name: string): number | null | undefined => (filled(name) ? (n(name) ?? undefined) : null);
  switch (draft.type) {
    case "unset":
      return null;
    case "value": {
      const value = n("value");
      return value === null ? undefined : { type: "value", value };
    }
    case "range": {
      const [min, max, step] = [n("min"), n("max"), optional("step")];
      return min === null || max === null || step === undefined ? undefined : { type: "range", min, max, step };
    }
    case "uniform": {
      const [min, max] = [n("min"), n("max")];
      return min === null || max === null ? undefined : { type: "uniform", min, max };
    }
    case "normal": {
      const [mean, sd, min, max] = [n("mean"), n("sd"), optional("min"), optional("max")];
      if (mean === null || sd === null || min === undefined || max === undefined) return undefined;
      return { type: "normal", mean, sd, min, max };
    }
    case "discrete": {
      const values = parseNumberList(draft.inputs.values);
      const weights = filled("weights") ? parseNumberList(draft.inputs.weights) : null;
      if (values === null || (filled("weights") && weights === null)) return undefined;
      return { type: "discrete", values, weights };
    }
    case "ref": {
      const parameter = (draft.inputs.parameter ?? "").trim();
      return parameter ? { type: "ref", parameter } : undefined;
    }
  }
}

/** A representative number of a value, carried over when the user switches its kind. */
function centre(draft: Draft): string {
  const inputs = draft.inputs;
  return inputs.value || inputs.mean || inputs.min || (inputs.values ?? "").split(/[,\s]+/)[0] || "";
}

/** The draft after the user picks another kind: the old number is kept where it fits. */
export function switchKind(draft: Draft, type: ParamType | "unset"): Draft {
  const c = centre(draft);
  const keep = (name: string, fallback: string) => draft.inputs[name] ?? fallback;
  switch (type) {
    case "unset":
      return { type, inputs: {} };
    case "value":
      return { type, inputs: { value: c } };
    case "range":
      return { type, inputs: { min: keep("min", c), max: keep("max", c), step: keep("step", "") } };
    case "uniform":
      return { type, inputs: { min: keep("min", c), max: keep("max", c) } };
    case "normal":
      return { type, inputs: { mean: c, sd: keep("sd", ""), min: keep("min", ""), max: keep("max", "") } };
    case "discrete":
      return { type, inputs: { values: c, weights: "" } };
    case "ref":
      return { type, inputs: { parameter: "" } };
  }
}

const list = (values: number[]) => values.join(", ");
/** A bound of a normal distribution: `?` where it is open, as the server writes it. */
const bound = (value: number | null): string => (value === null ? "?" : String(value));

/** A coordinate input's text: SceML's value notation (the server's `params.describe`, e.g. 8,
 * [5, 10] step 1, U(5, 10), N(8, 1) in [6, 10], {5, 8} weights {1, 2}, $speed), with every digit
 * of each number where the server's display text rounds to six. The cases both sides are tested
 * against: __tests__/value-notation.json. */
export function editText(value: ParamValue | null): string {
  if (value === null) return "";
  switch (value.type) {
    case "value":
      return String(value.value);
    case "range":
      return `[${value.min}, ${value.max}]` + (value.step === null ? "" : ` step ${value.step}`);
    case "uniform":
      return `U(${value.min}, ${value.max})`;
    case "normal":
      return (
        `N(${value.mean}, ${value.sd})` +
        (value.min === null && value.max === null ? "" : ` in [${bound(value.min)}, ${bound(value.max)}]`)
      );
    case "discrete":
      return `{${list(value.values)}}` + (value.weights ? ` weights {${list(value.weights)}}` : "");
    case "ref":
      return `$${value.parameter}`;
  }
}

const NUMBER = String.raw`\s*(-?[\d.eE+-]+)\s*`;
// A bound may be left open: empty, or `?` as the notation writes it.
const OPTIONAL = String.raw`\s*(\?|-?[\d.eE+-]*)\s*`;

/** Parse editText's text: null when empty, undefined when it cannot be read. */
export function parseParam(text: string): ParamValue | null | undefined {
  const t = text.trim();
  if (t === "") return null;
  const plain = parseNumber(t);
  if (plain !== null) return { type: "value", value: plain };
  let m = new RegExp(String.raw`^\[${NUMBER},${NUMBER}\](?:\s*step${NUMBER})?$`).exec(t);
  if (m) return checked({ type: "range", min: Number(m[1]), max: Number(m[2]), step: m[3] ? Number(m[3]) : null });
  m = new RegExp(String.raw`^U\(${NUMBER},${NUMBER}\)$`, "i").exec(t);
  if (m) return checked({ type: "uniform", min: Number(m[1]), max: Number(m[2]) });
  m = new RegExp(String.raw`^N\(${NUMBER},${NUMBER}\)(?:\s*in\s*\[${OPTIONAL},${OPTIONAL}\])?$`, "i").exec(t);
  if (m) {
    const given = (s: string | undefined) => (s && s !== "?" ? Number(s) : null);
    return checked({ type: "normal", mean: Number(m[1]), sd: Number(m[2]), min: given(m[3]), max: given(m[4]) });
  }
  m = /^\{([^}]*)\}(?:\s*weights\s*\{([^}]*)\})?$/i.exec(t);
  if (m) {
    const values = parseNumberList(m[1]);
    const weights = m[2] === undefined ? null : parseNumberList(m[2]);
    if (values === null || (m[2] !== undefined && weights === null)) return undefined;
    return { type: "discrete", values, weights };
  }
  m = /^\$([A-Za-z_][\w]*)$/.exec(t);
  if (m?.[1]) return { type: "ref", parameter: m[1] };
  return undefined;
}

function checked(value: ParamValue): ParamValue | undefined {
  const numbers = Object.values(value).filter((item): item is number => typeof item === "number");
  return numbers.every(Number.isFinite) ? value : undefined;
}
