/**
 * Test support: the World of a scene against the all-pairs reference (ReferenceWorld): the same
 * ordered events (kind, participants) and times within 1e-12 relative. A scene the World reports
 * as a Zeno state (a disc crushed between immovable bodies) is skipped (fc.pre), not compared.
 */
import fc from "fast-check";
import { expect } from "vitest";
import { outcome } from "./outcome.js";
import { ReferenceWorld, type SceneSpec } from "./referenceWorld.js";
import { worldFromSpec } from "./worldFromSpec.js";

export function expectMatchesReference(spec: SceneSpec, maxEvents: number): void {
  const run = outcome(worldFromSpec(spec), maxEvents);
  fc.pre(run.error === null);
  const fast = run.events;
  const ref = new ReferenceWorld(spec).run(maxEvents);
  expect(fast.map((e) => `${e.kind} ${e.a} ${e.b}`)).toEqual(ref.map((e) => `${e.kind} ${e.a} ${e.b}`));
  fast.forEach((e, i) => {
    const rt = (ref[i] as { time: number }).time;
    expect(Math.abs(e.time - rt)).toBeLessThanOrEqual(1e-12 * Math.abs(rt));
  });
}
