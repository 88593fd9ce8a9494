// Whether the canvas is zoomed out so far that a box's text cannot be read.

import { useStore, type ReactFlowState } from "@xyflow/react";

/** Below this zoom a box's 11-13 px text is drawn under 4 px: unreadable. Boxes are drawn
 * without it (a coloured box, its handles and its problem badge): at 500 nodes fitted to the
 * screen (zoom about 0.15) that is a third of the page's elements, and the text's style, layout
 * and paint were much of a first paint's drawing. UIS2 fits well above it. */
export const FAR_ZOOM = 0.3;

const isFar = (state: ReactFlowState) => state.transform[2] < FAR_ZOOM;

/** True while the canvas is zoomed out below FAR_ZOOM. A boolean, so a node draws again only
 * when the zoom crosses it, not on every pan or zoom step. */
export function useFar(): boolean {
  return useStore(isFar);
}
