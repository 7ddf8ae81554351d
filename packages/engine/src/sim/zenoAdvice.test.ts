// The Zeno reports name who is caught (the error's ids and its message) and say what to do, for each
// watch: many events at one instant (a jam), events converging on a finite time (a crush the windows
// find), a crush proven by the trap watch, and a sustained push. Bodies far away or that did not
// move are not named; a copy of the World names the same ones.
import { describe, expect, it } from "vitest";
import { ZENO_PUSH_STREAK } from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { PushWatch } from "./pushWatch.js";
import { World } from "./world.js";
import { bodiesNamed, listed } from "./zenoAdvice.js";

const INF = Number.POSITIVE_INFINITY;

function thrown(f: () => unknown): SimulationError {
  try {
    f();
  } catch (e) {
    if (e instanceof SimulationError) return e;
    throw e;
  }
  throw new Error("no SimulationError");
}

describe("names in reports", () => {
  it("lists ids as the messages do, the first ten and how many more", () => {
    expect(listed(['"a"'])).toBe('"a"');
    expect(listed(['"a"', '"b"', '"c"'])).toBe('"a", "b" and "c"');
    const many = Array.from({ length: 12 }, (_, i) => `"b${i}"`);
    expect(listed(many)).toBe(`${many.slice(0, 10).join(", ")} and 2 more`);
    expect(listed(many, true)).toBe(`${many.slice(0, 10).join(", ")} and at least 2 more`);
    expect(bodiesNamed(["p"], "immovable")).toBe('immovable body "p"');
    expect(bodiesNamed(["a", "b"])).toBe('bodies "a" and "b"');
  });
});

describe("a jam: many events at one instant", () => {
  it("a row of 80 touching discs between two immovable ones: the search stops at 64 and the report says at least", () => {
    const w = new World({ g: 0 });
    w.addBody("L", { x: 0, y: 0, r: 1, m: INF });
    for (let k = 0; k < 80; k++)
      w.addBody(`d${String(k).padStart(2, "0")}`, { x: 2 + 2 * k, y: 0, r: 1, m: 1, vx: k === 0 ? 1 : 0 });
    w.addBody("R", { x: 162, y: 0, r: 1, m: INF });
    const e = thrown(() => w.advance({}));
    expect(e.ids.length).toBe(64); // CAUGHT_MAX bodies, no line or point here
    expect(e.message).toMatch(
      /at the same instant t=0 among bodies "L", "d00", .* and at least 54 more \(the last: /,
    );
    expect(e.message).toMatch(
      /: to go on, place bodies "L", .* and at least 54 more a little apart from each other/,
    );
    expect(e.message).not.toMatch(/ and 54 more/);
  });

  it("a disc between two immovable discs: the three named, the bystander not; give them a finite mass", () => {
    const w = new World({ g: 0 });
    w.addBody("L", { x: 0, y: 0, r: 1, m: INF });
    w.addBody("d", { x: 2, y: 0, r: 1, m: 1, vx: 1 });
    w.addBody("R", { x: 4, y: 0, r: 1, m: INF });
    w.addBody("far", { x: 100, y: 0, r: 1, m: 1e12 });
    const e = thrown(() => w.advance({}));
    expect(e.ids).toEqual(["L", "R", "d"]);
    expect(e.message).toMatch(
      /^more than 257 events at the same instant t=0 among bodies "L", "R" and "d" \(the last: "d" and "[LR]"\): a Zeno state/,
    );
    expect(e.message).toMatch(
      /: to go on, place bodies "L", "R" and "d" a little apart from each other so that they do not touch at t=0, or give the immovable bodies "L" and "R" a finite mass$/,
    );
    expect(e.message).not.toMatch(/far/);
  });

  it("a disc pressed between two walls exactly its diameter apart: the walls named, the last event's too", () => {
    const w = new World({ g: 0 });
    w.addLine("lo", [-10, 0], [10, 0], "segment");
    w.addLine("hi", [-10, 2], [10, 2], "segment");
    w.addBody("d", { x: 0, y: 1, r: 1, m: 1, vy: 1 });
    w.addBody("still", { x: 0, y: 5, r: 1, m: 1 });
    const e = thrown(() => w.advance({}));
    expect(e.ids).toEqual(["d", "hi", "lo"]);
    expect(e.message).toMatch(
      /at the same instant t=0 among body "d" against line "hi" and line "lo" \(the last: "d" and line "(hi|lo)"\)/,
    );
    expect(e.message).toMatch(
      /: to go on, place body "d" a little apart from line "hi" and line "lo" so that they do not touch at t=0$/,
    );
  });

  it("a copy made in the middle of the jam names the same bodies in the same words", () => {
    const w = new World({ g: 0 });
    w.addLine("wall", [0, -5], [0, 5], "line");
    w.addBody("d", { x: 1, y: 0, r: 1, m: 1, vx: -1 });
    w.addBody("R", { x: 3, y: 0, r: 1, m: INF });
    w.addBody("aside", { x: 10, y: 10, r: 1, m: 1, vx: 1 });
    expect(w.advance({ maxEvents: 100 }).events).toBe(100);
    const copy = w.clone();
    const a = thrown(() => w.advance({}));
    const b = thrown(() => copy.advance({}));
    expect(a.ids).toEqual(["R", "d", "wall"]);
    expect(b.message).toBe(a.message);
    expect(b.ids).toEqual(a.ids);
    // asked again (nextEventTime), the same report
    expect(thrown(() => w.nextEventTime()).message).toBe(a.message);
  });
});

describe("a crush the windows find: events converging on a finite time", () => {
  it("names the disc, the crusher and the wall, not the other moving immovable disc; stop or remove", () => {
    // A second moving immovable disc far away keeps the trap watch's proof out: the windows report it.
    const w = new World({ g: 0 });
    w.addLine("wall", [0, -10], [0, 10], "line");
    w.addBody("d", { x: 5, y: 0, r: 1, m: 1, vx: -10 });
    w.addBody("p", { x: 10, y: 0, r: 1, m: INF, vx: -1 });
    w.addBody("far", { x: 100, y: 100, r: 1, m: INF, vx: 1, vy: 1 });
    const e = thrown(() => w.advance({}));
    expect(e.message).toMatch(/events accumulate at a finite time/);
    expect(e.ids).toEqual(["d", "p", "wall"]);
    expect(e.message).toMatch(/ among bodies "d" and "p" against line "wall": events accumulate/);
    expect(e.message).toMatch(
      /: to go on, stop the immovable body "p" \(or turn it away\) before it closes, give it a finite mass, or remove line "wall"$/,
    );
  });
});

describe("a crush the trap watch proves", () => {
  it("names the disc, the crusher and the wall, with the time it closes by", () => {
    const w = new World({ g: 0 });
    w.addLine("wall", [0, -5], [0, 5], "line");
    w.addBody("small", { x: 2, y: 0, r: 1, m: 1 });
    w.addBody("crusher", { x: 5, y: 0, r: 1, m: INF, vx: -1 });
    const e = thrown(() => w.advance({}));
    expect(e.ids).toEqual(["small", "crusher", "wall"]);
    const by = /close on it by t=(\S+):/.exec(e.message)?.[1];
    // the crusher's surface reaches the disc against the wall at t = 2 (the proof's bound a hair later)
    expect(Number(by)).toBeGreaterThanOrEqual(2);
    expect(Number(by)).toBeLessThan(2.001);
    expect(e.message).toMatch(
      `: to go on, stop the immovable body "crusher" (or turn it away) before t=${by}, give it a finite mass, or remove line "wall"`,
    );
  });
});

describe("a sustained push", () => {
  it("names the body and says to take its friction away or part it from its pusher", () => {
    const w = new PushWatch();
    for (let i = 0; i < ZENO_PUSH_STREAK; i++) w.stop("k09_08", true, 2.5);
    const e = thrown(() => w.stop("k09_08", true, 2.5));
    expect(e.ids).toEqual(["k09_08"]);
    expect(e.message).toMatch(
      /sustained push.*: to go on, give body "k09_08" no friction \(mu: 0, or the friction field g: 0\), or place it a little apart from the disc pressing on it$/,
    );
  });
});
