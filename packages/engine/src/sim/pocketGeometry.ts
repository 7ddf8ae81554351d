/**
 * Geometry of the sets a disc's centre may not enter, for the trap watch (pocket.ts). Pure
 * functions. A core is a point (an obstacle point, or the centre of an immovable disc of radius
 * `rad`) or the solid part of a line (a segment, a ray from p1 through p2, or an infinite line); a
 * disc of radius ρ keeps its centre out of the core widened by rad + ρ, a closed convex set. Here:
 * a core's nearest point and distance, the distance from a triangle (the hull of a path, possibly
 * flat) to a core, the points where the borders of two widened cores may cross, and the winding
 * number of a polygon around a point.
 */

/** Length of (x, y), by + * and sqrt only (Math.hypot's rounding is left to each JavaScript engine). */
export function length(x: number, y: number): number {
  return Math.sqrt(x * x + y * y);
}

/** The shape of a core: a point (or a disc's centre) or the solid part of a line. */
export type CoreKind = "point" | "segment" | "ray" | "line";

/** A core: a point at (x1, y1), or the line p1–p2 of its kind; `rad` its own radius (a disc's). */
export interface Core {
  readonly kind: CoreKind;
  readonly x1: number;
  readonly y1: number;
  readonly x2: number;
  readonly y2: number;
  readonly rad: number;
}

/** Nearest point of the core to (x, y), written to out[0], out[1]. */
export function coreNearest(core: Core, x: number, y: number, out: Float64Array): void {
  if (core.kind === "point") {
    out[0] = core.x1;
    out[1] = core.y1;
    return;
  }
  const ex = core.x2 - core.x1;
  const ey = core.y2 - core.y1;
  let lambda = ((x - core.x1) * ex + (y - core.y1) * ey) / (ex * ex + ey * ey);
  if (core.kind !== "line" && lambda < 0) lambda = 0;
  if (core.kind === "segment" && lambda > 1) lambda = 1;
  out[0] = core.x1 + lambda * ex;
  out[1] = core.y1 + lambda * ey;
}

const near = new Float64Array(2);

/** Distance from (x, y) to the core (its own radius not subtracted). */
export function coreDistance(core: Core, x: number, y: number): number {
  coreNearest(core, x, y, near);
  return length(x - (near[0] as number), y - (near[1] as number));
}

/** Orientation of c against the line a→b: > 0 on its left, < 0 on its right, 0 on it. */
function orient(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/**
 * Winding number of the closed polygon `ring` (x0, y0, x1, y1, ...; the last vertex joined to the
 * first) around (px, py): how many times it turns around the point, counterclockwise positive;
 * 0 when the point is outside it. The caller keeps the point off the edges.
 */
export function windingNumber(ring: readonly number[], px: number, py: number): number {
  let winding = 0;
  const n = ring.length;
  for (let i = 0; i < n; i += 2) {
    const ax = ring[i] as number;
    const ay = ring[i + 1] as number;
    const bx = ring[(i + 2) % n] as number;
    const by = ring[(i + 3) % n] as number;
    if (ay <= py) {
      if (by > py && orient(ax, ay, bx, by, px, py) > 0) winding++;
    } else if (by <= py && orient(ax, ay, bx, by, px, py) < 0) winding--;
  }
  return winding;
}

/** Distance from (px, py) to the segment a–b. */
function pointSegmentDistance(
  px: number,
  py: number,
  ax: number,
  ay: number,
  bx: number,
  by: number,
): number {
  const ex = bx - ax;
  const ey = by - ay;
  const ee = ex * ex + ey * ey;
  const lambda = ee > 0 ? Math.min(1, Math.max(0, ((px - ax) * ex + (py - ay) * ey) / ee)) : 0;
  return length(px - (ax + lambda * ex), py - (ay + lambda * ey));
}

/** Distance between the segments a–b and c–d (0 when they cross). */
function segmentsDistance(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  cx: number,
  cy: number,
  dx: number,
  dy: number,
): number {
  const o1 = orient(ax, ay, bx, by, cx, cy);
  const o2 = orient(ax, ay, bx, by, dx, dy);
  const o3 = orient(cx, cy, dx, dy, ax, ay);
  const o4 = orient(cx, cy, dx, dy, bx, by);
  // Crossing (not all four on one line: collinear segments are measured by their end points).
  if (o1 * o2 <= 0 && o3 * o4 <= 0 && !(o1 === 0 && o2 === 0)) return 0;
  return Math.min(
    pointSegmentDistance(ax, ay, cx, cy, dx, dy),
    pointSegmentDistance(bx, by, cx, cy, dx, dy),
    pointSegmentDistance(cx, cy, ax, ay, bx, by),
    pointSegmentDistance(dx, dy, ax, ay, bx, by),
  );
}

/** Whether (px, py) lies inside or on the triangle t (x0, y0, x1, y1, x2, y2); false when flat. */
function inTriangle(t: Float64Array, px: number, py: number): boolean {
  const [ax, ay, bx, by, cx, cy] = t as unknown as [number, number, number, number, number, number];
  if (orient(ax, ay, bx, by, cx, cy) === 0) return false;
  const o1 = orient(ax, ay, bx, by, px, py);
  const o2 = orient(bx, by, cx, cy, px, py);
  const o3 = orient(cx, cy, ax, ay, px, py);
  return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

/** Distance from the segment a–b to the triangle t (0 when they meet). */
function segmentTriangleDistance(t: Float64Array, ax: number, ay: number, bx: number, by: number): number {
  if (inTriangle(t, ax, ay) || inTriangle(t, bx, by)) return 0;
  let best = Number.POSITIVE_INFINITY;
  for (let k = 0; k < 3; k++) {
    const l = (k + 1) % 3;
    const d = segmentsDistance(
      ax,
      ay,
      bx,
      by,
      t[2 * k] as number,
      t[2 * k + 1] as number,
      t[2 * l] as number,
      t[2 * l + 1] as number,
    );
    best = Math.min(best, d);
  }
  return best;
}

/**
 * Distance from the triangle t (x0, y0, x1, y1, x2, y2; a flat one is the segment it spans) to the
 * core (its own radius not subtracted): 0 when they meet. An infinite line or a ray is measured by
 * its part alongside the triangle, which holds the nearest point.
 */
export function triangleCoreDistance(t: Float64Array, core: Core): number {
  if (core.kind === "point") {
    if (inTriangle(t, core.x1, core.y1)) return 0;
    let best = Number.POSITIVE_INFINITY;
    for (let k = 0; k < 3; k++) {
      const l = (k + 1) % 3;
      const d = pointSegmentDistance(
        core.x1,
        core.y1,
        t[2 * k] as number,
        t[2 * k + 1] as number,
        t[2 * l] as number,
        t[2 * l + 1] as number,
      );
      best = Math.min(best, d);
    }
    return best;
  }
  const ex = core.x2 - core.x1;
  const ey = core.y2 - core.y1;
  let lo = 0;
  let hi = 1;
  if (core.kind !== "segment") {
    let min = Number.POSITIVE_INFINITY;
    let max = Number.NEGATIVE_INFINITY;
    const ee = ex * ex + ey * ey;
    for (let k = 0; k < 3; k++) {
      const lambda = (((t[2 * k] as number) - core.x1) * ex + ((t[2 * k + 1] as number) - core.y1) * ey) / ee;
      min = Math.min(min, lambda);
      max = Math.max(max, lambda);
    }
    lo = core.kind === "ray" ? 0 : min - 1;
    hi = Math.max(lo, max) + 1;
  }
  return segmentTriangleDistance(
    t,
    core.x1 + lo * ex,
    core.y1 + lo * ey,
    core.x1 + hi * ex,
    core.y1 + hi * ey,
  );
}

/** The border at distance `reach` from a core, as pieces: lines (px, py, dx, dy) and circles (cx, cy, radius). */
function borderPieces(core: Core, reach: number, lines: number[], circles: number[]): void {
  if (core.kind === "point") {
    circles.push(core.x1, core.y1, reach);
    return;
  }
  const ex = core.x2 - core.x1;
  const ey = core.y2 - core.y1;
  const len = length(ex, ey);
  const nx = (-ey / len) * reach;
  const ny = (ex / len) * reach;
  lines.push(core.x1 + nx, core.y1 + ny, ex, ey, core.x1 - nx, core.y1 - ny, ex, ey);
  if (core.kind !== "line") circles.push(core.x1, core.y1, reach);
  if (core.kind === "segment") circles.push(core.x2, core.y2, reach);
}

/** Crossings of the line p + s d with the circle (c, L), pushed as x, y pairs. */
function lineCircle(
  px: number,
  py: number,
  dx: number,
  dy: number,
  cx: number,
  cy: number,
  L: number,
  out: number[],
): void {
  const fx = px - cx;
  const fy = py - cy;
  const a = dx * dx + dy * dy;
  const b = fx * dx + fy * dy;
  const c = fx * fx + fy * fy - L * L;
  const disc = b * b - a * c;
  if (!(disc >= 0)) return;
  const root = Math.sqrt(disc);
  for (const s of [(-b - root) / a, (-b + root) / a]) out.push(px + s * dx, py + s * dy);
}

/**
 * Points where the borders of core a widened to `reachA` and core b widened to `reachB` (each the
 * border's whole distance from its core, the core's own radius included) may cross, pushed to
 * `out` as x, y pairs: the crossings of every straight and round piece of one border
 * with every piece of the other, each piece taken whole (an end cap as its full circle). A
 * superset: the caller keeps only the points it verifies to lie in both sets.
 */
export function borderCrossings(a: Core, reachA: number, b: Core, reachB: number, out: number[]): void {
  const linesA: number[] = [];
  const circlesA: number[] = [];
  const linesB: number[] = [];
  const circlesB: number[] = [];
  borderPieces(a, reachA, linesA, circlesA);
  borderPieces(b, reachB, linesB, circlesB);
  for (let i = 0; i < linesA.length; i += 4) {
    const [px, py, dx, dy] = linesA.slice(i, i + 4) as [number, number, number, number];
    for (let j = 0; j < linesB.length; j += 4) {
      const [qx, qy, ex, ey] = linesB.slice(j, j + 4) as [number, number, number, number];
      const den = dx * ey - dy * ex;
      if (den === 0) continue;
      const s = ((qx - px) * ey - (qy - py) * ex) / den;
      out.push(px + s * dx, py + s * dy);
    }
    for (let j = 0; j < circlesB.length; j += 3)
      lineCircle(
        px,
        py,
        dx,
        dy,
        circlesB[j] as number,
        circlesB[j + 1] as number,
        circlesB[j + 2] as number,
        out,
      );
  }
  for (let i = 0; i < circlesA.length; i += 3) {
    const [cx, cy, L] = circlesA.slice(i, i + 3) as [number, number, number];
    for (let j = 0; j < linesB.length; j += 4) {
      const [qx, qy, ex, ey] = linesB.slice(j, j + 4) as [number, number, number, number];
      lineCircle(qx, qy, ex, ey, cx, cy, L, out);
    }
    for (let j = 0; j < circlesB.length; j += 3) {
      const [kx, ky, M] = circlesB.slice(j, j + 3) as [number, number, number];
      const dx = kx - cx;
      const dy = ky - cy;
      const d = length(dx, dy);
      if (d === 0 || d > L + M || d < Math.abs(L - M)) continue;
      const along = (L * L - M * M + d * d) / (2 * d);
      const h = Math.sqrt(Math.max(0, L * L - along * along));
      const mx = cx + (along * dx) / d;
      const my = cy + (along * dy) / d;
      out.push(mx - (h * dy) / d, my + (h * dx) / d, mx + (h * dy) / d, my - (h * dx) / d);
    }
  }
}
