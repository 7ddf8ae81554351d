/**
 * Runs a stress scene (bench/stress/cases.mjs) in the World and measures the engine's invariants:
 * worst overlap at sampled instants (all pairs and disc–wall, relative to the contact distance) and
 * at every disc–disc event (|distance − R| / R), bodies outside the box, kinetic-energy and momentum
 * errors. Pure measurement: the tests decide the thresholds.
 */
import type { StressScene } from "../../bench/stress/cases.mjs";
import { World, type WorldEvent } from "../../packages/engine/src/index.js";

export interface RunReport {
  events: number;
  bodyBody: number;
  worstOverlap: number;
  contactError: number;
  escaped: number;
  energyError: number;
  momentumError: number;
  firstEventTime: number;
  pairEvents: Map<string, number>;
}

export function buildWorld(scene: StressScene): World {
  const w = new World({ g: scene.g, gravity: scene.gravity });
  for (const l of scene.walls) w.addLine(l.id, l.p1, l.p2, l.kind);
  for (const b of scene.bodies)
    w.addBody(b.id, { x: b.x, y: b.y, r: b.r, m: b.m, mu: b.mu, vx: b.vx, vy: b.vy });
  return w;
}

function overlapNow(w: World, scene: StressScene): number {
  const s = scene.bodies.map((b) => w.body(b.id));
  let worst = 0;
  for (let i = 0; i < s.length; i++) {
    const a = s[i]!;
    for (let j = i + 1; j < s.length; j++) {
      const b = s[j]!;
      const R = a.r + b.r;
      const d = Math.hypot(a.x - b.x, a.y - b.y);
      if (d < R) worst = Math.max(worst, (R - d) / R);
    }
    for (const l of scene.walls) {
      const dist = (a.x - l.p1[0]) * l.inside[0] + (a.y - l.p1[1]) * l.inside[1];
      if (dist < a.r) worst = Math.max(worst, (a.r - dist) / a.r);
    }
  }
  return worst;
}

function outside(w: World, scene: StressScene): number {
  const box = scene.box;
  if (!box) return 0;
  let n = 0;
  for (const b of scene.bodies) {
    const s = w.body(b.id);
    if (!(s.x >= box.x0 && s.x <= box.x1 && s.y >= box.y0 && s.y <= box.y1)) n++;
  }
  return n;
}

function totals(w: World, scene: StressScene): { e: number; px: number; py: number; p: number } {
  let e = 0;
  let px = 0;
  let py = 0;
  let p = 0;
  for (const b of scene.bodies) {
    const s = w.body(b.id);
    e += 0.5 * s.m * (s.vx * s.vx + s.vy * s.vy);
    px += s.m * s.vx;
    py += s.m * s.vy;
    p += s.m * Math.hypot(s.vx, s.vy);
  }
  return { e, px, py, p };
}

export function runChecked(
  scene: StressScene,
  samples: number,
  maxEvents = Number.POSITIVE_INFINITY,
): RunReport {
  const w = buildWorld(scene);
  const radius = new Map(scene.bodies.map((b) => [b.id, b.r]));
  const t0 = totals(w, scene);
  const rep: RunReport = {
    events: 0,
    bodyBody: 0,
    worstOverlap: 0,
    contactError: 0,
    escaped: 0,
    energyError: 0,
    momentumError: 0,
    firstEventTime: Number.POSITIVE_INFINITY,
    pairEvents: new Map(),
  };
  const onEvent = (e: WorldEvent): void => {
    rep.firstEventTime = Math.min(rep.firstEventTime, e.time);
    if (e.kind !== "bodyBody" || e.b === null) return;
    rep.bodyBody++;
    const key = [e.a, e.b].sort().join("+");
    rep.pairEvents.set(key, (rep.pairEvents.get(key) ?? 0) + 1);
    const a = w.body(e.a, e.time);
    const b = w.body(e.b, e.time);
    const R = (radius.get(e.a) ?? 0) + (radius.get(e.b) ?? 0);
    rep.contactError = Math.max(rep.contactError, Math.abs(Math.hypot(a.x - b.x, a.y - b.y) - R) / R);
  };
  for (let k = 1; k <= samples && rep.events < maxEvents; k++) {
    rep.events += w.advance(
      { untilTime: (scene.span * k) / samples, maxEvents: maxEvents - rep.events },
      onEvent,
    ).events;
    rep.worstOverlap = Math.max(rep.worstOverlap, overlapNow(w, scene));
    rep.escaped = Math.max(rep.escaped, outside(w, scene));
  }
  const t1 = totals(w, scene);
  rep.energyError = t0.e > 0 ? Math.abs(t1.e - t0.e) / t0.e : 0;
  // momentum is not conserved where walls push; callers use it only for wall-free scenes
  rep.momentumError = t0.p > 0 ? Math.hypot(t1.px - t0.px, t1.py - t0.py) / t0.p : 0;
  return rep;
}
