/**
 * checkAction(raw, path): validates one action's fields (types, ranges, known type and keys, and the
 * World's magnitude limits: magnitudes.ts) and
 * returns it normalized (addBody gets mu 0 and v [0, 0] when absent; keys in canonical order).
 * Checks that need the scene's state (ids that exist, overlaps) are in sceneRules.ts.
 * ACTION_FIELDS gives the canonical key order used by serializeScene; ACTION_TYPES (frozen) the
 * type names in that order.
 */
import { beyondTimeMax, timeLimitReason } from "../sim/timeLimit.js";
import { SceneError } from "./errors.js";
import {
  count,
  finite,
  id,
  isObject,
  join,
  lineKind,
  mass,
  nonNegative,
  type Obj,
  onlyKeys,
  positive,
  refuse,
  vec2,
} from "./fields.js";
import { checkActionMagnitudes, lineDirection } from "./magnitudes.js";
import { type Action, type ActionType, SCENE_DEFAULTS, type Vec2 } from "./types.js";

type Reader = (o: Obj, key: string, path: string) => unknown;
/** [key, reader, required] */
type FieldSpec = readonly [string, Reader, boolean];

const ID: FieldSpec = ["id", id, true];

/** Per action type, its own fields in canonical order (after time and type, before until). */
export const ACTION_FIELDS: Readonly<Record<ActionType, readonly FieldSpec[]>> = {
  addBody: [
    ID,
    ["x", finite, true],
    ["y", finite, true],
    ["r", positive, true],
    ["m", mass, true],
    ["mu", nonNegative, false],
    ["v", vec2, false],
  ],
  giveVelocity: [ID, ["v", vec2, true]],
  updateBody: [
    ID,
    ["x", finite, false],
    ["y", finite, false],
    ["v", vec2, false],
    ["r", positive, false],
    ["m", mass, false],
    ["mu", nonNegative, false],
  ],
  removeBody: [ID],
  addLine: [ID, ["p1", vec2, true], ["p2", vec2, true], ["kind", lineKind, true]],
  updateLine: [ID, ["p1", vec2, false], ["p2", vec2, false], ["kind", lineKind, false]],
  removeLine: [ID],
  addPoint: [ID, ["p", vec2, true]],
  updatePoint: [ID, ["p", vec2, true]],
  removePoint: [ID],
  setGlobal: [
    ["g", nonNegative, false],
    ["gravity", vec2, false],
  ],
};

/** The type names of all actions ("addBody", "giveVelocity", ..., "setGlobal"), in the format's
 *  order. Frozen: a caller cannot change the list the error messages quote (push or sort throw a
 *  TypeError); copy it (`[...ACTION_TYPES]`) to edit. */
export const ACTION_TYPES: readonly ActionType[] = Object.freeze(Object.keys(ACTION_FIELDS) as ActionType[]);

function checkUntil(raw: unknown, path: string): { time?: number; events?: number } {
  if (!isObject(raw)) throw refuse(path, "must be an object with optional time and events", raw);
  onlyKeys(raw, ["time", "events"], path);
  const u: { time?: number; events?: number } = {};
  if (raw.time !== undefined) u.time = nonNegative(raw, "time", path);
  if (raw.events !== undefined) u.events = count(raw, "events", path);
  return u;
}

/** Validates and normalizes one action (see the header). Throws SceneError naming the field under
 *  `path` (default "action": `action.r`). */
export function checkAction(raw: unknown, path = "action"): Action {
  if (!isObject(raw)) throw refuse(path, "must be an object", raw);
  const type = raw.type;
  if (type === undefined) throw new SceneError(join(path, "type"), "is required");
  if (typeof type !== "string" || !Object.hasOwn(ACTION_FIELDS, type))
    throw new SceneError(
      join(path, "type"),
      `unknown action type ${JSON.stringify(type)} (known: ${ACTION_TYPES.join(", ")})`,
    );
  const specs = ACTION_FIELDS[type as ActionType];
  onlyKeys(raw, ["time", "type", "until", ...specs.map((s) => s[0])], path);
  const out: Obj = { time: nonNegative(raw, "time", path), type };
  const defaults: Obj = type === "addBody" ? { mu: SCENE_DEFAULTS.mu, v: [...SCENE_DEFAULTS.v] } : {};
  for (const [key, read, req] of specs) {
    if (req || raw[key] !== undefined) out[key] = read(raw, key, path);
    else if (key in defaults) out[key] = defaults[key]; // in place, so keys stay in canonical order
  }
  if (type === "addLine") {
    const p1 = out.p1 as readonly number[];
    const p2 = out.p2 as readonly number[];
    lineDirection(join(path, "p2"), p1 as Vec2, p2 as Vec2, "p1");
  }
  if (raw.until !== undefined) out.until = checkUntil(raw.until, join(path, "until"));
  untilReach(out as unknown as Action, path);
  checkActionMagnitudes(out as unknown as Action, path);
  return out as unknown as Action;
}

/** An action's until.time reaching past TIME_MAX from its time: SceneError naming it (sim/timeLimit.ts). */
function untilReach(a: Action, path: string): void {
  const time = a.until?.time;
  if (time === undefined) return;
  const reached = a.time + time;
  if (beyondTimeMax(reached, a.time))
    throw new SceneError(
      join(path, "until.time"),
      timeLimitReason(time, reached, `the action's time ${a.time}`, UNTIL_NO_LIMIT),
    );
}

/** What an action's until.time beyond TIME_MAX's refusal suggests. */
const UNTIL_NO_LIMIT = "for no time limit leave it out, and compute past TIME_MAX by events (until.events)";
