import { newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { sceneText } from "./sceneIo";
import { differsInMetaAlone, metaWithTitle, titleChange, titleOf } from "./sceneTitle";

const withMeta = (meta: Record<string, unknown> | undefined): SceneFile => ({ ...newtonsCradle(), meta });

describe("titleOf", () => {
  it("is meta.title when a string, else empty", () => {
    expect(titleOf(withMeta({ title: "Break" }))).toBe("Break");
    expect(titleOf(withMeta(undefined))).toBe("");
    expect(titleOf(withMeta({ name: "other" }))).toBe("");
    expect(titleOf(withMeta({ title: 3 }))).toBe("");
  });
});

describe("metaWithTitle", () => {
  it("sets the title trimmed and keeps the rest of meta as it is", () => {
    const view = { zoom: 2, centre: [1, 2] };
    expect(metaWithTitle({ view }, "  My break ")).toEqual({ view, title: "My break" });
    expect(metaWithTitle(undefined, 'Ünïcode ✓ "quoted"')).toEqual({ title: 'Ünïcode ✓ "quoted"' });
    expect(metaWithTitle({ title: 5, view }, "x")).toEqual({ title: "x", view });
  });

  it("a blank title removes meta.title, and meta once nothing else is in it", () => {
    expect(metaWithTitle({ title: "a", view: 1 }, "   ")).toEqual({ view: 1 });
    expect(metaWithTitle({ title: "a" }, "")).toBeUndefined();
    expect(metaWithTitle(undefined, "")).toBeUndefined();
  });

  it("any title makes a scene the engine writes and reads back (the format limits none)", () => {
    for (const title of ["a\tb", "\u{1F3B1} billiards", "x".repeat(5000), "\ud800 lone surrogate"]) {
      const scene = withMeta(metaWithTitle(undefined, title));
      const text = sceneText(scene);
      expect(JSON.parse(text).meta.title).toBe(title.trim());
    }
  });
});

describe("titleChange", () => {
  it("says what became of the title; null when it stayed", () => {
    expect(titleChange(withMeta(undefined), withMeta({ title: "B" }))).toBe('the title set to "B"');
    expect(titleChange(withMeta({ title: "A" }), withMeta(undefined))).toBe('the title "A" removed');
    expect(titleChange(withMeta({ title: "A" }), withMeta({ title: "B" }))).toBe(
      'the title changed from "A" to "B"',
    );
    expect(titleChange(withMeta({ title: "A" }), withMeta({ title: "A", view: 1 }))).toBeNull();
    expect(titleChange(withMeta({ title: 3 }), withMeta(undefined))).toBe("a change of the title");
  });
});

describe("differsInMetaAlone", () => {
  it("is true for scenes differing in meta alone, false when an action, g or gravity differs too", () => {
    const a = withMeta({ title: "A" });
    expect(differsInMetaAlone(a, withMeta({ title: "A" }))).toBe(false);
    expect(differsInMetaAlone(a, withMeta({ title: "B" }))).toBe(true);
    expect(differsInMetaAlone(a, withMeta(undefined))).toBe(true);
    const b = withMeta({ title: "B" });
    expect(differsInMetaAlone(a, { ...b, g: 1 })).toBe(false);
    expect(differsInMetaAlone(a, { ...b, gravity: [0, -1] })).toBe(false);
    expect(differsInMetaAlone(a, { ...b, actions: b.actions.slice(1) })).toBe(false);
    const moved = a.actions.map((x, i) => (i === 0 ? { ...x, time: 1 } : x));
    expect(differsInMetaAlone(a, { ...b, actions: moved })).toBe(false);
  });
});
