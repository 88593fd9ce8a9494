// One control per field of the view, chosen by the field's type only (no per-kind code).

import type { Field, ParamValue, Position } from "../types";
import { CommitInput, LabelledCheckbox, LabelledSelect } from "./inputs";
import { ParamEditor } from "./ParamEditor";
import { PositionEditor, WaypointsEditor } from "./PositionEditor";

export type FieldValue = string | boolean | null | ParamValue | Position | Position[];

export interface FieldContext {
  actorNames: string[];
  valueTypes: string[];
  disabled: boolean;
}

interface Props {
  field: Field;
  context: FieldContext;
  onSend: (field: Field, value: FieldValue) => void;
}

const NONE = "";

export function FieldControl({ field, context, onSend }: Props) {
  const { disabled } = context;
  const label = field.label;
  switch (field.type) {
    case "text":
      return (
        <CommitInput
          label={label}
          value={field.value ?? ""}
          disabled={disabled}
          onCommit={(text) => onSend(field, text === "" ? null : text)}
        />
      );
    case "enum":
      return (
        <LabelledSelect
          label={label}
          value={field.value ?? NONE}
          disabled={disabled}
          options={[
            ...(field.value === null ? [{ value: NONE, label: "(none)" }] : []),
            ...field.options.map((option) => ({ value: option, label: option })),
          ]}
          onChange={(value) => onSend(field, value === NONE ? null : value)}
        />
      );
    case "bool":
      return <LabelledCheckbox label={label} checked={field.value === true} disabled={disabled} onChange={(value) => onSend(field, value)} />;
    case "actor": {
      const names = field.value !== null && !context.actorNames.includes(field.value) ? [...context.actorNames, field.value] : context.actorNames;
      return (
        <LabelledSelect
          label={label}
          value={field.value ?? NONE}
          disabled={disabled}
          options={[{ value: NONE, label: "(none)" }, ...names.map((name) => ({ value: name, label: name }))]}
          onChange={(value) => onSend(field, value === NONE ? null : value)}
        />
      );
    }
    case "parameter":
      return (
        <ParamEditor
          label={label}
          value={field.value}
          valueTypes={context.valueTypes}
          unit={field.unit}
          text={field.text}
          defaultText={field.defaultText}
          disabled={disabled}
          onCommit={(value) => onSend(field, value)}
        />
      );
    case "position":
      return <PositionEditor label={label} value={field.value} text={field.text} disabled={disabled} onCommit={(value) => onSend(field, value)} />;
    case "positions":
      return <WaypointsEditor label={label} value={field.value ?? []} texts={field.texts} disabled={disabled} onCommit={(value) => onSend(field, value)} />;
  }
}

/** The fields of one object. Each control adopts the server's new value itself, so a field the
 * user is typing in is never re-created under the cursor. */
export function FieldList({ owner, fields, context, onSend }: { owner: string; fields: Field[]; context: FieldContext; onSend: Props["onSend"] }) {
  return (
    <>
      {fields.map((field) => (
        <FieldControl key={`${owner}:${field.name}`} field={field} context={context} onSend={onSend} />
      ))}
    </>
  );
}
