/**
 * serializeScene round-trips every valid scene file (property): random valid files, as JSON text,
 * with their optional parts left out or given (g, gravity, an addBody's mu and v, an until, meta),
 * masses "Infinity", every kind of action. For each: serializeScene takes the file's own object
 * (JSON.parse of its text: it refused one without g), parseScene of what it writes equals
 * parseScene of the file, parse → serialize → parse gives the same scene, and writing is stable
 * (serializing what it wrote writes the same text). The seed is printed; FC_SEED replays another.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { FIELD_MIN, MAGNITUDE_MAX, MASS_MAX, MASS_MIN, RADIUS_MIN, SPEED_MIN } from "../tolerances.js";
import { parseScene } from "./parse.js";
import { serializeScene } from "./serialize.js";

type Json = Record<string, unknown>;

/** A field (g, a gravity or speed component): 0, or FIELD_MIN (= SPEED_MIN) to MAGNITUDE_MAX in size. */
const field = (min: number) =>
  fc.oneof(
    fc.constant(0),
    fc.double({ min, max: MAGNITUDE_MAX, noNaN: true }),
    fc.double({ min, max: MAGNITUDE_MAX, noNaN: true }).map((v) => -v),
  );
const speed = field(SPEED_MIN);
/** The friction field g: 0, or FIELD_MIN to MAGNITUDE_MAX (never negative). */
const frictionField = fc.oneof(
  fc.constant(0),
  fc.double({ min: FIELD_MIN, max: MAGNITUDE_MAX, noNaN: true }),
);
const coordinate = fc.double({ min: -1e6, max: 1e6, noNaN: true });
const radius = fc.double({ min: RADIUS_MIN, max: 1, noNaN: true });
const mass = fc.oneof(fc.double({ min: MASS_MIN, max: MASS_MAX, noNaN: true }), fc.constant("Infinity"));
const mu = fc.oneof(fc.constant(0), fc.double({ min: FIELD_MIN, max: 2, noNaN: true }));
const time = fc.oneof(fc.constant(0), fc.double({ min: FIELD_MIN, max: 1e6, noNaN: true }));
const until = fc.record(
  { time: fc.double({ min: 0, max: 1e3, noNaN: true }), events: fc.nat({ max: 1e6 }) },
  { requiredKeys: [] },
);
/** Plain JSON data for meta (no -0: meta refuses it, as JSON would write it 0). */
const meta = fc.dictionary(
  fc.string({ maxLength: 6 }).filter((k) => k !== "__proto__"),
  fc.oneof(
    fc.string(),
    fc.integer(),
    fc.boolean(),
    fc.constant(null),
    fc.array(fc.integer(), { maxLength: 3 }),
  ),
  { maxKeys: 4 },
);

/** Optional fields: each entry of `fields` is kept or left out, as the generator decides. */
const some = (fields: Record<string, fc.Arbitrary<unknown>>) => fc.record(fields, { requiredKeys: [] });

/**
 * A valid scene file's object: bodies in a row on y = 0, 10 apart (radius at most 1), lines and
 * points far above and below them, then later actions on those bodies (a move keeps them apart:
 * each body has its own column). Friction (mu > 0) only without gravity, and gravity set again
 * (setGlobal) only where no body has friction, as the format requires.
 */
const sceneFile = fc
  .record({
    withGravity: fc.boolean(),
    frame: some({ g: frictionField, meta }),
    gravity: fc.tuple(field(FIELD_MIN), field(FIELD_MIN)),
    bodies: fc.array(
      fc.record({
        y: coordinate,
        r: radius,
        m: mass,
        optional: some({ mu, v: fc.tuple(speed, speed), until }),
      }),
      { minLength: 1, maxLength: 6 },
    ),
    obstacles: fc.array(fc.tuple(fc.boolean(), coordinate, time), { maxLength: 3 }),
    later: fc.array(
      fc.record({
        body: fc.nat(),
        time,
        kind: fc.constantFrom("giveVelocity", "updateBody", "removeBody", "setGlobal"),
        v: fc.tuple(speed, speed),
        patch: some({ y: coordinate, r: radius, m: mass, mu }),
        moveX: fc.boolean(),
        g: frictionField,
      }),
      { maxLength: 6 },
    ),
  })
  .map(({ withGravity, frame, gravity, bodies, obstacles, later }): Json => {
    const file: Json = { format: "chapgame", version: 1, ...frame };
    const nonZero = gravity[0] !== 0 || gravity[1] !== 0;
    if (withGravity) file.gravity = gravity;
    const frictionless = withGravity && nonZero;
    const noMu = (o: Json) => {
      if (frictionless) delete o.mu;
      return o;
    };
    const actions: Json[] = bodies.map((b, i) =>
      noMu({ time: 0, type: "addBody", id: `b${i}`, x: i * 10, y: b.y, r: b.r, m: b.m, ...b.optional }),
    );
    obstacles.forEach(([isLine, x, t], i) => {
      actions.push(
        isLine
          ? { time: t, type: "addLine", id: `l${i}`, p1: [x, 2e6], p2: [x + 1, 2e6 + i], kind: "segment" }
          : { time: t, type: "addPoint", id: `p${i}`, p: [x, -2e6] },
      );
    });
    const removed = new Set<number>();
    // in time order, so that nothing is done to a body removed before
    for (const a of [...later].sort((p, q) => p.time - q.time)) {
      const i = a.body % bodies.length;
      if (removed.has(i)) continue;
      const id = `b${i}`;
      if (a.kind === "giveVelocity") actions.push({ time: a.time, type: a.kind, id, v: a.v });
      else if (a.kind === "updateBody")
        actions.push(
          noMu({ time: a.time, type: a.kind, id, ...a.patch, ...(a.moveX ? { x: 1e5 + i * 10 } : {}) }),
        );
      else if (a.kind === "removeBody") {
        actions.push({ time: a.time, type: a.kind, id });
        removed.add(i);
      } else actions.push({ time: a.time, type: a.kind, g: a.g, ...(frictionless ? { gravity } : {}) });
    }
    file.actions = actions;
    return file;
  });

describe("serializeScene round trip of every valid scene file (property)", () => {
  it("takes the file's object as it is (g left out too) and writes what parseScene reads back the same", () => {
    const seed = seedFor("serialize file round-trip property", 20261124);
    let withoutG = 0;
    fc.assert(
      fc.property(sceneFile, (file) => {
        const text = JSON.stringify(file);
        const parsed = parseScene(text); // the generator writes valid files only
        if (file.g === undefined) withoutG++;
        // the file's own object, as JSON.parse reads it
        const written = serializeScene(JSON.parse(text));
        expect(parseScene(written)).toEqual(parsed);
        // parse → serialize → parse
        expect(parseScene(serializeScene(parsed))).toEqual(parsed);
        // writing is stable: what it wrote, read as an object and written again, is the same text
        expect(serializeScene(JSON.parse(written))).toBe(written);
      }),
      { seed, numRuns: 300 },
    );
    expect(withoutG).toBeGreaterThan(20); // the case at issue was met, not only files with a g
  });
});
