// The problems list: every diagnostic of the view; a click shows its node.

import { memo } from "react";
import type { Diagnostic } from "../types";

const ICONS = { error: "✖", warning: "⚠", info: "ℹ" } as const;

interface Props {
  diagnostics: Diagnostic[];
  onShow: (diagnostic: Diagnostic) => void;
}

// Memoised: a patch that leaves the problems as they were keeps the same list object.
export const Problems = memo(function Problems({ diagnostics, onShow }: Props) {
  return (
    <section className="problems" role="region" aria-label="Problems">
      <h2>
        Problems <span className="hint">({diagnostics.length})</span>
      </h2>
      {diagnostics.length === 0 ? (
        <p className="hint">No problems.</p>
      ) : (
        <ul>
          {diagnostics.map((diagnostic, index) => (
            <li key={`${diagnostic.code}-${index}`}>
              <button type="button" className={`problem severity-${diagnostic.severity}`} onClick={() => onShow(diagnostic)} title={diagnostic.path ?? undefined}>
                {diagnostic.code} {diagnostic.message}
                <span className="severity-icon" aria-hidden="true">
                  {ICONS[diagnostic.severity] ?? ""}
                </span>
              </button>
            </li>
          ))}
        </ul>
      )}
    </section>
  );
});
