/**
 * Hairline disc outlines rasterized in JavaScript into an RGBA pixel buffer (an ImageData's data),
 * for scenes of thousands of discs: stroking 20,000 arcs through the 2D canvas cost about 30 ms of
 * main-thread time per frame in headless Chromium's software canvas (7 ms building the path, the
 * rest rasterizing it when the canvas is committed), while writing the few pixels of each small ring
 * here costs a few milliseconds for all of them.
 *
 * A ring of radius R (device pixels) centred at (cx, cy) covers the pixel whose centre is at
 * distance d from (cx, cy) by max(0, 1 − |d − R|): a one-pixel-wide stroke with a tent filter, as
 * an antialiased hairline. Centres and radii are used as given (no rounding to pixels or sub-pixel
 * steps). Only the pixels of the annulus R − 1 < d < R + 1 are visited, row by row. Coverage is
 * composited over what the buffer holds ("source over" on the alpha channel); the colour channels
 * are left alone, so a buffer prefilled with one colour (fillRgb) draws rings of that colour.
 */

/** A rectangle of pixels, max exclusive; empty when maxX <= minX. */
export interface PixelRect {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

export function emptyRect(): PixelRect {
  return { minX: 0, minY: 0, maxX: 0, maxY: 0 };
}

/**
 * Sets every pixel of `rect` in `px` (RGBA, `width` pixels a row) to the colour (r, g, b) with
 * alpha 0: clears a region before rings are drawn into it.
 */
export function fillRgb(
  px: Uint8ClampedArray,
  width: number,
  rect: PixelRect,
  r: number,
  g: number,
  b: number,
): void {
  if (rect.maxX <= rect.minX || rect.maxY <= rect.minY) return;
  const word = new Uint8Array([r, g, b, 0]);
  const value = new Uint32Array(word.buffer)[0]!; // the platform's byte order, as px is read
  const words = new Uint32Array(px.buffer, px.byteOffset, px.length >> 2);
  for (let y = rect.minY; y < rect.maxY; y++) words.fill(value, y * width + rect.minX, y * width + rect.maxX);
}

/**
 * Draws a ring of radius `radius` centred at (cx, cy) (device pixels) into the alpha channel of
 * `px` (`width` × `height` pixels), clipped to the buffer. Widens `touched` to the pixels written.
 */
export function strokeRing(
  px: Uint8ClampedArray,
  width: number,
  height: number,
  cx: number,
  cy: number,
  radius: number,
  touched: PixelRect,
): void {
  const ro = radius + 1;
  const ri = radius - 1;
  const y0 = Math.max(0, Math.floor(cy - ro));
  const y1 = Math.min(height - 1, Math.ceil(cy + ro));
  if (y0 > y1) return;
  let any = false;
  for (let y = y0; y <= y1; y++) {
    const dy = y + 0.5 - cy;
    const dy2 = dy * dy;
    const outer = ro * ro - dy2;
    if (outer <= 0) continue;
    const xo = Math.sqrt(outer);
    // pixel columns whose centre lies strictly inside the outer circle's chord
    const xa = Math.max(0, Math.ceil(cx - xo - 0.5));
    const xb = Math.min(width - 1, Math.floor(cx + xo - 0.5));
    if (xa > xb) continue;
    // columns whose centre is within the inner circle's chord have d <= R − 1: no coverage
    let ia = xb + 1;
    let ib = xb;
    if (ri > 0 && ri * ri - dy2 > 0) {
      const xi = Math.sqrt(ri * ri - dy2);
      ia = Math.max(xa, Math.ceil(cx - xi - 0.5));
      ib = Math.floor(cx + xi - 0.5);
    }
    const row = y * width;
    for (let x = xa; x <= xb; x++) {
      if (x === ia && ia <= ib) {
        x = ib;
        continue;
      }
      const dx = x + 0.5 - cx;
      const a = 1 - Math.abs(Math.sqrt(dx * dx + dy2) - radius);
      if (a <= 0) continue;
      const i = 4 * (row + x) + 3;
      const old = px[i]!;
      px[i] = old + (255 - old) * a;
      any = true;
    }
  }
  if (!any) return;
  const x0 = Math.max(0, Math.floor(cx - ro));
  const x1 = Math.min(width, Math.ceil(cx + ro) + 1);
  if (touched.maxX <= touched.minX) {
    touched.minX = x0;
    touched.minY = y0;
    touched.maxX = x1;
    touched.maxY = y1 + 1;
    return;
  }
  if (x0 < touched.minX) touched.minX = x0;
  if (y0 < touched.minY) touched.minY = y0;
  if (x1 > touched.maxX) touched.maxX = x1;
  if (y1 + 1 > touched.maxY) touched.maxY = y1 + 1;
}
