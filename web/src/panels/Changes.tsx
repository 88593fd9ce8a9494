// The changes since the file was saved, while comparing (`sceml diff`'s lines), with the legend of
// the marks on the canvas: a sign and a word as well as a colour.

import type { Comparison } from "../types";

export function Changes({ comparison }: { comparison: Comparison }) {
  return (
    <section className="changes" role="region" aria-label="Changes since saved">
      <h2>
        Changes since {comparison.against} was saved <span className="hint">({comparison.changes.length})</span>
      </h2>
      <p className="legend">
        <span className="diff-badge diff-added">+ added</span> <span className="diff-badge diff-changed">~ changed</span>{" "}
        <span className="diff-badge diff-removed">− removed</span>
      </p>
      {!comparison.saved ? (
        <p className="hint">The file has not been saved yet: everything is new.</p>
      ) : comparison.changes.length === 0 ? (
        <p className="hint">No changes.</p>
      ) : (
        <ul>
          {comparison.changes.map((line, index) => (
            <li key={index}>{line}</li>
          ))}
        </ul>
      )}
      {comparison.removed.length > 0 && (
        <p>
          <span className="diff-badge diff-removed">− removed</span> {comparison.removed.join(", ")}
        </p>
      )}
    </section>
  );
}
