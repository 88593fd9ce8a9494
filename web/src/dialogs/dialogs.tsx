// The dialogs: Open, Export, Extract module, and "Use <module>" after dropping a module.

import { useState } from "react";
import type { Diagnostic, PaletteItem, View } from "../types";
import { Dialog, Field } from "./Dialog";

export function OpenDialog({ view, onOpen, onCancel }: { view: View | null; onOpen: (path: string, module: string) => void; onCancel: () => void }) {
  const [path, setPath] = useState(view?.document.path ?? "");
  const [module, setModule] = useState("");
  return (
    <Dialog title="Open" confirm="Open" onConfirm={() => path.trim() && onOpen(path.trim(), module.trim())} onCancel={onCancel}>
      <Field label="Path">{(id) => <input id={id} value={path} onChange={(e) => setPath(e.target.value)} size={50} />}</Field>
      <Field label="Module (in a library, optional)">{(id) => <input id={id} value={module} onChange={(e) => setModule(e.target.value)} />}</Field>
    </Dialog>
  );
}

export interface ExportResult {
  path?: string;
  error?: string;
  diagnostics?: Diagnostic[];
}

export function ExportDialog({
  view,
  onExport,
  onCancel,
}: {
  view: View;
  onExport: (version: string, profile: string, path: string) => Promise<ExportResult>;
  onCancel: () => void;
}) {
  const versions = view.choices.oscVersions ?? [];
  const profiles = view.choices.profiles ?? [];
  // "": the server writes the profile's default version (the newest; 1.0 for carla).
  const [version, setVersion] = useState("");
  const [profile, setProfile] = useState(profiles[0] ?? "");
  const [path, setPath] = useState("");
  const [busy, setBusy] = useState(false);
  const [result, setResult] = useState<ExportResult | null>(null);
  const run = async () => {
    setBusy(true);
    setResult(await onExport(version, profile, path.trim()));
    setBusy(false);
  };
  return (
    <Dialog title="Export" confirm="Export" onConfirm={() => void run()} onCancel={onCancel} busy={busy}>
      <Field label="Version">
        {(id) => (
          <select id={id} value={version} onChange={(e) => setVersion(e.target.value)}>
            <option value="">the profile's default</option>
            {versions.map((v) => (
              <option key={v} value={v}>
                OpenSCENARIO {v}
              </option>
            ))}
          </select>
        )}
      </Field>
      <Field label="Profile">
        {(id) => (
          <select id={id} value={profile} onChange={(e) => setProfile(e.target.value)}>
            {profiles.map((p) => (
              <option key={p} value={p}>
                {p}
              </option>
            ))}
          </select>
        )}
      </Field>
      <Field label="Path">{(id) => <input id={id} value={path} placeholder="beside the scenario (default)" onChange={(e) => setPath(e.target.value)} size={50} />}</Field>
      {result?.path && (
        <p className="success" role="status">
          Exported to {result.path}
        </p>
      )}
      {result?.error && (
        <div className="export-refused" role="alert">
          <p>{result.error}</p>
          {result.diagnostics && result.diagnostics.length > 0 && (
            <ul>
              {result.diagnostics.map((d, i) => (
                <li key={i} className={`severity-${d.severity}`}>
                  {d.code} {d.message}
                </li>
              ))}
            </ul>
          )}
        </div>
      )}
    </Dialog>
  );
}

export function ExtractDialog({
  count,
  libraries,
  onExtract,
  onCancel,
}: {
  count: number;
  /** The libraries the palette offers, as ops name them: suggestions, never a default. */
  libraries: string[];
  onExtract: (name: string, library: string) => void;
  onCancel: () => void;
}) {
  const [name, setName] = useState("");
  const [library, setLibrary] = useState("");
  const [missing, setMissing] = useState<string | null>(null);
  const confirm = () => {
    if (!name.trim()) return setMissing("Name the new module.");
    if (!library.trim()) return setMissing("Choose the library file the module is written into.");
    onExtract(name.trim(), library.trim());
  };
  return (
    <Dialog title="Extract module" confirm="Extract module" onConfirm={confirm} onCancel={onCancel}>
      <p className="hint">
        The {count} selected nodes become a module, replaced here by a use of it. The module is written into the library
        file at once; Undo takes it out again.
      </p>
      <Field label="Module name">{(id) => <input id={id} value={name} onChange={(e) => setName(e.target.value)} />}</Field>
      <Field label="Library">
        {(id) => (
          <>
            <input id={id} value={library} list={`${id}-known`} placeholder="library/my-modules.xmi" onChange={(e) => setLibrary(e.target.value)} size={40} />
            <datalist id={`${id}-known`}>
              {libraries.map((known) => (
                <option key={known} value={known} />
              ))}
            </datalist>
          </>
        )}
      </Field>
      {missing && (
        <p className="problem-text" role="alert">
          {missing}
        </p>
      )}
    </Dialog>
  );
}

export function UseModuleDialog({
  view,
  item,
  onAdd,
  onCancel,
}: {
  view: View;
  item: PaletteItem;
  onAdd: (bindings: Record<string, string>) => void;
  onCancel: () => void;
}) {
  const roles = item.roles ?? [];
  // Only the actors that fit a role are offered (the server judges the kinds); a role that only
  // one actor fits is bound to it from the start.
  const fitting = (role: (typeof roles)[number]) => role.actors ?? view.actors.map((actor) => actor.name);
  const [bindings, setBindings] = useState<Record<string, string>>(() =>
    Object.fromEntries(roles.flatMap((role) => (fitting(role).length === 1 ? [[role.role, fitting(role)[0] ?? ""]] : []))),
  );
  const kindOf = new Map(view.actors.map((actor) => [actor.name, actor.kind ?? actor.allowedKinds?.join(" | ") ?? "?"]));
  const chosen = () => Object.fromEntries(Object.entries(bindings).filter(([, actor]) => actor !== ""));
  return (
    <Dialog title={`Use ${item.module ?? item.label}`} confirm="Add" onConfirm={() => onAdd(chosen())} onCancel={onCancel}>
      <p className="hint">From {item.library}. Bind each role to an actor of the scenario.</p>
      {roles.length === 0 && <p className="hint">Roles can be bound in the properties after adding it.</p>}
      {roles.map((role) => (
        <Field key={role.role} label={role.role}>
          {(id) => (
            <select id={id} value={bindings[role.role] ?? ""} onChange={(e) => setBindings({ ...bindings, [role.role]: e.target.value })}>
              <option value="">(none)</option>
              {fitting(role).map((name) => (
                <option key={name} value={name}>
                  {name} ({kindOf.get(name) ?? "?"})
                </option>
              ))}
            </select>
          )}
        </Field>
      ))}
      {roles.length > 0 && <p className="hint">Allowed: {roles.map((r) => `${r.role}: ${r.allowedKinds.join(", ")}`).join("; ")}</p>}
    </Dialog>
  );
}
