/**
 * Section "solver": time per call against error for realRoots (engine), the closed-form
 * Ferrari/Descartes quartic, the same + Newton polishing, and the seed's 1e-6 bisection, on random
 * collision quartics and on hard cases. Errors are ulps to the nearest exact sign change (or exact
 * double root) of the polynomial with the given double coefficients, via the engine's exactPolySign.
 */
import { measure, median, quantile } from "../lib/timing.mjs";
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

/** ns per call over the whole set, median of `runs` passes after a warm-up pass. */
function timePerCall(fn, polys, lo, hi, runs, calls) {
  let sink = 0;
  const reps = Math.max(1, Math.round(calls / polys.length));
  const pass = () => {
    for (let r = 0; r < reps; r++) for (const c of polys) sink += fn(c, lo, hi).length;
  };
  const m = measure(pass, { warmup: 2, runs });
  return { nsPerCall: m.medianNs / (reps * polys.length), runs, sink };
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
  ms.forEach((m, i) => {
    const t = timePerCall(m.fn, polys, lo, hi, runs, quick ? 30000 : 200000);
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
  const hardPolys = hardQuartics();
  const hardTiming = ms.map((m) => {
    let sink = 0;
    const reps = quick ? 1000 : 5000;
    const r = measure(
      () => {
        for (let k = 0; k < reps; k++) for (const h of hardPolys) sink += m.fn(h.coeffs, h.lo, h.hi).length;
      },
      { warmup: 1, runs },
    );
    return { id: m.id, nsPerCall: r.medianNs / (reps * hardPolys.length), sink };
  });
  return {
    random: { count, seed: 7, interval: [lo, hi], methods: random },
    hard,
    hardTiming,
    targetNs: 150,
  };
}
