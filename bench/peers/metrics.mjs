/**
 * Engine-agnostic metrics on a sampled state: kinetic energy, worst overlap (disc–disc relative to
 * the contact distance r1 + r2, disc–wall relative to r), escaped bodies, and distance from an
 * exact final state. A state is { x, y, vx, vy } arrays in scene body order.
 */

export function kineticEnergy(scene, s) {
  let e = 0;
  scene.bodies.forEach((b, i) => {
    e += 0.5 * b.m * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
  });
  return e;
}

/** Worst relative overlap of any disc pair (sweep along x) or disc and wall; 0 when none. */
export function worstOverlap(scene, s) {
  const n = scene.bodies.length;
  let rmax = 0;
  for (const b of scene.bodies) rmax = Math.max(rmax, b.r);
  const order = Array.from({ length: n }, (_, i) => i).sort((a, b) => s.x[a] - s.x[b]);
  let worst = 0;
  for (let k = 0; k < n; k++) {
    const i = order[k];
    const bi = scene.bodies[i];
    for (let q = k + 1; q < n; q++) {
      const j = order[q];
      if (s.x[j] - s.x[i] > bi.r + rmax) break;
      const rr = bi.r + scene.bodies[j].r;
      const dx = s.x[j] - s.x[i];
      const dy = s.y[j] - s.y[i];
      const d2 = dx * dx + dy * dy;
      if (d2 < rr * rr) worst = Math.max(worst, (rr - Math.sqrt(d2)) / rr);
    }
  }
  for (const w of scene.walls) {
    const [ax, ay] = w.p1;
    const len = Math.hypot(w.p2[0] - ax, w.p2[1] - ay);
    const ux = (w.p2[0] - ax) / len;
    const uy = (w.p2[1] - ay) / len;
    const [nx, ny] = w.inside;
    for (let i = 0; i < n; i++) {
      const r = scene.bodies[i].r;
      const px = s.x[i] - ax;
      const py = s.y[i] - ay;
      const along = px * ux + py * uy;
      if (w.kind === "segment" && (along < 0 || along > len)) continue;
      const dist = px * nx + py * ny;
      if (dist < r && dist > -r) worst = Math.max(worst, (r - dist) / r);
    }
  }
  return worst;
}

/** Bodies outside the scene's box, or the scene's own escape test. */
export function escaped(scene, s) {
  if (scene.escaped) {
    const bodies = scene.bodies.map((_, i) => ({ x: s.x[i], y: s.y[i] }));
    return scene.escaped(bodies);
  }
  if (!scene.box) return 0;
  const { x0, y0, x1, y1 } = scene.box;
  let c = 0;
  for (let i = 0; i < scene.bodies.length; i++) {
    if (!(s.x[i] >= x0 && s.x[i] <= x1 && s.y[i] >= y0 && s.y[i] <= y1)) c++;
  }
  return c;
}

/** Largest position and velocity distance from the exact final state (null when none is known). */
export function finalError(scene, s) {
  const fin = scene.exact?.final;
  if (!fin) return null;
  let dp = 0;
  let dv = 0;
  fin.forEach((f, i) => {
    dp = Math.max(dp, Math.hypot(s.x[i] - f.x, s.y[i] - f.y));
    dv = Math.max(dv, Math.hypot(s.vx[i] - f.vx, s.vy[i] - f.vy));
  });
  return { position: dp, velocity: dv };
}

export function emptyState(n) {
  return { x: new Float64Array(n), y: new Float64Array(n), vx: new Float64Array(n), vy: new Float64Array(n) };
}
