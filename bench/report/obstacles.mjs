/**
 * Report section 3, obstacle-heavy scenes (bench/engine/obstacles.mjs): µs per event of a few discs
 * among 100 to 10,000 segments or points, with the grid and without it, the cost per event
 * against the row of fewest obstacles of the same kind, and the time to build each scene (a run
 * from before it was measured shows a dash). obstaclesBlock(engineResults, out) appends
 * markdown lines to `out`; a run from before these rows existed gets nothing.
 */
import { int, sig, table } from "./format.mjs";

export function obstaclesBlock(e, out) {
  const o = e.obstacles;
  if (!o) return;
  out.push("### Obstacle-heavy scenes: few discs, many segments or points\n");
  if (o.error) {
    out.push(`Not measured: ${o.error}\n`);
    return;
  }
  out.push(
    "A maze: discs of radius 1 at speed 10 in a square lattice of corridors 6 wide, walled by the boundary and random interior walls, 100 to 10,000 segments in all; a Galton board: balls of radius 1 falling under gravity through a triangular lattice of point pegs 4 apart in a box (`bench/scenes/obstacles.mjs`). The grid is laid out over the obstacles when its estimated cost per collision is at most 70 % of the layout sized by the bodies alone (`GRID_OBSTACLE_GAIN`, `sim/gridCost.ts`), so the cost per event should barely grow with the obstacles. Rows run one after the other in one process, each on a fresh World after a warm-up, then timed batches (median). Without the grid (`optimizations: { broadPhase: false }`) every prediction tests every body, segment and point: a smaller batch after a short warm-up, and whether the two Worlds then hold the same state, bit for bit. Build: a World, every wall, point and disc added through the public API, and `advance({ maxEvents: 0 })` (the grid laid out, the obstacles registered in its cells, the discs predicted), the median of the row's three builds; per obstacle it should not grow with the obstacles.\n",
  );
  const first = new Map();
  for (const r of o.rows) if (!r.error && !first.has(r.kind)) first.set(r.kind, r);
  out.push(
    table(
      [
        "scene",
        "discs",
        "obstacles",
        "grid cells",
        "events per batch",
        "runs",
        "µs per event",
        "vs fewest obstacles",
        "µs per event without the grid",
        "same state",
        "build ms",
        "build µs per obstacle",
      ],
      o.rows.map((r) =>
        r.error
          ? [r.kind, r.discs, int(r.obstacles), "", "", "", `error: ${r.error}`, "", "", "", "", ""]
          : [
              r.kind,
              r.discs,
              int(r.obstacles),
              int(r.cells),
              int(r.batch),
              r.runs,
              sig(r.usPerEvent),
              `${sig(r.usPerEvent / first.get(r.kind).usPerEvent)}×`,
              sig(r.offUsPerEvent),
              r.sameAsOff ? "yes" : "**no**",
              sig(r.buildMs),
              sig(r.buildUsPerObstacle),
            ],
      ),
    ),
  );
  out.push("");
}
