// The HTTP calls of the editor protocol. Every call that changes something answers with a view.

import type { Diagnostic, Op, View } from "./types";

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

async function call<T>(method: "GET" | "POST", path: string, body?: unknown): Promise<T> {
  let response: Response;
  try {
    response = await fetch(path, {
      method,
      headers: body === undefined ? undefined : { "Content-Type": "application/json" },
      body: body === undefined ? undefined : JSON.stringify(body),
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
  view: () => call<View>("GET", "/api/view"),
  ops: (ops: Op[], label?: string) =>
    call<View>("POST", "/api/ops", label ? { ops, label } : { ops }),
  undo: () => call<View>("POST", "/api/undo"),
  redo: () => call<View>("POST", "/api/redo"),
  copy: (nodes: string[]) => call<{ copied: number }>("POST", "/api/copy", { nodes }),
  save: (path?: string) => call<View>("POST", "/api/save", path ? { path } : {}),
  exportXosc: (version: string, profile: string, path?: string) =>
    call<{ path: string; version: string }>("POST", "/api/export", {
      version,
      profile,
      ...(path ? { path } : {}),
    }),
  open: (path: string, discard: boolean, module?: string) =>
    call<View>("POST", "/api/open", { path, discard, ...(module ? { module } : {}) }),
  openDefinition: (node: string) => call<View>("POST", "/api/open-definition", { node }),
};
