/**
 * Report section 3, bulk reads (bench/engine/bulkReads.mjs): the time of one read of every body of
 * a 20,000-disc gas as objects (stateAt, World.bodies) and as arrays written into the previous
 * result (bodyArraysAt, World.bodyArrays), and the heap bytes of one read each.
 * bulkReadsBlock(engineResults, out) appends markdown lines to `out`; a run from before these rows
 * existed gets nothing.
 */
import { int, ms, sig, table } from "./format.mjs";

const ORDER = {
  forwards: "forwards (playback)",
  backwards: "backwards (each read replays from the keyframe)",
  now: "at its current time",
};

const NAMES = {
  Timeline: ["stateAt(t)", "bodyArraysAt(t, into)"],
  World: ["bodies(t)", "bodyArrays(t, into)"],
};

export function bulkReadsBlock(e, out) {
  const b = e.bulkReads;
  if (!b) return;
  out.push("### Bulk reads: every body of 20,000 at one time\n");
  if (b.error) {
    out.push(`Not measured: ${b.error}\n`);
    return;
  }
  out.push(
    `One read of all ${int(b.bodies)} discs of a 10 % gas (${int(b.events)} events computed, horizon ${sig(b.horizon)} s): as one object per body, or as one \`Float64Array\` per field written into the previous read's arrays (\`BodyArrays\`). The timeline reads ${b.reads} times spread over the history in order, then in reverse; passes of the two ways alternate, and each figure is the median of ${b.passes} passes' means.\n`,
  );
  out.push(
    table(
      ["read", "times", "as objects", "as arrays", "objects / arrays"],
      b.rows.map((r) => {
        const [objects, arrays] = NAMES[r.api] ?? ["objects", "arrays"];
        return [
          `${r.api}: ${objects} vs ${arrays}`,
          ORDER[r.order] ?? r.order,
          ms(r.objectsNs),
          ms(r.arraysNs),
          `${sig(r.objectsNs / r.arraysNs)}×`,
        ];
      }),
    ),
  );
  out.push("");
  const a = b.allocation;
  if (a)
    out.push(
      `JS heap allocated by one read (typed arrays' stores not counted; the timeline one step of the playback on): stateAt ${int(a.stateAt)} bytes, bodyArraysAt ${int(a.bodyArraysAt)}; World.bodies ${int(a.bodies)}, bodyArrays ${int(a.bodyArrays)}.\n`,
    );
}
