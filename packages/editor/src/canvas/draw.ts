/**
 * Draws one Frame on a 2D canvas context already scaled to CSS pixels. Batched for thousands of
 * discs: one path for all disc outlines, one for velocity arrows; ids are drawn only when a disc is
 * large enough on screen to hold its label (LABEL_MIN_RADIUS_PX), arrows only when at least 2 px
 * long. Above FILL_MAX_DISCS discs, outlines and arrows are one device pixel wide (see STROKE_PX), and
 * the outlines are rasterized into one image (discLayer.ts) rather than stroked as arcs.
 */
import type { Vec2 } from "../engineTypes";
import { F_R, F_VX, F_VY, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { Selection, View } from "../store/uiStore";
import { clipToRect } from "./clip";
import { DiscLayer, parseHex } from "./discLayer";
import { type Size, toScreen, toWorld } from "./viewTransform";

export type Overlay =
  | { kind: "disc"; x: number; y: number; r: number }
  | { kind: "arrow"; from: Vec2; to: Vec2 }
  | { kind: "line"; p1: Vec2; p2: Vec2; lineKind: "line" | "ray" | "segment" };

export interface DrawOptions {
  selection: Selection;
  /** `kind:id` keys of the objects to light (uiStore's highlight). */
  highlight: ReadonlySet<string>;
  /** Recent world positions per body id, oldest first: x0, y0, x1, y1, ... */
  trails: ReadonlyMap<string, number[]> | null;
  /** The Path view's line in world coordinates (x0, y0, x1, y1, ...; a NaN pair breaks it), or null. */
  path?: Float64Array | null;
  overlay: Overlay | null;
  /** Device pixels per CSS pixel (the context is scaled by it). */
  pixelRatio: number;
}

/** Seconds of motion an arrow shows: the arrow ends where the disc would be after ARROW_SECONDS. */
export const ARROW_SECONDS = 0.5;
const LABEL_MIN_RADIUS_PX = 9;
/** Smallest outline radius drawn (CSS px): a disc smaller on screen is drawn this large. */
const MIN_RADIUS_PX = 0.5;
/** Above this many discs they are drawn as outlines only (a translucent fill costs a quarter of the frame). */
const FILL_MAX_DISCS = 500;
/**
 * Stroke width of outlines and arrows (CSS px). Chromium's software canvas (Skia) draws strokes at
 * most one device pixel wide as hairlines; a 1.25 px stroke is outlined and filled as a path. In a
 * trace of 2,000 discs playing (tests/e2e/editor.profile.ts), 1.25 px outlines cost about 19 ms of
 * main-thread CPU per frame more than hairlines, which cost about as much as no outline at all.
 * Many discs are therefore drawn with hairlines; few keep the wider stroke.
 */
const STROKE_PX = 1.25;
const COLORS = { disc: "#1d2a3a", fill: "rgba(70,110,160,0.12)", selected: "#d9480f", highlight: "#e8590c" };

export function drawFrame(
  ctx: CanvasRenderingContext2D,
  f: Frame | null,
  view: View,
  size: Size,
  o: DrawOptions,
) {
  ctx.fillStyle = "#fbfaf7";
  ctx.fillRect(0, 0, size.width, size.height);
  if (!f) return;
  const [x0, y1] = toWorld(view, size, 0, 0);
  const [x1, y0] = toWorld(view, size, size.width, size.height);
  const rect = { minX: x0, minY: y0, maxX: x1, maxY: y1 };
  const sel = o.selection;

  // lines
  for (const l of f.lines) {
    const c = clipToRect(l.p1, l.p2, l.kind, rect);
    if (!c) continue;
    const hot = (sel?.kind === "line" && sel.id === l.id) || o.highlight.has(`line:${l.id}`);
    ctx.strokeStyle = hot ? COLORS.selected : "#444";
    ctx.lineWidth = hot ? 3 : 2;
    ctx.beginPath();
    ctx.moveTo(...toScreen(view, size, c[0][0], c[0][1]));
    ctx.lineTo(...toScreen(view, size, c[1][0], c[1][1]));
    ctx.stroke();
  }
  // points
  for (const p of f.points) {
    const hot = (sel?.kind === "point" && sel.id === p.id) || o.highlight.has(`point:${p.id}`);
    const [sx, sy] = toScreen(view, size, p.p[0], p.p[1]);
    ctx.fillStyle = hot ? COLORS.selected : "#222";
    ctx.beginPath();
    ctx.arc(sx, sy, hot ? 5 : 4, 0, 2 * Math.PI);
    ctx.fill();
  }
  // trails
  if (o.trails) {
    ctx.strokeStyle = "rgba(60,90,140,0.35)";
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (const pts of o.trails.values()) {
      for (let k = 0; k + 1 < pts.length; k += 2) {
        const [sx, sy] = toScreen(view, size, pts[k]!, pts[k + 1]!);
        if (k === 0) ctx.moveTo(sx, sy);
        else ctx.lineTo(sx, sy);
      }
    }
    ctx.stroke();
  }
  if (o.path) drawPath(ctx, o.path, view, size);
  // discs: screen coordinates computed once into a reused buffer (no allocation per disc)
  const d = f.data;
  const n = f.ids.length;
  const scr = screenBuffer(n);
  const hw = size.width / 2;
  const hh = size.height / 2;
  const k = view.scale;
  const margin = 2;
  const many = n > FILL_MAX_DISCS;
  if (!many) ctx.beginPath();
  for (let i = 0; i < n; i++) {
    const b = i * FRAME_STRIDE;
    const rs = d[b + F_R]! * k;
    const sx = hw + (d[b + F_X]! - view.cx) * k;
    const sy = hh - (d[b + F_Y]! - view.cy) * k;
    const visible = !(
      sx + rs < -margin ||
      sx - rs > size.width + margin ||
      sy + rs < -margin ||
      sy - rs > size.height + margin
    );
    scr[3 * i] = sx;
    scr[3 * i + 1] = sy;
    scr[3 * i + 2] = visible ? rs : -1;
    if (!visible || many) continue;
    const r = Math.max(rs, MIN_RADIUS_PX);
    ctx.moveTo(sx + r, sy);
    ctx.arc(sx, sy, r, 0, 2 * Math.PI);
  }
  const thin = many ? 1 / o.pixelRatio : STROKE_PX;
  if (many) drawRings(ctx, scr, n, o.pixelRatio);
  else {
    ctx.fillStyle = COLORS.fill;
    ctx.fill();
    ctx.strokeStyle = COLORS.disc;
    ctx.lineWidth = thin;
    ctx.stroke();
  }
  // velocity arrows
  ctx.beginPath();
  const arrowK = ARROW_SECONDS * k;
  for (let i = 0; i < n; i++) {
    if (scr[3 * i + 2]! < 0) continue;
    const b = i * FRAME_STRIDE;
    const vx = d[b + F_VX]!;
    const vy = d[b + F_VY]!;
    if (vx === 0 && vy === 0) continue;
    // shorter than 2 px: not drawn (arrowPath's own test, without a call per disc)
    if ((vx * vx + vy * vy) * arrowK * arrowK < 4) continue;
    const sx = scr[3 * i]!;
    const sy = scr[3 * i + 1]!;
    arrowPath(ctx, sx, sy, sx + vx * arrowK, sy - vy * arrowK);
  }
  ctx.strokeStyle = "#2b8a3e";
  ctx.lineWidth = thin;
  ctx.stroke();
  // selected / highlighted discs and labels
  ctx.font = "11px system-ui, sans-serif";
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  const anyHot = o.highlight.size > 0 || sel?.kind === "body";
  for (let i = 0; i < n; i++) {
    const rs = scr[3 * i + 2]!;
    if (rs < 0 || (rs < LABEL_MIN_RADIUS_PX && !anyHot)) continue;
    const id = f.ids[i]!;
    const hot = anyHot && ((sel?.kind === "body" && sel.id === id) || o.highlight.has(`body:${id}`));
    if (!hot && rs < LABEL_MIN_RADIUS_PX) continue;
    const sx = scr[3 * i]!;
    const sy = scr[3 * i + 1]!;
    if (hot) {
      ctx.strokeStyle = COLORS.selected;
      ctx.lineWidth = 2.5;
      ctx.beginPath();
      ctx.arc(sx, sy, Math.max(rs, 3), 0, 2 * Math.PI);
      ctx.stroke();
    }
    if (rs >= LABEL_MIN_RADIUS_PX) {
      ctx.fillStyle = hot ? COLORS.selected : COLORS.disc;
      ctx.fillText(id, sx, sy);
    }
  }
  drawOverlay(ctx, view, size, rect, o.overlay);
}

const layer = new DiscLayer();
const DISC_RGB = parseHex(COLORS.disc);

/**
 * Largest ring drawn into the image (device px): the pixels of a ring grow with its radius, and a
 * disc larger on screen (a zoomed-in view, where few are in view) is cheaper stroked as an arc.
 * (20,000 rings took 3 ms at a radius of 0.75 device px, 30 ms at 8.)
 */
const RING_MAX_RADIUS = 6;

/**
 * Many discs: hairline outlines rasterized into one image (discLayer.ts); the discs too large for it,
 * or all of them where no offscreen canvas can be made, are one path of arcs stroked one device
 * pixel wide.
 */
function drawRings(ctx: CanvasRenderingContext2D, scr: Float64Array, n: number, pixelRatio: number): void {
  const imaged = layer.draw(ctx, scr, n, pixelRatio, MIN_RADIUS_PX, RING_MAX_RADIUS, DISC_RGB);
  let arcs = false;
  ctx.beginPath();
  for (let i = 0; i < n; i++) {
    const rs = scr[3 * i + 2]!;
    if (rs < 0) continue;
    const r = Math.max(rs, MIN_RADIUS_PX);
    if (imaged && r * pixelRatio <= RING_MAX_RADIUS) continue;
    ctx.moveTo(scr[3 * i]! + r, scr[3 * i + 1]!);
    ctx.arc(scr[3 * i]!, scr[3 * i + 1]!, r, 0, 2 * Math.PI);
    arcs = true;
  }
  if (!arcs) return;
  ctx.strokeStyle = COLORS.disc;
  ctx.lineWidth = 1 / pixelRatio;
  ctx.stroke();
}

let buffer = new Float64Array(0);
/** A scratch buffer of 3 numbers per disc (screen x, y, radius or −1 when off screen). */
function screenBuffer(n: number): Float64Array {
  if (buffer.length < 3 * n) buffer = new Float64Array(3 * n);
  return buffer;
}

function arrowPath(ctx: CanvasRenderingContext2D, sx: number, sy: number, ex: number, ey: number) {
  const dx = ex - sx;
  const dy = ey - sy;
  const len = Math.sqrt(dx * dx + dy * dy);
  if (len < 2) return;
  ctx.moveTo(sx, sy);
  ctx.lineTo(ex, ey);
  const h = Math.min(8, len / 3);
  const ux = dx / len;
  const uy = dy / len;
  ctx.moveTo(ex - h * ux + h * 0.5 * uy, ey - h * uy - h * 0.5 * ux);
  ctx.lineTo(ex, ey);
  ctx.lineTo(ex - h * ux - h * 0.5 * uy, ey - h * uy + h * 0.5 * ux);
}

function drawOverlay(
  ctx: CanvasRenderingContext2D,
  view: View,
  size: Size,
  rect: { minX: number; minY: number; maxX: number; maxY: number },
  o: Overlay | null,
) {
  if (!o) return;
  ctx.setLineDash([5, 4]);
  ctx.strokeStyle = COLORS.selected;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  if (o.kind === "disc") {
    const [sx, sy] = toScreen(view, size, o.x, o.y);
    ctx.arc(sx, sy, Math.max(o.r * view.scale, 2), 0, 2 * Math.PI);
  } else if (o.kind === "arrow") {
    const [sx, sy] = toScreen(view, size, o.from[0], o.from[1]);
    const [ex, ey] = toScreen(view, size, o.to[0], o.to[1]);
    arrowPath(ctx, sx, sy, ex, ey);
  } else {
    const c = clipToRect(o.p1, o.p2, o.lineKind, rect);
    if (c) {
      ctx.moveTo(...toScreen(view, size, c[0][0], c[0][1]));
      ctx.lineTo(...toScreen(view, size, c[1][0], c[1][1]));
    }
  }
  ctx.stroke();
  ctx.setLineDash([]);
}

/** The Path view's line (under the discs): one stroke, broken at NaN pairs. */
function drawPath(ctx: CanvasRenderingContext2D, pts: Float64Array, view: View, size: Size): void {
  ctx.strokeStyle = "rgba(217,72,15,0.75)";
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  let open = false;
  for (let k = 0; k + 1 < pts.length; k += 2) {
    const x = pts[k]!;
    const y = pts[k + 1]!;
    if (Number.isNaN(x)) {
      open = false;
      continue;
    }
    const [sx, sy] = toScreen(view, size, x, y);
    if (open) ctx.lineTo(sx, sy);
    else ctx.moveTo(sx, sy);
    open = true;
  }
  ctx.stroke();
}
