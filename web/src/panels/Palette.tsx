// The palette: the view's groups, coloured by their look; drag an item onto the canvas, or
// click / press Enter to add it in the middle of the view.

import { memo, useState } from "react";
import { resolveLook } from "../lib/looks";
import type { PaletteGroup, PaletteItem, Style } from "../types";

export const PALETTE_MIME = "application/x-sceml-palette";
/** The search field's id: "/" anywhere on the page focuses it. */
export const PALETTE_SEARCH_ID = "palette-search";

function matches(item: PaletteItem, query: string): boolean {
  const words = query.toLowerCase().split(/\s+/).filter(Boolean);
  const text = `${item.label} ${item.module ?? ""} ${item.library ?? ""}`.toLowerCase();
  return words.every((word) => text.includes(word));
}

interface Props {
  palette: PaletteGroup[];
  style: Style;
  disabled: boolean;
  onAdd: (item: PaletteItem) => void;
}

// Memoised on the view's parts it shows, which patches keep as they were unless they changed.
export const Palette = memo(function Palette({ palette, style, disabled, onAdd }: Props) {
  const [query, setQuery] = useState("");
  const groups = palette
    .map((group) => ({ ...group, items: group.items.filter((item) => matches(item, query)) }))
    .filter((group) => group.items.length > 0);
  const first = groups[0]?.items[0];
  return (
    <aside className="palette" role="region" aria-label="Palette">
      <h2>Palette</h2>
      {disabled && <p className="hint">Read-only: nothing can be added.</p>}
      <input
        id={PALETTE_SEARCH_ID}
        type="search"
        className="palette-search"
        aria-label="Search the palette"
        placeholder="Search ( / )"
        title="Type to filter; Enter adds the first match"
        value={query}
        disabled={disabled}
        onChange={(event) => setQuery(event.target.value)}
        onKeyDown={(event) => {
          if (event.key === "Enter" && first) {
            event.preventDefault();
            onAdd(first);
          }
          if (event.key === "Escape") setQuery("");
        }}
      />
      {groups.length === 0 && <p className="hint">Nothing in the palette matches “{query}”.</p>}
      {groups.map((group) => {
        const look = resolveLook(style, group.look);
        return (
          <section key={group.group} className="palette-group">
            <h3 style={{ borderLeftColor: look.border }}>{group.label}</h3>
            <div className="palette-items">
              {group.items.map((item) => (
                <button
                  key={`${item.kind}:${item.library ?? ""}:${item.module ?? ""}`}
                  type="button"
                  className={`palette-item look-${group.look}`}
                  style={{ background: look.fill, borderColor: look.border, color: look.text }}
                  disabled={disabled}
                  draggable={!disabled}
                  onDragStart={(event) => {
                    event.dataTransfer.setData(PALETTE_MIME, JSON.stringify(item));
                    event.dataTransfer.effectAllowed = "copy";
                  }}
                  onClick={() => onAdd(item)}
                  title={item.module ? `Use ${item.module} from ${item.library ?? "its library"}` : `Add ${item.label}`}
                >
                  {item.label}
                </button>
              ))}
            </div>
          </section>
        );
      })}
    </aside>
  );
});
