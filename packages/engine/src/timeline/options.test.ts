import { describe, expect, it } from "vitest";
import { galperin } from "../scene/presets.js";
import { Timeline } from "./timeline.js";
import type { TimelineOptions } from "./types.js";

describe("Timeline options", () => {
  it("refuses a misspelt or mistyped option instead of ignoring it (a history kept by a typo)", () => {
    const bad: [unknown, string][] = [
      [{ histroy: false }, "histroy: unknown field"],
      [{ history: "no" }, "history: must be true or false"],
      [{ compute: 0 }, "compute: must be true or false"],
    ];
    for (const [options, message] of bad) {
      expect(() => new Timeline(options as TimelineOptions)).toThrow(message);
      expect(() => Timeline.fromScene(galperin(1), options as TimelineOptions)).toThrow(message);
    }
    expect(() => new Timeline({ g: -1 })).toThrow("g: must be a non-negative finite number");
    // fromScene takes g and gravity from the scene: given as options they were silently overridden
    expect(() => Timeline.fromScene(galperin(1), { g: 0 } as TimelineOptions)).toThrow(
      "g: unknown field (fromScene takes g and gravity from the scene)",
    );
  });

  it("accepts the documented ones", () => {
    expect(new Timeline({ g: 1, gravity: [0, -1], history: false, compute: true }).history).toBe(false);
    expect(Timeline.fromScene(galperin(1), { history: true, compute: false }).history).toBe(true);
    expect(new Timeline().history).toBe(true);
  });
});
