// The HTTP calls of the editor protocol. Every call that changes something answers with a view.

import type { Answer, Diagnostic, Op, View, ViewPatch } from "./types";

/** A refused request: the server's `error` text, its status, and any diagnostics (export, 422). */
export class ApiError extends Error {
  readonly status: number;
  readonly diagnostics: Diagnostic[];

  constructor(message: string, status: number, diagnostics: Diagnostic[] = []) {
    super(message);
    this.status = status;
    this.diagnostics = diagnostics;
  }
}

const TAB_KEY = "sceml-tab";
/** Browsers allow 64 KiB of keepalive bodies in flight; larger requests are ordinary ones. */
const KEEPALIVE_LIMIT = 32_000;

function newTabId(): string {
  return typeof crypto.randomUUID === "function" ? crypto.randomUUID() : `t${Date.now()}-${Math.random().toString(36).slice(2)}`;
}

/** This tab's name for the server, so Undo undoes this tab's edits. It survives a reload of the
 * tab (sessionStorage is per tab), so Undo still works after one. */
export const TAB_ID: string = (() => {
  const kept = sessionStorage.getItem(TAB_KEY);
  if (kept) return kept;
  const made = newTabId();
  sessionStorage.setItem(TAB_KEY, made);
  return made;
})();

/** The view revision this page holds: every request names it, and the server answers a view
 * call with a patch to it when one applies (lib/patch.ts). */
let heldRevision: number | null = null;

export function holdRevision(revision: number | null): void {
  heldRevision = revision;
}

async function call<T>(method: "GET" | "POST", path: string, body?: unknown): Promise<T> {
  let response: Response;
  try {
    const headers: Record<string, string> = { "X-SceML-Tab": TAB_ID };
    if (heldRevision !== null) headers["X-SceML-Revision"] = String(heldRevision);
    if (body !== undefined) headers["Content-Type"] = "application/json";
    const json = body === undefined ? undefined : JSON.stringify(body);
    response = await fetch(path, {
      method,
      headers,
      body: json,
      // A small request outlives the page: the edit a reload or a closed tab commits arrives.
      keepalive: json !== undefined && json.length < KEEPALIVE_LIMIT,
    });
  } catch {
    throw new ApiError("The editor's server cannot be reached. Is `sceml edit` still running?", 0);
  }
  const text = await response.text();
  let data: unknown = null;
  try {
    data = text ? JSON.parse(text) : null;
  } catch {
    data = null;
  }
  if (!response.ok) {
    const record = (data ?? {}) as { error?: string; diagnostics?: Diagnostic[] };
    const message = record.error ?? `The server answered ${response.status} ${response.statusText}`;
    throw new ApiError(message, response.status, record.diagnostics ?? []);
  }
  return data as T;
}

export const api = {
  view: () => call<Answer>("GET", "/api/view"),
  ops: (ops: Op[], label?: string) =>
    call<Answer>("POST", "/api/ops", label ? { ops, label } : { ops }),
  undo: () => call<Answer>("POST", "/api/undo"),
  redo: () => call<Answer>("POST", "/api/redo"),
  copy: (nodes: string[]) => call<{ copied: number }>("POST", "/api/copy", { nodes }),
  save: (path?: string) => call<Answer>("POST", "/api/save", path ? { path } : {}),
  exportXosc: (version: string, profile: string, path?: string) =>
    call<{ path: string; version: string }>("POST", "/api/export", {
      version,
      profile,
      ...(path ? { path } : {}),
    }),
  open: (path: string, discard: boolean, module?: string) =>
    call<Answer>("POST", "/api/open", { path, discard, ...(module ? { module } : {}) }),
  openDefinition: (node: string) => call<Answer>("POST", "/api/open-definition", { node }),
  recovery: (restore: boolean) => call<Answer>("POST", "/api/recovery", { restore }),
  compare: (on: boolean) => call<Answer>("POST", "/api/compare", { on }),
};

/** A change event of the server's stream: the tab that made it, the view's shared small fields
 * (no undo or redo: those are each tab's own) and the patch to the new revision. */
export type ChangeEvent = Partial<Omit<View, "undo" | "redo">> & {
  version: number;
  revision: number;
  tab: string;
  patch?: ViewPatch;
};
