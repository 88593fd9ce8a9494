// Small inputs that send their value when it changed and the input loses focus or Enter is hit.

import { useId, useState } from "react";

interface CommitInputProps {
  label: string;
  value: string;
  onCommit: (text: string) => void;
  disabled?: boolean;
  placeholder?: string;
  inputMode?: "decimal" | "numeric" | "text";
  className?: string;
  invalid?: boolean;
  /** Why the text cannot be used; shown under the input and announced with it. */
  problem?: string | null;
}

/** A text input with its own label; commits on blur or Enter, reverts on Escape. */
export function CommitInput({ label, value, onCommit, disabled, placeholder, inputMode, className, invalid, problem }: CommitInputProps) {
  const id = useId();
  const problemId = `${id}-problem`;
  const [text, setText] = useState(value);
  const [focused, setFocused] = useState(false);
  // What the model holds as far as this input knows: the server's value, or what it last sent
  // (whose echo may not have been drawn yet when the user types the next value).
  const [sent, setSent] = useState<string | null>(null);
  // Follow the server's value (undo, another field's edit), but never overwrite what the user is
  // typing: the field keeps its text while it has the focus.
  const [seen, setSeen] = useState(value);
  if (value !== seen) {
    setSeen(value);
    setSent(null);
    if (!focused) setText(value);
  }
  const commit = () => {
    if (text !== (sent ?? value)) {
      setSent(text);
      onCommit(text);
    }
  };
  return (
    <div className={`control ${className ?? ""}`}>
      <label htmlFor={id}>{label}</label>
      <input
        id={id}
        type="text"
        value={text}
        disabled={disabled}
        readOnly={disabled}
        placeholder={placeholder}
        inputMode={inputMode}
        aria-invalid={invalid || Boolean(problem) || undefined}
        aria-errormessage={problem ? problemId : undefined}
        aria-describedby={problem ? problemId : undefined}
        onChange={(event) => setText(event.target.value)}
        onFocus={() => setFocused(true)}
        onBlur={() => {
          setFocused(false);
          commit();
        }}
        onKeyDown={(event) => {
          if (event.key === "Enter") commit();
          if (event.key === "Escape") setText(value);
        }}
      />
      {problem ? (
        <div id={problemId} className="problem-text">
          {problem}
        </div>
      ) : null}
    </div>
  );
}

interface SelectProps {
  label: string;
  value: string;
  options: { value: string; label: string }[];
  onChange: (value: string) => void;
  disabled?: boolean;
  className?: string;
}

export function LabelledSelect({ label, value, options, onChange, disabled, className }: SelectProps) {
  const id = useId();
  return (
    <div className={`control ${className ?? ""}`}>
      <label htmlFor={id}>{label}</label>
      <select id={id} value={value} disabled={disabled} onChange={(event) => onChange(event.target.value)}>
        {options.map((option) => (
          <option key={option.value} value={option.value}>
            {option.label}
          </option>
        ))}
      </select>
    </div>
  );
}

export function LabelledCheckbox({ label, checked, onChange, disabled }: { label: string; checked: boolean; onChange: (value: boolean) => void; disabled?: boolean }) {
  const id = useId();
  return (
    <div className="control control-bool">
      <input id={id} type="checkbox" checked={checked} disabled={disabled} onChange={(event) => onChange(event.target.checked)} />
      <label htmlFor={id}>{label}</label>
    </div>
  );
}
