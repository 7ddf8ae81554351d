import { describe, expect, it } from "vitest";
import { ZENO_PUSH_BODIES, ZENO_PUSH_STREAK } from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { PushWatch } from "./pushWatch.js";

/** `n` micro-stops of body `id` on watch `w`. */
const unmoved = (w: PushWatch, id: string, n: number): void => {
  for (let i = 0; i < n; i++) w.stop(id, true, 1);
};

describe("PushWatch", () => {
  it("allows ZENO_PUSH_STREAK micro-stops of one body in a row and throws at the next, naming it", () => {
    const w = new PushWatch();
    unmoved(w, "pushed", ZENO_PUSH_STREAK);
    expect(() => w.stop("pushed", true, 2.5)).toThrow(SimulationError);
    expect(() => w.stop("pushed", true, 2.5)).toThrow(/body "pushed" stopped .* in a row.*sustained push/);
  });

  it("a stop that throws counts nothing: tried again, it throws the same message", () => {
    const w = new PushWatch();
    unmoved(w, "pushed", ZENO_PUSH_STREAK);
    const message = `body "pushed" stopped ${ZENO_PUSH_STREAK + 1} times in a row`;
    expect(() => w.check("pushed", true, 2.5)).toThrow(message);
    expect(() => w.stop("pushed", true, 2.5)).toThrow(message);
    expect(() => w.stop("pushed", true, 2.5)).toThrow(message);
    // A stop that moved the body is no push whatever the streak, and ends it.
    expect(() => w.check("pushed", false, 2.5)).not.toThrow();
    w.stop("pushed", false, 2.5);
    expect(() => w.stop("pushed", true, 3)).not.toThrow();
  });

  it("a stop that moved the body, or an edit of it, ends its streak", () => {
    const moved = new PushWatch();
    unmoved(moved, "a", ZENO_PUSH_STREAK);
    moved.stop("a", false, 1);
    expect(() => unmoved(moved, "a", ZENO_PUSH_STREAK)).not.toThrow();
    const edited = new PushWatch();
    unmoved(edited, "a", ZENO_PUSH_STREAK);
    edited.forget("a");
    expect(() => unmoved(edited, "a", ZENO_PUSH_STREAK)).not.toThrow();
    const fields = new PushWatch();
    unmoved(fields, "a", ZENO_PUSH_STREAK);
    fields.clear();
    expect(() => unmoved(fields, "a", ZENO_PUSH_STREAK)).not.toThrow();
  });

  it("other bodies' micro-stops between a pushed body's do not hide its push", () => {
    const w = new PushWatch();
    const run = () => {
      for (let i = 0; i <= ZENO_PUSH_STREAK; i++) {
        w.stop("pushed", true, 1);
        // Nudged balls elsewhere, more of them than the watch keeps streaks of.
        w.stop(`nudged${i % (2 * ZENO_PUSH_BODIES)}`, true, 1);
      }
    };
    expect(run).toThrow(/body "pushed"/);
  });

  // Regression: a share of micro-stops per window of events refused a game of repeated breaks
  // (6 micro-stops among 47 events per break, of different balls).
  it("many bodies nudged now and then, each moving in between, are no push", () => {
    const w = new PushWatch();
    for (let shot = 0; shot < 50_000; shot++)
      for (let b = 0; b < 15; b++) w.stop(`ball${b}`, (shot + b) % 7 !== 0, shot);
    expect(w.save().every(([, n]) => n <= 7)).toBe(true);
  });

  it("save and load carry the streaks: a restored watch throws at the same stop", () => {
    const a = new PushWatch();
    unmoved(a, "x", 3);
    unmoved(a, "pushed", ZENO_PUSH_STREAK - 1);
    const b = new PushWatch();
    b.load(a.save());
    expect(b.save()).toEqual(a.save());
    for (const w of [a, b]) {
      w.stop("pushed", true, 1);
      expect(() => w.stop("pushed", true, 1)).toThrow(SimulationError);
    }
  });
});
