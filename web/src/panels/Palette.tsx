// The palette: the view's groups, coloured by their look; drag an item onto the canvas, or
// click / press Enter to add it in the middle of the view.

import { resolveLook } from "../lib/looks";
import type { PaletteItem, View } from "../types";

export const PALETTE_MIME = "application/x-sceml-palette";

interface Props {
  view: View;
  onAdd: (item: PaletteItem) => void;
}

export function Palette({ view, onAdd }: Props) {
  const disabled = view.readOnly;
  return (
    <aside className="palette" role="region" aria-label="Palette">
      <h2>Palette</h2>
      {disabled && <p className="hint">Read-only: nothing can be added.</p>}
      {view.palette.map((group) => {
        const look = resolveLook(view.style, group.look);
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
}
