// The view the server sent last, and the calls that replace it. Refusals become a message.

import { useCallback, useEffect, useRef, useState } from "react";
import { api, ApiError, TAB_ID, type ChangeEvent } from "../api";
import type { Op, View } from "../types";

export interface Server {
  view: View | null;
  error: string | null;
  clearError: () => void;
  /** Run a call that answers with a view; on refusal show its error and answer null. */
  run: (call: () => Promise<View>) => Promise<View | null>;
  ops: (ops: Op[], label?: string) => Promise<View | null>;
  report: (error: unknown) => void;
  /** Run any other call in turn with the view calls (copy, export). */
  enqueue: <T>(call: () => Promise<T>) => Promise<T>;
}

export function useServer(): Server {
  const [view, setView] = useState<View | null>(null);
  const [error, setError] = useState<string | null>(null);

  const report = useCallback((caught: unknown) => {
    setError(caught instanceof ApiError || caught instanceof Error ? caught.message : String(caught));
  }, []);

  // Requests go one after the other, so the server applies them in the order the user made them.
  const queue = useRef<Promise<unknown>>(Promise.resolve());
  const enqueue = useCallback(<T>(call: () => Promise<T>): Promise<T> => {
    const next = queue.current.then(call, call);
    queue.current = next.catch(() => undefined);
    return next;
  }, []);
  const run = useCallback(
    (call: () => Promise<View>) =>
      enqueue(async () => {
        try {
          const answer = await call();
          setView(answer);
          return answer;
        } catch (caught) {
          report(caught);
          return null;
        }
      }),
    [enqueue, report],
  );

  const ops = useCallback((list: Op[], label?: string) => run(() => api.ops(list, label)), [run]);

  useEffect(() => {
    void run(api.view);
  }, [run]);

  // Live for every tab: another tab's change (or a server that came back) fetches the view.
  const version = useRef(-1);
  useEffect(() => {
    version.current = view?.version ?? -1;
  }, [view]);
  useEffect(() => {
    const events = new EventSource("/api/events");
    const refresh = () => void run(api.view);
    events.addEventListener("change", (event) => {
      const change = JSON.parse((event as MessageEvent<string>).data) as ChangeEvent;
      if (change.tab !== TAB_ID) refresh();
    });
    // The first event of every connection: after a reconnect, catch up on what was missed.
    events.addEventListener("hello", (event) => {
      const hello = JSON.parse((event as MessageEvent<string>).data) as { version: number };
      if (version.current !== -1 && hello.version !== version.current) refresh();
    });
    return () => events.close();
  }, [run]);

  return { view, error, clearError: () => setError(null), run, ops, report, enqueue };
}
