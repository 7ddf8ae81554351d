/**
 * Who a Zeno state caught, for its report (zenoAdvice.ts), found only when the report is made (never
 * on the hot path) and from the World's state alone, so that a copy or a World rebuilt from a
 * keyframe names the same ones: from the event the watch stopped at (its bodies and its line or
 * point), every body whose motion changed at or after `since` (the instant, or the start of the last
 * window of converging events) and that touches one already caught, within what a contact allows
 * (contactResolved: CONTACT_UNRESOLVED_FRACTION of the contact distance), joins them, up to
 * CAUGHT_MAX bodies (a report then says "at least" of the bodies it does not list: its ids hold
 * those CAUGHT_MAX); then every line and point that a finite body caught touches the same way.
 * A body at rest far away, or one that has not moved since, is not named. An edit changes a motion
 * too, so a body added or set at that instant touching one caught is named though it took part in no
 * event: the World keeps no per-body record of events (one would cost every event a write), and a
 * record of edits would have to travel in the Timeline's keyframes for a World rebuilt from one to
 * name the same bodies.
 */
import { contactResolved } from "../physics/resolution.js";
import type { BodyStore } from "./bodyStore.js";
import type { Line, Point } from "./obstacles.js";
import { coreDistance } from "./pocketGeometry.js";
import { quoteId } from "./refusalText.js";
import { fill } from "./trapSides.js";
import type { ZenoCulprits } from "./zenoAdvice.js";

/** At most this many bodies are gathered (the search is quadratic in them; the report names 10). */
const CAUGHT_MAX = 64;

/** What the search reads of the World, at its current time. */
export interface CaughtView {
  readonly store: BodyStore;
  readonly lines: readonly Line[];
  readonly points: readonly Point[];
  x(s: number): number;
  y(s: number): number;
  moving(s: number): boolean;
}

/** The event the watch stopped at: its slots, and its line or point (null for none). */
export interface CaughtSeed {
  readonly slots: readonly number[];
  readonly obstacle: { readonly line: boolean; readonly id: string } | null;
  readonly last: string;
}

function touches(v: CaughtView, s: number, q: number): boolean {
  const b = v.store;
  const dx = v.x(q) - v.x(s);
  const dy = v.y(q) - v.y(s);
  return contactResolved(Math.sqrt(dx * dx + dy * dy), (b.r[s] as number) + (b.r[q] as number));
}

/** The culprits of a Zeno state met at the event `seed` (see the header). */
export function caught(v: CaughtView, seed: CaughtSeed, since: number): ZenoCulprits {
  const b = v.store;
  const slots = [...seed.slots];
  for (let k = 0; k < slots.length && slots.length < CAUGHT_MAX; k++) {
    const s = slots[k] as number;
    for (let q = 0; q < b.slotCount && slots.length < CAUGHT_MAX; q++)
      if (
        b.ids[q] !== undefined &&
        (b.mot[q * 8] as number) >= since &&
        !slots.includes(q) &&
        touches(v, s, q)
      )
        slots.push(q);
  }
  const lines = new Set<string>();
  const points = new Set<string>();
  if (seed.obstacle !== null) (seed.obstacle.line ? lines : points).add(seed.obstacle.id);
  for (const s of slots) {
    if (b.m[s] === Number.POSITIVE_INFINITY) continue;
    const x = v.x(s);
    const y = v.y(s);
    const r = b.r[s] as number;
    for (const l of v.lines)
      if (contactResolved(coreDistance(fill(l.kind, l.x1, l.y1, l.x2, l.y2, 0), x, y), r)) lines.add(l.id);
    for (const p of v.points)
      if (contactResolved(coreDistance(fill("point", p.x, p.y, p.x, p.y, 0), x, y), r)) points.add(p.id);
  }
  const byId = (a: string, c: string) => (a < c ? -1 : a > c ? 1 : 0);
  const ids = (of: readonly number[]) => of.map((s) => b.ids[s] as string).sort(byId);
  const immovable = slots.filter((s) => b.m[s] === Number.POSITIVE_INFINITY);
  const lineIds = [...lines].sort(byId);
  const pointIds = [...points].sort(byId);
  return {
    last: seed.last,
    bodies: ids(slots),
    immovable: ids(immovable),
    movers: ids(immovable.filter((s) => v.moving(s))),
    obstacles: [
      ...lineIds.map((id) => `line ${quoteId(id)}`),
      ...pointIds.map((id) => `point ${quoteId(id)}`),
    ],
    obstacleIds: [...lineIds, ...pointIds],
    bodiesBounded: slots.length >= CAUGHT_MAX,
  };
}
