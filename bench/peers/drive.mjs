/**
 * Drives one peer adapter over a scene at a fixed step rate. Only step() (and the harness's
 * per-step friction for scenes with friction, which a user of those engines must write too) is
 * timed; sampling for metrics happens between timed steps, at `sampleHz` (or every step if slower).
 * Returns { ns, steps, metrics | null, settings }.
 */
import { nowNs } from "../lib/timing.mjs";
import { emptyState, escaped, finalError, kineticEnergy, worstOverlap } from "./metrics.mjs";

function read(sim, n, s) {
  for (let i = 0; i < n; i++) {
    s.x[i] = sim.x(i);
    s.y[i] = sim.y(i);
    s.vx[i] = sim.vx(i);
    s.vy[i] = sim.vy(i);
  }
  return s;
}

function frictionKick(sim, scene, dt) {
  scene.bodies.forEach((b, i) => {
    if (!(b.mu > 0 && scene.g > 0)) return;
    const vx = sim.vx(i);
    const vy = sim.vy(i);
    const sp = Math.hypot(vx, vy);
    if (sp === 0) return;
    const dec = b.mu * scene.g * dt;
    const k = sp <= dec ? 0 : (sp - dec) / sp;
    sim.setVelocity(i, vx * k, vy * k);
  });
}

export function drivePeer(adapter, scene, { hz, tuned, sampleHz = 240, withMetrics = false }) {
  const sim = adapter.create(scene, { hz, tuned });
  const n = scene.bodies.length;
  const steps = Math.round(scene.span * hz);
  const dt = 1 / hz;
  const friction = scene.g > 0 && scene.bodies.some((b) => b.mu > 0);
  const every = Math.max(1, Math.round(hz / sampleHz));
  const s = emptyState(n);
  let worst = 0;
  let maxEscaped = 0;
  let ke0 = 0;
  if (withMetrics) ke0 = kineticEnergy(scene, read(sim, n, s));
  let ns = 0;
  for (let k = 1; k <= steps; k++) {
    const t0 = nowNs();
    sim.step();
    if (friction) frictionKick(sim, scene, dt);
    ns += nowNs() - t0;
    if (withMetrics && (k % every === 0 || k === steps)) {
      read(sim, n, s);
      worst = Math.max(worst, worstOverlap(scene, s));
      maxEscaped = Math.max(maxEscaped, escaped(scene, s));
    }
  }
  let metrics = null;
  if (withMetrics) {
    read(sim, n, s);
    const ke1 = kineticEnergy(scene, s);
    metrics = {
      energyError: ke0 > 0 ? (ke1 - ke0) / ke0 : null,
      kineticEnergyEnd: ke1,
      worstOverlap: worst,
      escaped: maxEscaped,
      escapedAtEnd: escaped(scene, s),
      collisions: sim.contacts(),
      finalError: finalError(scene, s),
    };
  }
  const settings = sim.settings;
  sim.dispose();
  return { ns, steps, metrics, settings };
}
