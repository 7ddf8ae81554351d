/**
 * The layer of disc outlines for scenes of many discs (draw.ts, above FILL_MAX_DISCS): rings drawn
 * in JavaScript into one ImageData (ringRaster.ts), put into an offscreen canvas and drawn onto the
 * scene canvas with one drawImage, in place of one arc per disc. Only the rectangle the rings
 * touched is cleared, put and drawn. The ImageData and the offscreen canvas are kept between
 * frames (reallocated only when the canvas changes size): no allocation per frame or per disc.
 */
import { emptyRect, fillRgb, type PixelRect, strokeRing } from "./ringRaster";

/** The part of a 2D context the layer draws its offscreen canvas with. */
export type LayerTarget = Pick<
  CanvasRenderingContext2D,
  "save" | "restore" | "setTransform" | "drawImage"
> & {
  canvas: { width: number; height: number; ownerDocument?: Document };
};

type OffscreenContext = Pick<CanvasRenderingContext2D, "createImageData" | "putImageData">;
type Offscreen = { width: number; height: number; getContext(id: "2d"): unknown };

/** An offscreen canvas of this size: a detached <canvas> of the target's document, else OffscreenCanvas. */
function offscreen(target: LayerTarget, width: number, height: number): Offscreen | null {
  const doc = target.canvas.ownerDocument;
  if (doc) {
    const c = doc.createElement("canvas");
    c.width = width;
    c.height = height;
    return c;
  }
  return typeof OffscreenCanvas === "undefined" ? null : new OffscreenCanvas(width, height);
}

export class DiscLayer {
  private canvas: Offscreen | null = null;
  private ctx: OffscreenContext | null = null;
  private image: ImageData | null = null;
  /** The pixels the last frame's rings touched (cleared before the next one). */
  private touched: PixelRect = emptyRect();
  private rgb: [number, number, number] = [0, 0, 0];

  /**
   * Draws a ring for each disc of `scr` (3 numbers per disc in CSS pixels: x, y, radius or −1 for
   * a disc not drawn) with a radius of at least `minRadius` CSS px, one device pixel wide, in
   * colour `rgb`, onto `target` (scaled by `pixelRatio`); discs whose ring would be larger than
   * `maxRadius` device px are left out (the caller strokes them). Returns false, drawing nothing,
   * when no offscreen canvas can be made (the caller strokes arcs instead).
   */
  draw(
    target: LayerTarget,
    scr: Float64Array,
    n: number,
    pixelRatio: number,
    minRadius: number,
    maxRadius: number,
    rgb: [number, number, number],
  ): boolean {
    const width = target.canvas.width;
    const height = target.canvas.height;
    if (!this.ready(target, width, height)) return false;
    const image = this.image!;
    const px = image.data;
    if (rgb[0] !== this.rgb[0] || rgb[1] !== this.rgb[1] || rgb[2] !== this.rgb[2]) {
      this.rgb = rgb;
      this.touched = { minX: 0, minY: 0, maxX: width, maxY: height };
    }
    fillRgb(px, width, this.touched, ...this.rgb);
    const touched = emptyRect();
    for (let i = 0; i < n; i++) {
      const rs = scr[3 * i + 2]!;
      if (rs < 0) continue;
      const r = Math.max(rs, minRadius) * pixelRatio;
      if (r > maxRadius) continue;
      strokeRing(px, width, height, scr[3 * i]! * pixelRatio, scr[3 * i + 1]! * pixelRatio, r, touched);
    }
    this.touched = touched;
    const w = touched.maxX - touched.minX;
    const h = touched.maxY - touched.minY;
    if (w <= 0 || h <= 0) return true;
    this.ctx!.putImageData(image, 0, 0, touched.minX, touched.minY, w, h);
    target.save();
    target.setTransform(1, 0, 0, 1, 0, 0);
    target.drawImage(
      this.canvas as CanvasImageSource,
      touched.minX,
      touched.minY,
      w,
      h,
      touched.minX,
      touched.minY,
      w,
      h,
    );
    target.restore();
    return true;
  }

  /** Makes the offscreen canvas and the ImageData match the target's size. */
  private ready(target: LayerTarget, width: number, height: number): boolean {
    if (this.canvas && this.image && this.canvas.width === width && this.canvas.height === height)
      return true;
    const canvas = offscreen(target, width, height);
    const ctx = canvas?.getContext("2d") as OffscreenContext | null | undefined;
    if (!canvas || !ctx) return false;
    this.canvas = canvas;
    this.ctx = ctx;
    this.image = ctx.createImageData(width, height);
    // a fresh ImageData is transparent black: the colour is written over all of it at the next fill
    this.touched = { minX: 0, minY: 0, maxX: width, maxY: height };
    return true;
  }
}

/** "#rrggbb" as [r, g, b]. */
export function parseHex(color: string): [number, number, number] {
  const v = Number.parseInt(color.slice(1), 16);
  return [(v >> 16) & 255, (v >> 8) & 255, v & 255];
}
