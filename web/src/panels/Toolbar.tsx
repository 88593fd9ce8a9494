// The toolbar: file and edit commands, layout, and the document's status.

import type { Direction } from "../lib/layout";
import type { View } from "../types";

export interface ToolbarActions {
  open: () => void;
  save: () => void;
  exportXosc: () => void;
  undo: () => void;
  redo: () => void;
  remove: () => void;
  copy: () => void;
  paste: () => void;
  arrange: () => void;
  fit: () => void;
  extract: () => void;
  compare: () => void;
  setDirection: (direction: Direction) => void;
}

interface Props {
  view: View | null;
  /** After "Open definition": the scenario to go back to. */
  back?: { name: string; go: () => void } | null;
  direction: Direction;
  hasSelection: boolean;
  canPaste: boolean;
  actions: ToolbarActions;
}

function Button({ label, onClick, disabled, title }: { label: string; onClick: () => void; disabled?: boolean; title?: string }) {
  return (
    <button type="button" onClick={onClick} disabled={disabled} title={title ?? label}>
      {label}
    </button>
  );
}

export function Toolbar({ view, back, direction, hasSelection, canPaste, actions }: Props) {
  const editable = view !== null && !view.readOnly;
  const summary = view?.summary;
  return (
    <div className="toolbar" role="toolbar" aria-label="Editor">
      <span className="app-name">SceML</span>
      <span className="document-name" title={view?.document.path}>
        {view ? (view.document.module ? `${view.document.name} — ${view.document.module}` : view.document.name) : ""}
        {view?.readOnly ? " (read-only)" : ""}
      </span>
      {back && (
        <div className="toolbar-group">
          <Button label="Back to scenario" onClick={back.go} title={`Back to ${back.name}`} />
        </div>
      )}
      <div className="toolbar-group">
        <Button label="Open" onClick={actions.open} />
        <Button label="Save" onClick={actions.save} disabled={!editable} title="Save (Ctrl+S)" />
        <Button label="Export" onClick={actions.exportXosc} disabled={!view} />
        <button
          type="button"
          onClick={actions.compare}
          disabled={!view || view.document.kind !== "scenario"}
          aria-pressed={Boolean(view?.comparison)}
          title="Mark what changed since the file was saved, as sceml diff does"
        >
          {view?.comparison ? "Stop comparing" : "Compare with saved"}
        </button>
      </div>
      <div className="toolbar-group">
        <Button label="Undo" onClick={actions.undo} disabled={!editable || !view.undo} title={view?.undo ? `Undo ${view.undo} (Ctrl+Z)` : "Undo (Ctrl+Z)"} />
        <Button label="Redo" onClick={actions.redo} disabled={!editable || !view.redo} title={view?.redo ? `Redo ${view.redo} (Ctrl+Shift+Z)` : "Redo (Ctrl+Shift+Z)"} />
        <Button label="Delete" onClick={actions.remove} disabled={!editable || !hasSelection} title="Delete (Del)" />
        <Button label="Copy" onClick={actions.copy} disabled={!editable || !hasSelection} title="Copy (Ctrl+C)" />
        <Button label="Paste" onClick={actions.paste} disabled={!editable || !canPaste} title="Paste (Ctrl+V)" />
        <Button label="Extract module" onClick={actions.extract} disabled={!editable || !hasSelection} />
      </div>
      <div className="toolbar-group">
        <Button label="Arrange" onClick={actions.arrange} disabled={!view} />
        <Button label="Fit view" onClick={actions.fit} title="Fit view (F)" />
        <label className="direction">
          <span className="visually-hidden">Layout direction</span>
          <select aria-label="Layout direction" value={direction} onChange={(event) => actions.setDirection(event.target.value as Direction)}>
            <option value="RIGHT">Left to right</option>
            <option value="DOWN">Top down</option>
          </select>
        </label>
      </div>
      <div className="status" role="status">
        <span className={view?.dirty ? "dirty" : "saved"}>{view ? (view.dirty ? "Unsaved changes" : "Saved") : "Loading…"}</span>
        {summary && (
          <>
            <span className="count count-error" title="errors">✖ {summary.errors} {summary.errors === 1 ? "error" : "errors"}</span>
            <span className="count count-warning" title="warnings">⚠ {summary.warnings} {summary.warnings === 1 ? "warning" : "warnings"}</span>
          </>
        )}
      </div>
    </div>
  );
}
