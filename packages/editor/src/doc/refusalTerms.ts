/**
 * A refused edit in the user's terms. The engine names the field of the one action it was given by
 * a path from `action` ("action.r: must be a positive finite number", "action.v[0]", "action.g"),
 * which the user never sees: refusalInUserTerms names it as the cell that was edited ("A r", "A vx",
 * "g", "gravity y", "L x1"), keeping the engine's reason. A refusal of the action as a whole (path
 * `action`) keeps the reason alone, which names the objects already, except that a disc, line or
 * point being added is named by its place ("a new disc here would overlap body "B"": its id was
 * never shown). A vector refused whole (`action.v`: "must be an array of two finite numbers") with
 * one component not finite names that component's cell ("A vx: must be a finite number"), since a
 * cell edits one component. A line's end refused whole for meeting the other end is named by both
 * of its cells and the other end's, with the values given ("L x1, y1: must differ from x2, y2 (got 1, 0):
 * a line needs two different ends", from the engine's "must differ from p2 (got [1, 0])"; the engine's
 * "L p1: must differ from p1 and p2 of the line" named fields no table has). Paths of other actions (`actions[i]`, doc/actionRefs.ts) and messages without a
 * path are left as they are. Pure.
 */
import type { Action } from "../engineTypes";

/** The field paths (after `action`) whose name in the tables is not the field's own. */
const FIELD_NAMES: Record<string, string> = {
  "v[0]": "vx",
  "v[1]": "vy",
  "gravity[0]": "gravity x",
  "gravity[1]": "gravity y",
  "p[0]": "x",
  "p[1]": "y",
  "p1[0]": "x1",
  "p1[1]": "y1",
  "p2[0]": "x2",
  "p2[1]": "y2",
  mu: "μ",
};

/** What an added object is called before it has been seen. */
const NEW_OBJECT: Partial<Record<Action["type"], { kind: string; noun: string }>> = {
  addBody: { kind: "body", noun: "disc" },
  addLine: { kind: "line", noun: "line" },
  addPoint: { kind: "point", noun: "point" },
};

/**
 * The message for `action` refused by the engine with `message` and `path` (the SceneError's),
 * naming what the user edited instead of the engine's path (see the module comment).
 */
export function refusalInUserTerms(message: string, path: string | null, action: Action): string {
  const m = path === null ? null : /^action(?:\.(.+))?$/.exec(path);
  if (m === null) return message;
  const reason = message.startsWith(`${path}: `) ? message.slice(`${path}: `.length) : message;
  const added = NEW_OBJECT[action.type];
  const id = "id" in action ? action.id : null;
  const field = m[1];
  if (field === undefined) {
    if (added === undefined || id === null) return reason;
    const self = `${added.kind} ${JSON.stringify(id)}`;
    return reason.startsWith(self) ? `a new ${added.noun} here${reason.slice(self.length)}` : reason;
  }
  const ends = lineEnds(action, field, reason);
  if (ends !== null) return `${subjectOf(action, ends.name)}: ${ends.reason}`;
  const part = oneBadComponent(action, field);
  if (part !== null)
    return `${subjectOf(action, FIELD_NAMES[`${field}[${part}]`] ?? field)}: ${narrowed(reason)}`;
  return `${subjectOf(action, FIELD_NAMES[field] ?? field)}: ${reason}`;
}

/** A line's end and the other one, as the Lines table's cells name them. */
const END_CELLS: Record<string, { name: string; other: string }> = {
  p1: { name: "x1, y1", other: "x2, y2" },
  p2: { name: "x2, y2", other: "x1, y1" },
};

/**
 * A line's end `field` refused for its distance to the other end (engine: "must differ from p1 (got [x, y])",
 * "must differ from p1 and p2 of the line", "must be at least … from p1 … in x or y"), in the
 * table's terms; null for any other refusal.
 */
function lineEnds(action: Action, field: string, reason: string): { name: string; reason: string } | null {
  const cells = END_CELLS[field];
  if (cells === undefined || (action.type !== "addLine" && action.type !== "updateLine")) return null;
  const m = /^(must differ from|must be at least \S+ from) p[12](?: and p[12] of the line)?(.*)$/.exec(
    reason,
  );
  if (m === null) return null;
  if (m[1] !== "must differ from") return { name: cells.name, reason: `${m[1]} ${cells.other}${m[2]}` };
  // the engine's "(got [x, y])" is the end's two cells, written as the cells show them
  const got = /^ \(got \[([^\]]*)\]\)$/.exec(m[2] ?? "");
  return {
    name: cells.name,
    reason: `${m[1]} ${cells.other}${got ? ` (got ${got[1]}): a line needs two different ends` : `${m[2]} (a line needs two different ends)`}`,
  };
}

/** The engine's reason for a vector refused whole, said of the one component at fault. */
const WHOLE_VECTOR = "must be an array of two finite numbers";
const narrowed = (reason: string): string => (reason === WHOLE_VECTOR ? "must be a finite number" : reason);

/** The index of the one component of the action's vector `field` that is not finite, or null. */
function oneBadComponent(action: Action, field: string): 0 | 1 | null {
  const v = (action as unknown as Record<string, unknown>)[field];
  if (!Array.isArray(v) || v.length !== 2) return null;
  const bad = v.map((x) => !(typeof x === "number" && Number.isFinite(x)));
  return bad[0] && !bad[1] ? 0 : bad[1] && !bad[0] ? 1 : null;
}

/** "A vx" for a field of object A, "g" for a global, "new disc r" for a field of an added disc. */
function subjectOf(action: Action, name: string): string {
  const added = NEW_OBJECT[action.type];
  const id = "id" in action ? action.id : null;
  return added !== undefined ? `new ${added.noun} ${name}` : id === null ? name : `${id} ${name}`;
}
