/**
 * The message confirming an edit of an object (a body, line or point) or of the globals: what it set,
 * at what time, and what Undo restores, in the style of the adds' and deletes' messages ("Added disc
 * "b3" at (50, 0), radius 20.", "Deleted body "b3" at t = 2 s (Undo brings it back)."). A move, a
 * velocity drag, a cue strike and a table cell said nothing, while an add or a delete did: the
 * author saw no value and no way back. Contract: `confirmEdit(action, before, how)` takes the edit's
 * action (updateBody, giveVelocity, updateLine, updatePoint or setGlobal, as sent: before any merge
 * into the action before it) and the object's state at the edit's time before it (`stateBefore`, from
 * the frame at that time; null when the frame does not hold the object: Undo is then said without
 * values); `how` "strike" says a cue strike. A body's x and y together are a move ("Moved … to
 * (x, y)"), as a point's p; a velocity is "velocity (vx, vy)"; other fields are "field = value"
 * (μ for mu, ∞ for an infinite mass). Pure.
 */
import type { Action, Vec2 } from "../engineTypes";
import type { Frame } from "../remote/protocol";
import { F_M, F_MU, F_R, F_VX, F_VY, F_X, F_Y, FRAME_STRIDE } from "../remote/protocol";

/** The actions an edit of a field sends. */
export type FieldEdit = Extract<
  Action,
  { type: "updateBody" | "giveVelocity" | "updateLine" | "updatePoint" | "setGlobal" }
>;

/** An object's fields as an edit names them (a body's x, y, v, r, m, mu; a line's p1, p2, kind; …). */
export type FieldValues = Record<string, number | Vec2 | string>;

/** "1.23457", "∞", "-2": a number as messages write it (6 significant digits). */
function num(x: number): string {
  if (x === Number.POSITIVE_INFINITY) return "∞";
  if (x === Number.NEGATIVE_INFINITY) return "-∞";
  return String(Number(x.toPrecision(6)));
}

function value(v: number | Vec2 | string): string {
  if (typeof v === "string") return v;
  if (typeof v === "number") return num(v);
  return `(${num(v[0])}, ${num(v[1])})`;
}

const NAMES: Record<string, string> = { mu: "μ", v: "velocity" };

/** "r = 5, velocity (2, -1)": the fields as set. */
function fieldList(fields: FieldValues): string {
  return Object.entries(fields)
    .map(([k, v]) => (k === "v" ? `velocity ${value(v)}` : `${NAMES[k] ?? k} = ${value(v)}`))
    .join(", ");
}

/** The fields the action sets, without its type, time and id. */
function setFields(action: FieldEdit): FieldValues {
  const out: FieldValues = {};
  for (const [k, v] of Object.entries(action))
    if (k !== "type" && k !== "time" && k !== "id" && v !== undefined) out[k] = v as FieldValues[string];
  return out;
}

/** What the message calls the edited object: `disc "b3"`, `ray "l1"`, `point "p1"` (null: the globals). */
function objectName(action: FieldEdit, before: FieldValues | null): string | null {
  if (action.type === "setGlobal") return null;
  const kind =
    action.type === "updateLine"
      ? typeof before?.kind === "string"
        ? before.kind
        : "line"
      : action.type === "updatePoint"
        ? "point"
        : "disc";
  return `${kind} ${JSON.stringify(action.id)}`;
}

export function confirmEdit(action: FieldEdit, before: FieldValues | null, how?: "strike"): string {
  const fields = setFields(action);
  const keys = Object.keys(fields).sort().join();
  const name = objectName(action, before);
  const at = `at t = ${num(action.time)} s`;
  const old = (k: string) => (before !== null && k in before ? before[k]! : null);
  const unchanged = Object.keys(fields).every((k) => {
    const o = old(k);
    return o !== null && value(o) === value(fields[k]!);
  });
  const restores = (what: string | null) =>
    unchanged
      ? "(unchanged: Undo takes the action back)"
      : what === null
        ? "(Undo takes it back)"
        : `(Undo restores ${what})`;
  const oldFields = (ks: string[]): string | null => {
    const o: FieldValues = {};
    for (const k of ks) {
      const v = old(k);
      if (v === null) return null;
      o[k] = v;
    }
    return fieldList(o);
  };

  // a place: a body's x and y together (a drag of the Move tool), a point's p
  const place: Vec2 | null =
    keys === "x,y" ? [fields.x as number, fields.y as number] : keys === "p" ? (fields.p as Vec2) : null;
  if (place !== null && name !== null) {
    const x = old("x");
    const y = old("y");
    const from = keys === "p" ? old("p") : x === null || y === null ? null : ([x, y] as Vec2);
    const undo = unchanged || from === null ? restores(null) : `(Undo moves it back to ${value(from)})`;
    return `Moved ${name} to ${value(place)} ${at} ${undo}.`;
  }
  if (keys === "v" && name !== null) {
    const v = value(fields.v!);
    const o = old("v");
    const undo = restores(o === null ? null : value(o));
    return how === "strike"
      ? `Struck ${name}: velocity ${v} ${at} ${undo}.`
      : `Set ${name}'s velocity to ${v} ${at} ${undo}.`;
  }
  const subject = name === null ? "" : `${name} `;
  return `Set ${subject}${fieldList(fields)} ${at} ${restores(oldFields(Object.keys(fields)))}.`;
}

/** The edited object's fields at the frame's time (before the edit), or null when it has none. */
export function stateBefore(frame: Frame, action: FieldEdit): FieldValues | null {
  if (action.type === "setGlobal") return { g: frame.g, gravity: frame.gravity };
  if (action.type === "updateLine") {
    const l = frame.lines.find((x) => x.id === action.id);
    return l ? { p1: l.p1, p2: l.p2, kind: l.kind } : null;
  }
  if (action.type === "updatePoint") {
    const p = frame.points.find((x) => x.id === action.id);
    return p ? { p: p.p } : null;
  }
  const i = frame.ids.indexOf(action.id);
  if (i < 0) return null;
  const d = (f: number) => frame.data[i * FRAME_STRIDE + f]!;
  return { x: d(F_X), y: d(F_Y), v: [d(F_VX), d(F_VY)], r: d(F_R), m: d(F_M), mu: d(F_MU) };
}
