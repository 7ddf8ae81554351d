// Local timing script for realRoots (not a test, not the benchmark): `npm run build` first, then
// `node packages/engine/src/roots/timing.mjs`. Collision-type quartics |d + u t + w t²/2|² − R² on
// [0, hi] from a fixed pseudo-random stream; reports per-call wall-time percentiles (each call
// timed over 64 repetitions), CPU time per call over the whole pool, the share of calls with roots,
// and a plain bisection baseline (the seed's method) on the same pool. Numbers depend on load: the
// script prints the 1-minute load average beside them.
import { loadavg } from "node:os";
import { evalPoly, realRoots } from "../../dist/roots/index.js";

let state = 987654321;
const rnd = () => {
  state = (state * 1103515245 + 12345) % 2147483648;
  return state / 2147483648;
};
const N = 4096;
const pool = [];
const his = [];
for (let i = 0; i < N; i++) {
  const dx = (rnd() * 2 - 1) * 10;
  const dy = (rnd() * 2 - 1) * 10;
  const ux = (rnd() * 2 - 1) * 5;
  const uy = (rnd() * 2 - 1) * 5;
  const wx = rnd() * 2 - 1;
  const wy = rnd() * 2 - 1;
  const R = 0.5 + rnd() * 2;
  pool.push(
    new Float64Array([
      dx * dx + dy * dy - R * R,
      2 * (dx * ux + dy * uy),
      ux * ux + uy * uy + (dx * wx + dy * wy),
      ux * wx + uy * wy,
      0.25 * (wx * wx + wy * wy),
    ]),
  );
  his.push(rnd() * 10);
}

/** The seed's method, as a baseline: derivative splitting with plain bisection (60 halvings). */
function bisectRoots(c, lo, hi) {
  const n = c.length - 1;
  if (n <= 0) return [];
  if (n === 1) {
    const r = -c[0] / c[1];
    return r >= lo && r <= hi ? [r] : [];
  }
  const d = [];
  for (let i = 1; i <= n; i++) d.push(i * c[i]);
  const pts = [lo, ...bisectRoots(d, lo, hi).filter((x) => x > lo && x < hi), hi];
  const out = [];
  for (let i = 0; i + 1 < pts.length; i++) {
    let a = pts[i];
    let b = pts[i + 1];
    let fa = evalPoly(c, a);
    if (fa === 0) out.push(a);
    if (fa * evalPoly(c, b) >= 0) continue;
    for (let k = 0; k < 60; k++) {
      const m = 0.5 * (a + b);
      const fm = evalPoly(c, m);
      if (fm * fa > 0) {
        a = m;
        fa = fm;
      } else b = m;
    }
    out.push(0.5 * (a + b));
  }
  return out;
}

function perCall(solve, idx = [...pool.keys()]) {
  const t = new Float64Array(idx.length);
  let sink = 0;
  for (let j = 0; j < idx.length; j++) {
    const c = pool[idx[j]];
    const h = his[idx[j]];
    const t0 = process.hrtime.bigint();
    for (let k = 0; k < 64; k++) sink += solve(c, 0, h).length;
    t[j] = Number(process.hrtime.bigint() - t0) / 64;
  }
  t.sort();
  const L = idx.length;
  const q = (f) => t[Math.min(L - 1, Math.floor(L * f))].toFixed(0);
  return { p10: q(0.1), median: q(0.5), p90: q(0.9), p99: q(0.99), sink };
}

function cpuPerCall(solve, idx) {
  const reps = Math.ceil(100000 / idx.length);
  let sink = 0;
  const u0 = process.cpuUsage();
  for (let r = 0; r < reps; r++) for (const i of idx) sink += solve(pool[i], 0, his[i]).length;
  const u = process.cpuUsage(u0);
  return { ns: (((u.user + u.system) * 1000) / (reps * idx.length)).toFixed(0), sink };
}

const all = [...pool.keys()];
const withRoots = all.filter((i) => realRoots(pool[i], 0, his[i]).length > 0);
for (let w = 0; w < 3; w++) {
  cpuPerCall(realRoots, all);
  cpuPerCall(bisectRoots, all);
}
console.log(
  JSON.stringify(
    {
      load1: loadavg()[0],
      calls: N,
      shareWithRoots: withRoots.length / N,
      realRoots: { perCallWallNs: perCall(realRoots), cpuNsAll: cpuPerCall(realRoots, all).ns },
      realRootsWithRoots: {
        perCallWallNs: perCall(realRoots, withRoots),
        cpuNs: cpuPerCall(realRoots, withRoots).ns,
      },
      bisectionBaseline: { perCallWallNs: perCall(bisectRoots), cpuNsAll: cpuPerCall(bisectRoots, all).ns },
    },
    null,
    1,
  ),
);
