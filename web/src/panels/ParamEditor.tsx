// A parameter: its kind (limited to the level's value types, or unset) and one input per number.
// What the value reads as (`[6, 10] step 1 m/s`, km/h) is the server's text, shown as it comes.

import { useState } from "react";
import { draftOf, isParamType, numberListProblem, numberProblem, PARAM_INPUTS, switchKind, valueOfDraft, type Draft } from "../lib/values";
import { sameJson } from "../lib/same";
import type { ParamValue } from "../types";
import { CommitInput, LabelledSelect } from "./inputs";

interface Props {
  label: string;
  value: ParamValue | null;
  valueTypes: string[];
  unit?: string | null;
  /** The server's display text of `value`, and of the default that applies while it is unset. */
  text?: string | null;
  defaultText?: string | null;
  disabled: boolean;
  onCommit: (value: ParamValue | null) => void;
}

/** Edits one parameter; adopts a new value from the server unless it is what the draft says. */
export function ParamEditor({ label, value, valueTypes, unit, text, defaultText, disabled, onCommit }: Props) {
  const [draft, setDraft] = useState<Draft>(() => draftOf(value));
  const [seen, setSeen] = useState(value);
  if (!sameJson(value, seen)) {
    setSeen(value);
    // The echo of our own edit leaves the draft (and any half-typed input) alone.
    if (!sameJson(value, valueOfDraft(draft))) setDraft(draftOf(value));
  }
  const complete = valueOfDraft(draft);
  const update = (next: Draft) => {
    setDraft(next);
    const result = valueOfDraft(next);
    if (result !== undefined && JSON.stringify(result) !== JSON.stringify(value)) onCommit(result);
  };
  const kinds = [...valueTypes.filter(isParamType)];
  if (draft.type !== "unset" && !kinds.includes(draft.type)) kinds.push(draft.type);
  const hint = defaultText ? `default ${defaultText}` : "";
  // The server's text is about its value: shown once the draft says the same (not while a typed
  // value is on its way).
  const shown = text && sameJson(complete, value) ? text : null;
  // An unset parameter still shows the inputs of the first kind: typing a number sets it.
  const shownType = draft.type === "unset" ? (kinds[0] ?? "value") : draft.type;
  const inputs = PARAM_INPUTS[shownType];
  const problemOf = (name: string): string | null => {
    const typed = draft.inputs[name];
    if (name === "parameter") return null;
    return name === "values" || name === "weights" ? numberListProblem(typed) : numberProblem(typed);
  };
  const anyProblem = inputs.some((input) => problemOf(input.name) !== null);
  return (
    <fieldset className="param">
      <legend>
        {label}
        {unit ? <span className="unit"> [{unit}]</span> : null}
      </legend>
      <LabelledSelect
        label={`${label} kind`}
        className="param-kind"
        value={draft.type}
        disabled={disabled}
        options={[...kinds.map((kind) => ({ value: kind, label: kind })), { value: "unset", label: "unset" }]}
        onChange={(kind) => update(switchKind(draft, kind as Draft["type"]))}
      />
      {inputs.map((input) => (
        <CommitInput
          key={`${shownType}-${input.name}`}
          label={input.name === "value" ? label : `${label} ${input.name}`}
          value={draft.inputs[input.name] ?? ""}
          disabled={disabled}
          inputMode={input.name === "parameter" ? "text" : "decimal"}
          placeholder={input.name === "value" || input.name === "mean" ? hint || unit || undefined : input.required ? (unit ?? undefined) : "optional"}
          invalid={complete === undefined && input.required && !(draft.inputs[input.name] ?? "").trim()}
          problem={problemOf(input.name)}
          onCommit={(typed) => {
            const next = { type: shownType, inputs: { ...draft.inputs, [input.name]: typed } };
            const empty = Object.values(next.inputs).every((item) => item.trim() === "");
            update(draft.type === "unset" && empty ? draft : next);
          }}
        />
      ))}
      {shown ? <div className="hint value-text">{shown}</div> : null}
      {complete === undefined && draft.type !== "unset" && !anyProblem ? <div className="hint incomplete">Fill in the required numbers to send it.</div> : null}
      {anyProblem ? <div className="hint incomplete">Not sent: the canvas keeps the value before.</div> : null}
    </fieldset>
  );
}
