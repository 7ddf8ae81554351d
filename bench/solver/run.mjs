/**
 * Section "solver": time per call against error for realRoots (engine), the closed-form
 * Ferrari/Descartes quartic, the same + Newton polishing, and the seed's 1e-6 bisection, on random
 * collision quartics and on hard cases. Errors are ulps to the nearest exact sign change (or exact
 * double root) of the polynomial with the given double coefficients, via the engine's exactPolySign.
 * Errors are measured here; times come from fresh child processes (timing.mjs says why): the median
 * over 3 processes (1 in quick runs), each the median of 9 (5) interleaved passes.
 */
import { median, quantile } from "../lib/timing.mjs";
import { collisionQuartics, hardQuartics } from "./quartics.mjs";
import { methods, timeSolvers } from "./timing.mjs";
import { ulpDistance, ulpsToSignChange } from "./ulps.mjs";

function rootError(sign, c, x, exactRoots) {
  let e = ulpsToSignChange(sign, c, x);
  if (exactRoots) for (const r of exactRoots) e = Math.min(e, ulpDistance(x, r));
  return e;
}

function summarize(errors) {
  const finite = errors.filter(Number.isFinite);
  return {
    roots: errors.length,
    medianUlps: finite.length ? median(finite) : null,
    p99Ulps: finite.length ? quantile(finite, 0.99) : null,
    worstUlps: finite.length ? Math.max(...finite) : null,
    spurious: errors.length - finite.length,
  };
}

export function runSolver({ quick, engine, log }) {
  const sign = engine.exactPolySign;
  if (typeof sign !== "function") throw new Error("exactPolySign missing from the built engine");
  const count = quick ? 300 : 4000;
  const runs = quick ? 5 : 9;
  const { polys, lo, hi } = collisionQuartics(count, 7);
  const ms = methods(engine);
  const random = [];
  const rootsPer = ms.map((m) => polys.map((c) => m.fn(c, lo, hi)));
  const errorsPer = rootsPer.map((list) =>
    list.map((roots, k) => roots.map((x) => rootError(sign, polys[k], x))),
  );
  // Reference count per polynomial: the most roots any method returned near a true sign change.
  const expected = polys.map((_, k) =>
    Math.max(...errorsPer.map((e) => e[k].filter(Number.isFinite).length)),
  );
  const processes = quick ? 1 : 3;
  const timing = timeSolvers({ quick, processes });
  ms.forEach((m, i) => {
    const t = { nsPerCall: timing.random[m.id], runs };
    let missed = 0;
    errorsPer[i].forEach((e, k) => {
      missed += Math.max(0, expected[k] - e.filter(Number.isFinite).length);
    });
    const s = summarize(errorsPer[i].flat());
    random.push({
      id: m.id,
      label: m.label,
      nsPerCall: t.nsPerCall,
      nsPerCallPerProcess: timing.perProcess.map((p) => p.random[m.id]),
      runs: t.runs,
      processes,
      missed,
      ...s,
    });
    log(
      `  solver ${m.id}: ${t.nsPerCall.toFixed(1)} ns/call, median ${s.medianUlps} ulps, worst ${s.worstUlps}, missed ${missed}`,
    );
  });
  const hard = hardQuartics().map((h) => {
    const entry = {
      id: h.id,
      note: h.note,
      coeffs: h.coeffs,
      lo: h.lo,
      hi: h.hi,
      expected: h.expected,
      results: [],
    };
    for (const m of ms) {
      const roots = m.fn(h.coeffs, h.lo, h.hi);
      const errors = roots.map((x) => rootError(sign, h.coeffs, x, h.exactRoots));
      const finite = errors.filter(Number.isFinite);
      entry.results.push({
        id: m.id,
        roots,
        errors: errors.map((e) => (Number.isFinite(e) ? e : null)),
        worstUlps: finite.length ? Math.max(...finite) : null,
        found: roots.length,
      });
    }
    return entry;
  });
  const hardTiming = ms.map((m) => ({ id: m.id, nsPerCall: timing.hard[m.id] }));
  return {
    random: { count, seed: 7, interval: [lo, hi], methods: random },
    hard,
    hardTiming,
    targetNs: 150,
  };
}
