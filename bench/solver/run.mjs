/**
 * Section "solver": time per call against error for realRoots (engine), the closed-form
 * Ferrari/Descartes quartic, the same + Newton polishing, and the seed's 1e-6 bisection, on random
 * collision quartics and on hard cases. Errors are ulps to the nearest exact sign change (or exact
 * double root) of the polynomial with the given double coefficients, via the engine's exactPolySign.
 */
import { median, nowNs, quantile } from "../lib/timing.mjs";
import { bisection, ferrari, ferrariNewton } from "./methods.mjs";
import { collisionQuartics, hardQuartics } from "./quartics.mjs";
import { ulpDistance, ulpsToSignChange } from "./ulps.mjs";

function methods(engine) {
  return [
    { id: "realRoots", label: "realRoots (engine)", fn: engine.realRoots },
    { id: "ferrari", label: "Ferrari closed form", fn: ferrari },
    { id: "ferrariNewton", label: "Ferrari + 2 Newton steps", fn: ferrariNewton },
    { id: "bisection", label: "seed bisection, eps 1e-6", fn: bisection },
  ];
}

/**
 * ns per call of every method over a set of polynomials: the methods are timed round-robin (one
 * pass each, `runs` rounds, after two warm-up rounds) so that load from other processes hits them
 * alike; the median pass time per method / calls per pass.
 */
function interleaved(ms, items, runs, calls) {
  const reps = Math.max(1, Math.round(calls / items.length));
  const times = ms.map(() => []);
  let sink = 0;
  for (let round = -2; round < runs; round++) {
    ms.forEach((m, i) => {
      const a = nowNs();
      for (let r = 0; r < reps; r++) for (const it of items) sink += m.fn(it.c, it.lo, it.hi).length;
      if (round >= 0) times[i].push(nowNs() - a);
    });
  }
  return { nsPerCall: times.map((t) => median(t) / (reps * items.length)), sink };
}

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
  const calls = quick ? 30000 : 200000;
  const timing = interleaved(
    ms,
    polys.map((c) => ({ c, lo, hi })),
    runs,
    calls,
  );
  ms.forEach((m, i) => {
    const t = { nsPerCall: timing.nsPerCall[i], runs };
    let missed = 0;
    errorsPer[i].forEach((e, k) => {
      missed += Math.max(0, expected[k] - e.filter(Number.isFinite).length);
    });
    const s = summarize(errorsPer[i].flat());
    random.push({ id: m.id, label: m.label, nsPerCall: t.nsPerCall, runs: t.runs, missed, ...s });
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
  const hardItems = hardQuartics().map((h) => ({ c: h.coeffs, lo: h.lo, hi: h.hi }));
  const hardNs = interleaved(ms, hardItems, runs, quick ? 10000 : 50000).nsPerCall;
  const hardTiming = ms.map((m, i) => ({ id: m.id, nsPerCall: hardNs[i] }));
  return {
    random: { count, seed: 7, interval: [lo, hi], methods: random },
    hard,
    hardTiming,
    targetNs: 150,
  };
}
