/**
 * The public API documented in docs/architecture.md and the READMEs is still there under its names
 * (extend, never rename): the package's entry exports them, and the classes have the documented
 * methods and getters. Additions pass; a removal or a rename fails here.
 */
import { describe, expect, it } from "vitest";
import * as api from "../src/index.js";

const EXPORTS = [
  "World",
  "Timeline",
  "parseScene",
  "serializeScene",
  "checkAction",
  "ACTION_TYPES",
  "SceneError",
  "ChapgameError",
  "SimulationError",
  "RootSolverError",
  "realRoots",
  "presets",
  "galperin",
  "newtonsCradle",
  "originalDemo",
  "brownian",
  "billiardsBreak",
  "bouncingBalls",
  "dilutedGas",
];

const WORLD = [
  "addBody",
  "addBodyMotion",
  "updateBody",
  "removeBody",
  "addLine",
  "updateLine",
  "removeLine",
  "addPoint",
  "updatePoint",
  "removePoint",
  "setGlobal",
  "hasBody",
  "hasLine",
  "hasPoint",
  "nextEventTime",
  "advance",
  "body",
  "bodies",
  "motion",
  "lines",
  "points",
  "clone",
];

const TIMELINE = [
  "toScene",
  "apply",
  "setActions",
  "prolong",
  "prolongSlice",
  "stateAt",
  "nextEventTime",
  "prevEventTime",
  "event",
  "eventsBetween",
  "eventRange",
  "eventDetail",
  "eventIndexAt",
  "path",
  "eventAction",
  "prolongTo",
  "counts",
  "historyBytes",
  "forgetBefore",
  "subscribe",
  "getSnapshot",
];

describe("the public API", () => {
  it("exports every documented name", () => {
    const missing = EXPORTS.filter((n) => !(n in api));
    expect(missing).toEqual([]);
  });

  it("World has the documented methods and fields", () => {
    const w = new api.World({ g: 0 });
    expect(WORLD.filter((m) => typeof (w as unknown as Record<string, unknown>)[m] !== "function")).toEqual(
      [],
    );
    expect(typeof w.time).toBe("number");
    expect(typeof w.g).toBe("number");
    expect(w.gravity).toEqual([0, 0]);
    expect(w.counts).toEqual({ bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0 });
  });

  it("Timeline has the documented methods, getters and fromScene", () => {
    const tl = new api.Timeline({ g: 0 });
    const t = tl as unknown as Record<string, unknown>;
    expect(TIMELINE.filter((m) => typeof t[m] !== "function")).toEqual([]);
    expect(typeof api.Timeline.fromScene).toBe("function");
    expect([tl.horizon, tl.eventCount, tl.actions.length]).toEqual([0, 0, 0]);
    expect([tl.historyStart, tl.firstEvent]).toEqual([0, 0]);
  });
});
