// The editor page: toolbar, palette, diagram, properties and problems around one server view.

import { useReactFlow, useStoreApi } from "@xyflow/react";
import { useCallback, useEffect, useMemo, useRef, useState } from "react";
import { api, ApiError } from "./api";
import { PENDING_PREFIX, pendingNode } from "./canvas/build";
import { Diagram } from "./canvas/Diagram";
import { ExportDialog, ExtractDialog, OpenDialog, UseModuleDialog, type ExportResult } from "./dialogs/dialogs";
import { RecoveryDialog } from "./dialogs/RecoveryDialog";
import { pasteOffset } from "./lib/clipboard";
import type { Direction } from "./lib/layout";
import { Palette, PALETTE_SEARCH_ID } from "./panels/Palette";
import { Changes } from "./panels/Changes";
import { Problems } from "./panels/Problems";
import { Properties } from "./panels/Properties";
import { Toolbar } from "./panels/Toolbar";
import { useDiagramState } from "./state/useDiagramState";
import { useExpanded } from "./state/useExpanded";
import { freeSpot } from "./lib/placement";
import { useServer } from "./state/useServer";
import { useShortcuts } from "./state/useShortcuts";
import { useStable } from "./state/useStable";
import type { Answer, Diagnostic, Op, PaletteItem, View, ViewNode, XY } from "./types";

type DialogState =
  | { type: "open" }
  | { type: "export" }
  | { type: "extract" }
  | { type: "use"; item: PaletteItem; position: XY }
  | null;

const DIRECTION_KEY = "sceml-layout-direction";
const BACK_KEY = "sceml-back-to";

function storedDirection(): Direction {
  return localStorage.getItem(DIRECTION_KEY) === "RIGHT" ? "RIGHT" : "DOWN";
}

/** Ops that change the picture: the first one also saves where every node is drawn. */
const STRUCTURAL = new Set(["add_node", "add_module_use", "move", "paste", "delete", "connect", "extract_module"]);

function hasUnsavedPositions(view: View): boolean {
  return view.nodes.some((node) => node.parent === null && node.position === null);
}

export function Editor() {
  const server = useServer();
  const { view } = server;
  const [expanded, toggleExpanded] = useExpanded(view);
  const [direction, setDirection] = useState<Direction>(storedDirection);
  const diagram = useDiagramState(view, expanded, direction);
  const flow = useReactFlow();
  const storeApi = useStoreApi();
  const [dialog, setDialog] = useState<DialogState>(null);
  const [clipboard, setClipboard] = useState<{ count: number; pastes: number }>({ count: 0, pastes: 0 });
  const canvas = useRef<HTMLDivElement>(null);
  // The recovery offer the user put off with Escape (it stays on the server until answered).
  const [recoveryLater, setRecoveryLater] = useState<string | null>(null);
  // A restore whose replay stopped at a change it could not apply: what, and where the rest is.
  const [replayStopped, setReplayStopped] = useState<string | null>(null);

  const editable = view !== null && !view.readOnly;
  const selectedNodes = useMemo(() => diagram.nodes.filter((node) => node.selected), [diagram.nodes]);
  const selectedEdges = useMemo(() => diagram.edges.filter((edge) => edge.selected), [diagram.edges]);
  const ownSelection = selectedNodes.filter((node) => node.deletable !== false).map((node) => node.id);

  // The page title and the warning before leaving with unsaved changes.
  useEffect(() => {
    document.title = view ? `${view.dirty ? "• " : ""}SceML — ${view.document.name}` : "SceML";
  }, [view]);
  // Text typed into a field without Enter is committed when the page goes away (reload, close):
  // blurring commits it, and the request is sent with keepalive, so it reaches the server.
  useEffect(() => {
    const commitFocused = () => {
      if (document.activeElement instanceof HTMLInputElement) document.activeElement.blur();
    };
    window.addEventListener("beforeunload", commitFocused);
    window.addEventListener("pagehide", commitFocused);
    return () => {
      window.removeEventListener("beforeunload", commitFocused);
      window.removeEventListener("pagehide", commitFocused);
    };
  }, []);
  useEffect(() => {
    if (!view?.dirty) return;
    const warn = (event: BeforeUnloadEvent) => {
      event.preventDefault();
      event.returnValue = "";
    };
    window.addEventListener("beforeunload", warn);
    return () => window.removeEventListener("beforeunload", warn);
  }, [view?.dirty]);

  // The first layout of a document fits the view.
  const fittedFor = useRef<string | null>(null);
  const laidOut = diagram.laidOut;
  // So does the layout after expanding or collapsing a module use, and ELK's layout after the
  // quick one a large graph is drawn in first.
  const fitNext = useRef(false);
  const wasQuick = useRef(false);
  useEffect(() => {
    if (!laidOut) return;
    if (wasQuick.current && !diagram.quick) fitNext.current = true;
    wasQuick.current = diagram.quick;
    const document = `${laidOut.document.path}#${laidOut.document.module ?? ""}`;
    if (fittedFor.current === document && !fitNext.current) return;
    // The first fit of a document is immediate (nothing to follow yet); a re-fit glides.
    const duration = fittedFor.current === document ? 200 : 0;
    fittedFor.current = document;
    fitNext.current = false;
    // React Flow learns its pane's size from a ResizeObserver: a fit before that (a layout
    // known from an earlier visit is ready at once) fits the page's first, narrow pane. Fit at
    // once (what is drawn shows), and again once React Flow knows the pane's real size.
    let frames = 0;
    const fitOnceSized = () => {
      const pane = canvas.current?.querySelector(".react-flow")?.getBoundingClientRect();
      const { width, height } = storeApi.getState();
      const sized = pane !== undefined && Math.abs(pane.width - width) < 1 && Math.abs(pane.height - height) < 1;
      if (sized || frames === 0) void flow.fitView({ padding: 0.06, maxZoom: 1.25, duration });
      if (!sized && frames++ < 60) requestAnimationFrame(fitOnceSized);
    };
    requestAnimationFrame(fitOnceSized);
  }, [laidOut, diagram.quick, flow, storeApi]);

  /** Where every top-level node is drawn now. */
  const drawnPositions = useCallback((): Record<string, XY> => {
    const positions: Record<string, XY> = {};
    for (const node of diagram.nodes) {
      if (!node.parentId && !node.id.startsWith(PENDING_PREFIX)) positions[node.id] = { x: Math.round(node.position.x), y: Math.round(node.position.y) };
    }
    return positions;
  }, [diagram.nodes]);

  /** Send ops as one undo step; select what they created. */
  const edit = useCallback(
    async (ops: Op[], label?: string) => {
      if (!view) return null;
      let list = ops;
      if (hasUnsavedPositions(view) && ops.some((op) => STRUCTURAL.has(op.op))) {
        const positions = drawnPositions();
        const moves = ops.filter((op) => op.op === "move");
        for (const move of moves) Object.assign(positions, move.positions as Record<string, XY>);
        list = [{ op: "move", positions }, ...ops.filter((op) => op.op !== "move")];
      }
      const next = await server.ops(list, label);
      if (next?.created?.length) diagram.selectNext(next.created);
      return next;
    },
    [view, server, drawnPositions, diagram],
  );
  const send = useCallback((op: Op) => void edit([op]), [edit]);

  const setSelection = useCallback(
    (ids: Set<string>) => {
      diagram.setNodes((nodes) => nodes.map((node) => ({ ...node, selected: ids.has(node.id) })));
      diagram.setEdges((edges) => edges.map((edge) => ({ ...edge, selected: false })));
    },
    [diagram],
  );

  const centreOn = useCallback(
    (id: string) => {
      const internal = flow.getInternalNode(id);
      if (!internal) return;
      const { x, y } = internal.internals.positionAbsolute;
      const width = internal.measured.width ?? internal.width ?? 0;
      const height = internal.measured.height ?? internal.height ?? 0;
      void flow.setCenter(x + width / 2, y + height / 2, { zoom: Math.max(flow.getZoom(), 0.8), duration: 300 });
    },
    [flow],
  );

  /** The drawn node nearest to a node (itself, or the collapsed use that holds it). */
  const drawnNode = useCallback(
    (id: string): string | null => {
      if (!view) return null;
      const byId = new Map(view.nodes.map((node) => [node.id, node]));
      const drawn = new Set(diagram.nodes.map((node) => node.id));
      let current = byId.get(id);
      while (current && !drawn.has(current.id)) current = current.parent === null ? undefined : byId.get(current.parent);
      return current?.id ?? null;
    },
    [view, diagram.nodes],
  );

  const showProblem = useCallback(
    (diagnostic: Diagnostic) => {
      if (!view) return;
      const target = diagnostic.node ?? view.nodes.find((node) => node.look === "root")?.id ?? null;
      const id = target === null ? null : drawnNode(target);
      if (id === null) return;
      setSelection(new Set([id]));
      centreOn(id);
    },
    [view, drawnNode, setSelection, centreOn],
  );

  const removeSelection = useCallback(() => {
    if (!editable) return;
    const edges = selectedEdges.filter((edge) => edge.deletable !== false).map((edge) => edge.id);
    if (ownSelection.length === 0 && edges.length === 0) return;
    void edit([{ op: "delete", nodes: ownSelection, edges }]);
  }, [editable, selectedEdges, ownSelection, edit]);

  const copy = useCallback(async () => {
    if (!editable || ownSelection.length === 0) return false;
    try {
      const answer = await server.enqueue(() => api.copy(ownSelection));
      setClipboard({ count: answer.copied, pastes: 0 });
      return true;
    } catch (caught) {
      server.report(caught);
      return false;
    }
  }, [editable, ownSelection, server]);

  const paste = useCallback(() => {
    if (!editable || clipboard.count === 0) return;
    const pastes = clipboard.pastes + 1;
    setClipboard({ ...clipboard, pastes });
    void edit([{ op: "paste", offset: pasteOffset(pastes) }], "Paste");
  }, [editable, clipboard, edit]);

  const cut = useCallback(async () => {
    if (await copy()) void edit([{ op: "delete", nodes: ownSelection, edges: [] }], "Cut");
  }, [copy, edit, ownSelection]);

  const centre = useCallback((): XY => {
    const rect = canvas.current?.getBoundingClientRect();
    if (!rect) return { x: 0, y: 0 };
    return flow.screenToFlowPosition({ x: rect.left + rect.width / 2, y: rect.top + rect.height / 2 });
  }, [flow]);

  const pendingCount = useRef(0);
  const addItem = useCallback(
    (item: PaletteItem, at?: XY) => {
      if (!editable) return;
      const where = at ?? centre();
      let position = { x: Math.round(where.x - 60), y: Math.round(where.y - 20) };
      if (!at) {
        // A click adds in the middle of the view; never on top of a node already there.
        const taken = flow
          .getNodes()
          .filter((node) => !node.parentId)
          .map((node) => ({ ...node.position, width: node.measured?.width ?? 0, height: node.measured?.height ?? 0 }));
        position = freeSpot({ ...position, width: 160, height: 70 }, taken);
      }
      if (item.module) {
        setDialog({ type: "use", item, position });
        return;
      }
      // The box shows at once; the server's answer (a round trip and a validation of the
      // whole model, most of a drop's time at 500 nodes) replaces it with the node.
      const look = view?.palette.find((group) => group.items.includes(item))?.look ?? "longitudinal";
      const pending = `${PENDING_PREFIX}${++pendingCount.current}`;
      diagram.showPending(pendingNode(pending, item.kind, item.label, look, position, direction));
      // Refused (or failed), the box goes; added, the next drawing has the node instead.
      const refused = () => diagram.dropPending(pending);
      void edit([{ op: "add_node", kind: item.kind, position }], `Add ${item.label}`).then((next) => next ?? refused(), refused);
    },
    [editable, centre, edit, flow, view, diagram, direction],
  );

  const addFromPalette = useStable((item: PaletteItem) => addItem(item));
  const stableShowProblem = useStable(showProblem);

  const arrange = useCallback(
    async (to: Direction = direction) => {
      const positions = await diagram.arrange(to);
      // Fit again once the arranged places are drawn (after an expand, the first fit came
      // before them).
      fitNext.current = true;
      if (editable) void server.ops([{ op: "move", positions }], "Arrange");
    },
    [diagram, direction, editable, server],
  );

  // Expanding or collapsing a use changes what takes room: lay the diagram out again (one
  // undoable "Arrange" step when positions are saved; ELK places unsaved ones anyway) and fit.
  const expandedOf = useRef<{ document: string; uses: string } | null>(null);
  useEffect(() => {
    if (!view) return;
    const now = { document: `${view.document.path}#${view.document.module ?? ""}`, uses: [...expanded].sort().join(",") };
    const before = expandedOf.current;
    expandedOf.current = now;
    if (!before || before.document !== now.document || before.uses === now.uses) return;
    fitNext.current = true;
    if (editable && view.nodes.some((node) => node.parent === null && node.position !== null)) void arrange();
  }, [view, expanded, editable, arrange]);

  const changeDirection = useCallback(
    (to: Direction) => {
      localStorage.setItem(DIRECTION_KEY, to);
      setDirection(to);
      // Saved positions would keep the old picture: arrange them anew (one undoable step).
      if (view && editable && view.nodes.some((node) => node.parent === null && node.position !== null)) void arrange(to);
    },
    [view, editable, arrange],
  );

  const fit = useCallback(() => void flow.fitView({ padding: 0.06, maxZoom: 1.25, duration: 200 }), [flow]);
  // Connecting by keyboard: C on the selected source, then C on the selected target.
  const [connectFrom, setConnectFrom] = useState<{ id: string; name: string } | null>(null);
  const connecting = useCallback(
    (id: string, end: "source" | "target") => {
      if (!editable) return;
      const name = view?.nodes.find((item) => item.id === id)?.name ?? id;
      if (connectFrom === null) {
        if (end === "source") setConnectFrom({ id, name });
        return;
      }
      if (id !== connectFrom.id) void edit([{ op: "connect", source: connectFrom.id, target: id }], "Connect");
      setConnectFrom(null);
    },
    [editable, view, connectFrom, edit],
  );
  // One function for the whole session: the nodes' context must not change with every view.
  const latestConnecting = useRef(connecting);
  useEffect(() => {
    latestConnecting.current = connecting;
  }, [connecting]);
  const keyConnect = useCallback((id: string, end: "source" | "target") => latestConnecting.current(id, end), []);
  const connectSelected = useCallback(() => {
    const only = selectedNodes.length === 1 ? selectedNodes[0] : undefined;
    if (only && only.connectable !== false) keyConnect(only.id, connectFrom === null ? "source" : "target");
  }, [selectedNodes, keyConnect, connectFrom]);

  const undo = useCallback(() => void (editable && view?.undo && server.run(api.undo)), [editable, view, server]);
  const redo = useCallback(() => void (editable && view?.redo && server.run(api.redo)), [editable, view, server]);
  const save = useCallback(() => {
    if (!editable) return;
    if (document.activeElement instanceof HTMLElement) document.activeElement.blur();
    void server.run(() => api.save());
  }, [editable, server]);

  const open = useCallback(
    async (path: string, module: string) => {
      setDialog(null);
      const attempt = async (discard: boolean): Promise<Answer | null> => {
        try {
          const next = await server.enqueue(() => api.open(path, discard, module || undefined));
          return next;
        } catch (caught) {
          if (caught instanceof ApiError && caught.status === 409 && !discard) {
            return window.confirm(`${caught.message}\n\nDiscard the unsaved changes?`) ? attempt(true) : null;
          }
          server.report(caught);
          return null;
        }
      };
      const next = await attempt(false);
      if (next) void server.run(() => Promise.resolve(next));
    },
    [server],
  );

  const exportXosc = useCallback(
    async (version: string, profile: string, path: string): Promise<ExportResult> => {
      try {
        const answer = await server.enqueue(() => api.exportXosc(version, profile, path || undefined));
        return { path: answer.path };
      } catch (caught) {
        if (caught instanceof ApiError) return { error: caught.message, diagnostics: caught.diagnostics };
        return { error: String(caught) };
      }
    },
    [server],
  );

  // "Back to scenario" after Open definition: where the user came from, kept per tab.
  const [cameFrom, setCameFrom] = useState<{ path: string; name: string } | null>(() => {
    const kept = sessionStorage.getItem(BACK_KEY);
    return kept ? (JSON.parse(kept) as { path: string; name: string }) : null;
  });
  useEffect(() => {
    if (cameFrom) sessionStorage.setItem(BACK_KEY, JSON.stringify(cameFrom));
    else sessionStorage.removeItem(BACK_KEY);
  }, [cameFrom]);

  // Opening another file with unsaved changes is refused (409): offer to save them first.
  const openDefinition = useCallback(
    (node: ViewNode) => {
      if (view && view.document.kind === "scenario") setCameFrom({ path: view.document.path, name: view.document.name });
      void server.run(async () => {
        try {
          return await api.openDefinition(node.id);
        } catch (caught) {
          if (!(caught instanceof ApiError) || caught.status !== 409) throw caught;
          if (!window.confirm(`${caught.message}\n\nSave the changes and open ${node.title}?`)) throw caught;
          await api.save();
          return api.openDefinition(node.id);
        }
      });
    },
    [server, view],
  );

  useShortcuts({
    undo,
    redo,
    remove: removeSelection,
    copy: () => void copy(),
    paste,
    cut: () => void cut(),
    selectAll: () => setSelection(new Set(diagram.nodes.filter((node) => node.selectable !== false).map((node) => node.id))),
    save,
    clearSelection: () => {
      setConnectFrom(null);
      setSelection(new Set());
    },
    fit,
    connect: connectSelected,
    search: () => document.getElementById(PALETTE_SEARCH_ID)?.focus(),
  });

  const single = selectedNodes.length === 1 && selectedNodes[0] ? selectedNodes[0].data.node : null;

  return (
    <div className={`editor${view?.readOnly ? " read-only" : ""}`}>
      <Toolbar
        view={view}
        back={view?.document.kind === "module" && cameFrom ? { name: cameFrom.name, go: () => void open(cameFrom.path, "") } : null}
        direction={direction}
        hasSelection={ownSelection.length > 0 || selectedEdges.length > 0}
        canPaste={clipboard.count > 0}
        actions={{
          open: () => setDialog({ type: "open" }),
          save,
          exportXosc: () => setDialog({ type: "export" }),
          undo,
          redo,
          remove: removeSelection,
          copy: () => void copy(),
          paste,
          arrange: () => void arrange(),
          fit,
          extract: () => setDialog({ type: "extract" }),
          compare: () => void server.run(() => api.compare(!view?.comparison)),
          setDirection: changeDirection,
        }}
      />
      {server.error && (
        <div className="banner" role="alert">
          <span>{server.error}</span>
          <button type="button" onClick={server.clearError} aria-label="Dismiss">
            ×
          </button>
        </div>
      )}
      {replayStopped && (
        <div className="banner" role="alert" aria-label="Restore stopped">
          <span>{replayStopped}</span>
          <button type="button" onClick={() => setReplayStopped(null)} aria-label="Dismiss">
            ×
          </button>
        </div>
      )}
      {view?.document.olderRelease && editable && (
        <div className="banner release" role="status">
          <span>
            {view.document.name} was saved with metamodel release {view.document.olderRelease.saved}
            ; SceML reads it as release {view.document.olderRelease.current}.
          </span>
          <button type="button" onClick={save}>
            Save in release {view.document.olderRelease.current}
          </button>
        </div>
      )}
      <div className="workspace">
        {view && !view.readOnly && <Palette palette={view.palette} style={view.style} disabled={view.readOnly} onAdd={addFromPalette} />}
        <div className="canvas" ref={canvas}>
          <Diagram
            view={view}
            state={diagram}
            direction={direction}
            toggleExpanded={toggleExpanded}
            connectFrom={connectFrom}
            keyConnect={keyConnect}
            onConnect={(source, target) => void edit([{ op: "connect", source, target }], "Connect")}
            onMoved={(positions) => void edit([{ op: "move", positions }], "Move")}
            onDropItem={addItem}
          />
        </div>
        {view && <Properties view={view} node={single} selectionCount={selectedNodes.length} send={send} openDefinition={openDefinition} />}
      </div>
      {view && <Problems diagnostics={view.diagnostics} onShow={stableShowProblem} />}
      {view?.comparison && <Changes comparison={view.comparison} />}
      {view?.recovery && editable && recoveryLater !== view.recovery.path && (
        <RecoveryDialog
          recovery={view.recovery}
          documentName={view.document.name}
          onAnswer={(restore) =>
            void server.run(() => api.recovery(restore)).then((answer) => {
              const replay = answer?.replay;
              if (replay?.stopped) {
                setReplayStopped(`Restored ${replay.replayed} logged changes; ${replay.stopped}. It and the changes after it are kept in ${replay.kept}.`);
              }
            })
          }
          onLater={() => setRecoveryLater(view.recovery?.path ?? null)}
        />
      )}
      {dialog?.type === "open" && <OpenDialog view={view} onOpen={(path, module) => void open(path, module)} onCancel={() => setDialog(null)} />}
      {dialog?.type === "export" && view && <ExportDialog view={view} onExport={exportXosc} onCancel={() => setDialog(null)} />}
      {dialog?.type === "extract" && (
        <ExtractDialog
          count={ownSelection.length}
          libraries={[...new Set(view?.palette.flatMap((group) => group.items.map((item) => item.library ?? "")).filter(Boolean))]}
          onCancel={() => setDialog(null)}
          onExtract={(name, library) => {
            setDialog(null);
            void edit([{ op: "extract_module", nodes: ownSelection, name, library }], `Extract ${name}`);
          }}
        />
      )}
      {dialog?.type === "use" && view && (
        <UseModuleDialog
          view={view}
          item={dialog.item}
          onCancel={() => setDialog(null)}
          onAdd={(bindings) => {
            setDialog(null);
            void edit(
              [{ op: "add_module_use", library: dialog.item.library, module: dialog.item.module, position: dialog.position, bindings, overrides: {} }],
              `Add ${dialog.item.label}`,
            );
          }}
        />
      )}
    </div>
  );
}
