// The view the server sent last, and the calls that replace it. Refusals become a message.
// Answers are patches to the view this page holds (lib/patch.ts); unchanged nodes and edges
// keep their objects, so the canvas redraws only what changed.

import { useCallback, useEffect, useRef, useState } from "react";
import { api, ApiError, holdRevision, TAB_ID, type ChangeEvent } from "../api";
import { applyAnswer } from "../lib/patch";
import type { Answer, Op, View } from "../types";

export interface Server {
  view: View | null;
  error: string | null;
  clearError: () => void;
  /** Run a call that answers with a view; on refusal show its error and answer null. */
  run: (call: () => Promise<Answer>) => Promise<View | null>;
  ops: (ops: Op[], label?: string) => Promise<View | null>;
  report: (error: unknown) => void;
  /** Run any other call in turn with the view calls (copy, export). */
  enqueue: <T>(call: () => Promise<T>) => Promise<T>;
}

/** The whole view, whatever revision the page holds. */
async function wholeView(): Promise<View> {
  holdRevision(null);
  const answer = await api.view();
  if ("patch" in answer) throw new Error("the server answered a patch to a request for the whole view");
  return answer;
}

export function useServer(): Server {
  const [view, setView] = useState<View | null>(null);
  const [error, setError] = useState<string | null>(null);
  // The view as of the last answer applied (state updates later): patches apply to it.
  const held = useRef<View | null>(null);

  const report = useCallback((caught: unknown) => {
    setError(caught instanceof ApiError || caught instanceof Error ? caught.message : String(caught));
  }, []);

  const adopt = useCallback(async (answer: Answer): Promise<View> => {
    // A patch to a revision this page does not hold (it missed a change): ask for it all.
    const next = applyAnswer(held.current, answer) ?? (await wholeView());
    held.current = next;
    holdRevision(next.revision);
    setView(next);
    return next;
  }, []);

  // Requests go one after the other, so the server applies them in the order the user made them.
  const queue = useRef<Promise<unknown>>(Promise.resolve());
  const enqueue = useCallback(<T>(call: () => Promise<T>): Promise<T> => {
    const next = queue.current.then(call, call);
    queue.current = next.catch(() => undefined);
    return next;
  }, []);
  const run = useCallback(
    (call: () => Promise<Answer>) =>
      enqueue(async () => {
        try {
          return await adopt(await call());
        } catch (caught) {
          report(caught);
          return null;
        }
      }),
    [enqueue, adopt, report],
  );

  const ops = useCallback((list: Op[], label?: string) => run(() => api.ops(list, label)), [run]);

  useEffect(() => {
    void run(api.view);
  }, [run]);

  // Live for every tab: another tab's change comes with its patch, which is drawn at once;
  // then this tab asks for its own undo and redo (another tab's step clears every redo).
  useEffect(() => {
    const events = new EventSource("/api/events");
    events.addEventListener("change", (event) => {
      const change = JSON.parse((event as MessageEvent<string>).data) as ChangeEvent;
      if (change.tab === TAB_ID) return;
      void enqueue(async () => {
        const { tab: _tab, patch, ...shared } = change;
        void _tab;
        const current = held.current;
        if (current && patch) {
          // Nothing shared changed (a save): the small fields are all there is to take.
          const base = current.revision === change.revision ? { base: current.revision } : patch;
          const next = applyAnswer(current, { ...shared, undo: current.undo, redo: current.redo, patch: base } as Answer);
          if (next) {
            held.current = next;
            holdRevision(next.revision);
            setView(next);
          }
        }
      });
      void run(api.view);
    });
    // The first event of every connection: after a reconnect, catch up on what was missed.
    events.addEventListener("hello", (event) => {
      const hello = JSON.parse((event as MessageEvent<string>).data) as { version: number };
      if (held.current !== null && hello.version !== held.current.version) void run(api.view);
    });
    return () => events.close();
  }, [run, enqueue]);

  return { view, error, clearError: () => setError(null), run, ops, report, enqueue };
}
