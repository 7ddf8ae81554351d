/**
 * Far approaches (part of section "stress"): a pair whose path spans 10^k contact distances before
 * it meets. The contact polynomial's terms grow like the span squared, so before re-anchoring
 * (engine: physics/farContact.ts) a disc dropped from 1e8 radii onto a point fell through it.
 * Two families, each against its closed form:
 * - drop: a disc of radius 1 at rest at (0.5, H) under gravity 10 falls onto a point at the
 *   origin; it touches at t = sqrt(2 (H - sqrt(0.75)) / 10).
 * - slide: a disc of radius 1 slides under friction (deceleration 2) towards a resting disc of
 *   radius 1 whose centre is L ahead, with the speed to stop 0.5 past the contact; it touches when
 *   it has covered L - 2, at t = 2 (L - 2) / (v + sqrt(v^2 - 4 (L - 2))).
 * Reported per row: whether the contact was found, the relative error of its time, and the contact
 * distance error measured from the reported positions, beside one ulp of the largest coordinate
 * relative to the contact distance (positions of size H cannot place a contact closer than that).
 */

function firstEvent(world) {
  let first = null;
  world.advance({ maxEvents: 1 }, (e) => {
    first ??= e;
  });
  return first;
}

const ulp = (x) => {
  const a = Math.abs(x);
  return a === 0 ? Number.MIN_VALUE : 2 ** (Math.floor(Math.log2(a)) - 52);
};

function row(family, span, event, kind, exactTime, distance, R, largest) {
  const found = event !== null && event.kind === kind;
  return {
    family,
    span,
    found,
    time: found ? event.time : null,
    exactTime,
    timeError: found ? Math.abs(event.time - exactTime) / exactTime : null,
    contactError: found ? Math.abs(distance(event.time) - R) / R : null,
    positionUlp: ulp(largest) / R,
  };
}

function drop(engine, H) {
  const world = new engine.World({ g: 0, gravity: [0, -10] });
  world.addPoint("pin", [0, 0]);
  world.addBody("ball", { x: 0.5, y: H, r: 1, m: 1, vx: 0, vy: 0 });
  const event = firstEvent(world);
  const distance = (t) => {
    const b = world.body("ball", t);
    return Math.hypot(b.x, b.y);
  };
  return row("drop", H, event, "bodyPoint", Math.sqrt((2 * (H - Math.sqrt(0.75))) / 10), distance, 1, H);
}

function slide(engine, L) {
  const world = new engine.World({ g: 10 });
  const v = Math.sqrt(2 * 2 * (L - 2 + 0.5));
  world.addBody("slider", { x: 0, y: 0, r: 1, m: 1, mu: 0.2, vx: v, vy: 0 });
  world.addBody("target", { x: L, y: 0, r: 1, m: 1, mu: 0.2, vx: 0, vy: 0 });
  const event = firstEvent(world);
  const distance = (t) => {
    const a = world.body("slider", t);
    const b = world.body("target", t);
    return Math.hypot(b.x - a.x, b.y - a.y);
  };
  // v^2 - 4 (L - 2) cancels about log10(L) digits: v^2 is taken exactly (Dekker's product) first.
  const exactTime = (2 * (L - 2)) / (v + Math.sqrt(squareMinus(v, 4 * (L - 2))));
  return row("slide", L, event, "bodyBody", exactTime, distance, 2, L);
}

/** v^2 - c with v^2 exact (Dekker's split product), for c within a factor 2 of v^2. */
function squareMinus(v, c) {
  const p = v * v;
  const big = 134217729 * v;
  const hi = big - (big - v);
  const lo = v - hi;
  const err = hi * hi - p + 2 * hi * lo + lo * lo;
  return p - c + err;
}

/** Both families at spans 10^2 … 10^12. */
export function runFarApproaches(engine, log) {
  const rows = [];
  for (let k = 2; k <= 12; k += 2) {
    for (const r of [drop(engine, 10 ** k), slide(engine, 10 ** k)]) {
      rows.push(r);
      log(
        `  far ${r.family} 1e${k}: ${r.found ? `time error ${r.timeError.toExponential(1)}, contact error ${r.contactError.toExponential(1)}` : "MISSED"}`,
      );
    }
  }
  return rows;
}
