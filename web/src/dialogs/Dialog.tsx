// A modal dialog with a name, a form, a confirm button named like the dialog, and Cancel.

import { useEffect, useRef, type FormEvent, type ReactNode } from "react";

interface Props {
  title: string;
  confirm: string;
  onConfirm: () => void;
  onCancel: () => void;
  busy?: boolean;
  children: ReactNode;
}

export function Dialog({ title, confirm, onConfirm, onCancel, busy, children }: Props) {
  const ref = useRef<HTMLFormElement>(null);
  useEffect(() => {
    ref.current?.querySelector<HTMLElement>("input, select, button")?.focus();
  }, []);
  const submit = (event: FormEvent) => {
    event.preventDefault();
    onConfirm();
  };
  return (
    <div className="dialog-backdrop" onMouseDown={(event) => event.target === event.currentTarget && onCancel()}>
      <div className="dialog" role="dialog" aria-modal="true" aria-label={title} onKeyDown={(event) => event.key === "Escape" && onCancel()}>
        <h2>{title}</h2>
        <form ref={ref} onSubmit={submit}>
          {children}
          <div className="dialog-buttons">
            <button type="submit" className="primary" disabled={busy}>
              {confirm}
            </button>
            <button type="button" onClick={onCancel}>
              Cancel
            </button>
          </div>
        </form>
      </div>
    </div>
  );
}

export function Field({ label, children }: { label: string; children: (id: string) => ReactNode }) {
  const id = `dialog-${label.toLowerCase().replace(/\W+/g, "-")}`;
  return (
    <div className="control">
      <label htmlFor={id}>{label}</label>
      {children(id)}
    </div>
  );
}
