/**
 * The words of the Zeno reports (zenoWatch.ts, pushWatch.ts, trapWatch.ts, lineWatch.ts): who is
 * caught and what to do, from what each watch detects. Each report names the bodies and the
 * obstacles involved (ids quoted as in JSON, the first NAMES_SHOWN of a kind and how many more) and
 * ends in ": to go on, …", a change of the scene that removes the state the watch saw:
 *
 * - many events at one instant (bodies pressed together, jammed between immovable bodies or
 *   obstacles, or resting on one): place them a little apart, or give an immovable one a finite
 *   mass (a finite exchange at one instant is no Zeno state);
 * - events converging on a finite time while an immovable body moves, or a pocket or a row proven
 *   to close (a crush): stop the immovable body before it closes, give it a finite mass, or remove
 *   a side it crushes against;
 * - a body stopping again and again where it was set in motion (a sustained push against
 *   friction): take its friction away, or part it from the body pressing on it.
 */
import { quoteId } from "./refusalText.js";

/** How many ids of one kind a message names before "and N more". */
const NAMES_SHOWN = 10;

/** Who a Zeno state caught: its bodies and the lines and points they press against. */
export interface ZenoCulprits {
  /** The event the watch stopped at, as "\"a\" and line \"w\"". */
  readonly last: string;
  /** Bodies caught, in id order. */
  readonly bodies: readonly string[];
  /** The immovable ones among them (for the advice). */
  readonly immovable: readonly string[];
  /** The moving immovable bodies among them: what feeds the energy a crush needs. */
  readonly movers: readonly string[];
  /** Lines and points they touch, each as the message names it (`line "w"`), in id order. */
  readonly obstacles: readonly string[];
  /** The ids of those obstacles, in the same order. */
  readonly obstacleIds: readonly string[];
  /** Whether the search stopped at its bound (zenoCaught.ts CAUGHT_MAX): more bodies may be caught. */
  readonly bodiesBounded?: boolean;
}

/** `"a", "b" and "c"`, the first NAMES_SHOWN and how many more ("at least" when `bounded`: the
 *  list itself stopped at a bound, so there may be more than it holds). */
export function listed(quoted: readonly string[], bounded = false): string {
  const shown = quoted.slice(0, NAMES_SHOWN);
  const more = quoted.length - shown.length;
  if (more > 0) return `${shown.join(", ")} and ${bounded ? "at least " : ""}${more} more`;
  if (shown.length <= 1) return shown.join("");
  return `${shown.slice(0, -1).join(", ")} and ${shown[shown.length - 1] as string}`;
}

/** `body "a"` or `bodies "a", "b" and "c"`; `prefix` qualifies them ("immovable"). */
export function bodiesNamed(ids: readonly string[], prefix = "", bounded = false): string {
  const kind = ids.length === 1 ? "body" : "bodies";
  return `${prefix === "" ? "" : `${prefix} `}${kind} ${listed(ids.map(quoteId), bounded)}`;
}

/** The report's ids: the bodies, then the obstacles. */
export function culpritIds(c: ZenoCulprits): string[] {
  return [...c.bodies, ...c.obstacleIds];
}

/** " among bodies … and line …" (empty when nobody is known). */
function among(c: ZenoCulprits): string {
  if (c.bodies.length === 0) return "";
  const against = c.obstacles.length === 0 ? "" : ` against ${listed(c.obstacles)}`;
  return ` among ${bodiesNamed(c.bodies, "", c.bodiesBounded === true)}${against}`;
}

/** The same-instant report (zenoWatch.ts): `count` events at `time`. */
export function sameInstantReport(count: number, time: number, c: ZenoCulprits | undefined): string {
  const who = c === undefined ? "" : `${among(c)} (the last: ${c.last})`;
  const state = `more than ${count} events at the same instant t=${time}${who}: a Zeno state (resting contact, two discs pressed together, or an inelastic collapse) that the exact model cannot resolve`;
  if (c === undefined || c.bodies.length === 0) return state;
  const each = c.bodies.length > 1 ? "from each other" : "";
  const walls = c.obstacles.length === 0 ? "" : `from ${listed(c.obstacles)}`;
  const apart = each !== "" && walls !== "" ? `${each} and ${walls}` : each + walls;
  const finite =
    c.immovable.length === 0 ? "" : `, or give the ${bodiesNamed(c.immovable, "immovable")} a finite mass`;
  return `${state}: to go on, place ${bodiesNamed(c.bodies, "", c.bodiesBounded === true)} a little apart ${apart} so that they do not touch at t=${time}${finite}`;
}

/** The advice of a crush by the moving immovable `crushers` against `sides` (named), before `by`. */
export function crushAdvice(
  crushers: readonly string[],
  sides: readonly string[],
  by: number | null,
): string {
  const who = bodiesNamed(crushers, "immovable");
  const when = by === null ? "before it closes" : `before t=${by}`;
  const them = crushers.length === 1 ? "it" : "them";
  if (sides.length === 0)
    return `to go on, stop the ${who} (or turn ${them} away) ${when}, or give ${them} a finite mass`;
  const remove = `remove ${sides.length === 1 ? "" : "one of "}${listed(sides)}`;
  return `to go on, stop the ${who} (or turn ${them} away) ${when}, give ${them} a finite mass, or ${remove}`;
}

/** The converging windows' report (zenoWatch.ts): windows of `perWindow` events. */
export function convergingReport(
  perWindow: number,
  progress: number,
  time: number,
  runStart: number,
  c: ZenoCulprits | undefined,
): string {
  const state = `${perWindow} events in ${progress} (to t=${time}), each window of ${perWindow} events shorter than the one before since t=${runStart}${c === undefined ? "" : among(c)}: events accumulate at a finite time (a Zeno state, e.g. a disc crushed by an immovable body), which the exact model cannot pass`;
  if (c === undefined || c.movers.length === 0) return state;
  return `${state}: ${crushAdvice(c.movers, c.obstacles, null)}`;
}

/** The push watch's report (pushWatch.ts): body `id` stopped `n` times unmoved. */
export function pushReport(id: string, n: number, time: number): string {
  return `body ${quoteId(id)} stopped ${n} times in a row where it had been set in motion, not moving by one rounding unit (to t=${time}): a disc pushed along against friction by another (a sustained push), which the model of elastic impulses and sliding friction resolves only by ever more collisions: to go on, give body ${quoteId(id)} no friction (mu: 0, or the friction field g: 0), or place it a little apart from the disc pressing on it`;
}
