// A position: none, world (x, y, z, heading), lane (road, lane, s, offset), road (road, s, t,
// heading), or relative to an actor (by lane, road, its own axes or the world's). Coordinates
// accept a number or a compact distribution (U(1, 2), N(8, 1), [5, 10] step 1, {1, 2}).

import { useState } from "react";
import {
  POSITION_INPUTS,
  POSITION_LABELS,
  positionDraft,
  positionOfDraft,
  type PositionDraft,
  type PositionInput,
  type PositionType,
} from "../lib/positions";
import { sameJson } from "../lib/same";
import { numberProblem, paramTextProblem } from "../lib/values";
import type { Position } from "../types";
import { CommitInput, LabelledSelect } from "./inputs";

interface Props {
  label: string;
  value: Position | null;
  /** The server's display text of `value` (`road 3 lane 1 s 30 m`). */
  text?: string | null;
  disabled: boolean;
  onCommit: (value: Position | null) => void;
  /** Offer "none" (a required position still may be unset while editing). */
  allowNone?: boolean;
}

/** Why an input's text cannot be used: a name is any text, a lane a whole number. */
function coordinateProblem(input: PositionInput, text: string | undefined): string | null {
  if (input.kind === "name") return null;
  if (input.kind === "integer") {
    const trimmed = (text ?? "").trim();
    if (trimmed === "") return null;
    return numberProblem(trimmed) ?? (Number.isInteger(Number(trimmed)) ? null : `${input.label} is a whole number, not ${trimmed}`);
  }
  return paramTextProblem(text);
}

const TYPES = Object.keys(POSITION_LABELS).filter((type) => type !== "none") as Exclude<PositionType, "none">[];

export function PositionEditor({ label, value, text, disabled, onCommit, allowNone = true }: Props) {
  const [draft, setDraft] = useState<PositionDraft>(() => positionDraft(value));
  const [seen, setSeen] = useState(value);
  if (!sameJson(value, seen)) {
    setSeen(value);
    // The echo of our own edit leaves the draft (and any half-typed coordinate) alone.
    if (!sameJson(value, positionOfDraft(draft))) setDraft(positionDraft(value));
  }
  const result = positionOfDraft(draft);
  const update = (next: PositionDraft) => {
    setDraft(next);
    const position = positionOfDraft(next);
    if (position !== undefined && JSON.stringify(position) !== JSON.stringify(value)) onCommit(position);
  };
  const types: PositionType[] = allowNone ? ["none", ...TYPES] : TYPES;
  return (
    <fieldset className="position">
      <legend>{label}</legend>
      <LabelledSelect
        label={`${label} type`}
        value={draft.type}
        disabled={disabled}
        options={types.map((type) => ({ value: type, label: POSITION_LABELS[type] }))}
        onChange={(type) => update({ type: type as PositionType, inputs: {}, kept: draft.kept })}
      />
      {draft.type !== "none" && (
        <div className="coordinates">
          {POSITION_INPUTS[draft.type].map((input) => (
            <CommitInput
              key={`${draft.type}-${input.key}`}
              className="coordinate"
              label={`${label} ${input.label}`}
              value={draft.inputs[input.key] ?? ""}
              disabled={disabled}
              inputMode={input.kind === "name" ? "text" : "decimal"}
              placeholder={input.required ? undefined : "optional"}
              invalid={result === undefined && input.required && !(draft.inputs[input.key] ?? "").trim()}
              problem={coordinateProblem(input, draft.inputs[input.key])}
              onCommit={(typed) => update({ ...draft, inputs: { ...draft.inputs, [input.key]: typed } })}
            />
          ))}
        </div>
      )}
      {text && sameJson(result, value) ? <div className="hint value-text">{text}</div> : null}
      {draft.type === "route" && Array.isArray(draft.kept?.waypoints) && (
        <div className="hint">
          route {String(draft.kept?.routeName ?? "")}: {draft.kept.waypoints.length} waypoints, as read from the file
        </div>
      )}
      {draft.type === "route" && !Array.isArray(draft.kept?.waypoints) && (
        <div className="hint incomplete">A route comes from an imported file; its waypoints are not made here.</div>
      )}
      {result === undefined && draft.type !== "route" && (
        <div className="hint incomplete">Fill in the required coordinates to send it.</div>
      )}
    </fieldset>
  );
}

interface WaypointsProps {
  label: string;
  value: Position[];
  /** The server's display text of each position. */
  texts?: (string | null)[];
  disabled: boolean;
  onCommit: (value: Position[]) => void;
}

/** A list of positions with add and remove; every change sends the whole list. */
export function WaypointsEditor({ label, value, texts, disabled, onCommit }: WaypointsProps) {
  const [adding, setAdding] = useState(false);
  return (
    <fieldset className="waypoints">
      <legend>{label}</legend>
      {value.length === 0 && !adding && <div className="hint">none</div>}
      <ol>
        {value.map((position, index) => (
          <li key={index}>
            <PositionEditor
              label={`${label} ${index + 1}`}
              value={position}
              text={texts?.[index]}
              disabled={disabled}
              allowNone={false}
              onCommit={(next) => next && onCommit(value.map((old, i) => (i === index ? next : old)))}
            />
            {!disabled && (
              <button type="button" onClick={() => onCommit(value.filter((_, i) => i !== index))}>
                Remove {label.toLowerCase()} {index + 1}
              </button>
            )}
          </li>
        ))}
        {adding && (
          <li>
            <PositionEditor
              label={`${label} ${value.length + 1}`}
              value={null}
              disabled={disabled}
              onCommit={(next) => {
                if (!next) return;
                setAdding(false);
                onCommit([...value, next]);
              }}
            />
          </li>
        )}
      </ol>
      {!disabled && !adding && (
        <button type="button" onClick={() => setAdding(true)}>
          Add {label.toLowerCase().replace(/s$/, "")}
        </button>
      )}
    </fieldset>
  );
}
