/**
 * applyToWorld(world, action, path): performs one (already validated) action on a World at its
 * current time. A ChapgameError from the World becomes a SceneError under the action's path.
 * touchedBodies(action): which bodies' motions the action restarts ("all" for setGlobal).
 */
import { SceneError } from "../scene/errors.js";
import type { Action, LineKind, Vec2 } from "../scene/types.js";
import { ChapgameError } from "../sim/errors.js";
import type { BodyPatch } from "../sim/types.js";
import type { World } from "../sim/world.js";

function perform(w: World, a: Action): void {
  switch (a.type) {
    case "addBody":
      w.addBody(a.id, {
        x: a.x,
        y: a.y,
        r: a.r,
        m: a.m,
        mu: a.mu ?? 0,
        vx: a.v?.[0] ?? 0,
        vy: a.v?.[1] ?? 0,
      });
      return;
    case "giveVelocity":
      w.updateBody(a.id, { vx: a.v[0], vy: a.v[1] });
      return;
    case "updateBody": {
      const p: BodyPatch = {};
      if (a.x !== undefined) p.x = a.x;
      if (a.y !== undefined) p.y = a.y;
      if (a.v !== undefined) {
        p.vx = a.v[0];
        p.vy = a.v[1];
      }
      if (a.r !== undefined) p.r = a.r;
      if (a.m !== undefined) p.m = a.m;
      if (a.mu !== undefined) p.mu = a.mu;
      w.updateBody(a.id, p);
      return;
    }
    case "removeBody":
      w.removeBody(a.id);
      return;
    case "addLine":
      w.addLine(a.id, a.p1, a.p2, a.kind);
      return;
    case "updateLine": {
      const p: { p1?: Vec2; p2?: Vec2; kind?: LineKind } = {};
      if (a.p1 !== undefined) p.p1 = a.p1;
      if (a.p2 !== undefined) p.p2 = a.p2;
      if (a.kind !== undefined) p.kind = a.kind;
      w.updateLine(a.id, p);
      return;
    }
    case "removeLine":
      w.removeLine(a.id);
      return;
    case "addPoint":
      w.addPoint(a.id, a.p);
      return;
    case "updatePoint":
      w.updatePoint(a.id, a.p);
      return;
    case "removePoint":
      w.removePoint(a.id);
      return;
    case "setGlobal": {
      const p: { g?: number; gravity?: Vec2 } = {};
      if (a.g !== undefined) p.g = a.g;
      if (a.gravity !== undefined) p.gravity = a.gravity;
      w.setGlobal(p);
      return;
    }
  }
}

export function applyToWorld(w: World, a: Action, path: string): void {
  try {
    perform(w, a);
  } catch (e) {
    if (e instanceof ChapgameError && !(e instanceof SceneError))
      throw new SceneError(`${path}.${e.path}`, e.reason);
    throw e;
  }
}

/** The id of the body whose motion the action restarts, "all", or null. */
export function touchedBodies(a: Action): string | "all" | null {
  if (a.type === "addBody" || a.type === "giveVelocity" || a.type === "updateBody") return a.id;
  if (a.type === "setGlobal") return "all";
  return null;
}
