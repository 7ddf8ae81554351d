/**
 * chapgame adapter for the side-by-side scenes: builds a World from the engine-neutral scene and
 * advances it to the end of the span in one call (timed), or sample by sample (for metrics: the
 * same sampling instants as the peers). Exact-time: there is no step size.
 */
import { nowNs } from "../lib/timing.mjs";
import { emptyState, escaped, finalError, kineticEnergy, worstOverlap } from "./metrics.mjs";

export function buildWorld(engine, scene, worldOptions = {}) {
  const world = new engine.World({ g: scene.g, gravity: scene.gravity, ...worldOptions });
  for (const w of scene.walls) world.addLine(w.id, w.p1, w.p2, w.kind);
  for (const p of scene.points ?? []) world.addPoint(p.id, p.p);
  for (const b of scene.bodies) {
    world.addBody(b.id, { x: b.x, y: b.y, r: b.r, m: b.m, mu: b.mu, vx: b.vx, vy: b.vy });
  }
  return world;
}

/** Copy every body's state at the world's time into the metrics arrays `s`. */
export function read(world, scene, s) {
  scene.bodies.forEach((b, i) => {
    const st = world.body(b.id);
    s.x[i] = st.x;
    s.y[i] = st.y;
    s.vx[i] = st.vx;
    s.vy[i] = st.vy;
  });
  return s;
}

const collisionsOf = (c) => c.bodyBody + c.bodyLine + c.bodyPoint;

export function runChapgame(engine, scene, { sampleHz = 240, withMetrics = false, worldOptions = {} } = {}) {
  const world = buildWorld(engine, scene, worldOptions);
  if (!withMetrics) {
    const t0 = nowNs();
    const r = world.advance({ untilTime: scene.span });
    const ns = nowNs() - t0;
    return { ns, events: r.events, collisions: collisionsOf(world.counts), metrics: null };
  }
  const n = scene.bodies.length;
  const s = emptyState(n);
  const ke0 = kineticEnergy(scene, read(world, scene, s));
  const samples = Math.round(scene.span * sampleHz);
  let worst = 0;
  let maxEscaped = 0;
  let events = 0;
  let ns = 0;
  for (let k = 1; k <= samples; k++) {
    const a = nowNs();
    events += world.advance({ untilTime: k === samples ? scene.span : k / sampleHz }).events;
    ns += nowNs() - a;
    read(world, scene, s);
    worst = Math.max(worst, worstOverlap(scene, s));
    maxEscaped = Math.max(maxEscaped, escaped(scene, s));
  }
  const ke1 = kineticEnergy(scene, s);
  return {
    ns, // the advance calls only (sampling excluded), as for the peers' step()
    events,
    collisions: collisionsOf(world.counts),
    metrics: {
      energyError: ke0 > 0 ? (ke1 - ke0) / ke0 : null,
      kineticEnergyEnd: ke1,
      worstOverlap: worst,
      escaped: maxEscaped,
      escapedAtEnd: escaped(scene, s),
      collisions: collisionsOf(world.counts),
      finalError: finalError(scene, s),
    },
  };
}
