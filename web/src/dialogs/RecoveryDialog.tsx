// After a crash or kill: offer the unsaved changes the server's journal kept, or drop them.

import { useEffect, useRef } from "react";
import type { View } from "../types";

interface Props {
  recovery: NonNullable<View["recovery"]>;
  documentName: string;
  onAnswer: (restore: boolean) => void;
  onLater: () => void;
}

export function RecoveryDialog({ recovery, documentName, onAnswer, onLater }: Props) {
  const restore = useRef<HTMLButtonElement>(null);
  useEffect(() => restore.current?.focus(), []);
  const written = new Date(recovery.written).toLocaleString();
  return (
    <div className="dialog-backdrop">
      <div
        className="dialog"
        role="dialog"
        aria-modal="true"
        aria-label="Restore unsaved changes"
        onKeyDown={(event) => event.key === "Escape" && onLater()}
      >
        <h2>Restore unsaved changes</h2>
        <p>
          The editor of <strong>{documentName}</strong> stopped on {written} with changes that were not saved. They were
          kept in <code>{recovery.path}</code>
          {recovery.changes ? `, with ${recovery.changes} later changes logged beside it` : ""}.
        </p>
        <p className="hint">Restore opens them as unsaved changes of the file; Discard deletes the copy.</p>
        <div className="dialog-buttons">
          <button type="button" className="primary" ref={restore} onClick={() => onAnswer(true)}>
            Restore
          </button>
          <button type="button" onClick={() => onAnswer(false)}>
            Discard
          </button>
        </div>
      </div>
    </div>
  );
}
