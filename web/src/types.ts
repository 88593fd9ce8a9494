// The editor protocol's JSON shapes (docs/editor-protocol.md). The server decides every value;
// these types only describe what it sends and what the page sends back.

export type Severity = "error" | "warning" | "info";

export interface XY {
  x: number;
  y: number;
}

export type ParamValue =
  | { type: "value"; value: number }
  | { type: "range"; min: number; max: number; step: number | null }
  | { type: "uniform"; min: number; max: number }
  | { type: "normal"; mean: number; sd: number; min: number | null; max: number | null }
  | { type: "discrete"; values: number[]; weights: number[] | null }
  | { type: "ref"; parameter: string };

export type ParamType = ParamValue["type"];

export type Position =
  | { type: "world"; x: ParamValue; y: ParamValue; z: ParamValue | null; h: ParamValue | null }
  | { type: "lane"; roadId: string; laneId: number; s: ParamValue; offset: ParamValue | null; h: ParamValue | null }
  | { type: "road"; roadId: string; s: ParamValue; t: ParamValue | null; h: ParamValue | null }
  | { type: "relativeLane"; entity: string; dLane: number; ds: ParamValue | null; offset: ParamValue | null }
  | { type: "relativeRoad"; entity: string; ds: ParamValue | null; dt: ParamValue | null }
  | { type: "relativeObject"; entity: string; dx: ParamValue | null; dy: ParamValue | null; dz: ParamValue | null; h: ParamValue | null }
  | { type: "relativeWorld"; entity: string; dx: ParamValue | null; dy: ParamValue | null; dz: ParamValue | null }
  | { type: "route"; routeName: string | null; closed: boolean; waypoints: RouteWaypoint[]; laneId: number | null; pathS: ParamValue | null; laneOffset: ParamValue | null; t: ParamValue | null };

/** One waypoint of a route position: a world, lane or road position and how the route reaches it. */
export interface RouteWaypoint {
  routeStrategy: string;
  position: Position;
}

interface FieldBase {
  name: string;
  label: string;
  required?: boolean;
}

export type Field =
  | (FieldBase & { type: "text"; value: string | null })
  | (FieldBase & { type: "enum"; options: string[]; value: string | null })
  | (FieldBase & { type: "bool"; value: boolean | null })
  | (FieldBase & { type: "actor"; value: string | null })
  | (FieldBase & {
      type: "parameter";
      unit?: string | null;
      default?: number | null;
      kmh?: boolean;
      value: ParamValue | null;
      /** The server's display text of the value (units, km/h), null when unset. */
      text: string | null;
      /** The server's display text of the language default, null when there is none. */
      defaultText: string | null;
    })
  | (FieldBase & { type: "position"; value: Position | null; text: string | null })
  | (FieldBase & { type: "positions"; value: Position[] | null; texts: (string | null)[] });

export type Look =
  | "longitudinal"
  | "lateral"
  | "composite"
  | "controller"
  | "appearance"
  | "coupling"
  | "condition"
  | "root"
  | "end"
  | "joinAll"
  | "joinOne"
  | "endOne"
  | "module"
  | "brokenModule"
  | "inPort"
  | "outPort";

export interface Binding {
  role: string;
  allowedKinds: string[];
  actor: string | null;
}

export interface ModuleParameter {
  name: string;
  unit?: string | null;
  default: ParamValue | null;
  override: ParamValue | null;
  /** The server's display texts of the default and the override (null when unset). */
  defaultText: string | null;
  text: string | null;
}

export interface ModuleInfo {
  definition: string;
  library: string;
  resolved: boolean;
  bindings: Binding[];
  parameters: ModuleParameter[];
}

export interface ViewNode {
  id: string;
  kind: string;
  look: Look | string;
  name: string;
  title: string;
  lines: string[];
  position: XY | null;
  parent: string | null;
  readOnly: boolean;
  severity: Severity | null;
  problems: number;
  fields: Field[];
  module?: ModuleInfo;
  /** While comparing with the saved file: what happened to this node since (`sceml diff`). */
  mark?: "added" | "changed";
}

export interface ViewEdge {
  id: string;
  source: string;
  target: string;
}

export interface Actor {
  id: string;
  name: string;
  kind?: string;
  isEgo?: boolean;
  allowedKinds?: string[];
  fields?: Field[];
}

export interface Diagnostic {
  severity: Severity;
  code: string;
  message: string;
  path?: string | null;
  node: string | null;
  actor: string | null;
  line?: number | null;
}

export interface PaletteItem {
  kind: string;
  label: string;
  module: string | null;
  library: string | null;
  /** Roles of a module item, for the "Use <module>" dialog (optional, see the protocol). */
  /** Each role, the kinds it accepts, and the actors (or outer roles) that fit it. */
  roles?: { role: string; allowedKinds: string[]; actors?: string[] }[];
}

export interface PaletteGroup {
  group: string;
  label: string;
  look: string;
  items: PaletteItem[];
}

export interface LookStyle {
  fill?: string;
  border?: string;
  shape?: string;
  [key: string]: unknown;
}

export interface Style {
  looks: Record<string, LookStyle>;
  symbols?: Record<string, string>;
  font?: string;
  /** How flows are drawn (`color`), as `sceml render` draws them. */
  edge: { color: string };
}

export interface DocumentInfo {
  kind: "scenario" | "module";
  path: string;
  name: string;
  module?: string;
  /** Set when the file was saved with an older metamodel release and read through a migration. */
  olderRelease?: { saved: string; current: string };
}

/** The comparison of the open scenario with its saved file, in `sceml diff`'s words. */
export interface Comparison {
  against: string;
  saved: boolean;
  changes: string[];
  removed: string[];
}

export interface View {
  version: number;
  /** The revision of the view's shared content: a patch applies to the page that holds its base. */
  revision: number;
  comparison?: Comparison;
  document: DocumentInfo;
  readOnly: boolean;
  dirty: boolean;
  undo: string | null;
  redo: string | null;
  created?: string[];
  level: string;
  valueTypes: string[];
  nodes: ViewNode[];
  edges: ViewEdge[];
  actors: Actor[];
  diagnostics: Diagnostic[];
  summary: { errors: number; warnings: number; infos: number };
  palette: PaletteGroup[];
  style: Style;
  choices: Record<string, string[]>;
  /** A recovery copy an earlier run left (after a crash or kill), offered until answered, and
   * how many logged changes a restore replays on it. */
  recovery: { path: string; written: string; changes?: number } | null;
  /** Only in the answer to a restore: how many logged changes were replayed, and the one that
   * could not be (with where it and the later ones were kept). */
  replay?: { replayed: number; stopped: string | null; kept: string | null };
}

/** The entries of a list that changed or were added, the ids removed, and the whole order of
 * ids when it is not the old order less the removed with the added at the end. */
export interface ListPatch<T> {
  changed: T[];
  removed: string[];
  order?: string[];
}

/** What changed in the shared content since revision `base` (docs/editor-protocol.md, Patches). */
export interface ViewPatch {
  base: number;
  nodes?: ListPatch<ViewNode>;
  edges?: ListPatch<ViewEdge>;
  actors?: Actor[];
  diagnostics?: Diagnostic[];
  palette?: PaletteGroup[];
  style?: Style;
  choices?: Record<string, string[]>;
  valueTypes?: string[];
  comparison?: Comparison | null;
}

/** A view, or (for a page that named its revision) the view's small fields and a patch. */
export type Answer = View | (Omit<View, "nodes" | "edges" | "actors" | "diagnostics" | "palette" | "style" | "choices" | "valueTypes" | "comparison"> & { patch: ViewPatch });

export type Op = { op: string } & Record<string, unknown>;
