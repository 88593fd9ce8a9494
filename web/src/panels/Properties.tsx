// The properties panel: the selected node's fields; the root adds the actors, a module use its
// role bindings and parameter overrides. Every change is one op.

import type { Actor, Field, Op, View, ViewNode } from "../types";
import { FieldList, type FieldContext, type FieldValue } from "./FieldControl";
import { LabelledSelect } from "./inputs";
import { ParamEditor } from "./ParamEditor";

interface Props {
  view: View;
  node: ViewNode | null;
  selectionCount: number;
  send: (op: Op) => void;
  openDefinition: (node: ViewNode) => void;
}

/** The op that sets a field of a node, by the field's type. */
function nodeOp(node: ViewNode, field: Field, value: FieldValue): Op {
  switch (field.type) {
    case "parameter":
      return { op: "set_parameter", node: node.id, field: field.name, value };
    case "position":
      return { op: "set_position", node: node.id, field: field.name, value };
    case "positions":
      return { op: "set_waypoints", node: node.id, value };
    default:
      return { op: "set", node: node.id, field: field.name, value };
  }
}

/** The op that sets a field of an actor, by the field's type. */
function actorOp(actor: Actor, field: Field, value: FieldValue): Op {
  switch (field.type) {
    case "parameter":
      return { op: "set_actor_parameter", actor: actor.id, field: field.name, value };
    case "position":
      return { op: "set_actor_position", actor: actor.id, value };
    default:
      return { op: "set_actor", actor: actor.id, field: field.name, value };
  }
}

function ActorsList({ view, context, send }: { view: View; context: FieldContext; send: (op: Op) => void }) {
  const kinds = view.choices.actorKinds ?? [];
  return (
    <section className="actors" aria-label="Actors">
      <h3>Actors</h3>
      {view.actors.map((actor) => (
        <div key={actor.id} className="actor" role="group" aria-label={`Actor ${actor.name}`}>
          <h4>
            {actor.name} <span className="hint">{actor.kind}{actor.isEgo ? ", ego" : ""}</span>
          </h4>
          <FieldList owner={actor.id} fields={actor.fields ?? []} context={context} onSend={(field, value) => send(actorOp(actor, field, value))} />
          {!context.disabled && (
            <button type="button" className="danger" onClick={() => send({ op: "remove_actor", actor: actor.id })}>
              Remove actor
            </button>
          )}
        </div>
      ))}
      {!context.disabled && (
        <button type="button" onClick={() => send({ op: "add_actor", kind: kinds.includes("Car") ? "Car" : (kinds[0] ?? "Car") })}>
          Add actor
        </button>
      )}
    </section>
  );
}

function ModuleUse({ view, node, context, send, openDefinition }: { view: View; node: ViewNode; context: FieldContext; send: (op: Op) => void; openDefinition: (node: ViewNode) => void }) {
  const module = node.module;
  if (!module) return null;
  return (
    <section className="module-use">
      <h3>
        Module {module.definition} <span className="hint">{module.library}</span>
      </h3>
      {!module.resolved && <p className="hint incomplete">The module's definition cannot be found.</p>}
      <button type="button" onClick={() => openDefinition(node)} disabled={!module.resolved}>
        Open definition
      </button>
      <h4>Roles</h4>
      {module.bindings.map((binding) => (
        <LabelledSelect
          key={`${binding.role}:${binding.actor ?? ""}`}
          label={binding.role}
          value={binding.actor ?? ""}
          disabled={context.disabled}
          options={[{ value: "", label: "(none)" }, ...view.actors.map((actor) => ({ value: actor.name, label: `${actor.name} (${actor.kind ?? "?"})` }))]}
          onChange={(actor) => send({ op: "bind_role", node: node.id, role: binding.role, actor: actor || null })}
        />
      ))}
      {module.bindings.length > 0 && <p className="hint">Allowed: {module.bindings.map((b) => `${b.role}: ${b.allowedKinds.join(", ")}`).join("; ")}</p>}
      <h4>Parameters</h4>
      {module.parameters.map((parameter) => (
        <ParamEditor
          key={`${parameter.name}:${JSON.stringify(parameter.override)}`}
          label={parameter.name}
          value={parameter.override}
          valueTypes={view.valueTypes}
          unit={parameter.unit}
          text={parameter.text}
          defaultText={parameter.defaultText}
          disabled={context.disabled}
          onCommit={(value) => send({ op: "set_override", node: node.id, parameter: parameter.name, value })}
        />
      ))}
    </section>
  );
}

export function Properties({ view, node, selectionCount, send, openDefinition }: Props) {
  const context: FieldContext = {
    actorNames: view.actors.map((actor) => actor.name),
    valueTypes: view.valueTypes,
    disabled: view.readOnly || (node?.readOnly ?? false),
  };
  return (
    <aside className="properties" role="region" aria-label="Properties">
      <h2>Properties</h2>
      {node === null ? (
        <p className="hint">{selectionCount > 1 ? `${selectionCount} selected.` : "Select a node to see its properties."}</p>
      ) : (
        <div key={node.id}>
          <p className="kind">
            {node.kind}
            {node.readOnly ? <span className="hint"> (read-only, inside a module use)</span> : null}
          </p>
          <FieldList owner={node.id} fields={node.fields} context={context} onSend={(field, value) => send(nodeOp(node, field, value))} />
          {node.module && <ModuleUse view={view} node={node} context={context} send={send} openDefinition={openDefinition} />}
          {node.look === "root" && <ActorsList view={view} context={context} send={send} />}
        </div>
      )}
    </aside>
  );
}
