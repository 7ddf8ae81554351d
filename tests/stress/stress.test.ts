/**
 * Numerical stress cases as fast invariant tests (the timings live only in `npm run bench`).
 * Each runs a scene of bench/stress/cases.mjs at a small size and asserts: no overlap beyond the
 * scene's tolerance (1e-9 of the contact distance, a few ulps of a coordinate at offsets ~1e6), at
 * sampled instants and at every disc–disc event; no body leaves its box; bounded energy drift.
 */
import { describe, expect, it } from "vitest";
import {
  grazing,
  highSpeed,
  largeOffset,
  massRatio,
  nearSimultaneous,
  roundOffContacts,
} from "../../bench/stress/cases.mjs";
import { type RunReport, runChecked } from "./invariants.js";

/** Runs the scene once, on first use inside a test (not at collection time). */
function lazy(f: () => RunReport): () => RunReport {
  let r: RunReport | null = null;
  return () => {
    r ??= f();
    return r;
  };
}

const ENERGY = 1e-10;

describe("stress: grazing collisions", () => {
  const scene = grazing(17);
  const run = lazy(() => runChecked(scene, 200));
  it("keeps every invariant", () => {
    const r = run();
    expect(r.worstOverlap).toBeLessThanOrEqual(scene.tolerance);
    expect(r.contactError).toBeLessThanOrEqual(scene.tolerance);
    expect(r.energyError).toBeLessThanOrEqual(ENERGY);
    expect(r.momentumError).toBeLessThanOrEqual(ENERGY);
  });
  it("collides exactly once in every lane whose impact parameter is inside the contact distance by ≥ 1e-14", () => {
    const r = run();
    for (let k = 0; k <= 14; k++) {
      const key = [`s${String(2 * k).padStart(5, "0")}`, `s${String(2 * k + 1).padStart(5, "0")}`].join("+");
      expect(r.pairEvents.get(key), `lane δ = 1e-${k}`).toBe(1);
    }
  });
});

describe("stress: near-simultaneous events", () => {
  const scene = nearSimultaneous(10);
  const run = lazy(() => runChecked(scene, 200));
  it("keeps every invariant and conserves momentum", () => {
    const r = run();
    expect(r.worstOverlap).toBeLessThanOrEqual(scene.tolerance);
    expect(r.contactError).toBeLessThanOrEqual(scene.tolerance);
    expect(r.energyError).toBeLessThanOrEqual(ENERGY);
    expect(r.momentumError).toBeLessThanOrEqual(ENERGY);
  });
  it("the striker meets both discs in every lane", () => {
    const r = run();
    expect(r.bodyBody).toBeGreaterThanOrEqual(2 * 10);
  });
});

describe("stress: contacts at t ≈ 0 after round-off", () => {
  const scene = roundOffContacts(3, 24);
  const run = lazy(() => runChecked(scene, 300));
  it("collides at once and keeps every invariant", () => {
    const r = run();
    expect(r.firstEventTime).toBeLessThanOrEqual(1e-12);
    expect(r.worstOverlap).toBeLessThanOrEqual(scene.tolerance);
    expect(r.contactError).toBeLessThanOrEqual(scene.tolerance);
    expect(r.energyError).toBeLessThanOrEqual(ENERGY);
    expect(r.momentumError).toBeLessThanOrEqual(ENERGY);
  });
});

describe("stress: large offsets (positions ~1e6, radii 1e-3)", () => {
  const scene = largeOffset(100);
  const run = lazy(() => runChecked(scene, 200));
  it("keeps overlaps within a few ulps of a coordinate, nothing escapes, energy bounded", () => {
    const r = run();
    expect(r.events).toBeGreaterThan(100);
    expect(r.worstOverlap).toBeLessThanOrEqual(scene.tolerance);
    expect(r.escaped).toBe(0);
    expect(r.energyError).toBeLessThanOrEqual(ENERGY);
  });
});

describe("stress: mass ratios up to 1e12", () => {
  for (const ratio of [1e3, 1e6, 1e9, 1e12]) {
    const scene = massRatio(ratio, 25);
    const run = lazy(() => runChecked(scene, 100));
    it(`ratio ${ratio}: no overlap, no escape, energy bounded`, () => {
      const r = run();
      expect(r.events).toBeGreaterThan(50);
      expect(r.worstOverlap).toBeLessThanOrEqual(scene.tolerance);
      expect(r.contactError).toBeLessThanOrEqual(scene.tolerance);
      expect(r.escaped).toBe(0);
      expect(r.energyError).toBeLessThanOrEqual(ENERGY);
    });
  }
});

describe("stress: speeds up to 1e6", () => {
  for (const speed of [1e2, 1e4, 1e6]) {
    const scene = highSpeed(speed, 30);
    const run = lazy(() => runChecked(scene, 100, 20000));
    it(`speed ${speed}: no overlap, no escape, energy bounded`, () => {
      const r = run();
      expect(r.events).toBeGreaterThan(20);
      expect(r.worstOverlap).toBeLessThanOrEqual(scene.tolerance);
      expect(r.contactError).toBeLessThanOrEqual(scene.tolerance);
      expect(r.escaped).toBe(0);
      expect(r.energyError).toBeLessThanOrEqual(ENERGY);
    });
  }
});

describe("stress: long run", () => {
  const scene = { ...highSpeed(1, 100, 0), span: 1e4 };
  const run = lazy(() => runChecked(scene, 50, 20000));
  it("20,000 events in a box gas: energy drift bounded, no overlap, no escape", () => {
    const r = run();
    expect(r.events).toBe(20000);
    expect(r.energyError).toBeLessThanOrEqual(ENERGY);
    expect(r.worstOverlap).toBeLessThanOrEqual(scene.tolerance);
    expect(r.contactError).toBeLessThanOrEqual(scene.tolerance);
    expect(r.escaped).toBe(0);
  });
});
