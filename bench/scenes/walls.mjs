/**
 * Wall helpers for the engine-neutral scene description.
 * A wall is { id, p1, p2, kind, inside: [nx, ny], thickness }: chapgame uses the segment/line
 * itself; the step-based peers build a solid box of `thickness` behind it (on the side opposite
 * `inside`), which is the usual way to give them a wall and generous to them (thick walls tunnel
 * less). `kind: "line"` walls are given to peers as a box `reach` long.
 */
export function boxWalls(x0, y0, x1, y1, thickness) {
  return [
    { id: "wall-bottom", p1: [x0, y0], p2: [x1, y0], kind: "segment", inside: [0, 1], thickness },
    { id: "wall-right", p1: [x1, y0], p2: [x1, y1], kind: "segment", inside: [-1, 0], thickness },
    { id: "wall-top", p1: [x1, y1], p2: [x0, y1], kind: "segment", inside: [0, -1], thickness },
    { id: "wall-left", p1: [x0, y1], p2: [x0, y0], kind: "segment", inside: [1, 0], thickness },
  ];
}

/**
 * The solid box a peer builds for a wall: centre, half extents along and across the wall, angle.
 * Segment walls are extended by `thickness` at both ends so box corners stay closed.
 */
export function wallBox(wall, reach = 1e4) {
  const [ax, ay] = wall.p1;
  const [bx, by] = wall.p2;
  const len = Math.hypot(bx - ax, by - ay);
  const ux = (bx - ax) / len;
  const uy = (by - ay) / len;
  const [nx, ny] = wall.inside;
  const t = wall.thickness;
  const half = wall.kind === "line" ? reach : len / 2 + t;
  const cx = (ax + bx) / 2 - (nx * t) / 2;
  const cy = (ay + by) / 2 - (ny * t) / 2;
  return { cx, cy, hx: half, hy: t / 2, angle: Math.atan2(uy, ux) };
}
