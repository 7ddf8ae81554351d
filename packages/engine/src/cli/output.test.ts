import { describe, expect, it } from "vitest";
import { galperin, newtonsCradle } from "../scene/presets.js";
import { Timeline } from "../timeline/timeline.js";
import { writeResult } from "./output.js";

/** The whole result as one JSON text, as the CLI printed it before it wrote in pieces. */
function atOnce(tl: Timeline, time: number, withLog: boolean): string {
  const c = tl.counts();
  const out: Record<string, unknown> = {
    time,
    events: c.bodyBody + c.bodyLine + c.bodyPoint + c.stop,
    counts: { bodyBody: c.bodyBody, bodyLine: c.bodyLine, bodyPoint: c.bodyPoint, stop: c.stop },
    bodies: tl
      .stateAt(time)
      .bodies.map((b) => ({ id: b.id, x: b.x, y: b.y, vx: b.vx, vy: b.vy, r: b.r, m: b.m, mu: b.mu })),
  };
  if (withLog) out.log = tl.eventsBetween(0, time);
  return `${JSON.stringify(out, (_k, v) => (v === Number.POSITIVE_INFINITY ? "Infinity" : v), 2)}\n`;
}

describe("writeResult", () => {
  it("writes the log in pieces of at most `chunk` events (a 1.7M-event log exceeded V8's longest string)", () => {
    const tl = Timeline.fromScene(galperin(3), { compute: false });
    tl.prolong({});
    const pieces: string[] = [];
    writeResult(tl, tl.lastLoggedTime(), (t) => pieces.push(t), { log: true, chunk: 50 });
    const text = pieces.join("");
    expect(text).toBe(atOnce(tl, tl.lastLoggedTime(), true));
    expect(JSON.parse(text).log).toHaveLength(314 + 3);
    expect(pieces.length).toBeGreaterThanOrEqual(Math.ceil(317 / 50));
    const longest = Math.max(...pieces.map((p) => (p.match(/"type"/g) ?? []).length));
    expect(longest).toBeLessThanOrEqual(50);
  });

  it("is byte-identical to the whole JSON without a log, with an empty log, and with an infinite mass", () => {
    const tl = Timeline.fromScene(newtonsCradle(), { compute: false });
    tl.prolong({ time: 3 });
    for (const withLog of [false, true]) {
      const pieces: string[] = [];
      writeResult(tl, 3, (t) => pieces.push(t), { log: withLog, chunk: 4 });
      expect(pieces.join("")).toBe(atOnce(tl, 3, withLog));
    }
    const still = new Timeline({ g: 0 });
    still.apply({ time: 0, type: "addBody", id: "wall", x: 0, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    const pieces: string[] = [];
    writeResult(still, 0, (t) => pieces.push(t), { log: true, chunk: 4 });
    expect(pieces.join("")).toBe(atOnce(still, 0, true));
    expect(pieces.join("")).toContain('"m": "Infinity"');
    const empty = new Timeline({ g: 0 });
    const nothing: string[] = [];
    writeResult(empty, 0, (t) => nothing.push(t), { log: true, chunk: 4 });
    expect(nothing.join("")).toBe(atOnce(empty, 0, true));
  });

  it("compact: the same value, without indentation, one log entry per line", () => {
    const tl = Timeline.fromScene(galperin(2), { compute: false });
    tl.prolong({});
    const end = tl.lastLoggedTime();
    for (const withLog of [false, true]) {
      const pieces: string[] = [];
      writeResult(tl, end, (t) => pieces.push(t), {
        log: withLog,
        end: { reason: "idle" },
        chunk: 7,
        compact: true,
      });
      const text = pieces.join("");
      const pretty = JSON.parse(atOnce(tl, end, withLog));
      expect(JSON.parse(text)).toEqual({ time: end, reason: "idle", ...pretty });
      const lines = text.trimEnd().split("\n");
      expect(lines).toHaveLength(withLog ? 1 + 31 + 3 + 1 : 1); // head, 31 collisions and 3 actions, "]}"
      if (withLog) expect(lines.slice(1, -1).every((l) => /^\{"time":.*\},?$/.test(l))).toBe(true);
    }
    const empty: string[] = [];
    writeResult(new Timeline({ g: 0 }), 0, (t) => empty.push(t), { log: true, chunk: 4, compact: true });
    expect(JSON.parse(empty.join(""))).toMatchObject({ log: [] });
  });
});
