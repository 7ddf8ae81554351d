import { describe, expect, it } from "vitest";
import { F_R, F_VX, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import { recordingContext } from "../testing/recordingContext";
import { type DrawOptions, drawFrame } from "./draw";

/** n discs of radius 1 on a grid 4 units apart, at rest unless `vx` is given. */
function frame(n: number, vx = 0): Frame {
  const data = new Float64Array(n * FRAME_STRIDE);
  const side = Math.ceil(Math.sqrt(n));
  for (let i = 0; i < n; i++) {
    data[i * FRAME_STRIDE + F_X] = 4 * (i % side);
    data[i * FRAME_STRIDE + F_Y] = 4 * Math.floor(i / side);
    data[i * FRAME_STRIDE + F_VX] = vx;
    data[i * FRAME_STRIDE + F_R] = 1;
  }
  const ids = Array.from({ length: n }, (_, i) => `d${i}`);
  return { t: 0, revision: 0, g: 9.81, gravity: [0, 0], ids, data, lines: [], points: [] };
}

const options: DrawOptions = {
  selection: null,
  highlight: new Set(),
  trails: null,
  overlay: null,
  pixelRatio: 1,
};

/** Draws `f` on a recording context of 400 × 300 CSS px at 2 device px per CSS px. */
function draw(f: Frame, document = true, size = { width: 400, height: 300 }) {
  const rec = recordingContext({ width: 2 * size.width, height: 2 * size.height, document });
  // the whole grid in view: world (0..4·side) across the canvas
  const side = 4 * Math.ceil(Math.sqrt(f.ids.length));
  const view = { cx: side / 2, cy: side / 2, scale: Math.min(size.width, size.height) / (side + 4) };
  drawFrame(rec.ctx, f, view, size, { ...options, pixelRatio: 2 });
  return { rec, view };
}

describe("drawFrame", () => {
  it("a few discs: one path of arcs, filled and stroked", () => {
    const { rec } = draw(frame(100));
    expect(rec.named("arc")).toHaveLength(100);
    expect(rec.named("fill")).toHaveLength(1);
    expect(rec.named("drawImage")).toHaveLength(0);
  });

  it("many discs: no arc per disc, the outlines drawn as one image of rings at the discs' places", () => {
    const f = frame(2000);
    const { rec, view } = draw(f);
    expect(rec.named("arc")).toHaveLength(0);
    expect(rec.named("drawImage")).toHaveLength(1);
    const off = rec.offscreens.at(-1)!;
    const [put] = off.named("putImageData");
    const image = put!.args[0] as { width: number; data: Uint8ClampedArray };
    expect(image.width).toBe(800);
    // every disc's ring has ink at its rightmost point (device px), none at its centre
    const r = 2 * view.scale; // device px
    for (let i = 0; i < f.ids.length; i += 97) {
      const sx = 2 * (200 + (f.data[i * FRAME_STRIDE + F_X]! - view.cx) * view.scale);
      const sy = 2 * (150 - (f.data[i * FRAME_STRIDE + F_Y]! - view.cy) * view.scale);
      const ink = (x: number, y: number) => image.data[4 * (Math.floor(y) * 800 + Math.floor(x)) + 3]!;
      expect(ink(sx + r, sy)).toBeGreaterThan(0);
      if (r > 3) expect(ink(sx, sy)).toBe(0);
    }
    // the image is drawn at device pixels, where it was put
    const [x, y, w, h] = put!.args.slice(3) as number[]; // (image, 0, 0, dirty rectangle)
    expect(put!.args.slice(1, 3)).toEqual([0, 0]);
    expect(rec.named("drawImage")[0]!.args.slice(1)).toEqual([x, y, w, h, x, y, w, h]);
    expect(rec.named("setTransform")[0]!.args).toEqual([1, 0, 0, 1, 0, 0]);
  });

  it("many discs: the image is cleared between frames (a moved disc leaves no ring behind)", () => {
    const f = frame(2000);
    const size = { width: 401, height: 300 }; // a size of its own: a new offscreen canvas
    const { rec } = draw(f, true, size);
    const off = rec.offscreens.at(-1)!;
    const image = off.named("putImageData")[0]!.args[0] as { data: Uint8ClampedArray };
    const inkBefore = image.data.reduce((s, v, i) => (i % 4 === 3 ? s + v : s), 0);
    for (let i = 0; i < 2000; i++) f.data[i * FRAME_STRIDE + F_X]! += 1.3;
    draw(f, true, size);
    expect(off.named("putImageData")).toHaveLength(2);
    expect(off.named("createImageData")).toHaveLength(1); // kept between frames
    const inkAfter = image.data.reduce((s, v, i) => (i % 4 === 3 ? s + v : s), 0);
    expect(Math.abs(inkAfter - inkBefore) / inkBefore).toBeLessThan(0.02);
  });

  it("many discs: a disc large on screen is stroked as an arc, not put in the image", () => {
    const f = frame(2000);
    f.data[5 * FRAME_STRIDE + F_R] = 3; // 3 world units: about 10 device px here
    f.data[7 * FRAME_STRIDE + F_R] = 4;
    const { rec } = draw(f);
    expect(rec.named("arc")).toHaveLength(2);
    expect(rec.named("drawImage")).toHaveLength(1);
    expect(rec.named("stroke").length).toBeGreaterThanOrEqual(1);
  });

  it("many discs without an offscreen canvas: one path of arcs, stroked one device pixel wide", () => {
    const { rec } = draw(frame(2000), false, { width: 123, height: 77 });
    expect(rec.named("arc")).toHaveLength(2000);
    expect(rec.named("drawImage")).toHaveLength(0);
    expect(rec.named("set lineWidth")[0]!.args).toEqual([0.5]);
  });

  it("velocity arrows shorter than 2 px are not drawn", () => {
    // scale ≈ 1.63 CSS px per unit: an arrow of 0.5 s at speed 2 is 1.6 px long, at speed 3 2.4 px
    expect(draw(frame(2000, 2)).rec.named("lineTo")).toHaveLength(0);
    expect(draw(frame(2000, 3)).rec.named("lineTo")).toHaveLength(3 * 2000);
  });

  it("velocity arrows of many discs are still one stroked path", () => {
    const { rec } = draw(frame(2000, 3));
    expect(rec.named("lineTo").length).toBeGreaterThanOrEqual(3 * 2000);
    expect(rec.named("stroke")).toHaveLength(1);
  });
});
