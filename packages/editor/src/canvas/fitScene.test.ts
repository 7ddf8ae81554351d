import { presets, type SceneFile, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { packFrame } from "../remote/packFrame";
import { FIT_MAX_COVERED, FIT_MIN_RADII, fitFrame } from "./fitScene";
import { frameBounds } from "./hitTest";
import { fit, toScreen } from "./viewTransform";

const size = { width: 800, height: 600 };

function frameOf(actions: SceneFile["actions"]) {
  const scene: SceneFile = { format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions };
  return packFrame(Timeline.fromScene(scene, { compute: false }).stateAt(0), 0);
}
const disc = (id: string, x: number, y: number, r: number) =>
  ({ time: 0, type: "addBody", id, x, y, r, m: 1 }) as const;

describe("fit to scene", () => {
  it("a lone disc is a disc in a space: it spans a fifth of the view's width, centred", () => {
    for (const r of [1e-3, 1, 250]) {
      const v = fitFrame(frameOf([disc("a", 3, -2, r)]), size);
      expect(v.cx).toBe(3);
      expect(v.cy).toBe(-2);
      const diameterPx = 2 * r * v.scale;
      expect(diameterPx / (800 - 48)).toBeCloseTo(2 / FIT_MIN_RADII, 9);
    }
  });

  it("an empty scene keeps the default view", () => {
    expect(fitFrame(frameOf([]), size)).toEqual({ cx: 0, cy: 0, scale: 1 });
    expect(fitFrame(null, size)).toEqual({ cx: 0, cy: 0, scale: 1 });
  });

  it("lines and points only are fitted to their bounds; a lone point keeps the default scale", () => {
    const lines = frameOf([
      { time: 0, type: "addLine", id: "l", p1: [0, 0], p2: [400, 0], kind: "segment" },
      { time: 0, type: "addPoint", id: "p", p: [200, 100] },
    ]);
    const v = fitFrame(lines, size);
    expect(v).toEqual({ cx: 200, cy: 50, scale: (800 - 48) / 400 });
    expect(fitFrame(frameOf([{ time: 0, type: "addPoint", id: "p", p: [5, 6] }]), size)).toEqual({
      cx: 5,
      cy: 6,
      scale: 1,
    });
  });

  it("a body far from the rest stays in view with the rest (Fit drops nothing)", () => {
    const f = frameOf([disc("a", 0, 0, 1), disc("b", 3, 0, 1), disc("far", 1e5, 4e4, 1)]);
    const v = fitFrame(f, size);
    for (const [x, y] of [
      [0, 0],
      [3, 0],
      [1e5, 4e4],
    ] as const) {
      const [sx, sy] = toScreen(v, size, x, y);
      expect(sx).toBeGreaterThanOrEqual(24 - 1e-9);
      expect(sx).toBeLessThanOrEqual(776 + 1e-9);
      expect(sy).toBeGreaterThanOrEqual(24 - 1e-9);
      expect(sy).toBeLessThanOrEqual(576 + 1e-9);
    }
  });

  it("one big disc with small ones near it is fitted to their bounds (the median radius sets the minimum)", () => {
    const f = frameOf([disc("planet", 0, 0, 10), disc("m1", 14, 0, 0.5), disc("m2", -14, 0, 0.5)]);
    expect(fitFrame(f, size)).toEqual(fit(frameBounds(f), size));
    expect(fitFrame(f, size).scale).toBeCloseTo((800 - 48) / 29, 12);
  });

  it("two close discs get the minimum extent too; the presets (but the original demo) fit as before", () => {
    const pair = fitFrame(frameOf([disc("a", 0, 0, 1), disc("b", 2.5, 0, 1)]), size);
    expect(pair.scale).toBeCloseTo((800 - 48) / (FIT_MIN_RADII * 1), 12);
    for (const p of presets) {
      const f = packFrame(Timeline.fromScene(p.make(), { compute: false }).stateAt(0), 0);
      const before = fit(frameBounds(f), size);
      // the original demo: two discs of radius 100, 350 apart, filled the view; now 10 radii across
      if (p.id === "originalDemo") expect(fitFrame(f, size)).toEqual({ ...before, scale: 752 / 1000 });
      else expect(fitFrame(f, size), p.id).toEqual(before);
    }
  });

  it("a strip covered at the canvas's top (the notices) is left out: the scene fits in the rest, centred there", () => {
    // a tall scene (a column of discs), so that the height sets the scale
    const f = frameOf([disc("top", 0, 300, 5), disc("mid", 0, 0, 5), disc("bottom", 0, -300, 5)]);
    for (const covered of [0, 40, 150]) {
      const v = fitFrame(f, size, covered);
      const [, top] = toScreen(v, size, 0, 305);
      const [, bottom] = toScreen(v, size, 0, -305);
      expect(top, `${covered} px covered`).toBeCloseTo(covered + 24, 9);
      expect(bottom, `${covered} px covered`).toBeCloseTo(576, 9);
      expect(v.scale).toBeCloseTo((600 - covered - 48) / 610, 12);
    }
    expect(fitFrame(f, size, 0)).toEqual(fitFrame(f, size));
  });

  it("a strip covering more than half the canvas is left out only up to half", () => {
    const f = frameOf([disc("top", 0, 300, 5), disc("bottom", 0, -300, 5)]);
    const half = FIT_MAX_COVERED * size.height;
    expect(fitFrame(f, size, 500)).toEqual(fitFrame(f, size, half));
    const [, top] = toScreen(fitFrame(f, size, 500), size, 0, 305);
    expect(top).toBeCloseTo(half + 24, 9);
  });
});
