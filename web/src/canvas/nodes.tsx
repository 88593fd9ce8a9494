// One component per kind of drawn node; colours and symbols come from the view's style.

import type { NodeProps } from "@xyflow/react";
import { resolveLook, symbolOf } from "../lib/looks";
import { nameAndLines } from "../lib/sizes";
import { useDiagram } from "./context";
import { Handles } from "./Handles";
import { ProblemBadge } from "./ProblemBadge";
import type { DiagramNode } from "./types";
import { useFar } from "./zoom";

type Props = NodeProps<DiagramNode>;

function TextLines({ lines }: { lines: string[] }) {
  return (
    <div className="node-lines">
      {lines.map((line, index) => (
        <div key={index}>{line}</div>
      ))}
    </div>
  );
}

export function ActionNode({ data, selected }: Props) {
  const { style, readOnly } = useDiagram();
  const far = useFar();
  const look = resolveLook(style, data.node.look);
  return (
    <div
      className={`sceml-box look-${data.node.look}${selected ? " selected" : ""}`}
      style={{
        background: look.fill,
        borderColor: look.border,
        color: look.text,
        borderRadius: look.rounded ? 14 : 0,
        borderStyle: look.dashed ? "dashed" : "solid",
      }}
    >
      <Handles connectable={!readOnly && !data.node.readOnly} name={data.node.name} />
      {!far && <div className="node-title">{data.node.title}</div>}
      {!far && <TextLines lines={nameAndLines(data.node)} />}
      <ProblemBadge node={data.node} />
    </div>
  );
}

export function RootNode({ data, selected }: Props) {
  const { style, readOnly } = useDiagram();
  const far = useFar();
  const look = resolveLook(style, data.node.look);
  return (
    <div
      className={`sceml-box sceml-root${selected ? " selected" : ""}`}
      style={{ background: look.fill, borderColor: look.border, color: look.text, borderRadius: 14 }}
    >
      <Handles connectable={!readOnly && !data.node.readOnly} name={data.node.name} />
      {!far && <div className="node-title">{data.node.title}</div>}
      {!far && <TextLines lines={data.node.lines} />}
      <ProblemBadge node={data.node} />
    </div>
  );
}

export function JoinNode({ data, selected }: Props) {
  const { style, readOnly } = useDiagram();
  const look = resolveLook(style, data.node.look);
  const one = data.node.look === "joinOne";
  const symbol = one ? symbolOf(style, "joinOne", "?") : symbolOf(style, "joinAll", "⇉");
  return (
    <div className={`sceml-join${one ? " join-one" : " join-all"}${selected ? " selected" : ""}`} title={data.node.name}>
      <div className="join-shape" style={{ background: look.fill, borderColor: look.border }} />
      <span className="join-symbol" style={{ color: look.text }}>
        {symbol}
      </span>
      <Handles connectable={!readOnly && !data.node.readOnly} name={data.node.name} />
      <ProblemBadge node={data.node} />
    </div>
  );
}

export function EndNode({ data, selected }: Props) {
  const { style, readOnly } = useDiagram();
  const look = resolveLook(style, data.node.look);
  const one = data.node.look === "endOne";
  return (
    <div className={`sceml-end${selected ? " selected" : ""}`} style={{ borderColor: look.border }}>
      <div className="end-inner" style={{ background: look.fill, color: "#ffffff" }}>
        {one ? `End ${symbolOf(style, "joinOne", "?")}` : "End"}
      </div>
      <Handles connectable={!readOnly && !data.node.readOnly} name={data.node.name} />
      <ProblemBadge node={data.node} />
    </div>
  );
}

export function PortNode({ data }: Props) {
  const out = data.node.look === "outPort";
  return (
    <div className={`sceml-port ${out ? "port-out" : "port-in"}`}>
      <svg width={data.width} height={data.height} viewBox="0 0 48 30" aria-hidden="true">
        <polygon
          points={out ? "1,29 1,11 24,1 47,11 47,29" : "1,1 47,1 47,19 24,29 1,19"}
          fill="#ffffff"
          stroke="#000000"
        />
        <text x="24" y={out ? 22 : 15} textAnchor="middle" fontSize="10">
          {out ? "out" : "in"}
        </text>
      </svg>
      <Handles connectable={false} />
    </div>
  );
}

function ExpandToggle({ id, expanded }: { id: string; expanded: boolean }) {
  const { toggleExpanded } = useDiagram();
  return (
    <button
      type="button"
      className="expand-toggle nodrag"
      onClick={(event) => {
        event.stopPropagation();
        toggleExpanded(id);
      }}
    >
      {expanded ? "Collapse" : "Expand"}
    </button>
  );
}

export function ModuleNode({ data, selected }: Props) {
  const { style, readOnly } = useDiagram();
  const far = useFar();
  const look = resolveLook(style, data.node.look);
  const broken = data.node.look === "brokenModule";
  return (
    <div
      className={`sceml-module${broken ? " broken" : ""}${selected ? " selected" : ""}`}
      style={{ background: look.fill, borderColor: look.border, color: look.text }}
    >
      <Handles connectable={!readOnly && !data.node.readOnly} name={data.node.name} />
      <div className="module-inner" style={{ borderColor: look.border }}>
        {!far && (
          <>
            <div className="node-title">{data.node.title}</div>
            <div className="node-subtitle">module</div>
            <TextLines lines={nameAndLines(data.node)} />
          </>
        )}
      </div>
      {data.canExpand && <ExpandToggle id={data.node.id} expanded={false} />}
      <ProblemBadge node={data.node} />
    </div>
  );
}

/** An expanded module use: a dashed frame holding the read-only inner nodes and the ports. */
export function FrameNode({ data, selected }: Props) {
  const title = data.node.name ? `${data.node.name}: ${data.node.title}` : data.node.title;
  return (
    <div className={`sceml-frame${selected ? " selected" : ""}`}>
      <div className="frame-header">
        <div className="frame-title">{title}</div>
        <TextLines lines={data.node.lines} />
      </div>
      <ExpandToggle id={data.node.id} expanded />
      <ProblemBadge node={data.node} />
      {/* Where edges into the use end: on the frame's border, clear of the header's text. */}
      <Handles connectable={false} />
    </div>
  );
}
